// base/output_folder.h: an output folder is claimed without touching what
// the user keeps in it, refused where a write would go through a link, and
// held by one process at a time (issue 56, items 1 and 9).
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "base/output_folder.h"
#include "temp_dir.h"

namespace rayspec {
namespace {
namespace fs = std::filesystem;

TEST(OutputFolder, TheOptionCheckChangesNothing) {
  const std::string dir = freshTempDir("outfolder-check");
  const std::string missing = dir + "/not/yet";
  EXPECT_EQ(outputFolderProblem(missing), "");
  EXPECT_FALSE(fs::exists(missing));  // made by the claim, after the command's own checks
  std::ofstream(dir + "/file") << "x";
  EXPECT_NE(outputFolderProblem(dir + "/file"), "");
  EXPECT_NE(outputFolderProblem("/"), "");
  EXPECT_NE(outputFolderProblem(""), "");
}

TEST(OutputFolder, LinksWhereNothingIsWrittenAreKept) {
  const std::string dir = freshTempDir("outfolder-kept");
  const std::string out = dir + "/out";
  fs::create_directories(out + "/venv/bin");
  fs::create_symlink("/usr/bin/true", out + "/venv/bin/python");
  fs::create_symlink(dir, out + "/up");
  ASSERT_EQ(mkfifo((out + "/fifo").c_str(), 0600), 0);
  const Result<OutputFolder> held = claimOutputFolder(out, {"summary.json", "fam/case"}, "run");
  ASSERT_TRUE(held) << held.error().format();
  EXPECT_TRUE(fs::is_symlink(out + "/venv/bin/python"));
  EXPECT_TRUE(fs::is_symlink(out + "/up"));
  EXPECT_EQ(fs::symlink_status(out + "/fifo").type(), fs::file_type::fifo);
}

TEST(OutputFolder, AnOddEntryOnAPathWrittenIsRefusedAndKept) {
  const std::string dir = freshTempDir("outfolder-refused");
  const std::string out = dir + "/out", elsewhere = dir + "/elsewhere";
  fs::create_directories(elsewhere);
  struct Trap {
    std::string entry, write;
  };
  for (const Trap& trap :
       {Trap{"summary.json", "summary.json"}, Trap{"fam", "fam/case"}, Trap{"fam/case", "fam/case"},
        Trap{"fam/case/device", "fam/case"}, Trap{kOutputLockFile, "summary.json"}}) {
    fs::remove_all(out);
    fs::create_directories(fs::path(out + "/" + trap.entry).parent_path());
    fs::create_symlink(elsewhere, out + "/" + trap.entry);
    const Result<OutputFolder> held = claimOutputFolder(out, {trap.write}, "run");
    ASSERT_FALSE(held) << trap.entry;
    EXPECT_NE(held.error().message.find(trap.entry + " is a symbolic link"), std::string::npos)
        << held.error().message;
    EXPECT_TRUE(fs::is_symlink(out + "/" + trap.entry)) << trap.entry;
  }
  EXPECT_TRUE(fs::is_empty(elsewhere));
  fs::remove_all(out);
  fs::create_directories(out + "/fam");
  ASSERT_EQ(mkfifo((out + "/fam/case").c_str(), 0600), 0);
  const Result<OutputFolder> fifo = claimOutputFolder(out, {"fam/case"}, "run");
  ASSERT_FALSE(fifo);
  EXPECT_NE(fifo.error().message.find("FIFO"), std::string::npos) << fifo.error().message;
  EXPECT_EQ(fs::symlink_status(out + "/fam/case").type(), fs::file_type::fifo);
}

// Whether another process can take the lock of `dir` now.
bool anotherProcessCanLock(const std::string& dir) {
  const pid_t child = fork();
  if (child == 0) {
    const int fd = open((dir + "/" + kOutputLockFile).c_str(), O_RDWR);
    _exit(fd >= 0 && flock(fd, LOCK_EX | LOCK_NB) == 0 ? 0 : 1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

TEST(OutputFolder, OneProcessHoldsItUntilItsLastClaimEnds) {
  const std::string dir = freshTempDir("outfolder-lock");
  const std::string out = dir + "/out";
  {
    const Result<OutputFolder> first = claimOutputFolder(out, {}, "reduce");
    ASSERT_TRUE(first) << first.error().format();
    EXPECT_FALSE(anotherProcessCanLock(out));
    {
      // The same process again (a command running another in-process).
      const Result<OutputFolder> again = claimOutputFolder(out, {}, "run");
      ASSERT_TRUE(again) << again.error().format();
    }
    EXPECT_FALSE(anotherProcessCanLock(out));
    std::ifstream lock(out + "/" + kOutputLockFile);
    std::string holder;
    std::getline(lock, holder);
    EXPECT_NE(holder.find("rayspec reduce, process " + std::to_string(getpid())), std::string::npos)
        << holder;
  }
  EXPECT_TRUE(anotherProcessCanLock(out));
}

TEST(OutputFolder, AFolderHeldElsewhereIsRefusedNamingTheHolder) {
  const std::string dir = freshTempDir("outfolder-held");
  const std::string out = dir + "/out";
  fs::create_directories(out);
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t holder = fork();
  if (holder == 0) {
    const int fd = open((out + "/" + kOutputLockFile).c_str(), O_RDWR | O_CREAT, 0644);
    flock(fd, LOCK_EX);
    const std::string who = "rayspec merge, process 4242\n\x1b]52;c;Zm9v\x07";
    (void)!write(fd, who.data(), who.size());
    (void)!write(ready[1], "x", 1);
    pause();
    _exit(0);
  }
  char byte;
  ASSERT_EQ(read(ready[0], &byte, 1), 1);
  const Result<OutputFolder> held = claimOutputFolder(out, {}, "run");
  kill(holder, SIGKILL);
  waitpid(holder, nullptr, 0);
  ASSERT_FALSE(held);
  const std::string message = held.error().format();
  EXPECT_NE(message.find("in use by another rayspec merge, process 4242"), std::string::npos)
      << message;
  EXPECT_EQ(message.find('\x1b'), std::string::npos) << "the holder's text is shown visibly";
  EXPECT_TRUE(claimOutputFolder(out, {}, "run"));  // free once its holder has gone
}

}  // namespace
}  // namespace rayspec
