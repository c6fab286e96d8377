// ModelTracer (model_tracer.h): Embree enumerates, the tracer decides (see
// the order documented in model_engine.h), then closest-hit or miss runs.
// An intersection program's reports and any-hit go through HitProtocol
// (hit_protocol.cpp); the exact tier's ambiguity check is in
// model_exact_tier.cpp, the path without decisions in model_fast_path.cpp.
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <utility>

#include "base/error_bounds.h"
#include "case/flag_names.h"
#include "model/hit_protocol.h"
#include "model/model_tracer.h"
#include "model/sphere_error.h"
#include "model/stage_interpreter.h"
#include "model/traversal.h"

namespace rayspec {
namespace trace_detail {

bool keyLess(uint32_t i0, uint32_t g0, uint32_t p0, uint32_t i1, uint32_t g1, uint32_t p1) {
  if (i0 != i1) return i0 < i1;
  if (g0 != g1) return g0 < g1;
  return p0 < p1;
}

const CHitGroup* groupOf(const CPipeline& p, const SbtRecord* rec) {
  if (!rec || !rec->group || *rec->group >= p.groups.size()) return nullptr;
  return &p.groups[*rec->group];
}

bool resolveOpaque(uint32_t geom_flags, uint32_t inst_flags, uint32_t ray_flags) {
  if (ray_flags & kRayOpaque) return true;
  if (ray_flags & kRayNoOpaque) return false;
  if (inst_flags & kInstanceForceOpaque) return true;
  if (inst_flags & kInstanceForceNoOpaque) return false;
  return (geom_flags & kGeometryOpaque) != 0;
}

Facing facing(const ModelScene& s, const ModelCandidate& c, const TraceRay& ray, uint32_t flags) {
  const ModelInstance& mi = s.instances[c.instance];
  const auto& tri = s.blases[mi.blas].geometries[c.geometry].triangles[c.primitive];
  const Vec3 d = applyAffine(mi.inverse_f, ray.direction, 0);
  double n[3];
  const double e1[3] = {double(tri[1][0]) - tri[0][0], double(tri[1][1]) - tri[0][1],
                        double(tri[1][2]) - tri[0][2]};
  const double e2[3] = {double(tri[2][0]) - tri[0][0], double(tri[2][1]) - tri[0][1],
                        double(tri[2][2]) - tri[0][2]};
  n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  n[2] = e1[0] * e2[1] - e1[1] * e2[0];
  const double sdot = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
  Facing f;
  f.front = sdot < 0;
  if (mi.src->flags & kInstanceFlipFacing) f.front = !f.front;
  if (c.in_plane) {
    // The ray in the triangle's plane: a zero-area projection in exact
    // arithmetic, either face on a device a step off it (R-PREC): the face
    // the ray's culling keeps, if one.
    f.front = !(flags & kRayCullFrontFacing) || (mi.src->flags & kInstanceFacingCullDisable);
  } else if (sdot == 0) {
    f.culled = true;  // zero-area projection (R-FACE-DET)
  }
  f.kind = f.front ? 0xFEu : 0xFFu;
  if (!(mi.src->flags & kInstanceFacingCullDisable)) {
    if ((flags & kRayCullBackFacing) && !f.front) f.culled = true;
    if ((flags & kRayCullFrontFacing) && f.front) f.culled = true;
  }
  return f;
}

// The environment of a stage that sees a hit (intersection, any-hit, closest-hit).
StageEnv hitStage(Stage stage, const std::vector<uint32_t>& record_data, Payload* payload,
                  const TraceRay& ray, const HitView& hv, float tmax_view, uint32_t depth) {
  StageEnv e;
  e.stage = stage;
  e.record_data = &record_data;
  e.payload = payload;
  e.ray = &ray;
  e.hit = &hv;
  e.tmax_view = tmax_view;
  e.depth = depth;
  return e;
}

// A hit's own values on the view of its primitive.
void setHit(HitView& hv, float t, uint32_t kind, float b1, float b2) {
  hv.t = t;
  hv.hit_kind = kind;
  hv.b1 = b1;
  hv.b2 = b2;
}

HitView viewOf(const ModelScene& s, const Case& c, const TraceRay& ray, uint32_t instance,
               uint32_t geometry, uint32_t primitive, bool object_ray) {
  HitView hv;
  const ModelInstance& mi = s.instances[instance];
  hv.instance = instance;
  hv.custom_index = c.scene.instances[instance].custom_index & kInstanceFieldMask;
  hv.geometry = geometry;
  hv.primitive = primitive;
  if (object_ray) {
    hv.object_origin = applyAffine(mi.inverse_f, ray.origin, 1);
    hv.object_direction = applyAffine(mi.inverse_f, ray.direction, 0);
  }
  const ModelGeometry& g = s.blases[mi.blas].geometries[geometry];
  if (g.kind == Geometry::Kind::Aabbs) {
    const auto& a = g.aabbs[primitive];
    hv.aabb_min = {a[0], a[1], a[2]};
    hv.aabb_max = {a[3], a[4], a[5]};
  } else if (primitive < g.triangles.size()) {
    hv.vertices = &g.triangles[primitive];
  }
  return hv;
}

// A ray Embree can trace. The rest (non-finite origin or direction, NaN or
// negative tmin, tmax below tmin or NaN: R-UB, any result is allowed) is
// never handed to Embree, whose debug checks would abort, and misses.
bool validRay(const TraceRay& r, const RTCRayHit& rh) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(r.origin[k]) || !std::isfinite(r.direction[k])) return false;
  if (!(r.tmin >= 0.0f) || !(r.tmin <= r.tmax)) return false;
  return (rh.ray.mask & kVisibilityMask) != 0;
}

