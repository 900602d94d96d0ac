/// @file proof_journal.cpp
#include "primes/proof_journal.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "io/atomic_file.hpp"
#include "io/checksum.hpp"
#include "io/error.hpp"
#include "io/file_lock.hpp"

namespace tk::primes {

namespace {

int open_append(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw errno_error(path, "open for appending", errno);
  return fd;
}

std::uint64_t file_size(int fd, const std::string& path) {
  struct stat status {};
  if (::fstat(fd, &status) != 0) throw errno_error(path, "read the size of", errno);
  return static_cast<std::uint64_t>(status.st_size);
}

/// `length` bytes of the file from `offset` (fewer at its end).
std::string read_at(int fd, const std::string& path, std::uint64_t offset, std::size_t length) {
  std::string bytes(length, '\0');
  std::size_t done = 0;
  while (done < length) {
    const ssize_t got = ::pread(fd, bytes.data() + done, length - done, static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw errno_error(path, "read", errno);
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  bytes.resize(done);
  return bytes;
}

std::string read_whole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

ProofJournal::ProofJournal(std::string directory, const Warn& warn) : directory_(std::move(directory)) {
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error) throw Error("cannot create the state directory: " + error.message(), Location{directory_, 0});
  lock_ = std::make_unique<io::FileLock>(directory_ + "/lock", directory_, "this state directory");
  load_journal(warn);
}

void ProofJournal::load_journal(const Warn& warn) {
  const std::string path = directory_ + "/journal.tsv";
  const std::string text = read_whole(path);
  const JournalText journal = read_journal(text);
  for (const JournalEntry& entry : journal.entries) finished_[entry.key] = entry.output;
  if (!journal.refused.empty()) {
    // Kept aside, not deleted: a refused line is still evidence of what ran.
    const std::string rejected_path = directory_ + "/journal.rejected";
    std::string rejected, kept;
    for (const auto& refused : journal.refused) rejected += refused.text + "\n";
    for (const JournalEntry& entry : journal.entries) kept += journal_line(entry) + "\n";
    const int rejected_fd = open_append(rejected_path);
    io::write_all_synced(rejected_fd, rejected_path, rejected);
    ::close(rejected_fd);
    io::write_file_atomically(path, kept, path + ".tmp");
    const auto& first = journal.refused.front();
    if (warn)
      warn(
          fmt::format("{}:{}: journal line {}{}; moved to {}, its record is proved again", path, first.line, first.why,
                      journal.refused.size() > 1 ? fmt::format(" (and {} more lines)", journal.refused.size() - 1) : "",
                      rejected_path));
  } else if (journal.whole_bytes < text.size()) {
    // A torn last line (killed mid-append): cut off, so the next starts on a line of its own.
    std::error_code size_error;
    std::filesystem::resize_file(path, journal.whole_bytes, size_error);
    if (size_error) throw Error("cannot cut its torn last line: " + size_error.message(), Location{path, 0});
  }
  journal_fd_ = open_append(path);
  log_fd_ = open_append(directory_ + "/lresults.txt");
  complete_log(journal.entries.empty() ? std::nullopt : std::optional<JournalEntry>(journal.entries.back()));
}

void ProofJournal::complete_log(const std::optional<JournalEntry>& last) {
  const std::string path = directory_ + "/lresults.txt";
  const std::uint64_t size = file_size(log_fd_, path);
  // Only the last record can have been cut short: records are journaled, then logged, one at a time.
  if (last && last->log_offset <= size) {
    const std::string expected = log_text(*last);
    if (size - last->log_offset < expected.size()) {
      const std::string written = read_at(log_fd_, path, last->log_offset, size - last->log_offset);
      if (const auto rest = log_completion(written, *last)) return io::write_all_synced(log_fd_, path, *rest);
    }
  }
  if (size > 0 && read_at(log_fd_, path, size - 1, 1) != "\n") io::write_all_synced(log_fd_, path, "\n");
}

ProofJournal::~ProofJournal() {
  for (const int fd : {journal_fd_, log_fd_})
    if (fd >= 0) ::close(fd);
}

std::optional<std::string> ProofJournal::finished(const std::string& key) const {
  const auto found = finished_.find(key);
  if (found == finished_.end()) return std::nullopt;
  return found->second;
}

void ProofJournal::record_finished(const std::string& key, const std::string& output_line,
                                   const std::vector<std::string>& log_lines) {
  const std::string log_path = directory_ + "/lresults.txt";
  const JournalEntry entry{key, output_line, file_size(log_fd_, log_path), log_lines};
  // The journal first: a kill before lresults.txt is written is repaired from it on the next start.
  io::write_all_synced(journal_fd_, directory_ + "/journal.tsv", journal_line(entry) + "\n");
  finished_[key] = output_line;
  io::write_all_synced(log_fd_, log_path, log_text(entry));
}

std::string ProofJournal::checkpoint_path(const std::string& member) const {
  return fmt::format("{}/checkpoint-{:016x}", directory_, io::fnv1a(member));
}

std::optional<ProofState> ProofJournal::load_checkpoint(const std::string& member, const Warn& warn) const {
  const std::string path = checkpoint_path(member);
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    return parse_checkpoint(read_whole(path), member);
  } catch (const Error& e) {
    if (warn) warn(fmt::format("{}: checkpoint {}", path, e.what()));
    return std::nullopt;
  }
}

void ProofJournal::save_checkpoint(const std::string& member, const ProofState& state) const {
  // One temporary name per thread: two proofs of one number may save at once.
  const std::string path = checkpoint_path(member),
                    temporary = fmt::format("{}.tmp{}", path, std::hash<std::thread::id>{}(std::this_thread::get_id()));
  io::write_file_atomically(path, checkpoint_text(member, state), temporary);
}

void ProofJournal::remove_checkpoint(const std::string& member) const { std::remove(checkpoint_path(member).c_str()); }

}  // namespace tk::primes
