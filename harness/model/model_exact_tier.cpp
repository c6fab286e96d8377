// The exact tier: is a trace's answer numerically clear? Candidates within
// the error bound of an edge, a vertex, an interval end, a tie or an AABB face,
// and intersection-program decisions within rounding, are tried the other way
// in sandboxed what-if runs; a ray whose answers differ is ambiguous and
// lists them all (results/results.h, RayAmbiguity). Here the tracer's side:
// classifyTrace, the what-if runs in their sandbox and their effects; the
// classifier of one trace is trace_classifier.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "case/share_frame.h"
#include "model/closed_fan.h"
#include "model/model_tracer.h"
#include "model/sphere_error.h"
#include "model/trace_classifier.h"
#include "model/traversal.h"
#include "results/record_layout.h"

namespace rayspec {

using namespace trace_detail;

bool ModelTracer::replayKnownTrace(std::optional<WhatIf>& chosen) {
  ReplayScript* script = st_.replay;
  const std::vector<WhatIf>* known = script ? script->knownAnswers() : nullptr;
  if (!known) return false;
  script->classified(*known, script->known_legal[script->traces]);
  chosen.reset();
  if (known->empty()) return true;
  chosen = (*known)[script->choose(known->size())];
  st_.ray_ambiguous = true;
  return true;
}

std::optional<WhatIf> ModelTracer::classifyTrace(
    Traversal& tr, const std::vector<ModelCandidate>& candidates,
    const std::vector<std::pair<size_t, double>>& reports,
    const std::vector<ShaderDecision>& shader_unsure, const Payload& payload_in) {
  TraceClassifier c(*this, tr, candidates, payload_in);
  c.findUnsure(reports);
  c.findSharedTriangles();
  c.tryUnsure();
  c.tryDoubleHits();
  c.tryNearBoxDecisions();
  c.tryOrders(reports);
  c.tryShaderDecisions(shader_unsure);
  c.boundT();
  return c.finish();
}

// R-ORDER-UNSPEC: an any-hit that may terminate runs on one of the candidates
// (a box, or a non-opaque triangle in the interval): the order decides.
bool ModelTracer::anyHitMayTerminate(const Traversal& tr,
                                     const std::vector<ModelCandidate>& cands) const {
  if (tr.query) return tr.query->may_terminate;  // R-RQ-TERMINATE: its blocks may end it
  if (!sh_.programs->any_hit_terminates) return false;
  const ModelScene& scene = *sh_.scene;
  for (const ModelCandidate& cand : cands) {
    if (cand.outside || (!cand.aabb && !cand.hit && cand.ambiguity == TriAmbiguity::None)) continue;
    const ModelInstance& mi = scene.instances[cand.instance];
    const ModelGeometry& g = scene.blases[mi.blas].geometries[cand.geometry];
    if (resolveOpaque(g.flags, mi.src->flags, tr.flags)) continue;
    const CHitGroup* grp = groupOf(*sh_.programs, sbt_.hit(cand.instance, cand.geometry, tr.ray));
    if (grp && grp->any_hit_terminates) return true;
  }
  return false;
}

Committed ModelTracer::decideAs(const Traversal& actual, const std::vector<ModelCandidate>& cands,
                                const WhatIf& how, Payload& payload,
                                std::vector<ShaderDecision>* noted,
                                std::vector<std::pair<size_t, double>>* reports) {
  Traversal v(actual.ray);
  v.flags = actual.flags;
  v.depth = actual.depth;
  v.tmin = actual.tmin;
  v.tmax_cur = actual.ray.tmax;
  v.exact = actual.exact;
  v.startQuery(actual.query);
  v.inlined = actual.inlined;
  v.prefer = how.prefer;
  v.first = how.first;
  v.shader_force = how.shaders.empty() ? nullptr : &how.shaders;
  v.order = how.order.empty() ? nullptr : &how.order;
  v.tie = how.tie;
  v.shader_unsure = noted;
  v.reports = reports;
  if (how.prefer >= 0) {
    const ModelCandidate& p = cands[static_cast<size_t>(how.prefer)];
    v.prefer_key[0] = p.instance;
    v.prefer_key[1] = p.geometry;
    v.prefer_key[2] = p.primitive;
  }
  v.payload = &payload;
  decide(v, cands, how.force.empty() ? nullptr : how.force.data(), payload);
  return v.best;
}

// One what-if run of the decision in a sandbox: counters, record and error
// are restored afterwards, the payload is a copy of the trace's incoming one.
Committed ModelTracer::sandbox(const Traversal& actual, const std::vector<ModelCandidate>& cands,
                               const WhatIf& how, const Payload& payload_in, OrderOutcome* left,
                               std::vector<ShaderDecision>* noted,
                               std::vector<std::pair<size_t, double>>* reports) {
  const LaunchState::Saved saved = st_.save();
  // A query's blocks change the frame of the stage that runs it: the what-if
  // run starts from the frame as traversal began, and is undone.
  std::optional<QueryFrameSaved> frame;
  if (actual.query) {
    frame = saveQueryFrame(*actual.query);
    restoreQueryFrame(*actual.query, actual.query->frame_before);
  }
  Payload p = payload_in;
  Committed best = decideAs(actual, cands, how, p, noted, reports);
  best.effect = effectOf(best, p, actual.query);
  if (left) {  // what this run leaves behind (tryPermutations)
    left->best = best;
    if (st_.rec) left->record.assign(st_.rec, st_.rec + recordWords());
    left->payload = p;
    if (actual.query) left->frame = saveQueryFrame(*actual.query);
  }
  st_.restore(saved);
  if (frame) restoreQueryFrame(*actual.query, *frame);
  return best;
}

namespace {

// The bytes of values without padding, gathered whole (`bytes`, cleared
// first) and hashed once by the standard library's hash of a byte string
// (libstdc++: 64-bit MurmurHash2, eight bytes a step). A digest held in
// memory for one run, never written: its value need not be stable.
struct Digest {
  std::string& bytes;
  explicit Digest(std::string& b) : bytes(b) { bytes.clear(); }
  template <typename T>
  void add(const T& v) {
    static_assert(std::has_unique_object_representations_v<T> || std::is_floating_point_v<T>);
    bytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  // Arrays of floats, words or 64-bit lanes: no padding, one append.
  template <typename T, size_t N>
  void add(const std::array<T, N>& a) {
    static_assert(sizeof(a) == sizeof(T) * N);
    static_assert(std::has_unique_object_representations_v<T> || std::is_floating_point_v<T>);
    bytes.append(reinterpret_cast<const char*>(a.data()), sizeof(a));
  }
  template <typename T>
  void addAll(const T* p, size_t n) {
    static_assert(std::has_unique_object_representations_v<T>);
    bytes.append(reinterpret_cast<const char*>(p), n * sizeof(T));
  }
  void add(const Payload& p) {
    add(p.color);
    add(p.value);
    add(p.depth);
    add(p.location);
    add(p.words);
    add(p.sized);
  }
  void add(const SizedSlots& s) {
    for (const auto& [type, lanes] : s.members) {
      add(static_cast<uint8_t>(type));
      add(lanes);
    }
  }
  void add(const CallData& k) {
    add(k.color);
    add(k.position);
    add(k.normal);
    add(k.value);
    add(k.location);
    add(k.words);
    add(k.sized);
  }
  void add(const Val& v) {
    add(v.f);
    add(v.u);
    add(static_cast<uint8_t>(v.b));
    add(v.x);
    add(static_cast<uint32_t>(v.sized));
  }
  uint64_t hash() const { return std::hash<std::string_view>{}(bytes); }
};

}  // namespace

uint64_t ModelTracer::effectOf(const Committed& b, const Payload& payload, const QueryRun* query) {
  Digest d(effect_bytes_);
  d.add(static_cast<uint8_t>(b.valid));
  if (b.valid) {
    d.add(b.t);
    d.add(b.instance);
    d.add(b.geometry);
    d.add(b.primitive);
    d.add(b.kind);
    d.add(b.b1);
    d.add(b.b2);
    d.add(b.words);
    d.add(b.sized);
  }
  d.add(payload);
  if (st_.rec) d.addAll(st_.rec, recordWords());
  d.addAll(st_.counters.data(), st_.counters.size());
  if (query && query->env) {
    for (const Val& v : query->env->locals) d.add(v);
    d.add(query->env->child);
    d.add(query->env->callee);
    // A restart goes on with its ray (and what it keeps committed).
    d.add(query->restarts);
    if (const std::optional<QueryRestart>& r = query->restart) {
      const TraceRay& ray = r->ray;
      d.add(ray.origin);
      d.add(ray.direction);
      d.add(ray.tmin);
      d.add(ray.tmax);
      d.add(ray.flags);
      d.add(ray.cull_mask);
      d.add(ray.tlas);
      d.add(static_cast<uint8_t>(r->keep.valid));
      if (r->keep.valid) {
        d.add(r->keep.instance);
        d.add(r->keep.geometry);
        d.add(r->keep.primitive);
      }
    }
  }
  return d.hash();
}

namespace {

// `unsure` with the candidates of each run met at one distance put in order
// of their share frames (stable): triangles of different frames decide apart
// (a device's object rays round apart there: one of each frame's may be hit,
// several in all), so unsureGroups makes each frame a group of its own.
std::vector<size_t> byFrame(const ModelScene& scene, const Traversal& actual,
                            const std::vector<ModelCandidate>& cands,
                            const std::vector<size_t>& unsure) {
  std::vector<size_t> out = unsure;
  size_t g0 = 0;
  while (g0 < out.size()) {
    size_t g1 = g0 + 1;
    while (g1 < out.size() &&
           std::fabs(cands[out[g1]].t - cands[out[g1 - 1]].t) <= actual.tol(cands[out[g1]].t))
      ++g1;
    std::stable_sort(out.begin() + static_cast<long>(g0), out.begin() + static_cast<long>(g1),
                     [&](size_t a, size_t b) {
                       return candidateFrame(scene, cands[a]) < candidateFrame(scene, cands[b]);
                     });
    g0 = g1;
  }
  return out;
}

// The unsure candidates grouped by distance and share frame, each group
// [first, last) in `unsure` (byFrame's order): a group crosses one edge or
// vertex, shared or not; a triangle the ray runs in the plane of, or a box
// its ray misses, is a group of its own.
std::vector<std::pair<size_t, size_t>> unsureGroups(const ModelScene& scene,
                                                    const Traversal& actual,
                                                    const std::vector<ModelCandidate>& cands,
                                                    const std::vector<size_t>& unsure) {
  auto alone = [&](size_t u) {
    return cands[unsure[u]].in_plane || cands[unsure[u]].outside;
  };
  std::vector<std::pair<size_t, size_t>> groups;
  size_t g0 = 0;
  while (g0 < unsure.size()) {
    size_t g1 = g0 + 1;
    while (g1 < unsure.size() && !alone(g0) && !alone(g1) &&
           std::fabs(cands[unsure[g1]].t - cands[unsure[g1 - 1]].t) <=
               actual.tol(cands[unsure[g1]].t) &&
           candidateFrame(scene, cands[unsure[g1]]) == candidateFrame(scene, cands[unsure[g0]]))
      ++g1;
    groups.emplace_back(g0, g1);
    g0 = g1;
  }
  return groups;
}

// What one group's choice forces: kOwn leaves its candidates to the model,
// a choice below the group's size makes that one alone a hit, kNone makes
// none of them one.
constexpr size_t kOwn = ~size_t{0}, kNone = kOwn - 1;

void forceGroup(WhatIf& how, const std::vector<size_t>& unsure, std::pair<size_t, size_t> g,
                size_t choice) {
  for (size_t b = g.first; b < g.second; ++b)
    how.force[unsure[b]] = choice == kOwn ? -1 : static_cast<int8_t>(choice == b - g.first ? 1 : 0);
}

// Every combination of the groups' choices, each group's kOwn among them,
// but all kOwn (the actual run): visit(pick), pick[g] group g's choice.
template <typename Visit>
void forEachCombination(const std::vector<std::vector<size_t>>& choices, Visit visit) {
  std::vector<size_t> at(choices.size(), 0);  // 0: kOwn, j > 0: choices[g][j - 1]
  std::vector<size_t> pick(choices.size(), kOwn);
  for (;;) {
    size_t g = 0;
    while (g < at.size() && at[g] == choices[g].size()) at[g++] = 0;
    if (g == at.size()) return;
    ++at[g];
    for (size_t h = 0; h < at.size(); ++h) pick[h] = at[h] == 0 ? kOwn : choices[h][at[h] - 1];
    visit(pick);
  }
}

}  // namespace

// The most what-if runs of one trace's combined groups (ModelTracer::whatIf).
constexpr size_t kMaxWhatIfCombinations = 256;

// What-if runs of the decision for an ambiguous trace: within a group of
// unsure candidates (unsureGroups: one distance, one share frame, so the
// triangles of instances moved apart decide apart and several of them may be
// hit) each candidate alone is a hit (watertight:
// at least one of a shared edge's triangles is hit); a group that does not
// close around the ray may also be no hit, and one that closes (a shared
// edge, a closed fan: closed_fan.h) no hit only as a leak. A ray may meet
// several groups one behind the other (a border edge or a leaked shared
// edge in front of a shared edge): every combination of the groups'
// choices is an answer, each group also left to the model, up to
// kMaxWhatIfCombinations runs; a combination where a closing group is no
// hit goes to `leaks`. Past the bound, each group's choices are tried with
// the others left to the model (stated: a device combining them is then
// judged on what the answers share). Stage programs run again, in a
// sandbox: their counters, record and payload effects are undone.
std::vector<WhatIfAnswer> ModelTracer::whatIf(const Traversal& actual,
                                              const std::vector<ModelCandidate>& cands,
                                              const std::vector<size_t>& unsure_found,
                                              const Payload& payload_in,
                                              std::vector<WhatIfAnswer>* leaks) {
  std::vector<WhatIfAnswer> out;
  if (unsure_found.empty()) return out;
  const std::vector<size_t> unsure = byFrame(*sh_.scene, actual, cands, unsure_found);
  const std::vector<std::pair<size_t, size_t>> groups =
      unsureGroups(*sh_.scene, actual, cands, unsure);
  // Each group's choices: its candidates alone, then none.
  std::vector<std::vector<size_t>> choices(groups.size());
  std::vector<bool> closes(groups.size());
  size_t combinations = 1;
  for (size_t g = 0; g < groups.size(); ++g) {
    const auto [g0, g1] = groups[g];
    for (size_t a = 0; a < g1 - g0; ++a) choices[g].push_back(a);
    choices[g].push_back(kNone);
    const std::vector<size_t> members(unsure.begin() + static_cast<long>(g0),
                                      unsure.begin() + static_cast<long>(g1));
    // At an interval end a device may find none of them (nearTmin): no leak.
    closes[g] = closesAroundRay(*sh_.scene, cands, members, actual.ray, actual.flags) &&
                std::none_of(members.begin(), members.end(), [&](size_t k) {
                  return actual.nearTmin(cands[k]) || actual.nearTmax(cands[k]);
                });
    combinations = std::min(combinations * (choices[g].size() + 1), kMaxWhatIfCombinations + 1);
  }
  WhatIf how{false, std::vector<int8_t>(cands.size(), -1), -1, -1, {}};
  auto run = [&](const std::vector<size_t>& pick) {
    bool leak = false;
    for (size_t g = 0; g < groups.size(); ++g) {
      forceGroup(how, unsure, groups[g], pick[g]);
      leak = leak || (closes[g] && pick[g] == kNone);
    }
    WhatIfAnswer a{{}, how, {}};
    a.best = sandbox(actual, cands, how, payload_in, nullptr, nullptr, &a.reports);
    (leak ? *leaks : out).push_back(std::move(a));
  };
  if (combinations <= kMaxWhatIfCombinations) {
    forEachCombination(choices, run);
    return out;
  }
  std::vector<size_t> pick(groups.size(), kOwn);
  for (size_t g = 0; g < groups.size(); ++g) {
    for (size_t c : choices[g]) {
      pick[g] = c;
      run(pick);
    }
    pick[g] = kOwn;
  }
  return out;
}

}  // namespace rayspec
