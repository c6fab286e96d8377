// Exact counters judged together against the replays of the ambiguous
// rays' legal answers (RayAmbiguity::replays): one answer per ray moves
// every counter at once, so per-counter ranges are not enough (one ray
// counted on neither of its two branches stays within each range), and the
// answer a ray's record shows is the one that moves them.
#include <set>
#include <vector>

#include "compare/compare_parts.h"
#include "compare/finding_rules.h"
#include "plan/plan.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// The most distinct sums of moves followed; beyond, the counters stay
// judged one by one.
constexpr size_t kMaxMoveSums = 4096;

using Moves = std::vector<int64_t>;  // one per judged counter, in their order

// The moves over `names` of each of a ray's replays that its device record
// `d` is; none where it is none of them (a leak, an answer outside the
// legal set, one judged by its record already: its moves are unknown).
std::set<Moves> rayMoves(const RayAmbiguity& a, const std::vector<std::string>& names,
                         const uint32_t* d, const std::vector<const RecordField*>& fields) {
  std::vector<const LegalReplay*> taken;
  for (const LegalReplay& r : a.replays)
    if (r.record.size() == recordWords() && replayMatches(r, d, fields, RayBounds{}))
      taken.push_back(&r);
  std::set<Moves> out;
  for (const LegalReplay* rp : taken) {
    const LegalReplay& r = *rp;
    Moves m(names.size(), 0);
    for (size_t k = 0; k < names.size(); ++k)
      if (const auto it = r.counter_moves.find(names[k]); it != r.counter_moves.end())
        m[k] = it->second;
    out.insert(m);
  }
  return out;
}

}  // namespace

void checkMovesTogether(const Case& c, const Plan& plan, const Results& device,
                        const std::map<std::string, int64_t>& device_moves, const Results& model,
                        Verdict& v) {
  // Without records (or bundles without the replays' records) nothing tells
  // which answer a ray took, nor whether it leaked (leakSlack).
  if (device_moves.empty() || device.records.empty()) return;
  const std::vector<const RecordField*> fields = comparedRecordFields(plan);
  const uint32_t words = recordWords();
  std::vector<std::string> names;
  Moves want;
  for (const auto& [name, move] : device_moves) {
    names.push_back(name);
    want.push_back(move);
  }
  std::set<Moves> sums{Moves(names.size(), 0)};
  for (const RayAmbiguity& a : model.ambiguous) {
    if ((size_t{a.ray} + 1) * words > device.records.size()) return;
    const std::set<Moves> moves =
        rayMoves(a, names, &device.records[size_t{a.ray} * words], fields);
    if (moves.empty()) return;  // a ray whose moves are unknown
    if (moves.size() == 1 && *moves.begin() == Moves(names.size(), 0)) continue;
    std::set<Moves> next;
    for (const Moves& s : sums)
      for (const Moves& m : moves) {
        Moves t = s;
        for (size_t k = 0; k < t.size(); ++k) t[k] += m[k];
        next.insert(std::move(t));
        if (next.size() > kMaxMoveSums) return;
      }
    sums = std::move(next);
  }
  if (sums.count(want)) return;
  std::string list;
  for (size_t k = 0; k < names.size(); ++k)
    list +=
        (k ? ", '" : "'") + names[k] + "' " + (want[k] >= 0 ? "+" : "") + std::to_string(want[k]);
  v.add(findingOf(
      Status::Fail, findingRule(rulesEvidencedByCounter(c, names[0]), c.rules, "counter"),
      "counters moved together from the model's as no choice of legal answers moves them (" + list +
          "): each ambiguous ray takes one answer, replayed, which moves every counter at once"));
}

}  // namespace rayspec