// R-ORDER-UNSPEC: the order the model decides candidates in (near to far,
// or a legal device's order: ModelFaultSeam).
void sortCandidates(std::vector<ModelCandidate>& cands, const ModelFaultSeam& seam) {
  std::sort(cands.begin(), cands.end(), [&seam](const ModelCandidate& a, const ModelCandidate& b) {
    const bool key_less =
        keyLess(a.instance, a.geometry, a.primitive, b.instance, b.geometry, b.primitive);
    if (seam.permutedOrder()) {  // a legal device's shuffle (rayspec mutate)
      const uint64_t ra = seam.permutedRank(a.instance, a.geometry, a.primitive),
                     rb = seam.permutedRank(b.instance, b.geometry, b.primitive);
      return ra != rb ? ra < rb : key_less;
    }
    const bool a_last = seam.decidedLast(a.instance, a.geometry, a.primitive),
               b_last = seam.decidedLast(b.instance, b.geometry, b.primitive);
    if (a_last != b_last) return b_last;  // a legal device's one candidate last
    return seam.decidedBefore(a.t, b.t, key_less);
  });
}

}  // namespace trace_detail

using namespace trace_detail;

Committed ModelTracer::committedHit(const TraceRay& r, uint32_t depth, const CStmt* site,
                                    Payload& payload, uint32_t& flags) {
  flags = r.flags;
  if (sh_.c->pipeline.flags & kPipelineSkipTriangles) flags |= kRaySkipTriangles;
  if (sh_.c->pipeline.flags & kPipelineSkipAabbs) flags |= kRaySkipAabbs;
  payload.depth = depth;
  // R-UB: a ray with a non-finite, NaN or negative parameter finds nothing
  // (validRay keeps it from Embree) and misses; one with an illegal flag
  // combination is traced with its flags as the model resolves them.
  st_.checkRayParameters(r, site, depth);
  return sh_.direct ? directHit(r, flags) : traverse(r, flags, depth, payload);
}

Payload ModelTracer::trace(const TraceRay& r, uint32_t depth, const CStmt* site, Payload payload) {
  uint32_t flags = 0;
  const Committed best = committedHit(r, depth, site, payload, flags);
  shade(r, flags, depth, best, payload);
  return payload;
}

bool ModelTracer::boxOffered(const ModelCandidate& cand, size_t k, const int8_t* force) const {
  if (force && force[k] >= 0) return force[k] == 1;
  return !cand.outside || sh_.fault_seam.nearBoxesOffered();
}

