/// @file tool_app.hpp
/// @brief The options layer every tool shares (CLI11) and the one place that
/// turns errors into messages and exit statuses.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "io/record_writer.hpp"

namespace tk::cli {

/// Options every record filter has.
struct CommonOptions {
  bool csv = false;
  bool quiet = false;
  bool progress = false;
  unsigned threads = 1;
  std::vector<std::string> inputs;
};

/// Wraps CLI11 with the toolkit's conventions: --help and --version on
/// stdout with exit 0; usage errors as "tool: message" plus "Try 'tool
/// --help' for more information." with exit 2; Error as
/// "tool: file:line: message" with exit 1; SIGPIPE at its default action;
/// write errors on stdout reported.
class ToolApp {
 public:
  ToolApp(std::string name, std::string description, std::string footer = {});

  CLI::App& app() { return app_; }
  CommonOptions& common() { return common_; }
  const std::string& name() const { return name_; }

  /// -j/--threads N for tools that work on several records at once.
  void add_threads_option();
  /// Positional FILE... (stdin when none; "-" is stdin).
  void add_input_files(const std::string& help = "input files; standard input when none or '-'");

  /// Parses argv and runs body; returns the process exit status.
  int run(int argc, char** argv, const std::function<void()>& body);

  io::OutputFormat output_format() const;
  /// Progress goes to stderr when it is a terminal or --progress is given, never with --quiet.
  bool show_progress() const;
  /// "tool: message" on stderr (suppressed by --quiet).
  void warn(const std::string& message) const;

 private:
  std::string name_;
  CLI::App app_;
  CommonOptions common_;
};

/// "name (toolkit) X.Y.Z (revision R)" as --version prints it; R is the
/// git revision the build came from, so a result in a log traces to a build.
std::string version_text(const std::string& name);

}  // namespace tk::cli
