// An --out that is a user's project folder (issue 56, item 1): it holds a
// venv-style link to a program, a node_modules/.bin link, a link to a
// folder, a FIFO and a user's file. After every subcommand that takes --out,
// the ones that run and the ones that refuse, each of them is still there
// and what the links point to is untouched. A link on a path rayspec would
// write makes the command refuse (exit 2) naming it, and it stays.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_helpers.h"

namespace {
namespace fs = std::filesystem;
using cli::caseArg;
using cli::fresh;
using cli::kBin;
using cli::sh;
using cli::slurp;

const std::string kCase = "anyhit/ignore-odd-primitives";

// The user's entries of a project folder, each checked after a command.
class OutLinks : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fresh("out-links");
    outside_ = cli::victim(root_, "outside");
    ASSERT_EQ(sh(kBin + " run --no-validation" + caseArg(kCase) + " --out " + root_ + "/saved",
                 root_ + "/saved.txt"),
              0)
        << slurp(root_ + "/saved.txt");
  }

  // A project folder named `name` holding the user's entries.
  static std::string project(const std::string& name) {
    const std::string p = root_ + "/" + name;
    fs::remove_all(p);
    fs::create_directories(p + "/venv/bin");
    fs::create_directories(p + "/node_modules");
    fs::create_symlink("/usr/bin/true", p + "/venv/bin/python");
    fs::create_symlink(outside_, p + "/node_modules/.bin");
    fs::create_symlink(outside_, p + "/linked-folder");
    EXPECT_EQ(mkfifo((p + "/a-fifo").c_str(), 0600), 0);
    std::ofstream(p + "/notes.txt") << "mine";
    return p;
  }

  // Every user entry of project p is as it was, and so is the folder the
  // links point to.
  static void expectUntouched(const std::string& p, const std::string& after) {
    for (const char* link : {"venv/bin/python", "node_modules/.bin", "linked-folder"})
      EXPECT_TRUE(fs::is_symlink(p + "/" + link)) << link << " after " << after;
    EXPECT_EQ(fs::read_symlink(p + "/venv/bin/python"), "/usr/bin/true") << after;
    EXPECT_EQ(fs::status(p + "/a-fifo").type(), fs::file_type::fifo) << after;
    EXPECT_EQ(slurp(p + "/notes.txt"), "mine") << after;
    EXPECT_EQ(slurp(outside_ + "/keep.txt"), "keep") << after;
    size_t files = 0;
    for (const auto& e : fs::recursive_directory_iterator(outside_)) files += e.is_regular_file();
    EXPECT_EQ(files, 1u) << "a file was written through a link, after " << after;
  }

  // Runs `rayspec ARGS --out <a project>`; its exit status and output.
  static std::pair<int, std::string> inProject(const std::string& name, const std::string& args) {
    const std::string p = project(name);
    const int rc = sh(kBin + " " + args + " --out " + p, root_ + "/" + name + ".txt");
    const std::string log = slurp(root_ + "/" + name + ".txt");
    expectUntouched(p, args);
    return {rc, log};
  }

  static std::string root_, outside_;
};
std::string OutLinks::root_, OutLinks::outside_;

TEST_F(OutLinks, CommandsThatRefuseTouchNothing) {
  for (const std::string& args :
       {std::string("compare no-such-A no-such-B"), std::string("merge no-such-shard"),
        std::string("mutate no-such-run"), std::string("reduce no-such/case"),
        std::string("stability --filter 'no-such/*'"),
        std::string("accuracy --ordinary 'no-such/*' --hard 'no-such/*'"),
        std::string("run --filter 'no-such/*' --baseline no-such.csv")}) {
    const auto [rc, log] = inProject("refused", args);
    EXPECT_EQ(rc, 2) << args << "\n" << log;
  }
}

TEST_F(OutLinks, CommandsThatRunTouchOnlyWhatTheyWrite) {
  auto [rc, log] = inProject("run", "run --no-validation" + caseArg(kCase));
  EXPECT_EQ(rc, 0) << log;
  EXPECT_TRUE(fs::is_regular_file(root_ + "/run/summary.json")) << log;
  std::tie(rc, log) = inProject("compare", "compare " + root_ + "/saved " + root_ + "/saved");
  EXPECT_EQ(rc, 0) << log;
  std::tie(rc, log) = inProject("merge", "merge " + root_ + "/saved");
  EXPECT_EQ(rc, 0) << log;
  std::tie(rc, log) = inProject("mutate", "mutate " + root_ + "/saved --filter '" + kCase + "'");
  EXPECT_NE(log.find("Kill matrix"), std::string::npos) << log;
  EXPECT_TRUE(fs::is_regular_file(root_ + "/mutate/mutate.json")) << log;
}

TEST_F(OutLinks, StudiesAndReductionsTouchOnlyWhatTheyWrite) {
  auto [rc, log] =
      inProject("stability", "stability --no-device --filter 'stability/fan/mag-1-n7-seed1'");
  EXPECT_EQ(rc, 0) << log;
  EXPECT_TRUE(fs::is_regular_file(root_ + "/stability/stability.json")) << log;
  std::tie(rc, log) = inProject("accuracy", "accuracy --no-device --ordinary '" + kCase +
                                                "' --hard 'stability/fan/mag-1-n7-seed1'");
  EXPECT_EQ(rc, 0) << log;
  EXPECT_TRUE(fs::is_regular_file(root_ + "/accuracy/accuracy.json")) << log;
  std::tie(rc, log) =
      inProject("reduce",
                "reduce inactive/before-active-mask-zero-instance/one-first --no-validation "
                "--plant-fault instance-mask-ignored --max-attempts 3");
  EXPECT_TRUE(fs::is_regular_file(root_ + "/reduce/reduced.yaml")) << rc << "\n" << log;
}