// Whether a triangle candidate's t is in the interval (open, R-CAND-TRI-OPEN),
// with the what-if runs' forced hits and preferences and the exact tier's
// tie rule.
bool ModelTracer::triangleInside(const Traversal& tr, const ModelCandidate& cand, size_t k,
                                 const int8_t* force) const {
  // A triangle the ray runs in the plane of (forced: never the model's own
  // hit): a device's t anywhere across it, within t_err of cand.t.
  if (cand.in_plane) return cand.t - cand.t_err < tr.tmax_cur && cand.t + cand.t_err > tr.tmin;
  bool inside = cand.t > tr.tmin && cand.t < tr.tmax_cur;
  if (sh_.fault_seam.closedTriangleInterval() && !tr.best.valid)
    inside = cand.t >= tr.tmin && cand.t <= tr.tmax_cur;
  // What-if run forcing a hit at an interval end (tmin-tie, tmax-tie): a
  // float ray test may put it a step inside, unless every device computes
  // this t exactly (R-CAND-TRI-OPEN, model/exact_interval.h).
  const bool exact_out =
      (cand.exact_tmin && cand.t <= tr.tmin) || (cand.exact_tmax && cand.t >= tr.tmax_cur);
  if (!inside && force && force[k] == 1 && !tr.best.valid && !exact_out &&
      cand.t > tr.tmin - tr.endTol(cand) && cand.t < tr.tmax_cur + tr.endTol(cand))
    inside = true;
  const bool tie = tr.exact && tr.ties(cand.t);
  const bool best_preferred = tr.isPreferred(tr.best.instance, tr.best.geometry, tr.best.primitive);
  if (tie && (tr.prefer == static_cast<long>(k) || best_preferred)) {
    // What-if run preferring one candidate (R-TIE).
    inside = tr.prefer == static_cast<long>(k) && cand.t > tr.tmin;
  } else if (tie && tr.tie != TieRule::Model) {
    // What-if run of another order (R-TIE): dropped before its any-hit, or
    // confirmed (then replacing the committed hit, or dropped in decide).
    inside = tr.tie != TieRule::Keep && cand.t > tr.tmin;
  } else if (!inside && tie &&
             keyLess(cand.instance, cand.geometry, cand.primitive, tr.best.instance,
                     tr.best.geometry, tr.best.primitive)) {
    // Exact tier, R-TIE: a tie with the committed hit goes to the smaller key.
    inside = true;
  }
  return inside;
}

namespace {

// Planted, inlined (ModelFaultSeam::inlinedQuery): the loop's confirm of
// an accepted triangle commits nothing, though a terminate still ends it.
bool inlinedConfirmLost(Traversal& tr, Flow any_hit) {
  const ModelFaultSeam::InlinedQuery& q = tr.inlined;
  if (!q.confirm_ignored && !(q.confirm_only_first && tr.best.valid)) return false;
  if (any_hit == Flow::Terminate) tr.stop = true;
  return true;
}

// What-if run (R-TIE, TieRule::ConfirmDrop): a triangle confirmed at the
// committed t is dropped there (Traversal::confirmDrops); an any-hit's
// terminate still ends the traversal.
bool confirmedThenDropped(Traversal& tr, const ModelCandidate& cand, Flow any_hit) {
  if (!tr.confirmDrops(cand.t)) return false;
  if (any_hit == Flow::Terminate) tr.stop = true;
  return true;
}

}  // namespace

std::optional<ModelTracer::OrderedCandidate> ModelTracer::candidateAt(
    const Traversal& tr, const std::vector<ModelCandidate>& cands, size_t pos) const {
  const size_t first = tr.first >= 0 ? static_cast<size_t>(tr.first) : 0;
  const size_t k = tr.order       ? (*tr.order)[pos]
                   : tr.first < 0 ? pos
                   : pos == 0     ? first
                   : pos <= first ? pos - 1
                                  : pos;
  const ModelCandidate& cand = cands[k];
  const ModelInstance& mi = sh_.scene->instances[cand.instance];
  const ModelGeometry& g = sh_.scene->blases[mi.blas].geometries[cand.geometry];
  const bool opaque = resolveOpaque(g.flags, mi.src->flags, tr.flags);
  if ((tr.flags & kRayCullOpaque) && opaque) return std::nullopt;
  if ((tr.flags & kRayCullNoOpaque) && !opaque) return std::nullopt;
  return OrderedCandidate{k, opaque};
}

