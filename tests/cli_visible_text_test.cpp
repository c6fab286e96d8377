// Issue 56, item 8: text from input that reaches the console, summary.txt and
// results.csv (a saved device's name and validation message, a case file's
// name) holding escape sequences (OSC 52, OSC 0, ESC[2J) and a line break
// before a forged "::error" annotation is shown by the visible-text rule:
// no output holds a control byte or a line a CI log reads as a command, and
// the text is still there to read, made visible.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"
#include "hostile_text.h"

namespace {
namespace fs = std::filesystem;
using cli::caseArg;
using cli::fresh;
using cli::sh;
using cli::slurp;
using rayspec::testing_support::kHostileText;
using rayspec::testing_support::obeyedText;

const std::string kCase = "results/miss-xor-closest-hit";

// What the visible-text rule makes of kHostileText's start: the escape
// sequence shown, so the test can tell the text arrived.
const std::string kShown = "dev\\x1B]52;c;cHduZWQ=\\x07";

// Each output of a run folder and the command's own output: none obeyed.
void expectNothingObeyed(const std::string& out, const std::string& log) {
  for (const std::string& file :
       {log, out + "/summary.txt", out + "/results.csv", out + "/failures.csv"}) {
    ASSERT_TRUE(fs::exists(file)) << file;
    EXPECT_EQ(obeyedText(slurp(file)), "") << file << ":\n" << slurp(file);
  }
}

// A device-only run whose saved bundle then names a hostile device and holds
// a hostile validation message, judged here (--device-results), and the
// judged run merged: the console of both, summary.txt and results.csv.
TEST(VisibleText, ASavedDevicesNameAndValidationMessageAreShownNotObeyed) {
  const std::string root = fresh("visible-text-saved");
  ASSERT_EQ(sh(cli::kBin + " run --no-model --no-validation" + caseArg(kCase) + " --out " + root +
                   "/saved",
               root + "/saved.txt"),
            77)  // one case, nothing compared
      << slurp(root + "/saved.txt");
  const std::string json = root + "/saved/" + kCase + "/device/results.json";
  nlohmann::json j = nlohmann::json::parse(slurp(json));
  j["device"] = kHostileText;
  j["validation_messages"] = {kHostileText};
  std::ofstream(json) << j.dump(1);

  const std::string judged = root + "/judged", log = root + "/judged.txt";
  EXPECT_EQ(sh(cli::kBin + " run --no-validation --device-results " + root + "/saved" +
                   caseArg(kCase) + " --out " + judged,
               log),
            1)  // the validation message fails the case
      << slurp(log);
  expectNothingObeyed(judged, log);
  EXPECT_NE(slurp(log).find("Device results saved in " + root + "/saved (" + kShown),
            std::string::npos)
      << slurp(log);
  EXPECT_NE(slurp(log).find("validation-layer error(s); first: " + kShown), std::string::npos)
      << slurp(log);
  EXPECT_NE(slurp(judged + "/summary.txt").find(kShown), std::string::npos)
      << slurp(judged + "/summary.txt");

  const std::string merged = root + "/merged", merge_log = root + "/merged.txt";
  EXPECT_EQ(sh(cli::kBin + " merge " + judged + " --out " + merged, merge_log), 1)
      << slurp(merge_log);
  expectNothingObeyed(merged, merge_log);
  EXPECT_NE(slurp(merge_log).find("cases on " + kShown), std::string::npos) << slurp(merge_log);
}

// Case files named with the same bytes (the file system takes all but '/'),
// and one named as a workflow command at the top of the cases folder, whose
// name begins the lines of results.csv and summary.txt: each a CaseError.
TEST(VisibleText, CaseFileNamesAreShownNotObeyed) {
  const std::string root = fresh("visible-text-names"), cases = root + "/cases";
  fs::create_directories(cases + "/fam");
  const std::string text = slurp(cli::kCases + kCase + ".yaml");
  for (const std::string& name :
       {"fam/" + kHostileText, std::string("::error file=y::forged"), std::string("fam/ok")})
    std::ofstream(cases + "/" + name + ".yaml") << text;
  ASSERT_TRUE(fs::exists(cases + "/fam/" + kHostileText + ".yaml"));
  const std::string out = root + "/out", log = root + "/run.txt";
  EXPECT_EQ(sh(cli::kBin + " run --no-validation --cases " + cases + " --out " + out, log), 1)
      << slurp(log);
  expectNothingObeyed(out, log);
  const std::string csv = slurp(out + "/results.csv");
  EXPECT_NE(csv.find("fam/ok,Pass,"), std::string::npos) << csv;
  // Each badly named case is a CaseError under a stand-in name that is a
  // case name (results/file_name.h caseNameFor); its message shows the file.
  EXPECT_NE(csv.find("_x3A_x3Aerror_x20file_x3Dy_x3A_x3Aforged,Fail,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("fam/dev_x1B_x5D52_x3B"), std::string::npos) << csv;
  EXPECT_NE(slurp(log).find("fam/" + kShown), std::string::npos) << slurp(log);
}

}  // namespace
