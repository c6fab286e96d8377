#include "reduce/reduce_report.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "base/visible_text.h"

namespace rayspec {
namespace {

bool writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}

// A table cell: no '|' or line break breaks the row.
std::string cell(std::string s) {
  for (char& ch : s)
    if (ch == '|' || ch == '\n') ch = ' ';
  return s;
}

// A fenced code block of text: its fence longer than any run of backticks in
// it, so that nothing in the text (a path's "```") ends the block early.
std::string fenced(const std::string& text, const std::string& info = "") {
  size_t longest = 0, run = 0;
  for (char ch : text) {
    run = ch == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  const std::string fence(std::max<size_t>(3, longest + 1), '`');
  return fence + info + "\n" + text + (text.empty() || text.back() == '\n' ? "" : "\n") + fence +
         "\n";
}

std::string raysTable(const CaseOutcome& o) {
  if (o.failing_rays.empty()) return "(no per-ray rows: the finding is not about single rays)\n";
  std::string t = "| ray | x | y | field | device | model |\n|---|---|---|---|---|---|\n";
  for (const RayRow& r : o.failing_rays)
    t += "| " + std::to_string(r.ray) + " | " + std::to_string(r.x) + " | " + std::to_string(r.y) +
         " | " + cell(r.field) + " | " + cell(r.device) + " | " + cell(r.model) +
         (r.device != r.model ? " **differs**" : "") + " |\n";
  return t;
}

// The report's lead: how to build and run repro.c without rayspec, and what
// it prints where the case was reduced; or why there is no repro.c.
std::string reproducerSection(const ReductionRecord& r) {
  std::string m = "## Without rayspec: " + std::string(kReproducerFile) + "\n\n";
  if (r.reproducer.empty())
    return m + "No " + kReproducerFile + ": " + visibleLine(r.reproducer_refused) + "\n\n";
  m += std::string(kReproducerFile) +
       ", beside this report, is the reduced case as one C file that needs only a C compiler "
       "and the Vulkan loader: it traces the case and compares each result with what "
       "rayspec's model expects.\n\n" +
       fenced(std::string(kReproducerBuildLine) + "\n" + kReproducerRunLine +
              "   # DEVICE: an index, or a part of the device's name") +
       "\nIt prints PASS (exit 0), or FAIL (exit 1) with the rule, the ray, the field, the "
       "expected and the observed value; 77: the device lacks a feature it names. ";
  if (!r.fault.empty())
    return m + "It carries the planted fault " + r.fault +
           " (its builds misread their inputs as the fault does), so it FAILs on a correct "
           "device; `rayspec export " +
           kReducedCaseFile + "` writes it without.\n\n";
  const std::string on = r.device.empty() ? std::string("the device it was reduced on") : r.device;
  return m + "rayspec judged the case " + statusName(r.signature.status) + " on " + on +
         (r.signature.status == Status::Fail ? ": expect FAIL there" : "") + ".\n\n";
}

// How to run repro.amber (Amber's ray tracing subset, as VK-GL-CTS's
// scripts use it), or why there is none.
std::string amberSection(const ReductionRecord& r) {
  std::string m = "## Without rayspec: " + std::string(kAmberScriptFile) + "\n\n";
  if (r.amber.empty())
    return m + "No " + kAmberScriptFile + ": " + visibleLine(r.amber_refused) + "\n\n";
  return m + std::string(kAmberScriptFile) +
         ", beside this report, is the reduced case as an Amber script (the SPIR-V rayspec "
         "compiled, with the model's expected buffers), for a test of Amber's kind:\n\n" +
         fenced(kAmberRunLine) + "\n";
}

std::string reportMarkdown(const ReductionRecord& r) {
  const FailureSignature& s = r.signature;
  std::string m =
      "# " + r.case_name + ": " + (s.rule.empty() ? "" : s.rule + ": ") + s.message + "\n\n";
  m += reproducerSection(r);
  m += amberSection(r);
  m += "Reduced by `rayspec reduce` from `" + r.case_path + "` in " + seconds(r.seconds) + " (" +
       std::to_string(r.attempts.size()) + " variants tried): " + sizeChange(r.before, r.after) +
       ".\n\n";
  m += "- Device: " + (r.device.empty() ? std::string("unknown") : r.device) + "\n";
  m += "- Driver manifest (ICD): " + (r.icd.empty() ? std::string("unknown") : r.icd) + "\n";
  if (!r.fault.empty())
    m += "- Planted fault (test only, standing in for a wrong device): " + r.fault + "\n";
  m += "- Verdict: " + r.outcome.headline + "\n";
  if (!s.rule.empty())
    m += "- Rule (references/spec-rules.yaml): " + (r.rule_title.empty() ? s.rule : r.rule_title) +
         "\n";
  m += "\n## Reproduce\n\n" + fenced(r.command) + "\n";
  m += "## The case\n\n" + fenced(r.reduced_text, "yaml") + "\n";
  m += "## Failing rays, device against model\n\n" + raysTable(r.outcome);
  return m;
}

std::string stepsText(const ReductionRecord& r) {
  std::string t = "# " + std::to_string(r.attempts.size()) + " variants of " + r.case_name +
                  ", in the order tried; kept: fails the same way (" +
                  (r.signature.rule.empty() ? "" : r.signature.rule + ": ") + r.signature.message +
                  ")\n";
  size_t n = 0;
  for (const Attempt& a : r.attempts) {
    char head[64];
    std::snprintf(head, sizeof head, "%4zu %6.2fs ", ++n, a.seconds);
    t += head + a.what + "\n            -> " + a.verdict + "\n";
  }
  return t;
}

}  // namespace

std::string notFailingText(const std::string& name, const std::string& keep,
                           const CaseOutcome& outcome) {
  // The headline begins with the status's name (compare/verdict.h): alone,
  // it says no more than the status.
  const std::string verdict =
      outcome.headline.empty() ? statusName(outcome.status) : outcome.headline;
  const std::string said =
      outcome.status == Status::Pass && verdict == statusName(Status::Pass) ? "it passes" : verdict;
  return visibleLine(name + " does not fail" + (keep.empty() ? "" : " by " + keep) +
                     " to begin with: " + said);
}

std::string reducedDescription(const ReductionRecord& r) {
  const FailureSignature& s = r.signature;
  std::string d = "Reduced by rayspec reduce from " + r.case_name + " (" + r.case_path +
                  "): shows " + std::string(statusName(s.status)) + ": " +
                  (s.rule.empty() ? "" : s.rule + ": ") + s.message;
  if (!r.device.empty()) d += ", on " + r.device;
  if (!r.fault.empty()) d += ", with the planted fault " + r.fault;
  return d + ".";
}

std::string writeReduction(const ReductionRecord& r, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  for (const auto& [name, text] :
       {std::pair{kReducedCaseFile, r.reduced_text}, std::pair{kReproducerFile, r.reproducer},
        std::pair{kAmberScriptFile, r.amber}, std::pair{kReductionReportFile, reportMarkdown(r)},
        std::pair{kReductionStepsFile, stepsText(r)}}) {
    const std::string path = dir + "/" + name;
    if (text.empty()) {  // no repro.c or repro.amber: none of an earlier reduction stays
      std::filesystem::remove(path, ec);
      continue;
    }
    if (!writeText(path, text)) return "cannot write " + path;
  }
  return "";
}

std::string reductionSummary(const ReductionRecord& r, const std::string& dir) {
  size_t ran = 0, kept = 0;
  for (const Attempt& a : r.attempts) ran += a.ran, kept += a.kept;
  return "Reduced " + r.case_name + ": " + sizeChange(r.before, r.after) + "\n" + "  " +
         std::to_string(r.attempts.size()) + " variants (" + std::to_string(ran) + " ran, " +
         std::to_string(kept) + " kept) in " + seconds(r.seconds) + "\n" +
         "  still: " + visibleLine(r.outcome.headline.substr(0, 300)) + "\n" + "  " + dir +
         "/reduced.yaml, " + (r.reproducer.empty() ? "" : std::string(kReproducerFile) + ", ") +
         (r.amber.empty() ? "" : std::string(kAmberScriptFile) + ", ") + "report.md, steps.txt\n";
}

}  // namespace rayspec