// A link, a FIFO or a socket where a command writes: it refuses, naming the
// entry, before it writes anything, and the entry stays.
TEST_F(OutLinks, ALinkWhereACommandWritesIsRefusedAndKept) {
  struct Trap {
    std::string command, entry;
  };
  for (const Trap& t :
       {Trap{"run --no-validation" + caseArg(kCase), "summary.json"},
        Trap{"run --no-validation" + caseArg(kCase), "anyhit"},
        Trap{"run --no-validation" + caseArg(kCase), kCase + "/device"},
        Trap{"run --no-validation" + caseArg(kCase), ".rayspec-lock"},
        Trap{"merge " + root_ + "/saved", "report.html"},
        Trap{"compare " + root_ + "/saved " + root_ + "/saved", "anyhit"},
        Trap{"mutate " + root_ + "/saved --filter '" + kCase + "'", "mutate.txt"}}) {
    const std::string p = project("trap");
    fs::create_directories(fs::path(p + "/" + t.entry).parent_path());
    fs::create_symlink(outside_, p + "/" + t.entry);
    const int rc = sh(kBin + " " + t.command + " --out " + p, root_ + "/trap.txt");
    const std::string log = slurp(root_ + "/trap.txt");
    EXPECT_EQ(rc, 2) << t.command << " with a link at " << t.entry << "\n" << log;
    EXPECT_NE(log.find(t.entry), std::string::npos) << log;
    EXPECT_NE(log.find("symbolic link"), std::string::npos) << log;
    EXPECT_TRUE(fs::is_symlink(p + "/" + t.entry)) << t.entry;
    EXPECT_FALSE(fs::exists(p + "/summary.json") && t.entry != "summary.json") << t.command;
    expectUntouched(p, t.command);
  }
  const std::string p = project("fifo-trap");
  ASSERT_EQ(mkfifo((p + "/results.csv").c_str(), 0600), 0);
  const int rc =
      sh(kBin + " run --no-validation" + caseArg(kCase) + " --out " + p, root_ + "/fifo-trap.txt");
  EXPECT_EQ(rc, 2) << slurp(root_ + "/fifo-trap.txt");
  EXPECT_EQ(fs::status(p + "/results.csv").type(), fs::file_type::fifo);
}

// `--out .` in a checkout: the checkout's links survive the run.
TEST_F(OutLinks, OutDotKeepsTheCheckoutsLinks) {
  const std::string p = project("checkout");
  const int rc =
      sh("cd " + p + " && " + kBin + " run --no-validation" + caseArg(kCase) + " --out .",
         root_ + "/checkout.txt");
  EXPECT_EQ(rc, 0) << slurp(root_ + "/checkout.txt");
  expectUntouched(p, "run --out .");
}

}  // namespace

namespace {

// Item 9: one rayspec at a time in an output folder. While a run holds OUT
// (a case that hangs), every other command into OUT exits 2 naming the
// holder, and writes nothing there; once it has ended, OUT is free again.
TEST(OutLock, ASecondCommandIntoAHeldFolderIsRefusedNamingTheHolder) {
  const std::string root = fresh("out-lock");
  const std::string out = root + "/out";
  ASSERT_EQ(sh(kBin + " run --no-validation" + caseArg(kCase) + " --out " + root + "/saved",
               root + "/saved.txt"),
            0);
  const std::string pid_file = root + "/holder.pid";
  ASSERT_EQ(std::system(("setsid " + kBin + " run --no-validation --plant-fault hang --timeout 60" +
                         caseArg(kCase) + " --out " + out + " > " + root + "/holder.txt 2>&1 & " +
                         "echo $! > " + pid_file)
                            .c_str()),
            0);
  // The holder has said who it is once its lock file names it.
  std::string holder;
  for (int i = 0; i < 600 && holder.find("rayspec run") == std::string::npos; ++i) {
    std::system("sleep 0.1");
    holder = slurp(out + "/.rayspec-lock");
  }
  ASSERT_NE(holder.find("rayspec run, process "), std::string::npos) << slurp(root + "/holder.txt");
  const std::string pid = slurp(pid_file).substr(0, slurp(pid_file).find('\n'));
  for (const std::string& args :
       {"run --no-validation" + caseArg(kCase), "run --resume --no-validation" + caseArg(kCase),
        "merge " + root + "/saved", "compare " + root + "/saved " + root + "/saved",
        "reduce " + kCase + " --plant-fault instance-mask-ignored",
        "mutate " + root + "/saved --filter '" + kCase + "'"}) {
    const int rc = sh(kBin + " " + args + " --out " + out, root + "/second.txt");
    const std::string log = slurp(root + "/second.txt");
    EXPECT_EQ(rc, 2) << args << "\n" << log;
    EXPECT_NE(log.find("in use by another rayspec run, process " + pid), std::string::npos)
        << args << "\n"
        << log;
    EXPECT_FALSE(std::filesystem::exists(out + "/mutate.json")) << args;
    EXPECT_FALSE(std::filesystem::exists(out + "/reduced.yaml")) << args;
  }
  std::system(("kill -TERM -" + pid + "; while kill -0 " + pid + " 2>/dev/null; do sleep 0.1; done")
                  .c_str());
  EXPECT_EQ(
      sh(kBin + " run --no-validation" + caseArg(kCase) + " --out " + out, root + "/after.txt"), 0)
      << slurp(root + "/after.txt");
}

}  // namespace
