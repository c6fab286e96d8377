#include "report/run_summary.h"

#include <cstdio>
#include <map>

#include <unistd.h>

#include "base/visible_text.h"
#include "report/baseline_gate.h"

namespace rayspec {
namespace {

std::string gateTag(const CaseOutcome& o) {
  return o.baseline == BaselineMatch::None ? std::string()
                                           : std::string("  [") + gateWord(o.baseline) + "]";
}

// A case's line: its name and headline, as they may come from input (a case
// file's name, a saved run, the device's words) made visible, each one field.
void printCaseLine(const CaseOutcome& o) {
  std::printf("  %-44s %s%s\n", visibleLine(o.name).c_str(), visibleLine(o.headline).c_str(),
              gateTag(o).c_str());
}

// What a NotSupported case's device lacks: its headline after the last
// "NotSupported: " (the backend's own words).
std::string notSupportedReason(const CaseOutcome& o) {
  const std::string tag = "NotSupported: ";
  const size_t at = o.headline.rfind(tag);
  return at == std::string::npos ? o.headline : o.headline.substr(at + tag.size());
}

// How many cases each missing feature or limit made NotSupported.
void printNotSupportedReasons(const std::vector<CaseOutcome>& outcomes) {
  std::map<std::string, int> reasons;
  for (const CaseOutcome& o : outcomes)
    if (o.status == Status::NotSupported) ++reasons[notSupportedReason(o)];
  if (reasons.empty()) return;
  std::printf("NotSupported, by what the device lacks:\n");
  for (const auto& [reason, n] : reasons)
    std::printf("  %5d  %s\n", n, visibleLine(reason).c_str());
}

}  // namespace

void RunSummary::starting(const std::string& name) {
  if (progress_ == Progress::Quiet || !isatty(STDOUT_FILENO)) return;
  std::printf("\r[%zu/%zu] running %s...\x1b[K", outcomes_.size() + 1, total_,
              visibleLine(name).c_str());
  std::fflush(stdout);
  live_ = true;
}

void RunSummary::add(const CaseOutcome& o) {
  outcomes_.push_back(o);
  if (progress_ == Progress::Quiet) return;
  if (progress_ == Progress::Brief && !failsRun(o)) return;
  if (live_) std::printf("\r\x1b[K");
  live_ = false;
  std::printf("[%zu/%zu] %-44s %-14s device %7.3f s  model %7.3f s\n", outcomes_.size(), total_,
              visibleLine(o.name).c_str(), statusName(o.status), o.device_seconds, o.model_seconds);
  if (o.status != Status::Pass) std::printf("        %s\n", visibleLine(o.headline).c_str());
  if (o.baseline != BaselineMatch::None)
    std::printf("        (%s: %s)\n", gateWord(o.baseline), visibleLine(o.baseline_note).c_str());
  std::fflush(stdout);
}

void RunSummary::addTeardownError(const std::string& m) {
  teardown_errors_.push_back(m);
}

bool RunSummary::failed() const {
  if (!teardown_errors_.empty()) return true;
  for (const CaseOutcome& o : outcomes_)
    if (failsRun(o)) return true;
  return false;
}

bool RunSummary::allNotSupported() const {
  for (const CaseOutcome& o : outcomes_)
    if (o.status != Status::NotSupported) return false;
  return !outcomes_.empty();
}

void RunSummary::print(bool brief, const std::string& baseline) const {
  std::map<Status, int> counts;
  for (const CaseOutcome& o : outcomes_) ++counts[o.status];
  std::printf("\n==== rayspec summary: %zu cases ====\n", outcomes_.size());
  for (Status s : kAllStatuses) std::printf("  %-15s %d\n", statusName(s), counts[s]);
  printNotSupportedReasons(outcomes_);
  bool header = false;
  for (const CaseOutcome& o : outcomes_) {
    if (o.status == Status::CaseError) continue;  // listed apart below
    if (o.status == Status::Pass && o.baseline == BaselineMatch::None) continue;
    if (brief && !failsRun(o)) continue;
    if (!header)
      std::printf(brief ? "Failing the run (--brief lists no other):\n"
                        : "Not passing, or not as the baseline expects:\n");
    header = true;
    printCaseLine(o);
  }
  header = false;
  for (const CaseOutcome& o : outcomes_) {
    if (o.status != Status::CaseError) continue;
    if (!header) std::printf("Case errors (the case itself is at fault, not the device):\n");
    header = true;
    printCaseLine(o);
  }
  if (!baseline.empty()) std::printf("%s\n", gateLine(outcomes_, baseline).c_str());
  for (const std::string& m : teardown_errors_)
    std::printf("  validation error at device teardown: %s\n", visibleLine(m).c_str());
}

}  // namespace rayspec
