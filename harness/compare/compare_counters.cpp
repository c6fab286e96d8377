#include <algorithm>
#include <optional>
#include <set>

#include "compare/compare_parts.h"
#include "compare/counter_modes.h"
#include "compare/finding_rules.h"
#include "compare/trace_shape.h"
#include "program/walk_program.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

uint64_t runTotal(const Results& r, const std::string& run_field) {
  const uint32_t words = recordWords(), offset = findRecordField(run_field)->offset;
  uint64_t total = 0;
  for (size_t i = offset; i < r.records.size(); i += words) total += r.records[i];
  return total;
}

// A counter that follows one stage's run count must agree with the device's
// own per-ray records of that count, on any device that records both.
void checkAgainstRecords(const Case& c, const std::string& name, const CounterSource& src,
                         uint64_t d, const Results& device, Verdict& v) {
  const uint64_t runs = runTotal(device, src.run_field);
  if (d == runs * src.per_run) return;
  v.add(findingOf(
      Status::Fail, findingRule(rulesEvidencedByCounter(c, name), c.rules, "counter"),
      "counter '" + name + "' is " + std::to_string(d) + ", but the device's own records say " +
          src.run_field + " totals " + std::to_string(runs) + " and each run counts it " +
          std::to_string(src.per_run) + " time(s): " + std::to_string(runs * src.per_run) +
          " (the counter and the records disagree)"));
}

// Whether a `count` of `name` stands in a program.
bool countsIn(const Program& p, const std::string& name) {
  bool counted = false;
  walkStatements(p, [&](const Stmt& s) {
    counted = counted || (s.kind == Stmt::Kind::Count && s.counter == name);
  });
  return counted;
}

// Whether a ray_query's candidate block of any stage counts `name`.
bool countedInQueryBlock(const Case& c, const std::string& name) {
  bool counted = false;
  const auto scan = [&](const Program& p) {
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::Candidates) counted = counted || countsIn(s.then_, name);
    });
  };
  const Pipeline& p = c.pipeline;
  scan(p.raygen);
  for (const Program& m : p.miss) scan(m);
  for (const Program& k : p.callables) scan(k);
  for (const HitGroup& g : p.hit_groups)
    for (const std::optional<Program>* h : {&g.closest_hit, &g.any_hit, &g.intersection})
      if (*h) scan(**h);
  return counted;
}

// The rules a count below the floor breaks: where `name` is counted.
std::vector<std::string> floorRules(const Case& c, const std::string& name) {
  if (countedInQueryBlock(c, name)) return {"R-RQ-CANDIDATES"};
  bool boxes = false;
  for (const HitGroup& g : c.pipeline.hit_groups) {
    if (g.intersection && countsIn(*g.intersection, name)) return {"R-AABB-CONS"};
    boxes = boxes || g.intersection.has_value();
  }
  if (boxes) return {"R-AHIT-CLOSEST", "R-ISECT-REPORT"};
  return {"R-AHIT-CLOSEST"};
}

// The model's floor (Results::counter_floors, model/counter_floors.cpp): in
// any order, with any duplicates, a device runs the intersection program of
// each box a clear ray enters before its committed hit (R-AABB-CONS), the
// any-hit of each non-opaque triangle hit there and of a non-opaque box's
// leading report there (R-AHIT-CLOSEST, R-ISECT-REPORT), and a ray query's
// blocks for each such candidate (R-RQ-CANDIDATES), each counting its
// leading counts. Checked whatever the counter's mode; rays with undefined
// behaviour may move it anywhere (`undefined`: none checked).
bool belowFloor(const Case& c, const std::string& name, uint64_t d, const Results& model,
                Verdict& v) {
  const auto it = model.counter_floors.find(name);
  if (it == model.counter_floors.end() || d >= it->second) return false;
  const std::vector<std::string> rules = floorRules(c, name);
  v.add(findingOf(Status::Fail, findingRule(rules, c.rules, rules.front()),
                  "counter '" + name + "': device " + std::to_string(d) + ", at least " +
                      std::to_string(it->second) +
                      " (the leading counts of the intersection programs of the boxes the "
                      "clear rays enter, of the any-hits of the non-opaque triangles they hit "
                      "and of the non-opaque boxes' leading reports, and of the ray query "
                      "blocks of those candidates, before the committed hit: run in every "
                      "order)"));
  return true;
}

}  // namespace

