// The state of one trace between ModelTracer (model_tracer.h) and the
// any-hit / intersection protocol (hit_protocol.h), and the helpers they
// share: model_traversal.cpp (candidates decided in order, closest-hit or
// miss), model_exact_tier.cpp (the exact tier's ambiguity and what-if runs),
// model_fast_path.cpp (Embree's own closest hit, no decisions to make) and
// hit_protocol.cpp (intersection programs' reports, any-hit).
#pragma once

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "base/affine.h"
#include "base/float_steps.h"
#include "model/model_fault_seam.h"
#include "model/model_program.h"
#include "model/model_scene.h"
#include "model/model_stage_env.h"
#include "model/model_trace_context.h"
#include "model/model_what_if.h"
#include "model/query_run.h"
#include "model/watertight.h"

namespace rayspec {

// A box's leading report (CHitGroup::leading_report) as the model's run made
// it: the candidate, its t, and how far a device's t may lie (a sphere
// root's error bound; 0 otherwise).
struct LeadReport {
  size_t k = 0;
  double t = 0, err = 0;
};

struct Traversal {
  const TraceRay& ray;
  uint32_t flags = 0;  // ray flags with the pipeline's skip flags
  uint32_t depth = 1;
  double tmin = 0, tmax_cur = 0;
  Committed best;
  bool stop = false;
  bool exact = false;
  Payload* payload = nullptr;
  // A ray_query's traversal (model_query.cpp): its candidate blocks decide,
  // no shader runs; null for traceRayEXT.
  QueryRun* query = nullptr;
  // A trace a --through ray-query* run inlines as a query loop: the planted
  // query faults as that loop breaks them (ModelFaultSeam::inlinedQuery).
  ModelFaultSeam::InlinedQuery inlined;
  // The AABB candidate whose intersection program runs.
  bool cur_opaque = false;
  const SbtRecord* cur_rec = nullptr;
  const CHitGroup* cur_group = nullptr;
  const ModelCandidate* cur = nullptr;
  size_t cur_index = 0;
  // Exact tier, sandboxed what-if runs (R-TIE, R-TOFH): `prefer` is the
  // candidate that wins every tie with the committed hit (and never loses
  // one), `first` the candidate processed before all others; -1: none.
  long prefer = -1, first = -1;
  uint32_t prefer_key[3] = {0, 0, 0};
  // Exact tier, what-if runs of another order (R-ORDER-UNSPEC): the candidate
  // indices in the order processed (null: the model's own), and what a
  // candidate at the committed t does (R-TIE, TieRule).
  const std::vector<uint32_t>* order = nullptr;
  TieRule tie = TieRule::Model;
  // The actual run of the exact tier: every report (candidate index, t) in [tmin, tmax].
  std::vector<std::pair<size_t, double>>* reports = nullptr;
  // ... and every report of an intersection program's leading report
  // (CHitGroup::leading_report), in or out of the interval (counter_floors.cpp).
  std::vector<LeadReport>* lead_reports = nullptr;
  // Exact tier, R-PREC: the actual run notes its intersection programs'
  // decisions that rounding may flip; a what-if run flips some of them.
  std::vector<ShaderDecision>* shader_unsure = nullptr;
  const std::vector<ShaderDecision>* shader_force = nullptr;
  uint32_t sphere_ord = 0, report_ord = 0;  // within the current intersection run
  // The forced value of this decision, if it is one of those forced.
  const ShaderDecision* forced(uint8_t kind, uint32_t ordinal) const {
    if (!shader_force) return nullptr;
    for (const ShaderDecision& f : *shader_force)
      if (f.kind == kind && f.ordinal == ordinal && f.cand == cur_index) return &f;
    return nullptr;
  }

