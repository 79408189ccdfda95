// io::AtomicTextFile: a text file appears complete under its name or not at all.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/io/atomic_file.h"
#include "tracked_vehicle_dynamics/io/mat_file.h"
#include "tracked_vehicle_dynamics/io/staged_files.h"

namespace tracked_vehicle_dynamics {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

int fileCount(const fs::path& dir) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(dir))
    n += entry.exists() ? 1 : 0;
  return n;
}

class AtomicTextFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tvd_atomic_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(AtomicTextFileTest, CommitPutsTheWholeFileUnderItsName) {
  const fs::path path = dir_ / "a.csv";
  io::AtomicTextFile file(path.string());
  file.stream() << "x,y\n1,2\n";
  EXPECT_FALSE(fs::exists(path));  // nothing under the final name before commit()
  file.commit();
  EXPECT_EQ(readAll(path), "x,y\n1,2\n");
  EXPECT_EQ(fileCount(dir_), 1);  // no temporary file left
}

TEST_F(AtomicTextFileTest, WithoutCommitTheOldFileStaysAndNothingIsLeft) {
  const fs::path path = dir_ / "a.csv";
  std::ofstream(path) << "old\n";
  {
    io::AtomicTextFile file(path.string());
    file.stream() << "new, but abandoned (an exception before commit)\n";
  }
  EXPECT_EQ(readAll(path), "old\n");
  EXPECT_EQ(fileCount(dir_), 1);
}

// Two writers of one file in one process (two threads: the same pid, as two containers' pid 1s
// are) each stage apart: their temporary was path + ".tmp" + pid, shared, and the two writes
// interleaved in it; the rename put the mix in place and the other writer's rename failed.
// Here both interleave on purpose (the first is still open when the second writes and commits):
// both commit, and the file is one of them whole.
TEST_F(AtomicTextFileTest, TwoWritersOfOneFileStageApart) {
  const fs::path path = dir_ / "cache.csv";
  const std::string a(100000, 'a'), b(50000, 'b');
  io::AtomicTextFile first(path.string());
  first.stream() << a << std::flush;
  {
    io::AtomicTextFile second(path.string());
    second.stream() << b;
    second.commit();
  }
  EXPECT_EQ(readAll(path), b);
  first.stream() << "\n";
  first.commit();
  EXPECT_EQ(readAll(path), a + "\n");
  EXPECT_EQ(fileCount(dir_), 1);
  const std::string one = io::createTemporaryBeside(path.string(), ".mat");
  const std::string two = io::createTemporaryBeside(path.string(), ".mat");
  EXPECT_NE(one, two);
  EXPECT_EQ(one.size(), path.string().size() + 2 + 6 + 4);  // ".~" + six characters + ".mat"
  EXPECT_EQ(one.substr(0, path.string().size() + 2), path.string() + ".~");
  EXPECT_EQ(one.substr(one.size() - 4), ".mat");
  // Created as a file written in place is (0666 less the umask), not mkstemps' 0600, which the
  // rename gave every output and cache entry: another user could not read a shared cache.
  const mode_t mask = ::umask(022);
  const std::string shared = io::createTemporaryBeside(path.string());
  ::umask(mask);
  EXPECT_EQ(fs::status(shared).permissions(), fs::perms::owner_read | fs::perms::owner_write |
                                                  fs::perms::group_read | fs::perms::others_read);
  EXPECT_TRUE(fs::is_regular_file(one));
}

// matio drops a failed write (its fwrite's EFBIG or ENOSPC) and closes clean: a file size limit or
// a full disk put a truncated .mat in place with no error (review 166). close() checks the file's
// layout and throws, naming the file; the old file stays, no staged file is left.
TEST_F(AtomicTextFileTest, AMatFileCutShortByTheDiskIsRefusedAtClose) {
  const fs::path path = dir_ / "big.mat";
  std::ofstream(path) << "old\n";
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);
  std::string message;
  for (const rlim_t limit : {rlim_t{100}, rlim_t{4096}, rlim_t{20000}}) {
    rlimit limited = saved;
    limited.rlim_cur = limit;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
    message.clear();
    try {
      io::MatWriter mat(path.string());
      mat.writeScalar("first", 1.0);
      mat.writeMatrix("big", Matrix::Random(100, 100));  // 80 kB that do not compress
      mat.writeScalar("last", 2.0);
      mat.close();
    } catch (const InputError& e) {
      message = e.what();
    }
    ::setrlimit(RLIMIT_FSIZE, &saved);
    EXPECT_NE(message.find(path.string() + ": "), std::string::npos) << limit << ": " << message;
    EXPECT_EQ(readAll(path), "old\n") << limit;
    EXPECT_EQ(fileCount(dir_), 1) << limit;
  }
  std::signal(SIGXFSZ, previous_handler);
  // Within the limit it is written whole, compressed too.
  for (const bool compress : {false, true}) {
    io::MatWriter mat(path.string(), io::MatFormat::Mat5, compress);
    mat.writeScalar("first", 1.0);
    mat.writeMatrix("big", Matrix::Constant(100, 100, 0.5));
    mat.writeString("text", "abc");
    mat.close();
    EXPECT_EQ(io::MatReader(path.string()).readMatrix("big")(99, 99), 0.5);
  }
}

