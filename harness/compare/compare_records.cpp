#include <algorithm>
#include <bit>
#include <map>
#include <optional>
#include <set>

#include "compare/compare_parts.h"
#include "compare/finding_rules.h"
#include "compare/shared_edge.h"
#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {
namespace {

// The rule a mismatch of a field names (finding_rules.h: the field's own,
// or the one rule the case claims that it evidences) and what it evidences.
std::string fieldRule(const std::string& field);
FindingRule ruleForField(const std::string& field, const std::vector<std::string>& case_rules) {
  return findingRule(rulesEvidencedByField(field), case_rules, fieldRule(field));
}

// The rule column of results/record_field_table.h.
std::string fieldRule(const std::string& field) {
  const RecordField* f = findRecordField(field);
  return f ? f->rule : "R-BUILTIN";
}

// What checkAmbiguous made of the device's answer: one of the legal ones
// (or one it cannot tell), a finding (wrongs, leak or passed), or one outside
// the legal set that no rule forbids (a miss through a mesh's outer border).
enum class DeviceAnswer { Legal, Finding, Outside };

// The device's answer for an ambiguous ray, checked against the legal set.
// A hit only a device passing between the triangles of a shared edge or
// vertex reaches goes to `passed` (R-WATERTIGHT, a "should"), where its
// record is one of the leak replays if the model has any (`leak_replayed`).
DeviceAnswer checkAmbiguous(const Case& c, const RayAmbiguity& a, const uint32_t* rec,
                            bool leak_replayed, std::map<std::string, FindingBuilder>& wrongs,
                            FindingBuilder& leak, FindingBuilder& passed) {
  // A trace that ran no miss shader hit, whether or not closest-hit ran
  // (SkipClosestHit, or a hit group without one, runs neither): a hit of
  // unknown identity. Unless a miss may run nothing too (an all-zero miss
  // record, R-SBT-ZERO): then only what the shaders wrote tells.
  bool silent_miss = false;
  for (const SbtRecord& r : c.pipeline.sbt_miss) silent_miss = silent_miss || !r.group;
  // No miss record at all (a launch of ray queries only), no closest-hit or
  // miss run and no hit field: nothing tells a hit from a miss, or which.
  if (c.pipeline.sbt_miss.empty() && fieldWord(rec, "closest_hit_runs") == 0 &&
      fieldWord(rec, "miss_runs") == 0 && !written(rec, recordFieldIndex("hit")))
    return DeviceAnswer::Legal;
  const bool device_hit = fieldWord(rec, "closest_hit_runs") > 0 ||
                          (written(rec, recordFieldIndex("hit")) && fieldWord(rec, "hit") == 1) ||
                          (fieldWord(rec, "miss_runs") == 0 && !silent_miss);
  bool legal = false, miss_legal = false;
  for (const Candidate& k : a.candidates) {
    miss_legal = miss_legal || !k.hit;
    legal = legal || (device_hit && hitFits(rec, k));
  }
  if (!device_hit) {
    // A miss where triangles share the crossed edge or close a fan around the
    // crossed vertex is a leak (R-WATERTIGHT, a "should"), even when no
    // "must" rule forbids it; so is a miss no rule allows.
    // Through the outer border of a mesh only, a miss is always legal.
    // A legal miss after the device's any-hit saw a candidate (and ignored
    // it) is no leak: the device found the edge.
    // A miss no rule allows on a ray that crosses no edge or vertex (a tie,
    // a first hit, an AABB face, a shader's decision) is no leak: it breaks
    // the rule of that ambiguity.
    const bool found_candidate = fieldWord(rec, "any_hit_runs") > 0;
    const bool shared = crossesSharedEdge(c, a) && !(miss_legal && found_candidate);
    const bool watertight =
        a.reason == AmbiguityReason::Edge || a.reason == AmbiguityReason::Vertex;
    if (shared || (!miss_legal && watertight && !crossesBorderOnly(c, a))) {
      leak.addRay(a.ray);
      return DeviceAnswer::Finding;
    }
    if (!miss_legal && !watertight) {
      const std::string rule = ruleForAmbiguity(a.reason);
      FindingBuilder& wrong = wrongs[rule + " miss"];
      if (wrong.finding.rule.empty())
        wrong.finding = {Status::Fail, rule,
                         "numerically ambiguous ray (" +
                             std::string(ambiguityReasonName(a.reason)) +
                             ") missed, and no legal answer is a miss"};
      wrong.addRay(a.ray);
      return DeviceAnswer::Finding;
    }
    return miss_legal ? DeviceAnswer::Legal : DeviceAnswer::Outside;
  }
  const bool behind_edge = (a.leak_replays.empty() || leak_replayed) &&
                           std::any_of(a.leak_answers.begin(), a.leak_answers.end(),
                                       [&](const Candidate& k) { return hitFits(rec, k); });
  if (!legal && behind_edge) {
    passed.addRay(a.ray);
    return DeviceAnswer::Finding;
  }
  if (!legal) {
    const std::string rule = ruleForAmbiguity(a.reason);
    FindingBuilder& wrong = wrongs[rule];
    if (wrong.finding.rule.empty())
      wrong.finding = {Status::Fail, rule,
                       "numerically ambiguous ray (" + std::string(ambiguityReasonName(a.reason)) +
                           ") hit a primitive that is not one of its legal answers"};
    wrong.addRay(a.ray);
    return DeviceAnswer::Finding;
  }
  return DeviceAnswer::Legal;
}

// An ambiguous ray whose legal answers the model replayed (each with a
// record) whose record is one of them as a whole.
bool hasReplays(const RayAmbiguity& a) {
  return !a.replays.empty() && a.replays[0].record.size() == recordWords();
}

// Whether checkAmbiguous cannot tell the ambiguous trace's answer from the
// record: no replays (a legal hit at no one t drops them, legal_replays.cpp)
// where the ray makes more than one traversal, its hit fields maybe a later
// trace's (a miss shader's child hit: fuzz/seed-120385 ray 5 on NVIDIA 580)
// or query's; or where the ambiguous traversal is a ray query's, whose
// answer no trace's hit, miss and run fields show (fuzz/seed-150445 and
// 150663 on Mesa 26.2.6: the trace missed, the query's legal answers hit).
// Held to what its answers share (checkAmbiguousShared).
bool identityUnknown(const RayAmbiguity& a, const TraceShape& shape) {
  return !hasReplays(a) && (a.from_query || shape.several_traces);
}

// The rule a record that is none of the replays breaks (finding_rules.h),
// of those the field evidences and the ambiguity's own (the device answered
// outside its legal set).
FindingRule unreplayedRule(const Case& c, const RayAmbiguity& a, const std::string& field) {
  std::vector<std::string> evidenced = rulesEvidencedByField(field);
  evidenced.push_back(ruleForAmbiguity(a.reason));
  return findingRule(evidenced, c.rules, fieldRule(field));
}

// A finding of R-WATERTIGHT, a "should" of the specification.
FindingBuilder watertightWarning(const char* message) {
  FindingBuilder b;
  b.finding = {Status::QualityWarning, "R-WATERTIGHT", message};
  return b;
}

// A record that is none of the replays of the legal answers it took.
void addUnreplayed(const Case& c, const RayAmbiguity& a, const RecordField& f,
                   std::map<std::string, FindingBuilder>& wrongs) {
  FindingBuilder& b = wrongs[std::string("replay ") + f.name];
  if (b.finding.rule.empty())
    b.finding =
        findingOf(Status::Fail, unreplayedRule(c, a, f.name),
                  std::string("per-ray field '") + f.name +
                      "' is what none of the legal answers of a numerically ambiguous ray (" +
                      ambiguityReasonName(a.reason) +
                      ") leaves, each replayed through the launch ray (the nearest differs there)");
  b.addRay(a.ray);
}

// A ray whose ambiguous traversal is a ray query (RayAmbiguity::from_query):
// every compared field its answer cannot reach (queryReachedFields) is the
// model's, as on a clear ray.
void checkQueryUnreached(const Case& c, const std::set<std::string>& reached, const RayAmbiguity& a,
                         const uint32_t* d, const uint32_t* m,
                         const std::vector<const RecordField*>& fields, const RayBounds& bounds,
                         std::map<std::string, FindingBuilder>& wrongs) {
  for (const RecordField* f : fields) {
    if (reached.count(f->name) || sameField(*f, d, m, bounds)) continue;
    FindingBuilder& b = wrongs[std::string("query unreached ") + f->name];
    if (b.finding.rule.empty())
      b.finding = findingOf(Status::Fail, ruleForField(f->name, c.rules),
                            std::string("per-ray field '") + f->name +
                                "' differs from the model on a ray whose ambiguous ray query (" +
                                ambiguityReasonName(a.reason) +
                                ") writes it neither in its blocks nor after");
    b.addRay(a.ray);
  }
}

// What an ambiguous ray is held to, the same for every ray of the case.
struct AmbiguousJudge {
  const Case& c;
  const TraceShape shape;
  const std::optional<std::set<std::string>> query_reached;
  const std::vector<const RecordField*>& fields;
  std::map<std::string, FindingBuilder>& wrongs;
  FindingBuilder& leak;
  FindingBuilder& passed;
  FindingBuilder& doubled;
};

// Held to its legal answers as a whole where the model replayed them: a
// record that is one of them is legal; one that is none fails, unless it is
// one of the double-hit replays (any-hit ran on several triangles closing
// around the ray: R-WATERTIGHT, a "should"), a leak or an answer outside
// the legal set that no rule forbids (then held to what every answer
// shares, as without replays). A ray query's answer is
// read from no trace's fields: without replays, the fields it cannot reach
// are the model's.
void judgeAmbiguousRay(const AmbiguousJudge& j, const RayAmbiguity& a, const uint32_t* d,
                       const uint32_t* m, const RayBounds& bounds) {
  const RecordField* unreplayed =
      hasReplays(a) ? fieldNoReplayLeaves(a, d, j.fields, bounds) : nullptr;
  if (hasReplays(a) && !unreplayed) return;
  if (unreplayed && doubleReplayMatches(a, d, j.fields, bounds)) {
    j.doubled.addRay(a.ray);
    return;
  }
  const bool leak_replayed = leakReplayMatches(a, d, j.fields, bounds);
  const DeviceAnswer answer =
      identityUnknown(a, j.shape)
          ? DeviceAnswer::Legal
          : checkAmbiguous(j.c, a, d, leak_replayed, j.wrongs, j.leak, j.passed);
  if (answer == DeviceAnswer::Finding) return;
  // A record only a leak leaves, where the record names no hit to tell it
  // from a legal one: passed between (R-WATERTIGHT, a "should").
  if (unreplayed && answer == DeviceAnswer::Legal) {
    leak_replayed ? j.passed.addRay(a.ray) : addUnreplayed(j.c, a, *unreplayed, j.wrongs);
    return;
  }
  checkAmbiguousShared(j.c, j.shape, a, d, m, j.fields, bounds, j.wrongs);
  if (a.from_query && j.query_reached)
    checkQueryUnreached(j.c, *j.query_reached, a, d, m, j.fields, bounds, j.wrongs);
}

// R-WATERTIGHT's three findings, one builder each.
struct WatertightFindings {
  FindingBuilder leak =
      watertightWarning("ray on a shared edge or vertex leaked (missed every candidate)");
  FindingBuilder passed = watertightWarning(
      "ray on a shared edge or vertex passed between its triangles and hit what lies behind them");
  FindingBuilder doubled = watertightWarning(
      "double hit: any-hit ran on several of the triangles closing around a shared edge or vertex "
      "(the record is what the model leaves running their any-hits so)");
};

}  // namespace