  explicit Traversal(const TraceRay& r) : ray(r) {}
  // A ray query's traversal, from what it starts with committed (nothing,
  // but for the planted fault rq_init_keeps_committed).
  void startQuery(QueryRun* q) {
    query = q;
    if (!q || !q->start.valid) return;
    best = q->start;
    tmax_cur = best.t;
  }
  bool isPreferred(uint32_t i, uint32_t g, uint32_t p) const {
    return prefer >= 0 && prefer_key[0] == i && prefer_key[1] == g && prefer_key[2] == p;
  }
  // The t a report must not pass (R-CAND-AABB-CLOSED): the current tmax, or
  // where an inlined query's commits keep the interval (planted), the
  // committed t the loop holds reports to (glsl/emit_ray_query.cpp).
  double reportTmax() const {
    return inlined.commit_keeps_interval && best.valid ? best.t : tmax_cur;
  }
  bool ties(double t) const { return best.valid && std::fabs(t - best.t) <= tol(t); }
  // What-if run (R-TIE, TieRule::ConfirmDrop): a triangle or report confirmed
  // at the committed t is dropped there ("may be set as the current closest
  // hit or dropped", Ray Closest Hit Determination).
  bool confirmDrops(double t) const { return tie == TieRule::ConfirmDrop && exact && ties(t); }
  // A triangle candidate's t against an interval end: its own error bound
  // (translated frame, model/watertight.h) where known.
  double endTol(const ModelCandidate& c) const { return c.t_err > 0 ? c.t_err : tol(c.t); }
  // R-CAND-TRI-OPEN: the candidate's t within rounding of tmin (of tmax),
  // where a device's t may round across that end (model/exact_interval.h):
  // a device may find no candidate there at all.
  bool nearTmin(const ModelCandidate& c) const {
    return !c.exact_tmin && std::fabs(c.t - ray.tmin) <= endTol(c);
  }
  bool nearTmax(const ModelCandidate& c) const {
    return !c.exact_tmax && std::fabs(c.t - ray.tmax) <= endTol(c);
  }
  double tol(double t) const {
    const double om =
        std::max({std::fabs(ray.origin[0]), std::fabs(ray.origin[1]), std::fabs(ray.origin[2])});
    const double dm = std::max(
        {std::fabs(ray.direction[0]), std::fabs(ray.direction[1]), std::fabs(ray.direction[2])});
    return kDeviceRelTolerance * (std::fabs(t) + (dm > 0 ? om / dm : 0.0));
  }
};

namespace trace_detail {

bool keyLess(uint32_t i0, uint32_t g0, uint32_t p0, uint32_t i1, uint32_t g1, uint32_t p1);
const CHitGroup* groupOf(const CPipeline& p, const SbtRecord* rec);
// R-OPACITY: ray flag, then instance flag, then the geometry's OPAQUE bit.
bool resolveOpaque(uint32_t geom_flags, uint32_t inst_flags, uint32_t ray_flags);

// Facing of a triangle candidate (R-FACE-DET) and its hit kind (R-HITKIND-TRI).
struct Facing {
  bool front = true;
  bool culled = false;
  uint32_t kind = 0xFE;
};
Facing facing(const ModelScene& s, const ModelCandidate& c, const TraceRay& ray, uint32_t flags);

// The environment of a stage that sees a hit (intersection, any-hit, closest-hit).
StageEnv hitStage(Stage stage, const std::vector<uint32_t>& record_data, Payload* payload,
                  const TraceRay& ray, const HitView& hv, float tmax_view, uint32_t depth);
// A hit's own values on the view of its primitive.
void setHit(HitView& hv, float t, uint32_t kind, float b1, float b2);
HitView viewOf(const ModelScene& s, const Case& c, const TraceRay& ray, uint32_t instance,
               uint32_t geometry, uint32_t primitive, bool object_ray = true);

// An Embree ray for a launch ray (Ray) or a traced one (TraceRay): inline, the
// fast path builds one per launch ray.
template <typename AnyRay>
inline RTCRayHit embreeRay(const AnyRay& r, uint32_t flags) {
  RTCRayHit rh;
  rh.ray.org_x = r.origin[0];
  rh.ray.org_y = r.origin[1];
  rh.ray.org_z = r.origin[2];
  rh.ray.dir_x = r.direction[0];
  rh.ray.dir_y = r.direction[1];
  rh.ray.dir_z = r.direction[2];
  rh.ray.time = 0;
  rh.ray.mask = (r.cull_mask & kVisibilityMask) |
                ((flags & kRaySkipTriangles) ? 0u : kMaskTriangles) |
                ((flags & kRaySkipAabbs) ? 0u : kMaskAabbs);
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// A ray Embree can trace. The rest (non-finite origin or direction, NaN or
// negative tmin, tmax below tmin or NaN: R-UB, any result is allowed) is
// never handed to Embree, whose debug checks would abort, and misses.
bool validRay(const TraceRay& r, const RTCRayHit& rh);

}  // namespace trace_detail
}  // namespace rayspec
