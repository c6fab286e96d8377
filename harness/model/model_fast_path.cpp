// The model's path with nothing to decide: Embree's own closest hit (no
// any-hit, intersection programs, culls or special triangles), for one trace
// or for a block of launch rays whose programs are counts only.
#include <bit>

#include "case/flag_names.h"
#include "model/model_tracer.h"
#include "model/traversal.h"
#include "results/record_layout.h"

namespace rayspec {

using namespace trace_detail;

namespace {

// Embree's own closest hit (no filters, no culls, no AABBs in this case); the
// open interval by moving Embree's ends. No culls here, so the facing only
// gives hit_kind: computed when a program reads it.
Committed embreeClosestHit(const ModelScene& scene, RTCIntersectContext& ctx, const TraceRay& r,
                           uint32_t flags, bool need_facing) {
  Committed best;
  RTCRayHit rh = embreeRay(r, flags);
  if (!validRay(r, rh)) return best;
  rh.ray.tnear = scene.tier == ModelTier::Robust ? nextUp(r.tmin) : r.tmin;
  rh.ray.tfar = nextDown(r.tmax);
  rtcIntersect1(scene.tops[r.tlas], &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return best;
  best = {true,          rh.ray.tfar, rh.hit.instID[0], rh.hit.geomID,
          rh.hit.primID, 0xFEu,       rh.hit.u,         rh.hit.v};
  if (need_facing) {
    ModelCandidate cand;
    cand.instance = best.instance;
    cand.geometry = best.geometry;
    cand.primitive = best.primitive;
    best.kind = facing(scene, cand, r, flags).kind;
  }
  return best;
}

}  // namespace

Committed ModelTracer::directHit(const TraceRay& r, uint32_t flags) {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  return embreeClosestHit(*sh_.scene, ctx, r, flags, sh_.need_facing);
}

namespace {

// Ray flags that some combination makes undefined (checkRayParameters).
constexpr uint32_t kExclusiveRayFlags = kRayOpaque | kRayNoOpaque | kRayCullOpaque |
                                        kRayCullNoOpaque | kRayCullBackFacing |
                                        kRayCullFrontFacing | kRaySkipTriangles | kRaySkipAabbs;

bool sameTraceParameters(const Ray& a, const Ray& b) {
  return a.flags == b.flags && a.cull_mask == b.cull_mask && a.sbt_offset == b.sbt_offset &&
         a.sbt_stride == b.sbt_stride && a.miss == b.miss;
}

// A float that is neither infinite nor NaN (exponent bits not all ones).
inline bool finiteBits(float f) {
  return (std::bit_cast<uint32_t>(f) & 0x7F800000u) != 0x7F800000u;
}

}  // namespace

// One pass over the block: each ray is traced and shaded at once, with no
// TraceRay copy or per-ray stage state on the common path. What a counts-only
// closest-hit or miss program does is resolved once per block for the block's
// first ray's trace parameters (per instance and geometry for hits), and the
// counts are kept in locals, added to `counters` when the resolution changes
// and at the end (no per-ray writes to memory another thread may share). Any
// other ray (other parameters, SkipClosestHit, programs that are more than
// counts) goes through shade() exactly as trace() would.
// Finite origin and direction, 0 <= tmin <= tmax, a cull mask that lets
// something through (validRay, without branches).
inline bool validLaunchRay(const Ray& ray) {
  return finiteBits(ray.origin[0]) & finiteBits(ray.origin[1]) & finiteBits(ray.origin[2]) &
         finiteBits(ray.direction[0]) & finiteBits(ray.direction[1]) &
         finiteBits(ray.direction[2]) & (ray.tmin >= 0.0f) & (ray.tmin <= ray.tmax) &
         ((ray.cull_mask & kVisibilityMask) != 0);
}

// The miss shader a launch ray's miss index selects, when all it does is
// count; null otherwise.
const CountsOnly* ModelTracer::countedMiss(const TraceRay& r0) const {
  const CPipeline& programs = *sh_.programs;
  const uint32_t mi = r0.miss & kTraceMissIndexMask;
  if (mi < sbt_.miss().size() && sbt_.miss()[mi].group &&
      *sbt_.miss()[mi].group < programs.miss.size() &&
      programs.miss_counts[*sbt_.miss()[mi].group].yes)
    return &programs.miss_counts[*sbt_.miss()[mi].group];
  return nullptr;
}

void ModelTracer::shadeLaunchRay(uint32_t i, const Ray& ray, uint32_t flags, const RTCRayHit& rh,
                                 bool hit, uint32_t* rec) {
  const TraceRay r = launchRay(ray);
  Committed h;
  if (hit) {
    h = {true,          rh.ray.tfar, rh.hit.instID[0], rh.hit.geomID,
         rh.hit.primID, 0xFEu,       rh.hit.u,         rh.hit.v};
    if (sh_.need_facing) {
      ModelCandidate cand;
      cand.instance = h.instance;
      cand.geometry = h.geometry;
      cand.primitive = h.primitive;
      h.kind = facing(*sh_.scene, cand, r, flags).kind;
    }
  }
  st_.index = i;
  st_.x = i % sh_.c->rays.width;
  st_.y = i / sh_.c->rays.width;
  st_.rec = rec;
  st_.ray_ambiguous = false;
  Payload payload;
  payload.depth = 1;
  shade(r, flags, 1, h, payload);
}

// The launch ray's closest hit as Embree finds it (embreeRay + validRay +
// embreeClosestHit for the launch ray itself); R-UB: a ray with undefined
// behaviour diagnosed, and not traced (a miss) or traced with its flags.
RTCRayHit ModelTracer::launchClosestHit(uint32_t i, const Ray& ray, uint32_t flags, RTCScene top,
                                        RTCIntersectContext& ctx) {
  RTCRayHit rh = embreeRay(ray, flags);
  const bool valid = validLaunchRay(ray);
  st_.ray_undefined = false;
  if (!valid || (ray.flags & kExclusiveRayFlags)) {
    st_.index = i;
    st_.checkRayParameters(launchRay(ray), &sh_.programs->raygen[0], 1);
  }
  if (valid) {
    rh.ray.tnear = sh_.scene->tier == ModelTier::Robust ? nextUp(ray.tmin) : ray.tmin;
    rh.ray.tfar = nextDown(ray.tmax);
    rtcIntersect1(top, &ctx, &rh);
  }
  return rh;
}

void ModelTracer::flushCounts(const CountsOnly* k, uint64_t& n) {
  if (k && n)
    for (int c : k->counters) st_.counters[c] += n;
  n = 0;
}

bool ModelTracer::countedAlone(const RTCRayHit& rh, bool hit, const TraceRay& r0, LaunchCounts& q,
                               uint32_t* rec) {
  if (!hit) {
    if (!q.miss_counts) return false;
    ++q.miss_pending;
    if (rec) rec[q.runs_miss] += 1;
    return true;
  }
  if (rh.hit.instID[0] != q.last_instance || rh.hit.geomID != q.last_geometry) {
    q.last_instance = rh.hit.instID[0];
    q.last_geometry = rh.hit.geomID;
    const CHitGroup* grp = groupOf(*sh_.programs, sbt_.hit(q.last_instance, q.last_geometry, r0));
    const CountsOnly* k =
        grp && grp->closest_hit && grp->closest_hit_counts.yes ? &grp->closest_hit_counts : nullptr;
    if (k != q.hit_counts) {
      flushCounts(q.hit_counts, q.hit_pending);
      q.hit_counts = k;
    }
  }
  if (!q.hit_counts) return false;
  ++q.hit_pending;
  if (rec) rec[q.runs_hit] += 1;
  return true;
}

void ModelTracer::runLaunchRaysDirect(uint32_t begin, uint32_t end) {
  const Rays& rays = sh_.c->rays;
  const uint32_t words = st_.records ? recordWords() : 0;
  uint32_t pipe_flags = 0;
  if (sh_.c->pipeline.flags & kPipelineSkipTriangles) pipe_flags |= kRaySkipTriangles;
  if (sh_.c->pipeline.flags & kPipelineSkipAabbs) pipe_flags |= kRaySkipAabbs;
  const RTCScene top = sh_.scene->tops[0];  // launch rays traverse the first top level
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);

