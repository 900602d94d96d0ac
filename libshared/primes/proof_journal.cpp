/// @file proof_journal.cpp
#include "primes/proof_journal.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "io/atomic_file.hpp"
#include "io/error.hpp"

namespace tk::primes {

namespace {

constexpr std::string_view kCheckpointMagic = "riesel-checkpoint 1";

std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (unsigned char byte : bytes) hash = (hash ^ byte) * 0x100000001b3ull;
  return hash;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw Error(fmt::format("cannot {}: {}", what, std::strerror(errno)), Location{path, 0});
}

std::FILE* open_append(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "a");
  if (!file) fail(path, "open for appending");
  return file;
}

void append_synced(std::FILE* file, const std::string& path, const std::string& line) {
  if (std::fputs(line.c_str(), file) < 0 || std::fputc('\n', file) < 0 || std::fflush(file) != 0 ||
      ::fsync(fileno(file)) != 0)
    fail(path, "write");
}

}  // namespace

ProofJournal::ProofJournal(std::string directory) : directory_(std::move(directory)) {
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error) throw Error("cannot create the state directory: " + error.message(), Location{directory_, 0});
  const std::string lock = directory_ + "/lock";
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) fail(lock, "open the lock");
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw Error("another run holds this state directory's lock", Location{directory_, 0});
  }
  // Finished records; a torn last line (killed mid-write) has no newline:
  // it is cut off so that the next record starts on a line of its own.
  const std::string journal = directory_ + "/journal.tsv";
  std::uint64_t whole_lines = 0;
  {
    std::ifstream in(journal, std::ios::binary);
    std::string line;
    while (std::getline(in, line)) {
      if (in.eof()) break;  // no newline: torn
      whole_lines += line.size() + 1;
      const auto tab = line.find('\t');
      if (tab == std::string::npos) continue;
      if (Record::accept(line.substr(tab + 1)))  // a damaged line is not a finished record
        finished_[line.substr(0, tab)] = line.substr(tab + 1);
    }
  }
  std::error_code size_error;
  if (std::filesystem::exists(journal) && std::filesystem::file_size(journal, size_error) > whole_lines && !size_error)
    std::filesystem::resize_file(journal, whole_lines, size_error);
  journal_ = open_append(journal);
  log_ = open_append(directory_ + "/lresults.txt");
}

ProofJournal::~ProofJournal() {
  if (journal_) std::fclose(journal_);
  if (log_) std::fclose(log_);
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

std::optional<std::string> ProofJournal::finished(const std::string& key) const {
  const auto found = finished_.find(key);
  if (found == finished_.end()) return std::nullopt;
  return found->second;
}

void ProofJournal::record_finished(const std::string& key, const std::string& output_line) {
  append_synced(journal_, directory_ + "/journal.tsv", key + "\t" + output_line);
  finished_[key] = output_line;
}

void ProofJournal::log_result(const std::string& line) { append_synced(log_, directory_ + "/lresults.txt", line); }

std::string ProofJournal::checkpoint_path(const std::string& member) const {
  return fmt::format("{}/checkpoint-{:016x}", directory_, fnv1a(member));
}

std::optional<ProofState> ProofJournal::load_checkpoint(const std::string& member,
                                                      const std::function<void(const std::string&)>& warn) const {
  const std::string path = checkpoint_path(member);
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  auto damaged = [&](const std::string& why) -> std::optional<ProofState> {
    if (warn) warn(fmt::format("{}: checkpoint {}", path, why));
    return std::nullopt;
  };
  std::string magic, name, iteration, value, checksum;
  if (!std::getline(in, magic) || !std::getline(in, name) || !std::getline(in, iteration) || !std::getline(in, value) ||
      !std::getline(in, checksum))
    return damaged("is truncated");
  const std::string body = magic + "\n" + name + "\n" + iteration + "\n" + value + "\n";
  if (magic != kCheckpointMagic) return damaged("is not a riesel checkpoint");
  if (checksum != fmt::format("{:016x}", fnv1a(body))) return damaged("fails its checksum");
  if (name != member) return damaged("belongs to " + name);
  ProofState state;
  try {
    state.iteration = std::stoull(iteration);
    if (state.value.set_str(value, 16) != 0 || state.value < 0) return damaged("holds no valid residue");
  } catch (const std::exception&) {
    return damaged("holds no valid iteration");
  }
  return state;
}

void ProofJournal::save_checkpoint(const std::string& member, const ProofState& state) const {
  const std::string body =
      fmt::format("{}\n{}\n{}\n{}\n", kCheckpointMagic, member, state.iteration, state.value.get_str(16));
  const std::string text = body + fmt::format("{:016x}\n", fnv1a(body));
  // One temporary name per thread: two proofs of one number may save at once.
  const std::string path = checkpoint_path(member),
                    temporary = fmt::format("{}.tmp{}", path, std::hash<std::thread::id>{}(std::this_thread::get_id()));
  io::write_file_atomically(path, text, temporary);
}

void ProofJournal::remove_checkpoint(const std::string& member) const { std::remove(checkpoint_path(member).c_str()); }

}  // namespace tk::primes