// The model's decision over the sorted candidates (R-ORDER-UNSPEC: in
// ascending distance). `force`, when given, overrides per candidate whether a
// triangle is a hit (-1: the model's own decision, 0: no, 1: yes).
void ModelTracer::decide(Traversal& tr, const std::vector<ModelCandidate>& cands,
                         const int8_t* force, Payload& payload) {
  if (tr.query) {
    decideQuery(tr, cands, force);
    return;
  }
  const Case& c = *sh_.c;
  const ModelScene& scene = *sh_.scene;
  const TraceRay& r = tr.ray;
  for (size_t pos = 0; pos < cands.size(); ++pos) {
    if (tr.stop) break;
    const std::optional<OrderedCandidate> at = candidateAt(tr, cands, pos);
    if (!at) continue;
    const size_t k = at->k;
    const bool opaque = at->opaque;
    const ModelCandidate& cand = cands[k];
    const SbtRecord* rec = sbt_.hit(cand.instance, cand.geometry, r);
    const CHitGroup* grp = groupOf(*sh_.programs, rec);
    if (cand.aabb) {
      if (!boxOffered(cand, k, force)) continue;
      // A preferred box entered at the committed t (within the error bound) still runs.
      if (cand.t > tr.tmax_cur && !(tr.prefer == static_cast<long>(k) && tr.ties(cand.t))) continue;
      // Planted, inlined: a box runs the triangle block, whose confirm of a box commits nothing.
      if (tr.inlined.candidate_type_swapped) continue;
      if (grp && grp->intersection) hits_.runIntersection(tr, cand, k, opaque, rec, grp);
      continue;
    }
    if (!(force && force[k] >= 0 ? force[k] == 1 : cand.hit)) continue;
    if (!triangleInside(tr, cand, k, force)) continue;
    Facing f = facing(scene, cand, r, tr.flags);
    if (f.culled) continue;
    if (tr.inlined.front_face_inverted) f.kind ^= 1u;  // 0xFE (front) and 0xFF swapped
    // A candidate of the inlined query's loop, not committed by the query itself.
    const bool offered = !opaque || tr.inlined.opaque_offered;
    // Planted, inlined: a triangle runs the box block; a triangle group has no intersection.
    if (offered && tr.inlined.candidate_type_swapped) continue;
    Flow ah = Flow::Continue;
    if (offered && grp && grp->any_hit) {
      HitView hv = viewOf(scene, c, r, cand.instance, cand.geometry, cand.primitive);
      setHit(hv, static_cast<float>(cand.t), f.kind, cand.b1, cand.b2);
      st_.checkPayloadType(payload, grp->payload, "pipeline.hit_groups", *rec->group, ".any_hit");
      StageEnv a = hitStage(Stage::AnyHit, rec->data, &payload, r, hv, hv.t, tr.depth);
      const ModelInstance& mi = scene.instances[cand.instance];
      ah = hits_.runAnyHit(*grp->any_hit, a, hv,
                           scene.blases[mi.blas].geometries[cand.geometry].flags);
      if (ah == Flow::Ignore) continue;
    }
    if (offered && inlinedConfirmLost(tr, ah)) continue;
    if (confirmedThenDropped(tr, cand, ah)) continue;
    // Exact tier, R-PREC: how far a device's t may lie (its frame's rounding).
    tr.best = {true,   cand.t,  cand.instance, cand.geometry, cand.primitive,
               f.kind, cand.b1, cand.b2,       cand.t_err};
    if (!tr.inlined.commit_keeps_interval) tr.tmax_cur = cand.t;
    if ((ah == Flow::Terminate || (tr.flags & kRayTerminateOnFirstHit)) &&
        !tr.inlined.terminate_ignored)
      tr.stop = true;
  }
}