AmbiguousRecordJudge::AmbiguousRecordJudge(const Case& c, const Plan& plan)
    : c_(c),
      shape_(traceShape(c)),
      query_reached_(queryReachedFields(c)),
      fields_(comparedRecordFields(plan)) {}

Finding AmbiguousRecordJudge::judge(const RayAmbiguity& a, const uint32_t* d, const uint32_t* m,
                                    const RayBounds& bounds) const {
  std::map<std::string, FindingBuilder> wrongs;
  WatertightFindings w;
  const AmbiguousJudge j{c_, shape_, query_reached_, fields_, wrongs, w.leak, w.passed, w.doubled};
  judgeAmbiguousRay(j, a, d, m, bounds);
  for (const auto& [key, b] : wrongs)
    if (b.finding.ray_count) return b.finding;
  for (const FindingBuilder* b : {&w.leak, &w.passed, &w.doubled})
    if (b->finding.ray_count) return b->finding;
  return {Status::Pass, "", "", {}, 0, {}};
}

void compareRecords(const Case& c, const Plan& plan, const Results& device, const Results& model,
                    const std::set<uint32_t>& undefined, Verdict& v) {
  const uint32_t words = recordWords();
  const size_t rays = device.records.size() / words;
  const auto ambiguous = ambiguityByRay(model);
  // R-PREC: clear rays whose t the model bounds more widely than the default.
  const ModelRayBounds model_bounds(c, model);
  const std::vector<const RecordField*> fields = comparedRecordFields(plan);

  // R-AHIT-DUP: per ray, the fields a repeated any-hit may change.
  std::map<uint32_t, FieldMask> repeat;
  for (const RepeatDependentRay& d : model.repeat_dependent) repeat[d.ray] = d.fields;

  std::map<std::string, FindingBuilder> mismatches;
  std::map<std::string, FindingBuilder> wrongs;
  WatertightFindings w;
  const AmbiguousJudge judge{c,        traceShape(c), queryReachedFields(c), fields, wrongs, w.leak,
                             w.passed, w.doubled};

  for (size_t i = 0; i < rays; ++i) {
    const uint32_t* d = &device.records[i * words];
    const uint32_t* m = &model.records[i * words];
    const uint32_t ray = static_cast<uint32_t>(i);
    if (undefined.count(ray)) continue;  // R-UB: never judged
    const RayBounds bounds = model_bounds.of(ray);
    const auto repeated = repeat.find(ray);
    const FieldMask repeat_fields = repeated == repeat.end() ? 0 : repeated->second;
    if (const auto it = ambiguous.find(ray); it != ambiguous.end()) {
      // Its legal answers and what repetition changes: not judged.
      if (!repeat_fields) judgeAmbiguousRay(judge, *it->second, d, m, bounds);
      continue;
    }
    for (const RecordField* f : fields) {
      if ((repeat_fields & fieldBit(f->index)) || sameField(*f, d, m, bounds)) continue;
      FindingBuilder& b = mismatches[f->name];
      if (b.finding.message.empty())
        b.finding = findingOf(
            Status::Fail, ruleForField(f->name, c.rules),
            std::string("per-ray field '") + f->name + "' differs from the model on clear rays");
      b.addRay(ray);
    }
  }
  for (auto& [name, b] : mismatches) b.flush(v);
  for (auto& [rule, b] : wrongs) b.flush(v);
  w.leak.flush(v);
  w.passed.flush(v);
  w.doubled.flush(v);
  if (!ambiguous.empty()) {
    Finding note{Status::Pass, "R-PREC",
                 std::to_string(ambiguous.size()) +
                     " numerically ambiguous rays checked against their legal answers"};
    v.add(note);
  }
}

}  // namespace rayspec
