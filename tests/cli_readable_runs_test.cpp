// Whatever a run writes, its readers accept (issue 56): a run folder whose
// journal a kill cut mid-line resumes and merges, again and again; a report
// that cannot be written (a full disk) leaves the copy that was there and
// makes the run exit 4 naming it; a case file badly named (a space, bytes
// that are not UTF-8) is a CaseError, and the folder still resumes and
// merges with other shards.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"

namespace {
namespace fs = std::filesystem;
using cli::fresh;
using cli::sh;
using cli::slurp;

const std::string kCaseFile = cli::kCases + "results/miss-xor-closest-hit.yaml";  // about 2 s

// A cases folder under root holding kCaseFile under each of `names`
// (relative paths, .yaml added).
std::string casesFolder(const std::string& root, const std::vector<std::string>& names) {
  const std::string dir = root + "/cases";
  for (const std::string& name : names) {
    fs::create_directories(fs::path(dir + "/" + name).parent_path());
    fs::copy_file(kCaseFile, dir + "/" + name + ".yaml");
  }
  return dir;
}

// `rayspec run` of a cases folder into out (more options in `extra`), its
// output in log. Its exit status.
// One cases folder holding those of every shard (as a checkout's cases/
// does), for merge, which judges each case anew by its case file.
std::string mergeCases(const std::string& root, const std::vector<std::string>& folders) {
  const std::string all = root + "/merge-cases";
  fs::remove_all(all);
  fs::create_directories(all);
  for (const std::string& f : folders)
    fs::copy(f, all, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  return " --cases " + all;
}

int run(const std::string& cases, const std::string& out, const std::string& log,
        const std::string& extra = "") {
  return sh(cli::kBin + " run --no-validation --cases '" + cases + "' --out " + out + extra, log);
}

nlohmann::json summaryOf(const std::string& dir) {
  return nlohmann::json::parse(slurp(dir + "/summary.json"));
}

std::set<std::string> caseNames(const nlohmann::json& summary) {
  std::set<std::string> names;
  for (const nlohmann::json& c : summary["cases"]) names.insert(c["name"].get<std::string>());
  return names;
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The folder as a run killed while it wrote a line of its journal leaves
// it: summary.json marked interrupted (a killed run's reports say so until
// its end), the journal's last `lost` lines not written (their cases had not
// ended) and the line before them cut in half, without its newline.
void killMidLine(const std::string& out, size_t lost) {
  nlohmann::json summary = summaryOf(out);
  summary["interrupted"] = true;
  std::ofstream(out + "/summary.json") << summary.dump(1);
  const std::vector<std::string> lines = linesOf(slurp(out + "/outcomes.jsonl"));
  ASSERT_GT(lines.size(), lost);
  std::string journal;
  for (size_t i = 0; i + lost + 1 < lines.size(); ++i) journal += lines[i] + "\n";
  const std::string& cut = lines[lines.size() - lost - 1];
  std::ofstream(out + "/outcomes.jsonl", std::ios::trunc)
      << journal + cut.substr(0, cut.size() / 2);
}

// Issue 56, item 2: killed mid-line, resumed (two cases run again), killed
// mid-line again, resumed again: each resume runs what was cut, the journal
// holds whole lines only, and the folder merges with another shard. Before,
// the first resume wrote after the half line, and the second found a line
// that was no outcome in the middle of the journal.
TEST(CutJournal, AFolderKilledMidLineTwiceResumesAndMerges) {
  const std::string root = fresh("cut-journal");
  const std::string cases = casesFolder(root, {"fam/a", "fam/b", "fam/c"});
  const std::string out = root + "/out";
  ASSERT_EQ(run(cases, out, root + "/run.txt"), 0) << slurp(root + "/run.txt");
  for (int resume = 1; resume <= 2; ++resume) {
    killMidLine(out, resume == 1 ? 1 : 0);
    const std::string log = root + "/resume-" + std::to_string(resume) + ".txt";
    EXPECT_EQ(run(cases, out, log, " --resume"), 0) << slurp(log);
    EXPECT_NE(slurp(log).find("Resuming"), std::string::npos) << slurp(log);
    for (const std::string& line : linesOf(slurp(out + "/outcomes.jsonl")))
      EXPECT_TRUE(nlohmann::json::accept(line)) << "resume " << resume << ": '" << line << "'";
    const nlohmann::json summary = summaryOf(out);
    EXPECT_FALSE(summary["interrupted"].get<bool>());
    EXPECT_EQ(caseNames(summary), (std::set<std::string>{"fam/a", "fam/b", "fam/c"}));
  }
  // It merges with another shard; killed once more, it merges as it stands:
  // the cut case is not there, and the merge says the shard was interrupted
  // (exit 1).
  const std::string other = root + "/other";
  const std::string other_cases = casesFolder(other, {"other/d"});
  ASSERT_EQ(run(other_cases, other + "/out", other + "/run.txt"), 0) << slurp(other + "/run.txt");
  const std::string merged = root + "/merged", cut = root + "/merged-cut";
  const std::string with_cases = mergeCases(root, {cases, other_cases});
  EXPECT_EQ(sh(cli::kBin + " merge " + out + " " + other + "/out --out " + merged + with_cases,
               root + "/merge.txt"),
            0)
      << slurp(root + "/merge.txt");
  EXPECT_EQ(summaryOf(merged)["counts"]["Pass"], 4);
  killMidLine(out, 0);
  EXPECT_EQ(sh(cli::kBin + " merge " + out + " " + other + "/out --out " + cut + with_cases,
               root + "/merge-cut.txt"),
            1)
      << slurp(root + "/merge-cut.txt");
  const nlohmann::json summary = summaryOf(cut);
  EXPECT_TRUE(summary["interrupted"].get<bool>());
  EXPECT_EQ(summary["cases"].size(), 3u) << "fam: two of three, other: one";
  EXPECT_EQ(summary["counts"]["Pass"], 3);
}

// `rayspec ARGS` with every file it writes limited to 2 blocks of ulimit -f
// (1 KiB in dash, 2 in bash): a write past that fails with EFBIG, as on a
// full disk. Its output goes through a pipe, which the limit does not touch,
// into log. Its exit status.
int withFileLimit(const std::string& args, const std::string& log) {
  const std::string rc = log + ".rc";
  sh("(trap '' XFSZ; ulimit -f 2; " + cli::kBin + args + "; echo $? > " + rc + ") 2>&1 | cat", log);
  return std::stoi("0" + slurp(rc));
}

// Issue 56, item 3: report.html (about 20 KiB) cannot be written: the run
// exits 4 naming the file and why, the copy that was there stays whole, and
// what was written is whole too.
TEST(FullDisk, AReportNotWrittenKeepsTheCopyThatWasThereAndFailsTheRun) {
  const std::string root = fresh("full-disk");
  const std::string cases = casesFolder(root, {"fam/a"});
  const std::string out = root + "/out";
  ASSERT_EQ(run(cases, out, root + "/run.txt"), 0) << slurp(root + "/run.txt");
  const std::string kept = slurp(out + "/report.html") + "<!-- the copy that was there -->\n";
  std::ofstream(out + "/report.html") << kept;
  const std::string log = root + "/full.txt";
  const int rc = withFileLimit(" run --no-validation --resume --cases " + cases + " --out " + out +
                                   " --cache-dir " + root + "/cache",
                               log);
  EXPECT_EQ(rc, 4) << slurp(log);
  EXPECT_NE(slurp(log).find(out + "/report.html: cannot write: File too large"), std::string::npos)
      << slurp(log);
  EXPECT_EQ(slurp(out + "/report.html"), kept);
  EXPECT_TRUE(nlohmann::json::accept(slurp(out + "/summary.json"))) << slurp(out + "/summary.json");
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".part."), std::string::npos) << e.path();
  // With room again, the same resume writes it anew.
  EXPECT_EQ(run(cases, out, root + "/again.txt", " --resume"), 0) << slurp(root + "/again.txt");
  const std::string html = slurp(out + "/report.html");
  EXPECT_EQ(html.find("the copy that was there"), std::string::npos);
  EXPECT_EQ(html.substr(html.size() - 8), "</html>\n");
}

// Issue 56, item 4: fam/my case.yaml and fam/bad<0xFF>.yaml beside a good
// case. The run, --resume and a merge with another shard each report them as
// CaseErrors (under names that are case names) naming the files, and every
// file the run writes reads back: summary.json whole and complete, results.csv
// as deqp-runner reads it, failures.csv as a baseline.
TEST(BadCaseName, ASpaceOrABadByteInAFileNameIsACaseErrorAndTheFolderStillMerges) {
  const std::string root = fresh("bad-case-name");
  const std::string cases = casesFolder(root, {"fam/good", "fam/my case", "fam/bad\xff"});
  const std::string out = root + "/out";
  const std::set<std::string> names = {"fam/good", "fam/my_x20case", "fam/bad_xFF"};
  const auto check = [&](const std::string& dir, const std::string& log, size_t cases_there) {
    const nlohmann::json summary = summaryOf(dir);
    EXPECT_FALSE(summary["interrupted"].get<bool>()) << log;
    EXPECT_EQ(summary["cases"].size(), cases_there) << log;
    EXPECT_EQ(summary["case_errors"], (nlohmann::json{"fam/bad_xFF", "fam/my_x20case"})) << log;
    for (const nlohmann::json& c : summary["cases"]) {
      if (c["status"] != "CaseError") continue;
      const std::string headline = c["headline"];
      EXPECT_TRUE(headline.find("/fam/my case.yaml") != std::string::npos ||
                  headline.find("/fam/bad\\xFF.yaml") != std::string::npos)
          << headline;
      EXPECT_NE(headline.find("is no case name"), std::string::npos) << headline;
    }
    const auto csv = cli::readDeqpCsv(dir + "/results.csv");
    EXPECT_EQ(csv.size(), cases_there) << log;
  };
  EXPECT_EQ(run(cases, out, root + "/run.txt"), 1) << slurp(root + "/run.txt");
  check(out, slurp(root + "/run.txt"), 3);
  EXPECT_EQ(caseNames(summaryOf(out)), names);
  EXPECT_EQ(run(cases, out, root + "/resume.txt", " --resume"), 1) << slurp(root + "/resume.txt");
  EXPECT_NE(slurp(root + "/resume.txt").find("3 cases already ran"), std::string::npos)
      << slurp(root + "/resume.txt");
  check(out, slurp(root + "/resume.txt"), 3);
  const std::string other = root + "/other";
  const std::string other_cases = casesFolder(other, {"other/d"});
  ASSERT_EQ(run(other_cases, other + "/out", other + "/run.txt"), 0) << slurp(other + "/run.txt");
  const std::string merged = root + "/merged";
  const std::string with_cases = mergeCases(root, {cases, other_cases});
  EXPECT_EQ(sh(cli::kBin + " merge " + out + " " + other + "/out --out " + merged + with_cases,
               root + "/merge.txt"),
            1)
      << slurp(root + "/merge.txt");
  check(merged, slurp(root + "/merge.txt"), 4);
  // failures.csv, appended to a baseline as it says, is one that loads: the
  // two CaseErrors are then expected and the merge passes.
  EXPECT_EQ(sh(cli::kBin + " merge " + out + " " + other + "/out --out " + root +
                   "/gated --baseline " + merged + "/failures.csv" + with_cases,
               root + "/gated.txt"),
            0)
      << slurp(root + "/gated.txt");
}

}  // namespace