// A counter the case declares exact is exact (the case claims every legal
// answer counts it alike); a raygen count that follows raygen_runs cannot
// move; one that follows miss or closest-hit runs moves only on rays with
// both a hit and a miss among their answers (one trace per ray: the rest
// differ in which hit, not in whether); one that only the programs run decide
// (trace_shape.h) moves only on rays whose answers run other programs;
// anything else, once per ambiguous trace of a ray.
namespace {

uint64_t answersSlack(const Case& c, const std::string& name, const Results& model) {
  const std::map<std::string, CounterSource> sources = counterSources(c);
  const auto src = sources.find(name);
  const TraceShape shape = traceShape(c);
  if (src != sources.end() && src->second.run_field == "raygen_runs") return 0;
  const bool follows_outcome =
      src != sources.end() &&
      (src->second.run_field == "miss_runs" || src->second.run_field == "closest_hit_runs");
  if (follows_outcome && shape.single_trace) {
    uint64_t rays = 0;
    for (const RayAmbiguity& a : model.ambiguous) {
      bool hit = false, miss = false;
      for (const Candidate& k : a.candidates) (k.hit ? hit : miss) = true;
      rays += hit && miss;
    }
    return rays * src->second.per_run;
  }
  // Counted where only the programs that run decide it: rays whose answers
  // run other programs, each by at most every count of it.
  if (shape.single_trace && countedByProgramsAlone(c, name))
    return raysRunningOtherPrograms(model) * countStatements(c, name);
  // Once per ambiguous trace: a ray traced twice through a vertex moves it twice.
  uint64_t traces = 0;
  for (const RayAmbiguity& a : model.ambiguous) traces += std::max<uint32_t>(a.traces, 1);
  return traces;
}

// Whether device count d stands within `slack` of the model's m, as the mode says.
bool withinSlack(CounterMode mode, uint64_t d, uint64_t m, const CounterSlack& slack) {
  switch (mode) {
    case CounterMode::Exact:
      return d <= m + slack.above && d + slack.below >= m;
    case CounterMode::AtLeast:
      return d + slack.below >= m;
    case CounterMode::AtMost:
      return d <= m + slack.above;
    case CounterMode::Informational:
      break;
  }
  return true;
}

// The replays' reach (CounterSlack), or nullopt where a ray has none.
std::optional<CounterSlack> replaysSlack(const std::string& name, const Results& model) {
  CounterSlack s{0, 0, true};
  for (const RayAmbiguity& a : model.ambiguous) {
    if (a.replays.empty()) return std::nullopt;
    int64_t low = 0, high = 0;  // the model's own answer moves nothing
    for (const LegalReplay& r : a.replays)
      if (const auto it = r.counter_moves.find(name); it != r.counter_moves.end()) {
        low = std::min(low, it->second);
        high = std::max(high, it->second);
      }
    s.below += static_cast<uint64_t>(-low);
    s.above += static_cast<uint64_t>(high);
  }
  return s;
}

std::string slackText(const CounterSlack& s) {
  if (!s.replayed)
    return " (within " + std::to_string(s.above) +
           ", what the ambiguous rays' legal answers may move it)";
  return " (within " + std::to_string(s.below) + " below and " + std::to_string(s.above) +
         " above, what the ambiguous rays' legal answers, each replayed, move it)";
}

}  // namespace

CounterSlack counterSlack(const Case& c, const std::string& name, const Results& model) {
  if (c.outputs.counter_modes.count(name) && c.outputs.counter_modes.at(name) == "exact") return {};
  if (const std::optional<CounterSlack> r = replaysSlack(name, model)) return *r;
  const uint64_t slack = answersSlack(c, name, model);
  return {slack, slack, false};
}

namespace {

// The device's record of an ambiguous ray took one of its leak answers and
// none of its legal ones (identity fields where written; a miss as a miss).
bool tookLeakAnswer(const RayAmbiguity& a, const uint32_t* rec) {
  const bool hit = fieldWord(rec, "closest_hit_runs") > 0 ||
                   (written(rec, recordFieldIndex("hit")) && fieldWord(rec, "hit") == 1);
  auto fits = [&](const Candidate& k) {
    return k.hit ? hit && hitFits(rec, k) : !hit;
  };
  return std::any_of(a.leak_answers.begin(), a.leak_answers.end(), fits) &&
         std::none_of(a.candidates.begin(), a.candidates.end(), fits);
}

}  // namespace

