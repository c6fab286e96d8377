#include "compare/finding_rules.h"

#include <algorithm>
#include <map>
#include <set>

#include "program/walk_program.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

using Rules = std::vector<std::string>;

// Rules that decide whether a trace hits and which candidate it commits: any
// of them shows in the hit, the identity fields, t, and which shaders ran
// (facing among them: with a culling flag it decides what is culled; the
// top level a trace names decides which instances it can find).
const Rules& decisionRules() {
  static const Rules r = {
      "R-CAND-TRI-OPEN", "R-CAND-AABB-CLOSED", "R-TIE",       "R-ORDER-UNSPEC",     "R-INST-XFORM",
      "R-AABB-CONS",     "R-ISECT-CLOSEST",    "R-SKIP-TRI",  "R-SKIP-AABB",        "R-MASK",
      "R-FACE-CULL",     "R-OPACITY",          "R-CULL-OPQ",  "R-AHIT-OPAQUE-SKIP", "R-AHIT-UNUSED",
      "R-AHIT-CLOSEST",  "R-IGNORE",           "R-TERMINATE", "R-ISECT-REPORT",     "R-TOFH",
      "R-MISS-XOR-CHIT", "R-SBT-HIT",          "R-SBT-MISS",  "R-SBT-ZERO",         "R-INACTIVE",
      "R-DEGEN",         "R-WATERTIGHT",       "R-PREC",      "R-FACE-DET",         "R-TLAS-ARRAY"};
  return r;
}

// Rules of what flows through shader stages: payloads, attributes, callable
// data, shader records, nesting.
const Rules& dataRules() {
  static const Rules r = {"R-PAYLOAD",   "R-CALLABLE",  "R-SBT-CALL", "R-SBT-RECORD",
                          "R-RECURSION", "R-TMAX-VIEW", "R-BUILTIN",  "R-CULLMASK-BUILTIN"};
  return r;
}

// Rules of how often any-hit and intersection programs run.
const Rules& traversalRules() {
  static const Rules r = {"R-AHIT-DUP", "R-ISECT-MULTI", "R-ISECT-CLOSEST", "R-AHIT-CLOSEST",
                          "R-ORDER-UNSPEC"};
  return r;
}

Rules join(std::initializer_list<const Rules*> parts, Rules own = {}) {
  for (const Rules* p : parts) own.insert(own.end(), p->begin(), p->end());
  return own;
}

// Rules of how the pipeline is built and how shader code runs (and whether
// it runs through ray queries): whatever shaders observe, any field or
// counter may show them broken.
const Rules& pipelineRules() {
  static const Rules r = {"R-LIBRARY",
                          "R-RAYGEN-REGION",
                          "R-NULL-SHADERS",
                          "R-INDIRECT",
                          "R-STACK",
                          "R-LAUNCH-3D",
                          "R-AS-COPY",
                          "R-AS-UPDATE",
                          "R-AS-SIZE",
                          "R-AS-BUILD",
                          "R-AS-MEMORY",
                          "R-AS-CREATE",
                          "R-VERTEX-FORMAT",
                          "R-POSITION-FETCH",
                          "R-LIVE-STATE",
                          "R-CONTROL-FLOW",
                          "R-RQ-EQUIV",
                          "R-RQ-INIT",
                          "R-RQ-CANDIDATES",
                          "R-RQ-COMMIT",
                          "R-RQ-TERMINATE",
                          "R-RQ-VALUES",
                          "R-DEFERRED",
                          "R-EMPTY-LAYOUT",
                          "R-HIT-OBJECT",
                          "R-HIT-OBJECT-DEFERRED",
                          "R-HIT-OBJECT-RECORD"};
  return r;
}