// Every candidate from Embree, decided by the model in order (see
// model_engine.h), then the exact tier's ambiguity check.
Committed ModelTracer::traverse(const TraceRay& r, uint32_t flags, uint32_t depth, Payload& payload,
                                QueryRun* query) {
  const ModelScene& scene = *sh_.scene;
  Traversal tr(r);
  tr.flags = flags;
  tr.depth = depth;
  tr.tmin = r.tmin;
  tr.tmax_cur = r.tmax;
  tr.exact = scene.tier == ModelTier::Exact;
  tr.payload = &payload;
  tr.startQuery(query);
  if (!query) tr.inlined = sh_.fault_seam.inlinedQuery(depth);
  const Payload payload_in = payload;  // for the exact tier's what-if variants
  // A legal device's other answer (ModelFaultSeam) replays the trace from here.
  std::optional<LaunchState::Saved> before;
  // So does a legal replay (legal_replays.h; the model's own run takes each
  // trace's actual answer).
  if (tr.exact && ((sh_.fault_seam.answersOtherwise() && !st_.ray_ambiguous) ||
                   (st_.replay && !st_.replay->own)))
    before = st_.save();
  if (query && tr.exact) query->frame_before = saveQueryFrame(*query);

  std::vector<ModelCandidate>* cands = candidatesOf(r, tr.flags, depth, query);
  std::vector<std::pair<size_t, double>> reports;  // exact tier: every report of the actual run
  std::vector<ShaderDecision> shader_unsure;       // exact tier: decisions rounding may flip
  std::vector<LeadReport> leads;                   // exact tier: the boxes' leading reports
  if (cands) {
    tr.reports = tr.exact ? &reports : nullptr;
    tr.lead_reports = tr.exact ? &leads : nullptr;
    tr.shader_unsure = tr.exact && sh_.programs->reads_sphere ? &shader_unsure : nullptr;
    decide(tr, *cands, nullptr, payload);
    tr.reports = nullptr;
    tr.lead_reports = nullptr;
    tr.shader_unsure = nullptr;
    if (!query) checkCandidates(tr, *cands);  // a query reads no hit record
  }

  if (cands && tr.exact && (!st_.ray_ambiguous || st_.replay)) {
    std::optional<WhatIf> chosen;
    if (!replayKnownTrace(chosen))
      chosen = classifyTrace(tr, *cands, reports, shader_unsure, payload_in);
    if (chosen && before && !chosen->actual) {
      st_.restore(*before);
      if (query) restoreQueryFrame(*query, query->frame_before);
      payload = payload_in;
      tr.best = decideAs(tr, *cands, *chosen, payload);
    }
    if (!query) checkLegalAnswerRecords(r, tr.flags);
    countFloors(tr, *cands, leads);
  }
  return tr.best;
}

std::vector<ModelCandidate>* ModelTracer::candidatesOf(const TraceRay& r, uint32_t flags,
                                                       uint32_t depth, const QueryRun* query) {
  RTCRayHit rh = embreeRay(r, flags);
  if (!validRay(r, rh)) return nullptr;
  // A query's candidates apart from the traces': a query's block may run
  // another query, nested; a trace's by depth.
  std::vector<ModelCandidate>* cands = nullptr;
  if (query) {
    cands = &query_pool_[query->level % kMaxQueryNesting];
  } else {
    if (cand_pool_.size() < depth) cand_pool_.resize(depth);
    cands = &cand_pool_[depth - 1];
  }
  cands->clear();
  const ModelScene& scene = *sh_.scene;
  TraceContext tc;
  rtcInitIntersectContext(&tc.rtc);
  tc.scene = &scene;
  tc.origin = {r.origin[0], r.origin[1], r.origin[2]};
  tc.direction = {r.direction[0], r.direction[1], r.direction[2]};
  tc.tmin = r.tmin;
  tc.tmax = r.tmax;
  tc.candidates = cands;
  // Slightly wider than the interval: the model checks both ends itself.
  rh.ray.tnear = std::max(0.0f, r.tmin - std::fabs(r.tmin) * kEnumerationPadRelF);
  rh.ray.tfar = r.tmax + std::fabs(r.tmax) * kEnumerationPadRelF;
  rtcIntersect1(scene.tops[r.tlas], &tc.rtc, &rh);
  sortCandidates(*cands, sh_.fault_seam);
  return cands;
}