  const Ray& first = rays.launchRay(begin);
  const TraceRay r0 = launchRay(first);
  const bool quick = !((first.flags | pipe_flags) & kRaySkipClosestHit);
  LaunchCounts q;
  q.miss_counts = quick ? countedMiss(r0) : nullptr;
  q.runs_hit = st_.runsOffset(kRunsClosestHit);
  q.runs_miss = st_.runsOffset(kRunsMiss);
  const uint32_t runs_raygen = st_.runsOffset(kRunsRaygen);

  for (uint32_t i = begin; i < end; ++i) {
    if (!rays.same && i + 8 < end) __builtin_prefetch(&rays.rays[i + 8]);
    const Ray& ray = rays.launchRay(i);
    const uint32_t flags = ray.flags | pipe_flags;
    uint32_t* rec = st_.records ? st_.records + static_cast<size_t>(i) * words : nullptr;
    if (rec) rec[runs_raygen] += 1;
    const RTCRayHit rh = launchClosestHit(i, ray, flags, top, ctx);
    const bool hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    if (quick && sameTraceParameters(ray, first) && countedAlone(rh, hit, r0, q, rec)) continue;
    shadeLaunchRay(i, ray, flags, rh, hit, rec);
  }
  flushCounts(q.hit_counts, q.hit_pending);
  flushCounts(q.miss_counts, q.miss_pending);
}

}  // namespace rayspec
