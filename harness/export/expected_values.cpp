#include "export/expected_values.h"

#include <algorithm>
#include <limits>
#include <map>

#include "compare/finding_rules.h"

namespace rayspec {
namespace {

// The rule a counter's mismatch names, as the judge names it (compare_counters.cpp).
std::string counterRule(const Case& c, const std::string& name) {
  return findingRule(rulesEvidencedByCounter(c, name), c.rules, "counter").rule;
}

// How far the ambiguous rays' legal answers may move a counter from the
// model's count, together: each ray's replays' smallest and largest move
// (the model's own answer moves it by 0), summed over the rays.
std::pair<int64_t, int64_t> replayedMoves(const Results& model, const std::string& name) {
  int64_t down = 0, up = 0;
  for (const RayAmbiguity& a : model.ambiguous) {
    int64_t least = 0, most = 0;
    for (const LegalReplay& r : a.replays) {
      const auto move = r.counter_moves.find(name);
      const int64_t m = move == r.counter_moves.end() ? 0 : move->second;
      least = std::min(least, m);
      most = std::max(most, m);
    }
    down += least;
    up += most;
  }
  return {down, up};
}

// A counter's range, as compare_counters.cpp judges it: the model's count,
// moved as far as the legal answers move it (not where the case declares it
// exact), then opened below (at_least), above (at_most) or both
// (informational; moved by a ray with undefined behaviour, or by a repeated
// any-hit, R-AHIT-DUP), and never below the model's floor (the leading
// counts of the programs every legal order runs) but where undefined.
std::pair<uint64_t, uint64_t> counterRange(const Case& c, const Results& model,
                                           const std::string& name, CounterMode how) {
  const auto found = model.counters.find(name);
  const int64_t m = found == model.counters.end() ? 0 : static_cast<int64_t>(found->second);
  const auto declared = c.outputs.counter_modes.find(name);
  const bool exact = declared != c.outputs.counter_modes.end() && declared->second == "exact";
  const auto [down, up] = exact ? std::pair<int64_t, int64_t>{0, 0} : replayedMoves(model, name);
  uint64_t lo = static_cast<uint64_t>(std::max<int64_t>(0, m + down));
  uint64_t hi = static_cast<uint64_t>(m + up);
  const bool undefined = !model.undefined.empty() && countersUndefinedRaysMayMove(c).count(name);
  const bool repeated =
      std::count(model.repeat_counters.begin(), model.repeat_counters.end(), name);
  if (undefined || repeated) how = CounterMode::Informational;
  if (how == CounterMode::AtMost || how == CounterMode::Informational) lo = 0;
  if (how == CounterMode::AtLeast || how == CounterMode::Informational)
    hi = std::numeric_limits<uint64_t>::max();
  if (const auto floor = model.counter_floors.find(name);
      !undefined && floor != model.counter_floors.end())
    lo = std::max(lo, floor->second);
  return {lo, hi};
}

}  // namespace

std::vector<ExpectedCounter> expectedCounters(const Case& c, const Plan& plan,
                                              const Results& model) {
  const std::map<std::string, CounterMode> modes = counterModes(c);
  std::vector<ExpectedCounter> out;
  for (const std::string& name : plan.counters) {
    const auto mode = modes.find(name);
    const CounterMode how = mode == modes.end() ? CounterMode::Exact : mode->second;
    const auto [lo, hi] = counterRange(c, model, name, how);
    out.push_back({name, counterRule(c, name), lo, hi, how});
  }
  return out;
}

std::string caseRulesText(const Case& c) {
  std::string out;
  for (const std::string& r : c.rules) out += (out.empty() ? "" : ", ") + r;
  return out.empty() ? "(none)" : out;
}

std::string expectedFieldRule(const Case& c, const RecordField& f) {
  return findingRule(rulesEvidencedByField(f.name), c.rules, f.rule).rule;
}

}  // namespace rayspec
