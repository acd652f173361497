// The CLI's output module (cli/output.hpp): no silent write failure, a closed
// pipe ends quietly, files replaced atomically, destinations checked first.
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/output.hpp"

namespace fs = std::filesystem;
using cemv::cli::check_writable;
using cemv::cli::check_writable_directory;
using cemv::cli::ClosedPipe;
using cemv::cli::Output;
using cemv::cli::OutputError;
using cemv::cli::write_output;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// A fresh folder per test, removed afterwards.
class OutputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cemv-output-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  int files_in_dir() const {
    int n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++n;
    return n;
  }
  fs::path dir_;
};

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const OutputError& e) {
    return e.what();
  }
  return "(no OutputError)";
}

}  // namespace

TEST_F(OutputTest, FullDeviceFailsNamingIt) {
  std::string msg = message_of([] { write_output("/dev/full", std::string(100000, 'x')); });
  EXPECT_EQ(msg.rfind("/dev/full: cannot write: ", 0), 0u) << msg;
}

TEST_F(OutputTest, WritesAndReplacesAFile) {
  fs::path p = dir_ / "r.json";
  write_output(p.string(), "first\n");
  EXPECT_EQ(slurp(p), "first\n");
  write_output(p.string(), "second\n");
  EXPECT_EQ(slurp(p), "second\n");
  EXPECT_EQ(files_in_dir(), 1);  // no temporary left
}

TEST_F(OutputTest, DestinationUntouchedUntilCommit) {
  fs::path p = dir_ / "r.json";
  write_output(p.string(), "old\n");
  {
    Output out(p.string());
    out.write("new, partly written");
    EXPECT_EQ(slurp(p), "old\n");
    EXPECT_EQ(files_in_dir(), 2);  // the temporary sits next to the destination
    out.write(" and complete\n");
    out.commit();
  }
  EXPECT_EQ(slurp(p), "new, partly written and complete\n");
  EXPECT_EQ(files_in_dir(), 1);
}

TEST_F(OutputTest, AbandonedOutputLeavesOldFileAndNoTemporary) {
  fs::path p = dir_ / "r.json";
  write_output(p.string(), "old\n");
  {
    Output out(p.string());
    out.write("half of a new fi");
  }  // destroyed without commit, as when an exception unwinds
  EXPECT_EQ(slurp(p), "old\n");
  EXPECT_EQ(files_in_dir(), 1);
}

TEST_F(OutputTest, ProcessKilledWhileWritingLeavesOldFile) {
  fs::path p = dir_ / "r.json";
  write_output(p.string(), "old\n");
  pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    Output out(p.string());
    out.write(std::string(1 << 20, 'n'));
    ::raise(SIGKILL);  // killed mid-run: commit never happens
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(slurp(p), "old\n");
}

TEST_F(OutputTest, KilledBeforeFirstCommitLeavesNoDestination) {
  fs::path p = dir_ / "new.json";
  pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    Output out(p.string());
    out.write("{\"partial\": ");
    ::raise(SIGKILL);
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_FALSE(fs::exists(p));
}

TEST_F(OutputTest, KeepsTheModeOfTheReplacedFile) {
  fs::path p = dir_ / "r.txt";
  write_output(p.string(), "a");
  fs::permissions(p, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  write_output(p.string(), "b");
  EXPECT_EQ(fs::status(p).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST_F(OutputTest, UnwritableDestinationsFailBeforeAnyWork) {
  std::string missing = (dir_ / "no" / "such" / "dir" / "r.json").string();
  std::string msg = message_of([&] { check_writable(missing); });
  EXPECT_EQ(msg.rfind(missing + ": cannot write: ", 0), 0u) << msg;

  fs::path file = dir_ / "plain";
  write_output(file.string(), "x");
  std::string under_file = (file / "r.json").string();
  msg = message_of([&] { check_writable(under_file); });
  EXPECT_EQ(msg.rfind(under_file + ": cannot write: ", 0), 0u) << msg;

  msg = message_of([&] { check_writable(dir_.string()); });
  EXPECT_NE(msg.find("it is a folder"), std::string::npos) << msg;

  msg = message_of([&] { check_writable_directory(file.string()); });
  EXPECT_NE(msg.find("not a folder"), std::string::npos) << msg;

  // /proc accepts no new files, even for root.
  msg = message_of([] { check_writable("/proc/cemv-report.json"); });
  EXPECT_EQ(msg.rfind("/proc/cemv-report.json: cannot write: ", 0), 0u) << msg;

  // Checking leaves nothing behind.
  EXPECT_EQ(files_in_dir(), 1);
}

TEST_F(OutputTest, WritableDestinationsPass) {
  EXPECT_NO_THROW(check_writable("-"));
  EXPECT_NO_THROW(check_writable((dir_ / "r.json").string()));
  EXPECT_NO_THROW(check_writable("/dev/null"));
  EXPECT_NO_THROW(check_writable_directory((dir_ / "out" / "cex").string()));
  EXPECT_TRUE(fs::is_directory(dir_ / "out" / "cex"));
  EXPECT_TRUE(fs::is_empty(dir_ / "out" / "cex"));
  EXPECT_FALSE(fs::exists(dir_ / "r.json"));
}

TEST_F(OutputTest, DeviceIsWrittenInPlaceNotReplaced) {
  EXPECT_NO_THROW(write_output("/dev/null", "discarded"));
  EXPECT_FALSE(fs::is_regular_file("/dev/null"));
}

TEST_F(OutputTest, ClosedPipeOnStdoutIsClosedPipeNotError) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::close(fds[0]);  // nobody reads
    ::dup2(fds[1], 1);
    try {
      Output out("-");
      out.write(std::string(1 << 20, 'x'));
      out.commit();
    } catch (const ClosedPipe&) {
      ::_exit(42);
    } catch (...) {
      ::_exit(1);
    }
    ::_exit(0);
  }
  ::close(fds[0]);
  ::close(fds[1]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 42);
}

TEST_F(OutputTest, StdoutNamedInMessages) {
  Output out("-");
  EXPECT_EQ(out.name(), "<stdout>");
  EXPECT_TRUE(out.is_stdout());
}