std::vector<std::string> fieldRules(const std::string& field) {
  static const std::set<std::string> decision = {
      "hit",   "instance_id",  "instance_custom_index", "geometry_index", "primitive_id",
      "hit_t", "barycentrics", "hit_position",          "miss_runs",      "closest_hit_runs"};
  if (field == "barycentrics" || field == "hit_position")  // hit attributes
    return join({&decisionRules()}, {"R-BUILTIN", "R-PAYLOAD"});
  if (decision.count(field)) return join({&decisionRules()}, {"R-BUILTIN"});
  if (field == "hit_kind")
    return join({&decisionRules()}, {"R-HITKIND-TRI", "R-FACE-DET", "R-BUILTIN"});
  if (isFreeField(field)) return join({&dataRules(), &decisionRules()});
  if (field == "ray_tmin" || field == "ray_tmax")
    return join({&decisionRules()}, {"R-TMAX-VIEW", "R-BUILTIN"});
  if (field == "depth") return {"R-RECURSION", "R-BUILTIN"};
  if (field == "callable_runs") return {"R-CALLABLE", "R-SBT-CALL"};
  if (field == "raygen_runs") return {"R-BUILTIN"};
  if (field == "incoming_ray_flags") return {"R-BUILTIN", "R-TOFH"};
  if (field == "world_ray_origin" || field == "world_ray_direction") return {"R-BUILTIN"};
  if (field == "object_ray_origin" || field == "object_ray_direction")
    return {"R-BUILTIN", "R-INST-XFORM"};
  return {"R-BUILTIN"};
}

std::vector<std::string> counterRules(const Case& c, const std::string& counter) {
  std::set<Stage> stages;
  auto visit = [&](const Program& p, Stage stage) {
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::Count && s.counter == counter) stages.insert(stage);
    });
  };
  const Pipeline& pipe = c.pipeline;
  visit(pipe.raygen, Stage::Raygen);
  for (const Program& p : pipe.miss) visit(p, Stage::Miss);
  for (const Program& p : pipe.callables) visit(p, Stage::Callable);
  for (const HitGroup& g : pipe.hit_groups) {
    if (g.closest_hit) visit(*g.closest_hit, Stage::ClosestHit);
    if (g.any_hit) visit(*g.any_hit, Stage::AnyHit);
    if (g.intersection) visit(*g.intersection, Stage::Intersection);
  }
  Rules out;
  for (Stage s : stages) {
    switch (s) {
      case Stage::Raygen:
        out = join({&decisionRules(), &dataRules()}, out);
        break;  // after a trace: its outcome
      case Stage::Miss:
      case Stage::ClosestHit:
        out = join({&decisionRules(), &dataRules()}, out);
        break;
      case Stage::AnyHit:
      case Stage::Intersection:
        out = join({&decisionRules(), &traversalRules()}, out);
        break;
      case Stage::Callable:
        out = join({&dataRules()}, out);
        break;
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> rulesEvidencedByField(const std::string& field) {
  return join({&pipelineRules()}, fieldRules(field));
}

std::vector<std::string> rulesEvidencedByCounter(const Case& c, const std::string& counter) {
  return join({&pipelineRules()}, counterRules(c, counter));
}

namespace {

// The one rule of `claimed` the finding names, "" when none is alone.
std::string aloneAmong(const std::vector<std::string>& claimed, const std::string& own) {
  if (std::find(claimed.begin(), claimed.end(), own) != claimed.end()) return own;
  if (claimed.size() == 1) return claimed[0];
  // The one claim the value speaks of itself, apart from how the pipeline is
  // built and run (which every field and counter may show).
  std::vector<std::string> own_kind;
  for (const std::string& r : claimed)
    if (std::find(pipelineRules().begin(), pipelineRules().end(), r) == pipelineRules().end())
      own_kind.push_back(r);
  return own_kind.size() == 1 ? own_kind[0] : "";
}

}  // namespace

FindingRule findingRule(const std::vector<std::string>& evidenced,
                        const std::vector<std::string>& case_rules, const std::string& own) {
  FindingRule out;
  for (const std::string& r : case_rules)
    if (std::find(evidenced.begin(), evidenced.end(), r) != evidenced.end() &&
        std::find(out.evidence.begin(), out.evidence.end(), r) == out.evidence.end())
      out.evidence.push_back(r);
  out.rule = aloneAmong(out.evidence, own);
  if (!out.rule.empty()) return out;
  if (own.rfind("R-", 0) == 0 || out.evidence.empty()) {
    out.rule = own;
    return out;
  }
  std::vector<std::string> named = out.evidence;  // no rule of its own: the claims, joined
  std::sort(named.begin(), named.end());
  for (const std::string& r : named) out.rule += (out.rule.empty() ? "" : "/") + r;
  return out;
}

Finding findingOf(Status status, const FindingRule& r, std::string message) {
  Finding f;
  f.status = status;
  f.rule = r.rule;
  f.message = std::move(message);
  f.evidence = r.evidence;
  return f;
}

}  // namespace rayspec