// Every staged file is recorded while it is staged and forgotten once committed or dropped, so
// the signal handler removes exactly the writers' leftovers.
TEST_F(AtomicTextFileTest, StagedFilesAreRecordedUntilCommittedOrDropped) {
  const std::size_t before = io::stagedFileCount();
  {
    io::AtomicTextFile kept((dir_ / "kept.csv").string());
    io::AtomicTextFile dropped((dir_ / "dropped.csv").string());
    io::MatWriter mat((dir_ / "kept.mat").string());
    EXPECT_EQ(io::stagedFileCount(), before + 3);
    kept.stream() << "x\n";
    kept.commit();
    mat.writeScalar("x", 1.0);
    mat.close();
    EXPECT_EQ(io::stagedFileCount(), before + 1);
  }
  EXPECT_EQ(io::stagedFileCount(), before);
  EXPECT_EQ(fileCount(dir_), 2);  // kept.csv and kept.mat
  // A failed rename (onto a directory) removes the staged file and forgets it too.
  fs::create_directories(dir_ / "taken.csv");
  {
    io::AtomicTextFile blocked((dir_ / "taken.csv").string());
    EXPECT_THROW(blocked.commit(), InputError);
  }
  EXPECT_EQ(io::stagedFileCount(), before);
  EXPECT_EQ(fileCount(dir_), 3);
}

// A process stopped by SIGINT, SIGTERM or SIGHUP while it writes (Ctrl-C on a long tvd run, or
// roslaunch stopping tvd_make_bag) leaves no staged file, keeps the old file, and still ends by
// the signal (a shell sees 128 + n). Run in a child process, which the signal ends.
TEST_F(AtomicTextFileTest, ASignalRemovesTheStagedFilesAndEndsTheProcess) {
  {
    std::ofstream old(dir_ / "out.csv");
    old << "old\n";
  }
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      io::removeStagedFilesOnSignals();
      io::AtomicTextFile text((dir_ / "out.csv").string());
      text.stream() << "half written";
      text.stream().flush();
      io::MatWriter mat((dir_ / "out.mat").string());
      mat.writeScalar("x", 1.0);
      ::raise(signal_number);
      ::_exit(0);  // not reached: the signal ends the child
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "signal " << signal_number << ", status " << status;
    EXPECT_EQ(WTERMSIG(status), signal_number);
    EXPECT_EQ(fileCount(dir_), 1) << "signal " << signal_number;  // out.csv alone, as it was
    EXPECT_EQ(readAll(dir_ / "out.csv"), "old\n");
  }
  // A file size limit (ulimit -f) ends a process by SIGXFSZ at the write that crosses it, its
  // staged files left (review 167): with the handlers installed the write fails instead, and the
  // writer reports it and cleans up. The child exits 3 when close() threw.
  const pid_t limited = ::fork();
  ASSERT_GE(limited, 0);
  if (limited == 0) {
    io::removeStagedFilesOnSignals();
    rlimit small{};
    ::getrlimit(RLIMIT_FSIZE, &small);
    small.rlim_cur = 4096;
    ::setrlimit(RLIMIT_FSIZE, &small);
    try {
      io::MatWriter mat((dir_ / "out.mat").string());
      mat.writeMatrix("big", Matrix::Random(100, 100));
      mat.close();
    } catch (const InputError&) {
      ::_exit(3);
    }
    ::_exit(0);
  }
  int limited_status = 0;
  ASSERT_EQ(::waitpid(limited, &limited_status, 0), limited);
  ASSERT_TRUE(WIFEXITED(limited_status)) << "ended by signal " << WTERMSIG(limited_status);
  EXPECT_EQ(WEXITSTATUS(limited_status), 3);
  EXPECT_EQ(fileCount(dir_), 1);  // out.csv alone

  // An ignored signal stays ignored (a background job's SIGINT): the child writes on.
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGINT, SIG_IGN);
    io::removeStagedFilesOnSignals();
    io::AtomicTextFile text((dir_ / "out.csv").string());
    text.stream() << "new\n";
    ::raise(SIGINT);
    text.commit();
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(readAll(dir_ / "out.csv"), "new\n");
}

TEST_F(AtomicTextFileTest, MissingDirectoryIsNamed) {
  const std::string path = (dir_ / "missing" / "a.csv").string();
  expectInputError([&] { io::AtomicTextFile file(path); }, {"cannot write", path});
}

// A full disk, simulated by a file-size limit (writes past it fail with EFBIG once SIGXFSZ is
// ignored): commit() throws naming the file, the old file is kept and no temporary is left.
TEST_F(AtomicTextFileTest, FailedWriteThrowsAndLeavesNoPartialFile) {
  const fs::path path = dir_ / "big.csv";
  std::ofstream(path) << "old\n";
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limited = saved;
  limited.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
  std::string message;
  try {
    io::AtomicTextFile file(path.string());
    for (int i = 0; i < 10000; ++i)
      file.stream() << "0123456789\n";
    file.commit();
  } catch (const InputError& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, previous_handler);
  EXPECT_NE(message.find("cannot write " + path.string()), std::string::npos) << message;
  EXPECT_EQ(readAll(path), "old\n");
  EXPECT_EQ(fileCount(dir_), 1);
}

}  // namespace
}  // namespace tracked_vehicle_dynamics