void ModelTracer::checkLegalAnswerRecords(const TraceRay& r, uint32_t flags) {
  if (!st_.ray_ambiguous || st_.ray_undefined || st_.ambiguous.empty() ||
      st_.ambiguous.back().ray != st_.index)
    return;
  for (const Candidate& k : st_.ambiguous.back().candidates) {
    if (k.hit && !(flags & kRaySkipClosestHit) && !sbt_.hit(k.instance, k.geometry, r))
      st_.hitRecordOutOfRange(k.instance, k.geometry, r);
    if (!k.hit && (r.miss & kTraceMissIndexMask) >= sbt_.miss().size()) st_.missRecordOutOfRange(r);
  }
}

// The planted fault nested_trace_clobbers_hit: the closest-hit that made
// this nested trace now reads its committed hit.
void ModelTracer::clobberCaller(const TraceRay& r, const Committed& best) {
  if (!shading_hit_ || !sh_.fault_seam.nestedTraceClobbersHit()) return;
  HitView nested = viewOf(*sh_.scene, *sh_.c, r, best.instance, best.geometry, best.primitive,
                          sh_.need_object_ray);
  setHit(nested, static_cast<float>(best.t), best.kind, best.b1, best.b2);
  nested.words = best.words;
  nested.sized = best.sized;
  *shading_hit_ = nested;
}

// R-MISS-XOR-CHIT: closest-hit or miss for the committed hit.
void ModelTracer::shade(const TraceRay& r, uint32_t flags, uint32_t depth, const Committed& best,
                        Payload& payload, std::optional<uint64_t> hit_index) {
  const Case& c = *sh_.c;
  const ModelScene& scene = *sh_.scene;
  if (best.valid) {
    if (!(flags & kRaySkipClosestHit)) {
      const uint64_t index = hit_index.value_or(sbt_.hitIndex(best.instance, best.geometry, r));
      const SbtRecord* rec = sbt_.hitAt(index);
      // R-UB: the closest-hit's record beyond the hit region; the model runs none.
      if (!rec && !st_.ray_undefined) st_.hitRecordOutOfRange(best.instance, best.geometry, r);
      const CHitGroup* grp = groupOf(*sh_.programs, rec);
      if (rec && !rec->group)
        st_.nullShader(kPipelineNoNullClosestHit, "a closest-hit", "hit",
                       static_cast<uint32_t>(index));
      if (grp && grp->closest_hit)
        st_.checkPayloadType(payload, grp->payload, "pipeline.hit_groups", *rec->group,
                             ".closest_hit");
      if (grp && grp->closest_hit && grp->closest_hit_counts.yes) {
        st_.bump(grp->closest_hit_counts);
        st_.bumpRuns(kRunsClosestHit);
      } else if (grp && grp->closest_hit) {
        HitView hv =
            viewOf(scene, c, r, best.instance, best.geometry, best.primitive, sh_.need_object_ray);
        setHit(hv, static_cast<float>(best.t), best.kind, best.b1, best.b2);
        hv.words = best.words;
        hv.sized = best.sized;
        st_.bumpRuns(kRunsClosestHit);
        StageEnv env = hitStage(Stage::ClosestHit, rec->data, &payload, r, hv, hv.t, depth);
        HitObjectState own;  // the stage's hit object, empty at its start
        env.hit_object = &own;
        HitView* caller = std::exchange(shading_hit_, &hv);
        interp_.exec(*grp->closest_hit, env);
        shading_hit_ = caller;
      }
      if (grp && grp->closest_hit) clobberCaller(r, best);
    }
  } else {
    const uint32_t mi = r.miss & kTraceMissIndexMask;
    // R-UB: beyond the miss region; the model runs no miss shader.
    if (mi >= sbt_.miss().size() && !st_.ray_undefined) st_.missRecordOutOfRange(r);
    if (mi < sbt_.miss().size()) {
      const SbtRecord& rec = sbt_.miss()[mi];
      if (!rec.group) st_.nullShader(kPipelineNoNullMiss, "a miss shader", "miss", mi);
      if (rec.group && *rec.group < c.pipeline.miss.size())
        st_.checkPayloadType(payload, c.pipeline.missPayload(*rec.group), "pipeline.miss",
                             *rec.group, "");
      if (rec.group && *rec.group < c.pipeline.miss.size() &&
          sh_.programs->miss_counts[*rec.group].yes) {
        st_.bump(sh_.programs->miss_counts[*rec.group]);
        st_.bumpRuns(kRunsMiss);
      } else if (rec.group && *rec.group < c.pipeline.miss.size()) {
        st_.bumpRuns(kRunsMiss);
        StageEnv env;
        env.stage = Stage::Miss;
        env.record_data = &rec.data;
        env.payload = &payload;
        env.ray = &r;
        env.tmax_view = r.tmax;
        env.depth = depth;
        HitObjectState own;
        env.hit_object = &own;
        HitView* caller = std::exchange(shading_hit_, nullptr);
        interp_.exec(sh_.programs->miss[*rec.group], env);
        shading_hit_ = caller;
      }
    }
  }
}