// R-WATERTIGHT: how far the rays whose device records passed between the
// triangles of a shared edge (took a leak answer) may move the counter
// besides; 0 where the records show none (a device without records too).
uint64_t leakSlack(const Case& c, const std::string& name, const Results& device,
                   const Results& model) {
  const uint32_t words = recordWords();
  Results leaky;
  for (const RayAmbiguity& a : model.ambiguous) {
    if (a.leak_answers.empty() || (static_cast<size_t>(a.ray) + 1) * words > device.records.size())
      continue;
    if (!tookLeakAnswer(a, &device.records[static_cast<size_t>(a.ray) * words])) continue;
    RayAmbiguity& l = leaky.ambiguous.emplace_back(a);
    l.candidates.insert(l.candidates.end(), a.leak_answers.begin(), a.leak_answers.end());
  }
  return leaky.ambiguous.empty() ? 0 : answersSlack(c, name, leaky);
}

void compareCounters(const Case& c, const Plan& plan, const Results& device, const Results& model,
                     size_t undefined_rays, Verdict& v) {
  auto modes = counterModes(c);
  const std::map<std::string, CounterSource> sources = counterSources(c);
  // R-UB: what a ray with undefined behaviour counts is anyone's guess.
  std::set<std::string> moved;
  if (undefined_rays) moved = countersUndefinedRaysMayMove(c);
  // R-AHIT-DUP: a counter a repeated any-hit moves.
  const std::set<std::string> repeat(model.repeat_counters.begin(), model.repeat_counters.end());
  std::map<std::string, int64_t> together;  // checkMovesTogether's, while every counter is within
  bool all_within = true;
  for (auto& [name, mode] : modes) {
    const bool undefined = moved.count(name) > 0;
    const bool repeated = repeat.count(name) > 0;
    if (undefined || repeated) mode = CounterMode::Informational;
    const auto d_it = device.counters.find(name);
    const auto m_it = model.counters.find(name);
    const uint64_t d = d_it == device.counters.end() ? 0 : d_it->second;
    const uint64_t m = m_it == model.counters.end() ? 0 : m_it->second;
    // A case without per-ray records (plan.records off) has none to agree with.
    if (!undefined_rays && sources.count(name) && !device.records.empty())
      checkAgainstRecords(c, name, sources.at(name), d, device, v);
    Finding f = findingOf(Status::Fail,
                          findingRule(rulesEvidencedByCounter(c, name), c.rules, "counter"), "");
    const std::string values = "counter '" + name + "' (" + counterModeName(mode) + "): device " +
                               std::to_string(d) + ", model " + std::to_string(m);
    const CounterSlack slack =
        mode == CounterMode::Informational ? CounterSlack{} : counterSlack(c, name, model);
    const std::string within = slackText(slack);
    const bool ok = withinSlack(mode, d, m, slack);
    if (mode != CounterMode::Exact)
      f.message = values;
    else if (ok && d != m)
      f.message = values + within;
    if (undefined)
      f.message = values + " (informational: " + std::to_string(undefined_rays) +
                  " rays with undefined behaviour, R-UB, may have moved it)";
    else if (repeated)
      f.message = values +
                  " (informational: a device may run any-hit more than once for a "
                  "primitive, R-AHIT-DUP, and that moves it)";
    if (!undefined && belowFloor(c, name, d, model, v)) {
      all_within = false;
      continue;
    }
    all_within = all_within && ok;
    if (ok && mode == CounterMode::Exact && slack.replayed)
      together[name] = static_cast<int64_t>(d) - static_cast<int64_t>(m);
    const uint64_t leaks = ok ? 0 : leakSlack(c, name, device, model);
    if (!ok && withinSlack(mode, d, m, {slack.below + leaks, slack.above + leaks, false})) {
      f.status = Status::QualityWarning;
      f.rule = "R-WATERTIGHT";
      f.evidence.clear();
      f.message = values +
                  " (beyond what the legal answers allow, within what passing between "
                  "the triangles of shared edges moves it)";
      v.add(f);
    } else if (!ok) {
      f.status = Status::Fail;
      f.message = values + (slack.below || slack.above ? within : "");
      v.add(f);
    } else if (!f.message.empty()) {
      f.status = Status::Pass;
      v.add(f);
    }
  }
  if (all_within) checkMovesTogether(c, plan, device, together, model, v);
}

}  // namespace rayspec
