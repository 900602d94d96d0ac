/// @file atomic_file_test.cpp
/// @brief io::AtomicFile: the target changes only on commit(); temporaries
/// of dead writers are removed, a live writer's are left; devices are
/// written in place, links followed.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "io/atomic_file.hpp"
#include "io/error.hpp"

namespace {

namespace fs = std::filesystem;

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A fresh directory per test, removed afterwards.
class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tk_atomic_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::size_t entries() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {})); }

  fs::path dir_;
};

/// The pid of a process that has ended (reaped, so no longer running).
long dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

TEST_F(AtomicFileTest, TheTargetKeepsItsContentUntilCommitAndWithoutOne) {
  const std::string target = path("trace.jsonl");
  std::ofstream(target) << "old\n";
  {
    tk::io::AtomicFile file(target);
    std::fputs("new\n", file.stream());
    std::fflush(file.stream());
    EXPECT_EQ(read_all(target), "old\n");
    EXPECT_EQ(read_all(tk::io::temporary_name(target, ::getpid())), "new\n");
  }  // no commit: an error on the way
  EXPECT_EQ(read_all(target), "old\n");
  EXPECT_EQ(entries(), 1u);
  {
    tk::io::AtomicFile file(target);
    std::fputs("new\n", file.stream());
    file.commit();
  }
  EXPECT_EQ(read_all(target), "new\n");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, TheReplacementKeepsThePermissions) {
  const std::string target = path("plot.svg");
  std::ofstream(target) << "old";
  ::chmod(target.c_str(), 0600);
  tk::io::write_file_atomically(target, "new");
  struct stat st {};
  ASSERT_EQ(::stat(target.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_EQ(read_all(target), "new");
}

TEST_F(AtomicFileTest, TemporariesOfDeadWritersGoThoseOfLiveOnesStay) {
  const std::string target = path("trace.jsonl");
  const std::string dead = tk::io::temporary_name(target, dead_pid());
  const std::string live = tk::io::temporary_name(target, ::getppid());  // our parent runs
  const std::string other = path(".other.jsonl.tmp.1");                  // another target's
  const std::string unrelated = path(".trace.jsonl.tmp.notes");
  for (const std::string& name : {dead, live, other, unrelated}) std::ofstream(name) << "x";
  tk::io::write_file_atomically(target, "new\n");
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));
  EXPECT_TRUE(fs::exists(unrelated));
  EXPECT_EQ(read_all(target), "new\n");
}

TEST_F(AtomicFileTest, ALinkIsFollowedADeviceWrittenInPlace) {
  const std::string real = path("real.svg"), link = path("link.svg");
  std::ofstream(real) << "old";
  fs::create_symlink(real, link);
  tk::io::write_file_atomically(link, "new");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read_all(real), "new");

  tk::io::write_file_atomically("/dev/null", "bytes");  // not replaced by a regular file
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST_F(AtomicFileTest, AnUnwritableDirectoryIsAnErrorNamingTheTarget) {
  const std::string target = path("missing/plot.svg");
  try {
    tk::io::write_file_atomically(target, "x");
    FAIL() << "no error";
  } catch (const tk::Error& e) {
    EXPECT_EQ(e.where().file, target);
  }
}

}  // namespace