void ModelTracer::checkCandidates(const Traversal& tr, const std::vector<ModelCandidate>& cands) {
  if (st_.ray_undefined || !sh_.check_candidates) return;
  const ModelScene& scene = *sh_.scene;
  const TraceRay& r = tr.ray;
  for (const ModelCandidate& cand : cands) {
    const ModelInstance& mi = scene.instances[cand.instance];
    const ModelGeometry& g = scene.blases[mi.blas].geometries[cand.geometry];
    // R-CULL-OPQ drops it whatever it is (Embree has applied the masks and skips).
    const bool opaque = resolveOpaque(g.flags, mi.src->flags, tr.flags);
    if (((tr.flags & kRayCullOpaque) && opaque) || ((tr.flags & kRayCullNoOpaque) && !opaque))
      continue;
    if (cand.nan_triangle) {
      const Geometry& src = sh_.c->scene.blases[mi.blas].geometries[cand.geometry];
      const std::string field = !src.loc.field.empty()
                                    ? src.loc.field
                                    : "scene.blas." + sh_.c->scene.blases[mi.blas].name + "[" +
                                          std::to_string(cand.geometry) + "]";
      st_.markUndefined(UndefinedReason::NanTriangle,
                        field + ": triangle " + std::to_string(cand.primitive) +
                            " has NaN in Y or Z (instance " + std::to_string(cand.instance) + ")");
      return;
    }
    const double tl = tr.tol(cand.t);
    if (cand.t < r.tmin - tl || cand.t > r.tmax + tl) continue;
    // A device reads the record of every box (its intersection shader runs)
    // and of every non-opaque triangle (its any-hit may run), in any order:
    // beyond the hit region, or all zero where the pipeline promises that
    // shader (R-NULL-SHADERS), the ray is undefined.
    const SbtRecord* rec = sbt_.hit(cand.instance, cand.geometry, r);
    if (rec && rec->group) continue;
    const bool needed =
        cand.aabb || (!opaque && (cand.hit || cand.ambiguity != TriAmbiguity::None) &&
                      !facing(scene, cand, r, tr.flags).culled);
    if (needed && !rec) {
      st_.hitRecordOutOfRange(cand.instance, cand.geometry, r);
      return;
    }
    if (needed)
      st_.nullShader(cand.aabb ? kPipelineNoNullIntersection : kPipelineNoNullAnyHit,
                     cand.aabb ? "an intersection shader" : "an any-hit", "hit",
                     static_cast<uint32_t>(sbt_.hitIndex(cand.instance, cand.geometry, r)));
    if (st_.ray_undefined) return;
  }
}

}  // namespace rayspec
