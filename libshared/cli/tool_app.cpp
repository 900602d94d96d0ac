/// @file tool_app.cpp
#include "cli/tool_app.hpp"

#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <new>

#include "cli/build_info.hpp"
#include "io/error.hpp"

namespace tk::cli {

std::string version_text(const std::string& name) {
  return name + " (toolkit) " + toolkit_version() + " (revision " + toolkit_revision() + ")";
}

ToolApp::ToolApp(std::string name, std::string description, std::string footer)
    : name_(std::move(name)), app_(std::move(description), name_) {
  app_.set_version_flag("--version", version_text(name_), "print the version and exit");
  app_.add_flag("--csv", common_.csv, "write CSV with a header row instead of JSON Lines");
  app_.add_flag("-q,--quiet", common_.quiet, "no warnings or progress on stderr");
  app_.add_flag("--progress", common_.progress, "show progress on stderr even when it is not a terminal");
  if (!footer.empty()) app_.footer(std::move(footer));
  app_.get_formatter()->column_width(30);
}

void ToolApp::add_threads_option() {
  app_.add_option("-j,--threads", common_.threads, "use N threads (the output does not depend on N)")
      ->check(CLI::Range(1u, 1024u))
      ->type_name("N");
}

void ToolApp::add_input_files(const std::string& help) {
  app_.add_option("files", common_.inputs, help)->type_name("FILE");
}

io::OutputFormat ToolApp::output_format() const {
  return common_.csv ? io::OutputFormat::csv : io::OutputFormat::json_lines;
}

bool ToolApp::show_progress() const { return !common_.quiet && (common_.progress || isatty(STDERR_FILENO)); }

void ToolApp::warn(const std::string& message) const {
  if (!common_.quiet) std::fprintf(stderr, "%s: %s\n", name_.c_str(), message.c_str());
}

int ToolApp::run(int argc, char** argv, const std::function<void()>& body) {
  std::signal(SIGPIPE, SIG_DFL);
  // Room for a long record (a loop's polyline) in one write: RecordWriter
  // flushes on record boundaries, and the default 4 KiB buffer would send a
  // longer record in two writes, which a kill can part. Before any output.
  static char stdout_buffer[1 << 16];
  if (!isatty(STDOUT_FILENO)) std::setvbuf(stdout, stdout_buffer, _IOFBF, sizeof stdout_buffer);
  auto usage_error = [&](const std::string& message) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: %s\nTry '%s --help' for more information.\n", name_.c_str(), message.c_str(),
                 name_.c_str());
    return 2;
  };
  try {
    app_.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app_.exit(e) == 0 ? 0 : 2;
  } catch (const CLI::CallForAllHelp& e) {
    return app_.exit(e) == 0 ? 0 : 2;
  } catch (const CLI::CallForVersion& e) {
    return app_.exit(e) == 0 ? 0 : 2;
  } catch (const CLI::ParseError& e) {
    std::string message = e.what();
    // Lowercase a sentence's first word ("The following..."), not a name ("SHARD is required").
    if (message.size() > 1 && std::islower(static_cast<unsigned char>(message[1])))
      message[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(message[0])));
    return usage_error(message);
  }

  int status = 0;
  try {
    body();
  } catch (const UsageError& e) {
    return usage_error(e.located_message());
  } catch (const Error& e) {
    std::fflush(stdout);  // records already decided stay written
    std::fprintf(stderr, "%s: %s\n", name_.c_str(), e.located_message().c_str());
    status = 1;
  } catch (const std::bad_alloc&) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: out of memory\n", name_.c_str());
    status = 1;
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: internal error: %s\n", name_.c_str(), e.what());
    status = 1;
  }
  // Like coreutils' close_stdout: a full disk or closed descriptor is an error.
  if (std::fflush(stdout) != 0 || std::ferror(stdout) || std::fclose(stdout) != 0) {
    if (status == 0) std::fprintf(stderr, "%s: write error: %s\n", name_.c_str(), std::strerror(errno));
    status = 1;
  }
  return status;
}

}  // namespace tk::cli
