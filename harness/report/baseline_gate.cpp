#include "report/baseline_gate.h"

#include <sstream>

#include "base/visible_text.h"
#include "base/whole_file.h"
#include "report/escape.h"
#include "report/write_reports.h"

namespace rayspec {

Status expectedStatus(const Baseline& baseline, const std::string& name) {
  const auto it = baseline.expected.find(name);
  return it == baseline.expected.end() ? Status::Pass : it->second;
}

bool applyBaseline(const Baseline& baseline, CaseOutcome& o) {
  o.baseline = BaselineMatch::None;
  o.baseline_note.clear();
  if (baseline.empty()) return false;
  const bool listed = baseline.expected.count(o.name) != 0;
  const Status expected = expectedStatus(baseline, o.name);
  if (o.status == expected) {
    if (listed) {
      o.baseline = BaselineMatch::Expected;
      o.baseline_note = std::string("the baseline lists ") + statusName(expected);
    }
    return false;
  }
  const bool improved = isFailing(expected) && !isFailing(o.status);
  if (!improved && !isFailing(o.status)) return false;  // judged by its status alone
  const std::string was = std::string("the baseline expects ") + statusName(expected);
  if (const NamePattern* p = findPattern(baseline.flakes, o.name)) {
    o.baseline = BaselineMatch::KnownFlake;
    o.baseline_note = was + "; a known flake (" + p->where + ": " + p->text + ")";
    return false;
  }
  o.baseline_note = was;
  if (improved) {
    o.baseline = BaselineMatch::UnexpectedPass;
    return false;
  }
  return true;
}

void applyRerun(CaseOutcome& o, const CaseOutcome& rerun) {
  if (rerun.status == o.status) {
    o.baseline_note += std::string("; the re-run gave ") + statusName(rerun.status) + " again";
    return;
  }
  o.baseline = BaselineMatch::Flake;
  o.baseline_note += std::string("; a flake: the re-run gave ") + statusName(rerun.status);
  // The headline quotes what the case produced (a validation message): one line.
  if (rerun.status != Status::Pass) o.baseline_note += " (" + visibleLine(rerun.headline) + ")";
}

CaseOutcome skippedOutcome(const std::string& name, const NamePattern& pattern) {
  CaseOutcome o;
  o.name = name;
  o.verdict.add({Status::NotSupported,
                 "skipped",
                 "not run: the skips file names it (" + pattern.where + ": " + pattern.text + ")",
                 {},
                 0});
  o.deriveFromVerdict();
  o.baseline = BaselineMatch::Skipped;
  o.baseline_note = "skipped by " + pattern.where;
  return o;
}

bool failsRun(const CaseOutcome& o) {
  switch (o.baseline) {
    case BaselineMatch::Expected:
    case BaselineMatch::KnownFlake:
    case BaselineMatch::Flake:
    case BaselineMatch::Skipped:
      return false;
    case BaselineMatch::UnexpectedPass:
      return true;
    case BaselineMatch::None:
      break;
  }
  return isFailing(o.status);
}

Result<void> writeFailuresCsv(const std::vector<CaseOutcome>& outcomes,
                              const std::string& baseline_file, const std::string& path) {
  std::ostringstream out;
  out << "# Results "
      << (baseline_file.empty() ? "that fail the run (no baseline given)"
                                : "the baseline " + baseline_file + " did not expect")
      << ", in its own form (case,Status):\n# append the failures to the baseline once they are "
         "understood, delete the unexpected passes\n# from it, and add the flakes' names to the "
         "flakes file.\n";
  for (const CaseOutcome& o : outcomes) {
    if (!failsRun(o) && o.baseline != BaselineMatch::Flake) continue;
    out << csvField(visibleLine(o.name)) << ',' << statusName(o.status) << "  # "
        << deqpResultName(o);
    // One line a case, whatever its note holds (read back from a saved run).
    if (!o.baseline_note.empty()) out << ": " << visibleLine(o.baseline_note);
    out << '\n';
  }
  return writeWholeFile(path, out.str());
}

std::string gateLine(const std::vector<CaseOutcome>& outcomes, const std::string& baseline_file) {
  size_t failing = 0, unexpected_passes = 0, expected = 0, flakes = 0;
  for (const CaseOutcome& o : outcomes) {
    failing += failsRun(o) && o.baseline != BaselineMatch::UnexpectedPass;
    unexpected_passes += o.baseline == BaselineMatch::UnexpectedPass;
    expected += o.baseline == BaselineMatch::Expected && isFailing(o.status);
    flakes += o.baseline == BaselineMatch::Flake || o.baseline == BaselineMatch::KnownFlake;
  }
  const auto count = [](size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  std::string line =
      "Gate (baseline " +
      (baseline_file.empty() ? std::string("none: every failing status fails the run")
                             : visibleLine(baseline_file)) +
      "): ";
  if (failing + unexpected_passes == 0)
    line += "PASS";
  else
    line += "FAIL, " + count(failing, "unexpected failure", "unexpected failures") + ", " +
            count(unexpected_passes, "unexpected pass", "unexpected passes") + " (failures.csv)";
  if (!baseline_file.empty())
    line += "; " + count(expected, "expected failure", "expected failures") + ", " +
            count(flakes, "flake", "flakes");
  return line;
}

const char* gateWord(BaselineMatch m) {
  switch (m) {
    case BaselineMatch::None:
      return "";
    case BaselineMatch::Expected:
      return "expected";
    case BaselineMatch::UnexpectedPass:
      return "UNEXPECTED PASS, update the baseline";
    case BaselineMatch::KnownFlake:
      return "known flake";
    case BaselineMatch::Flake:
      return "FLAKE, add it to the flakes file";
    case BaselineMatch::Skipped:
      return "skipped";
  }
  return "";
}

const char* deqpResultName(const CaseOutcome& o) {
  switch (o.baseline) {
    case BaselineMatch::Expected:
      if (o.status != Status::Pass) return "ExpectedFail";
      break;
    case BaselineMatch::UnexpectedPass:
      return o.status == Status::Pass           ? "UnexpectedImprovement(Pass)"
             : o.status == Status::NotSupported ? "UnexpectedImprovement(Skip)"
                                                : "UnexpectedImprovement(Warn)";
    case BaselineMatch::KnownFlake:
      return "KnownFlake";
    case BaselineMatch::Flake:
      return "Flake";
    case BaselineMatch::Skipped:
      return "Skip";
    case BaselineMatch::None:
      break;
  }
  return deqpStatusName(o.status);
}

}  // namespace rayspec
