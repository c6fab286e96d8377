// Exact counters judged together against the replays of the ambiguous
// rays' legal answers (RayAmbiguity::replays): one answer per ray moves
// every counter at once, so per-counter ranges are not enough (one ray
// counted on neither of its two branches stays within each range).
#include <set>
#include <vector>

#include "compare/compare_parts.h"
#include "compare/finding_rules.h"

namespace rayspec {
namespace {

// The most distinct sums of moves followed; beyond, the counters stay
// judged one by one.
constexpr size_t kMaxMoveSums = 4096;

using Moves = std::vector<int64_t>;  // one per judged counter, in their order

// The moves of each of a ray's replays over `names` (the model's own, none, among them).
std::set<Moves> rayMoves(const RayAmbiguity& a, const std::vector<std::string>& names) {
  std::set<Moves> out{Moves(names.size(), 0)};
  for (const LegalReplay& r : a.replays) {
    Moves m(names.size(), 0);
    for (size_t k = 0; k < names.size(); ++k)
      if (const auto it = r.counter_moves.find(names[k]); it != r.counter_moves.end())
        m[k] = it->second;
    out.insert(m);
  }
  return out;
}

}  // namespace

void checkMovesTogether(const Case& c, const std::map<std::string, int64_t>& device_moves,
                        const Results& model, Verdict& v) {
  if (device_moves.size() < 2) return;  // one counter: its range says it all
  std::vector<std::string> names;
  Moves want;
  for (const auto& [name, move] : device_moves) {
    names.push_back(name);
    want.push_back(move);
  }
  std::set<Moves> sums{Moves(names.size(), 0)};
  for (const RayAmbiguity& a : model.ambiguous) {
    const std::set<Moves> moves = rayMoves(a, names);
    if (moves.size() < 2) continue;
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
  v.add({Status::Fail,
         findingRule(rulesEvidencedByCounter(c, names[0]), c.rules, "counter"),
         "counters moved together from the model's as no choice of legal answers moves them (" +
             list +
             "): each ambiguous ray takes one answer, replayed, which moves every counter at once",
         {},
         0});
}

}  // namespace rayspec
