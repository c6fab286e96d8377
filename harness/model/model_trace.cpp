// traceRayEXT in the model: Embree enumerates, the model decides (see the
// order documented in model_backend.h), then closest-hit or miss runs.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "model/model_machine.h"
#include "model/sphere_error.h"
#include "model/watertight.h"
#include "results/tolerances.h"
#include "results/record_layout.h"

namespace rayspec {

struct Traversal {
  Machine& m;
  const TraceRay& ray;
  uint32_t flags = 0;  // ray flags with the pipeline's skip flags
  uint32_t depth = 1;
  double tmin = 0, tmax_cur = 0;
  Committed best;
  bool stop = false;
  bool exact = false;
  Payload* payload = nullptr;
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
  // The actual run of the exact tier: every report (candidate index, t) in [tmin, tmax].
  std::vector<std::pair<size_t, double>>* reports = nullptr;
  // Exact tier, R-PREC: the actual run notes its intersection programs'
  // decisions that rounding may flip; a what-if run flips one of them.
  std::vector<ShaderDecision>* shader_unsure = nullptr;
  const ShaderDecision* shader_force = nullptr;
  uint32_t sphere_ord = 0, report_ord = 0;  // within the current intersection run
  // The forced value of this decision, if it is the one forced.
  const ShaderDecision* forced(uint8_t kind, uint32_t ordinal) const {
    const ShaderDecision* f = shader_force;
    return f && f->kind == kind && f->ordinal == ordinal && f->cand == cur_index ? f : nullptr;
  }

  Traversal(Machine& machine, const TraceRay& r) : m(machine), ray(r) {}
  bool isPreferred(uint32_t i, uint32_t g, uint32_t p) const {
    return prefer >= 0 && prefer_key[0] == i && prefer_key[1] == g && prefer_key[2] == p;
  }
  bool ties(double t) const { return best.valid && std::fabs(t - best.t) <= tol(t); }
  double tol(double t) const {
    const double om = std::max({std::fabs(ray.origin[0]), std::fabs(ray.origin[1]), std::fabs(ray.origin[2])});
    const double dm = std::max({std::fabs(ray.direction[0]), std::fabs(ray.direction[1]), std::fabs(ray.direction[2])});
    return kDeviceRelTolerance * (std::fabs(t) + (dm > 0 ? om / dm : 0.0));
  }
};

namespace {

bool keyLess(uint32_t i0, uint32_t g0, uint32_t p0, uint32_t i1, uint32_t g1, uint32_t p1) {
  if (i0 != i1) return i0 < i1;
  if (g0 != g1) return g0 < g1;
  return p0 < p1;
}

Vec3 xform(const std::array<float, 12>& m, const Vec3& v, float w) {
  Vec3 r;
  for (int k = 0; k < 3; ++k)
    r[k] = m[k * 4] * v[0] + m[k * 4 + 1] * v[1] + m[k * 4 + 2] * v[2] + (w != 0 ? m[k * 4 + 3] : 0.0f);
  return r;
}

const CHitGroup* groupOf(const CPipeline& p, const SbtRecord* rec) {
  if (!rec || !rec->group || *rec->group >= p.groups.size()) return nullptr;
  return &p.groups[*rec->group];
}

// The neighbouring floats (Embree's interval ends moved to the open interval).
float nextUp(float x) {
  if (std::isnan(x) || x == INFINITY) return x;
  if (x == 0.0f) return std::numeric_limits<float>::denorm_min();
  uint32_t u;
  std::memcpy(&u, &x, 4);
  u = x > 0 ? u + 1 : u - 1;
  std::memcpy(&x, &u, 4);
  return x;
}
float nextDown(float x) { return -nextUp(-x); }

bool resolveOpaque(uint32_t geomFlags, uint32_t instFlags, uint32_t rayFlags) {
  if (rayFlags & kRayOpaque) return true;
  if (rayFlags & kRayNoOpaque) return false;
  if (instFlags & kInstanceForceOpaque) return true;
  if (instFlags & kInstanceForceNoOpaque) return false;
  return (geomFlags & kGeometryOpaque) != 0;
}

}  // namespace

const SbtRecord* Machine::hitRecord(uint32_t instance, uint32_t geometry, const TraceRay& r) const {
  const Instance& inst = sh_.c->scene.instances[instance];
  const uint64_t idx = static_cast<uint64_t>(inst.sbt_offset & 0xFFFFFF) +
                       static_cast<uint64_t>(geometry) * (r.sbt_stride & 0xF) + (r.sbt_offset & 0xF);
  return idx < default_hit_.size() ? &default_hit_[idx] : nullptr;
}

namespace {

// Facing of a triangle candidate (R-FACE-DET) and its hit kind (R-HITKIND-TRI).
struct Facing { bool front = true; bool culled = false; uint32_t kind = 0xFE; };

Facing facing(const ModelScene& s, const ModelCandidate& c, const TraceRay& ray, uint32_t flags) {
  const ModelInstance& mi = s.instances[c.instance];
  const auto& tri = s.blases[mi.blas].geometries[c.geometry].triangles[c.primitive];
  const Vec3 d = xform(mi.inverse_f, ray.direction, 0);
  double n[3];
  const double e1[3] = {double(tri[1][0]) - tri[0][0], double(tri[1][1]) - tri[0][1], double(tri[1][2]) - tri[0][2]};
  const double e2[3] = {double(tri[2][0]) - tri[0][0], double(tri[2][1]) - tri[0][1], double(tri[2][2]) - tri[0][2]};
  n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  n[2] = e1[0] * e2[1] - e1[1] * e2[0];
  const double sdot = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
  Facing f;
  f.front = sdot < 0;
  if (mi.src->flags & kInstanceFlipFacing) f.front = !f.front;
  f.kind = f.front ? 0xFEu : 0xFFu;
  if (sdot == 0) f.culled = true;  // zero-area projection (R-FACE-DET)
  if (!(mi.src->flags & kInstanceFacingCullDisable)) {
    if ((flags & kRayCullBackFacing) && !f.front) f.culled = true;
    if ((flags & kRayCullFrontFacing) && f.front) f.culled = true;
  }
  return f;
}

// The environment of a stage that sees a hit (intersection, any-hit, closest-hit).
StageEnv hitStage(Stage stage, const std::vector<uint32_t>& record_data, Payload* payload, const TraceRay& ray,
                  const HitView& hv, float tmax_view, uint32_t depth) {
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

HitView viewOf(const ModelScene& s, const Case& c, const TraceRay& ray, uint32_t instance, uint32_t geometry,
               uint32_t primitive, bool objectRay = true) {
  HitView hv;
  const ModelInstance& mi = s.instances[instance];
  hv.instance = instance;
  hv.custom_index = c.scene.instances[instance].custom_index & 0xFFFFFF;
  hv.geometry = geometry;
  hv.primitive = primitive;
  if (objectRay) {
    hv.object_origin = xform(mi.inverse_f, ray.origin, 1);
    hv.object_direction = xform(mi.inverse_f, ray.direction, 0);
  }
  const ModelGeometry& g = s.blases[mi.blas].geometries[geometry];
  if (g.kind == Geometry::Kind::Aabbs) {
    const auto& a = g.aabbs[primitive];
    hv.aabb_min = {a[0], a[1], a[2]};
    hv.aabb_max = {a[3], a[4], a[5]};
  }
  return hv;
}

}  // namespace

Flow Machine::report(const CStmt& s, StageEnv& env) {
  Traversal* tr = env.traversal;
  if (!tr || !tr->cur) return Flow::Continue;
  const Val tv = eval(s.t, env);
  const float t = s.t.type == ValueType::Uint ? static_cast<float>(tv.u) : tv.f[0];
  const uint32_t kind = eval(s.hit_kind, env).u;
  Val attr;
  if (s.has_attribute) attr = eval(s.attribute, env);
  bool accepted = false;
  Flow flow = Flow::Continue;
  // R-ISECT-REPORT, R-CAND-AABB-CLOSED: tmin <= t <= current tmax.
  bool inside = t >= tr->ray.tmin && static_cast<double>(t) <= tr->tmax_cur;
  if (tr->reports && t >= tr->ray.tmin && t <= tr->ray.tmax + tr->tol(t)) tr->reports->push_back({tr->cur_index, t});
  if (tr->exact) {
    // R-PREC: a sphere root within its error bound of an interval end may
    // fall on either side on a device. Not against the current candidate's
    // own committed report: the device compares its own roots consistently.
    const uint32_t ord = tr->report_ord++;
    if (const ShaderDecision* f = tr->forced(1, ord)) {
      inside = f->value;
    } else if (tr->shader_unsure && s.t.kind == Expr::Kind::Op &&
               (s.t.op == OpCode::SphereNear || s.t.op == OpCode::SphereFar) && env.hit && env.ray) {
      const HitView& h = *env.hit;
      const ModelInstance& mi = sh_.scene->instances[h.instance];
      const SphereError se = sphereError(h.aabb_min, h.aabb_max, h.object_origin, h.object_direction,
                                         objectRayError(mi.inverse_f, env.ray->origin, env.ray->direction));
      const double et = (s.t.op == OpCode::SphereNear ? se.near_err : se.far_err) + tr->tol(t);
      const bool own = tr->best.valid && tr->best.instance == h.instance && tr->best.geometry == h.geometry &&
                       tr->best.primitive == h.primitive;
      const bool nearEnd = std::fabs(double(t) - tr->ray.tmin) <= et ||
                           (!own && std::fabs(double(t) - tr->tmax_cur) <= et);
      if (nearEnd) tr->shader_unsure->push_back({tr->cur_index, 1, ord, inside});
    }
  }
  // What-if run preferring one candidate (R-TIE): it wins every tie, and a
  // committed preferred hit loses none.
  if (tr->prefer >= 0 && t >= tr->ray.tmin && tr->ties(t)) {
    if (tr->cur_index == static_cast<size_t>(tr->prefer)) inside = true;
    else if (tr->isPreferred(tr->best.instance, tr->best.geometry, tr->best.primitive)) inside = false;
  }
  if (inside) {
    HitView hv = *env.hit;
    setHit(hv, t, kind, attr.f[0], attr.f[1]);
    Flow ah = Flow::Continue;
    if (!tr->cur_opaque && tr->cur_group && tr->cur_group->any_hit) {
      bumpRuns(kRunsAnyHit);
      // R-TMAX-VIEW: any-hit sees the candidate's t.
      StageEnv a = hitStage(Stage::AnyHit, tr->cur_rec->data, tr->payload, tr->ray, hv, t, tr->depth);
      ah = exec(*tr->cur_group->any_hit, a);
    }
    if (ah != Flow::Ignore) {
      accepted = true;
      tr->best = {true, static_cast<double>(t), hv.instance, hv.geometry, hv.primitive, kind, hv.b1, hv.b2};
      if (tr->exact && s.t.kind == Expr::Kind::Op &&
          (s.t.op == OpCode::SphereNear || s.t.op == OpCode::SphereFar) && env.hit && env.ray) {
        // R-PREC: how far a device's root may lie from this one.
        const ModelInstance& mi = sh_.scene->instances[hv.instance];
        const SphereError se = sphereError(hv.aabb_min, hv.aabb_max, hv.object_origin, hv.object_direction,
                                           objectRayError(mi.inverse_f, env.ray->origin, env.ray->direction));
        tr->best.t_err = s.t.op == OpCode::SphereNear ? se.near_err : se.far_err;
      }
      tr->tmax_cur = t;
      env.tmax_view = t;
      if (ah == Flow::Terminate || (tr->flags & kRayTerminateOnFirstHit)) {
        tr->stop = true;
        return Flow::Terminate;  // R-TERMINATE: the intersection program stops too
      }
    }
  }
  const Flow f = exec(accepted ? s.then_ : s.else_, env);
  return f != Flow::Continue ? f : flow;
}

Payload Machine::trace(const TraceRay& r, uint32_t depth) {
  uint32_t flags = r.flags;
  if (sh_.c->pipeline.flags & 0x1000) flags |= kRaySkipTriangles;
  if (sh_.c->pipeline.flags & 0x2000) flags |= kRaySkipAabbs;
  Payload payload;
  payload.depth = depth;
  const Committed best = sh_.direct ? directHit(r, flags) : traverse(r, flags, depth, payload);
  shade(r, flags, depth, best, payload);
  return payload;
}

namespace {

RTCRayHit embreeRay(const TraceRay& r, uint32_t flags) {
  RTCRayHit rh;
  rh.ray.org_x = r.origin[0]; rh.ray.org_y = r.origin[1]; rh.ray.org_z = r.origin[2];
  rh.ray.dir_x = r.direction[0]; rh.ray.dir_y = r.direction[1]; rh.ray.dir_z = r.direction[2];
  rh.ray.time = 0;
  rh.ray.mask = (r.cull_mask & 0xFF) | ((flags & kRaySkipTriangles) ? 0u : kMaskTriangles) |
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
bool validRay(const TraceRay& r, const RTCRayHit& rh) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(r.origin[k]) || !std::isfinite(r.direction[k])) return false;
  if (!(r.tmin >= 0.0f) || !(r.tmin <= r.tmax)) return false;
  return (rh.ray.mask & 0xFF) != 0;
}

}  // namespace

namespace {

// Embree's own closest hit (no filters, no culls, no AABBs in this case); the
// open interval by moving Embree's ends. No culls here, so the facing only
// gives hit_kind: computed when a program reads it.
Committed embreeClosestHit(const ModelScene& scene, RTCIntersectContext& ctx, const TraceRay& r, uint32_t flags,
                           bool needFacing) {
  Committed best;
  RTCRayHit rh = embreeRay(r, flags);
  if (!validRay(r, rh)) return best;
  rh.ray.tnear = scene.tier == ModelTier::Robust ? nextUp(r.tmin) : r.tmin;
  rh.ray.tfar = nextDown(r.tmax);
  rtcIntersect1(scene.top, &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return best;
  best = {true, rh.ray.tfar, rh.hit.instID[0], rh.hit.geomID, rh.hit.primID, 0xFEu, rh.hit.u, rh.hit.v};
  if (needFacing) {
    ModelCandidate cand;
    cand.instance = best.instance;
    cand.geometry = best.geometry;
    cand.primitive = best.primitive;
    best.kind = facing(scene, cand, r, flags).kind;
  }
  return best;
}

}  // namespace

Committed Machine::directHit(const TraceRay& r, uint32_t flags) {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  return embreeClosestHit(*sh_.scene, ctx, r, flags, sh_.need_facing);
}

namespace {

bool sameTraceParameters(const Ray& a, const Ray& b) {
  return a.flags == b.flags && a.cull_mask == b.cull_mask && a.sbt_offset == b.sbt_offset &&
         a.sbt_stride == b.sbt_stride && a.miss == b.miss;
}

// A float that is neither infinite nor NaN (exponent bits not all ones).
inline bool finiteBits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return (u & 0x7F800000u) != 0x7F800000u;
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
void Machine::runLaunchRaysDirect(uint32_t begin, uint32_t end) {
  const std::vector<Ray>& rays = sh_.c->rays.rays;
  const CPipeline& programs = *sh_.programs;
  const uint32_t width = sh_.c->rays.width;
  const uint32_t words = records_ ? recordWords() : 0;
  uint32_t pipeFlags = 0;
  if (sh_.c->pipeline.flags & 0x1000) pipeFlags |= kRaySkipTriangles;
  if (sh_.c->pipeline.flags & 0x2000) pipeFlags |= kRaySkipAabbs;
  const ModelScene& scene = *sh_.scene;
  const RTCScene top = scene.top;
  const bool robust = scene.tier == ModelTier::Robust;
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);

  const Ray& first = rays[begin];
  const TraceRay r0 = launchRay(first);
  const bool quick = !((first.flags | pipeFlags) & kRaySkipClosestHit);
  const CountsOnly* missCounts = nullptr;
  if (quick) {
    const uint32_t mi = r0.miss & 0xFFFF;
    if (mi < default_miss_.size() && default_miss_[mi].group && *default_miss_[mi].group < programs.miss.size() &&
        programs.miss_counts[*default_miss_[mi].group].yes)
      missCounts = &programs.miss_counts[*default_miss_[mi].group];
  }
  uint32_t lastInstance = ~0u, lastGeometry = ~0u;
  const CountsOnly* hitCounts = nullptr;
  uint64_t hitPending = 0, missPending = 0;  // quick hits (for hitCounts) and misses
  auto flush = [this](const CountsOnly* k, uint64_t& n) {
    if (k && n)
      for (int c : k->counters) counters[c] += n;
    n = 0;
  };
  const uint32_t runsRaygen = runs_offset_[kRunsRaygen], runsHit = runs_offset_[kRunsClosestHit],
                 runsMiss = runs_offset_[kRunsMiss];

  for (uint32_t i = begin; i < end; ++i) {
    if (i + 8 < end) __builtin_prefetch(&rays[i + 8]);
    const Ray& ray = rays[i];
    const uint32_t flags = ray.flags | pipeFlags;
    uint32_t* rec = records_ ? records_ + static_cast<size_t>(i) * words : nullptr;
    if (rec) rec[runsRaygen] += 1;
    // embreeRay + validRay + embreeClosestHit, for the launch ray itself.
    RTCRayHit rh;
    rh.ray.org_x = ray.origin[0]; rh.ray.org_y = ray.origin[1]; rh.ray.org_z = ray.origin[2];
    rh.ray.dir_x = ray.direction[0]; rh.ray.dir_y = ray.direction[1]; rh.ray.dir_z = ray.direction[2];
    rh.ray.time = 0;
    rh.ray.mask = (ray.cull_mask & 0xFF) | ((flags & kRaySkipTriangles) ? 0u : kMaskTriangles) |
                  ((flags & kRaySkipAabbs) ? 0u : kMaskAabbs);
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    const bool valid = finiteBits(ray.origin[0]) & finiteBits(ray.origin[1]) & finiteBits(ray.origin[2]) &
                       finiteBits(ray.direction[0]) & finiteBits(ray.direction[1]) &
                       finiteBits(ray.direction[2]) & (ray.tmin >= 0.0f) & (ray.tmin <= ray.tmax) &
                       ((ray.cull_mask & 0xFF) != 0);
    if (valid) {
      rh.ray.tnear = robust ? nextUp(ray.tmin) : ray.tmin;
      rh.ray.tfar = nextDown(ray.tmax);
      rtcIntersect1(top, &ctx, &rh);
    }
    const bool hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    if (quick && sameTraceParameters(ray, first)) {
      if (hit) {
        if (rh.hit.instID[0] != lastInstance || rh.hit.geomID != lastGeometry) {
          lastInstance = rh.hit.instID[0];
          lastGeometry = rh.hit.geomID;
          const CHitGroup* grp = groupOf(programs, hitRecord(lastInstance, lastGeometry, r0));
          const CountsOnly* k =
              grp && grp->closest_hit && grp->closest_hit_counts.yes ? &grp->closest_hit_counts : nullptr;
          if (k != hitCounts) {
            flush(hitCounts, hitPending);
            hitCounts = k;
          }
        }
        if (hitCounts) {
          ++hitPending;
          if (rec) rec[runsHit] += 1;
          continue;
        }
      } else if (missCounts) {
        ++missPending;
        if (rec) rec[runsMiss] += 1;
        continue;
      }
    }
    // Everything else: as trace() does, with this ray's launch state.
    const TraceRay r = launchRay(ray);
    Committed h;
    if (hit) {
      h = {true, rh.ray.tfar, rh.hit.instID[0], rh.hit.geomID, rh.hit.primID, 0xFEu, rh.hit.u, rh.hit.v};
      if (sh_.need_facing) {
        ModelCandidate cand;
        cand.instance = h.instance;
        cand.geometry = h.geometry;
        cand.primitive = h.primitive;
        h.kind = facing(scene, cand, r, flags).kind;
      }
    }
    index_ = i;
    x_ = i % width;
    y_ = i / width;
    rec_ = rec;
    ray_ambiguous_ = false;
    Payload payload;
    payload.depth = 1;
    shade(r, flags, 1, h, payload);
  }
  flush(hitCounts, hitPending);
  flush(missCounts, missPending);
}

// The model's decision over the sorted candidates (R-ORDER-UNSPEC: in
// ascending distance). `force`, when given, overrides per candidate whether a
// triangle is a hit (-1: the model's own decision, 0: no, 1: yes).
void Machine::decide(Traversal& tr, const std::vector<ModelCandidate>& cands, const int8_t* force, Payload& payload) {
  const Case& c = *sh_.c;
  const ModelScene& scene = *sh_.scene;
  const TraceRay& r = tr.ray;
  const uint32_t depth = tr.depth;
  const size_t n = cands.size();
  const size_t first = tr.first >= 0 ? static_cast<size_t>(tr.first) : 0;
  for (size_t pos = 0; pos < n; ++pos) {
    // R-TOFH what-if: `first` ahead of all others, the rest in order.
    const size_t k = tr.first < 0 ? pos : pos == 0 ? first : pos <= first ? pos - 1 : pos;
    const ModelCandidate& cand = cands[k];
    if (tr.stop) break;
    const ModelInstance& mi = scene.instances[cand.instance];
    const ModelGeometry& g = scene.blases[mi.blas].geometries[cand.geometry];
    const bool opaque = resolveOpaque(g.flags, mi.src->flags, tr.flags);
    if ((tr.flags & kRayCullOpaque) && opaque) continue;
    if ((tr.flags & kRayCullNoOpaque) && !opaque) continue;
    const SbtRecord* rec = hitRecord(cand.instance, cand.geometry, r);
    const CHitGroup* grp = groupOf(*sh_.programs, rec);
    if (cand.aabb) {
      if (force && force[k] == 0) continue;
      // A preferred box entered at the committed t (within the error bound) still runs.
      if (cand.t > tr.tmax_cur && !(tr.prefer == static_cast<long>(k) && tr.ties(cand.t))) continue;
      if (!grp || !grp->intersection) continue;
      HitView hv = viewOf(scene, c, r, cand.instance, cand.geometry, cand.primitive);
      tr.cur = &cand;
      tr.cur_index = k;
      tr.cur_opaque = opaque;
      if (tr.reports) tr.reports->push_back({k, NAN});  // it ran (the exact tier's tie check)
      tr.sphere_ord = 0;
      tr.report_ord = 0;
      tr.cur_rec = rec;
      tr.cur_group = grp;
      bumpRuns(kRunsIntersection);
      // R-TMAX-VIEW: the intersection shader sees the closest t so far.
      StageEnv env = hitStage(Stage::Intersection, rec->data, nullptr, r, hv, static_cast<float>(tr.tmax_cur), depth);
      env.traversal = &tr;
      exec(*grp->intersection, env);
      tr.cur = nullptr;
      continue;
    }
    if (!(force && force[k] >= 0 ? force[k] == 1 : cand.hit)) continue;
    bool inside = cand.t > tr.tmin && cand.t < tr.tmax_cur;
    // What-if run forcing a hit at an interval end (tmin-tie, tmax-tie): a
    // float ray test may put it a step inside.
    if (!inside && force && force[k] == 1 && !tr.best.valid && cand.t > tr.tmin - tr.tol(cand.t) &&
        cand.t < tr.tmax_cur + tr.tol(cand.t))
      inside = true;
    const bool tie = tr.exact && tr.ties(cand.t);
    const bool bestPreferred = tr.isPreferred(tr.best.instance, tr.best.geometry, tr.best.primitive);
    if (tie && (tr.prefer == static_cast<long>(k) || bestPreferred)) {
      // What-if run preferring one candidate (R-TIE).
      inside = tr.prefer == static_cast<long>(k) && cand.t > tr.tmin;
    } else if (!inside && tie &&
               keyLess(cand.instance, cand.geometry, cand.primitive, tr.best.instance, tr.best.geometry,
                       tr.best.primitive)) {
      // Exact tier, R-TIE: a tie with the committed hit goes to the smaller key.
      inside = true;
    }
    if (!inside) continue;
    const Facing f = facing(scene, cand, r, tr.flags);
    if (f.culled) continue;
    Flow ah = Flow::Continue;
    if (!opaque && grp && grp->any_hit) {
      HitView hv = viewOf(scene, c, r, cand.instance, cand.geometry, cand.primitive);
      setHit(hv, static_cast<float>(cand.t), f.kind, cand.b1, cand.b2);
      bumpRuns(kRunsAnyHit);
      StageEnv a = hitStage(Stage::AnyHit, rec->data, &payload, r, hv, hv.t, depth);
      ah = exec(*grp->any_hit, a);
      if (ah == Flow::Ignore) continue;
    }
    tr.best = {true, cand.t, cand.instance, cand.geometry, cand.primitive, f.kind, cand.b1, cand.b2};
    tr.tmax_cur = cand.t;
    if (ah == Flow::Terminate || (tr.flags & kRayTerminateOnFirstHit)) tr.stop = true;
  }
}

// Every candidate from Embree, decided by the model in order (see
// model_backend.h), then the exact tier's ambiguity check.
Committed Machine::traverse(const TraceRay& r, uint32_t flags, uint32_t depth, Payload& payload) {
  const ModelScene& scene = *sh_.scene;
  Traversal tr(*this, r);
  tr.flags = flags;
  tr.depth = depth;
  tr.tmin = r.tmin;
  tr.tmax_cur = r.tmax;
  tr.exact = scene.tier == ModelTier::Exact;
  tr.payload = &payload;
  const Payload payloadIn = payload;  // for the exact tier's what-if variants

  RTCRayHit rh = embreeRay(r, tr.flags);
  std::vector<ModelCandidate>* cands = nullptr;
  std::vector<std::pair<size_t, double>> reports;  // exact tier: every report of the actual run
  std::vector<ShaderDecision> shaderUnsure;  // exact tier: decisions rounding may flip
  if (validRay(r, rh)) {
    if (cand_pool_.size() < depth) cand_pool_.resize(depth);
    cands = &cand_pool_[depth - 1];
    cands->clear();
    TraceContext tc;
    rtcInitIntersectContext(&tc.rtc);
    tc.scene = &scene;
    tc.origin = {r.origin[0], r.origin[1], r.origin[2]};
    tc.direction = {r.direction[0], r.direction[1], r.direction[2]};
    tc.tmin = r.tmin;
    tc.tmax = r.tmax;
    tc.candidates = cands;
    // Slightly wider than the interval: the model checks both ends itself.
    rh.ray.tnear = std::max(0.0f, r.tmin - std::fabs(r.tmin) * 1e-5f);
    rh.ray.tfar = r.tmax + std::fabs(r.tmax) * 1e-5f;
    rtcIntersect1(scene.top, &tc.rtc, &rh);
    std::sort(cands->begin(), cands->end(), [](const ModelCandidate& a, const ModelCandidate& b) {
      if (a.t != b.t) return a.t < b.t;
      return keyLess(a.instance, a.geometry, a.primitive, b.instance, b.geometry, b.primitive);
    });
    tr.reports = tr.exact ? &reports : nullptr;
    tr.shader_unsure = tr.exact && sh_.programs->reads_sphere ? &shaderUnsure : nullptr;
    decide(tr, *cands, nullptr, payload);
    tr.reports = nullptr;
    tr.shader_unsure = nullptr;
  }

  // Exact tier: is this trace's answer numerically clear?
  if (cands && tr.exact && !ray_ambiguous_) {
    RayAmbiguity amb;
    amb.ray = index_;
    const double finalT = tr.best.valid ? tr.best.t : INFINITY;
    // A triangle candidate that a device may see as a hit in the interval.
    auto eligible = [&](const ModelCandidate& cand) {
      const ModelInstance& mi = scene.instances[cand.instance];
      const ModelGeometry& g = scene.blases[mi.blas].geometries[cand.geometry];
      const bool opaque = resolveOpaque(g.flags, mi.src->flags, tr.flags);
      if (((tr.flags & kRayCullOpaque) && opaque) || ((tr.flags & kRayCullNoOpaque) && !opaque)) return false;
      if (facing(scene, cand, r, tr.flags).culled) return false;
      const double tl = tr.tol(cand.t);
      return !(cand.t < r.tmin - tl || cand.t > r.tmax + tl);
    };
    auto add = [&](bool hit, uint32_t i, uint32_t g, uint32_t p) {
      for (const Candidate& k : amb.candidates)
        if (k.hit == hit && (!hit || (k.instance == i && k.geometry == g && k.primitive == p))) return;
      amb.candidates.push_back({hit, i, g, p});
    };
    std::vector<size_t> unsure;  // candidates whose decision could flip
    bool faces = false;
    for (size_t k = 0; k < cands->size(); ++k) {
      const ModelCandidate& cand = (*cands)[k];
      if (cand.aabb) {
        // A grazed box matters only if its what-if runs change the answer (below).
        if (cand.near_face && cand.t <= finalT + tr.tol(cand.t)) {
          unsure.push_back(k);
          faces = true;
        }
        continue;
      }
      if (!eligible(cand)) continue;
      const double tl = tr.tol(cand.t);
      const char* why = nullptr;
      if (cand.ambiguity != TriAmbiguity::None && cand.t <= finalT + tl)
        why = cand.ambiguity == TriAmbiguity::Vertex ? "vertex" : "edge";
      else if (cand.hit && std::fabs(cand.t - r.tmin) <= tl) why = "tmin-tie";
      else if (cand.hit && std::fabs(cand.t - r.tmax) <= tl) why = "tmax-tie";
      if (why) {
        if (amb.reason.empty()) amb.reason = why;
        unsure.push_back(k);
      }
    }
    if (amb.reason == "edge" || amb.reason == "vertex") {
      // The triangles of one instance the model decided as hits within the
      // bound of the same shared edge or vertex (same t): a watertight device
      // finds one of them, so a double hit shows as extra any-hit runs.
      const ModelCandidate* first = nullptr;
      for (const ModelCandidate& cand : *cands) {
        if (cand.aabb || !cand.hit || cand.ambiguity == TriAmbiguity::None || !eligible(cand)) continue;
        if (!first) first = &cand;
        if (cand.instance == first->instance && std::fabs(cand.t - first->t) <= tr.tol(first->t))
          amb.shared_triangles.push_back({true, cand.instance, cand.geometry, cand.primitive});
      }
    }
    if (!amb.reason.empty() || faces) {
      // The legal answers: this run's, and those of the what-if runs where
      // the unsure candidates decide otherwise (whatIf).
      auto addCommitted = [&](const Committed& b) {
        if (b.valid) add(true, b.instance, b.geometry, b.primitive);
        else add(false, 0, 0, 0);
      };
      addCommitted(tr.best);
      for (const Committed& b : whatIf(tr, *cands, unsure, payloadIn)) {
        const bool same = b.valid == tr.best.valid &&
                          (!b.valid || (b.instance == tr.best.instance && b.geometry == tr.best.geometry &&
                                        b.primitive == tr.best.primitive && b.kind == tr.best.kind &&
                                        std::fabs(b.t - tr.best.t) <= tr.tol(b.t)));
        if (!same && amb.reason.empty()) amb.reason = "aabb-face";
        addCommitted(b);
      }
    }
    // R-TIE, R-ORDER-UNSPEC: candidates confirmed at the committed t (within
    // the error bound) may end in any order; R-TOFH: any candidate may be
    // confirmed first. Each is tried in a sandboxed what-if run (preferred in
    // ties, or processed first); those runs' answers are legal.
    const bool tofh = (tr.flags & kRayTerminateOnFirstHit) != 0;
    std::vector<long> prefers, firsts, potential;
    std::set<std::array<uint32_t, 3>> tied;  // distinct keys confirmable at the committed t
    if (tofh) {
      for (size_t k = 0; k < cands->size(); ++k) {
        const ModelCandidate& cand = (*cands)[k];
        if (cand.aabb || ((cand.hit || cand.ambiguity != TriAmbiguity::None) && eligible(cand)))
          firsts.push_back(static_cast<long>(k));
      }
    } else if (tr.best.valid) {
      tied.insert({tr.best.instance, tr.best.geometry, tr.best.primitive});
      // Per box: 1 its intersection program ran, 2 it reported at the committed t.
      std::vector<uint8_t> boxes(cands->size(), 0);
      for (const auto& [index, t] : reports) boxes[index] |= tr.ties(t) ? 3 : 1;
      for (size_t k = 0; k < cands->size(); ++k) {
        const ModelCandidate& cand = (*cands)[k];
        bool tie = false;
        if (cand.aabb) {
          tie = (boxes[k] & 2) != 0;
          // A box entered just past the committed t may still report at it.
          if (!boxes[k] && tr.ties(cand.t)) potential.push_back(static_cast<long>(k));
        } else {
          tie = cand.hit && tr.ties(cand.t) && eligible(cand);
        }
        if (!tie) continue;
        tied.insert({cand.instance, cand.geometry, cand.primitive});
        if (cand.instance != tr.best.instance || cand.geometry != tr.best.geometry ||
            cand.primitive != tr.best.primitive)
          prefers.push_back(static_cast<long>(k));
      }
      if (tied.size() < 2) prefers.clear();
      prefers.insert(prefers.end(), potential.begin(), potential.end());
    }
    if (!prefers.empty() || firsts.size() > 1) {
      const bool before = !amb.candidates.empty();
      bool differs = false;
      auto addOne = [&](const Committed& b) {
        if (b.valid) add(true, b.instance, b.geometry, b.primitive);
        else add(false, 0, 0, 0);
        differs = differs || b.valid != tr.best.valid ||
                  (b.valid && (b.instance != tr.best.instance || b.geometry != tr.best.geometry ||
                               b.primitive != tr.best.primitive));
      };
      const size_t saved = amb.candidates.size();
      addOne(tr.best);
      for (long k : prefers) addOne(sandbox(tr, *cands, nullptr, k, -1, payloadIn));
      if (firsts.size() > 1)
        for (long k : firsts) {
          // An edge or vertex triangle the model left out may be the device's first hit.
          std::vector<int8_t> force(cands->size(), -1);
          if ((*cands)[k].ambiguity != TriAmbiguity::None) force[k] = 1;
          addOne(sandbox(tr, *cands, force.data(), -1, k, payloadIn));
        }
      const bool ambiguousNow = tofh ? differs : (differs || tied.size() >= 2);
      if (ambiguousNow && amb.reason.empty()) amb.reason = tofh ? "first-hit" : "t-tie";
      if (!ambiguousNow && !before) amb.candidates.resize(saved);
    }
    // R-PREC: an intersection program's decision that rounding may flip
    // (sphere discriminant or root near an end): each flipped alone in a
    // what-if run; the ray is ambiguous, as the device's counters may differ.
    if (!shaderUnsure.empty()) {
      auto addCommitted = [&](const Committed& b) {
        if (b.valid) add(true, b.instance, b.geometry, b.primitive);
        else add(false, 0, 0, 0);
      };
      addCommitted(tr.best);
      for (const ShaderDecision& d : shaderUnsure) {
        ShaderDecision flipped = d;
        flipped.value = !d.value;
        addCommitted(sandbox(tr, *cands, nullptr, -1, -1, payloadIn, &flipped));
      }
      if (amb.reason.empty()) amb.reason = "shader-arith";
    }
    // R-PREC: the committed t is a root whose rounding on a device may exceed
    // the comparison's tolerance for hit_t: the answer is sure, its t is
    // checked against this wider bound.
    if (tr.best.valid && tr.best.t_err > 0) {
      const Tolerance tol = toleranceFor("hit_t");
      if (tr.best.t_err > tol.abs + tol.rel * std::max(std::fabs(tr.best.t), 1.0))
        t_bounds.push_back({index_, static_cast<float>(tr.best.t_err)});
    }
    if (!amb.reason.empty()) {
      ambiguous.push_back(std::move(amb));
      ray_ambiguous_ = true;
    }
  }
  return tr.best;
}

bool Machine::sphereHitDecision(StageEnv& env, bool modelValue, float disc) {
  Traversal* tr = env.traversal;
  if (!tr->exact || !tr->cur || env.stage != Stage::Intersection) return modelValue;
  const uint32_t ord = tr->sphere_ord++;
  if (const ShaderDecision* f = tr->forced(0, ord)) return f->value;
  if (tr->shader_unsure && env.hit && env.ray) {
    const HitView& h = *env.hit;
    const ModelInstance& mi = sh_.scene->instances[h.instance];
    const SphereError se = sphereError(h.aabb_min, h.aabb_max, h.object_origin, h.object_direction,
                                       objectRayError(mi.inverse_f, env.ray->origin, env.ray->direction));
    if (std::fabs(double(disc)) <= se.disc_err) tr->shader_unsure->push_back({tr->cur_index, 0, ord, modelValue});
  }
  return modelValue;
}

// One what-if run of the decision in a sandbox: counters, record and error
// are restored afterwards, the payload is a copy of the trace's incoming one.
Committed Machine::sandbox(const Traversal& actual, const std::vector<ModelCandidate>& cands, const int8_t* force,
                           long prefer, long first, const Payload& payloadIn, const ShaderDecision* shaderForce) {
  const std::vector<uint64_t> savedCounters = counters;
  const std::string savedError = error;
  std::vector<uint32_t> savedRecord;
  if (rec_) savedRecord.assign(rec_, rec_ + recordWords());
  Traversal v(*this, actual.ray);
  v.flags = actual.flags;
  v.depth = actual.depth;
  v.tmin = actual.tmin;
  v.tmax_cur = actual.ray.tmax;
  v.exact = actual.exact;
  v.prefer = prefer;
  v.first = first;
  v.shader_force = shaderForce;
  if (prefer >= 0) {
    const ModelCandidate& p = cands[static_cast<size_t>(prefer)];
    v.prefer_key[0] = p.instance;
    v.prefer_key[1] = p.geometry;
    v.prefer_key[2] = p.primitive;
  }
  Payload p = payloadIn;
  v.payload = &p;
  decide(v, cands, force, p);
  counters = savedCounters;
  error = savedError;
  if (rec_) std::copy(savedRecord.begin(), savedRecord.end(), rec_);
  return v.best;
}

// What-if runs of the decision for an ambiguous trace: the unsure candidates
// are grouped by distance (a group crosses one edge or vertex, shared or not).
// Within a group each candidate alone is a hit (watertight: at least one of a
// shared edge's triangles is hit); a group of one may also be no hit. Stage
// programs run again, in a sandbox: their counters, record and payload
// effects are undone.
std::vector<Committed> Machine::whatIf(const Traversal& actual, const std::vector<ModelCandidate>& cands,
                                       const std::vector<size_t>& unsure, const Payload& payloadIn) {
  std::vector<Committed> out;
  if (unsure.empty()) return out;
  std::vector<int8_t> force(cands.size(), -1);
  auto run = [&] { out.push_back(sandbox(actual, cands, force.data(), -1, -1, payloadIn)); };
  size_t g0 = 0;
  while (g0 < unsure.size()) {
    size_t g1 = g0 + 1;
    while (g1 < unsure.size() &&
           std::fabs(cands[unsure[g1]].t - cands[unsure[g1 - 1]].t) <= actual.tol(cands[unsure[g1]].t))
      ++g1;
    for (size_t a = g0; a < g1; ++a) {
      for (size_t b = g0; b < g1; ++b) force[unsure[b]] = a == b ? 1 : 0;
      run();
    }
    if (g1 - g0 == 1) {
      force[unsure[g0]] = 0;
      run();
    }
    for (size_t b = g0; b < g1; ++b) force[unsure[b]] = -1;
    g0 = g1;
  }
  return out;
}

// R-MISS-XOR-CHIT: closest-hit or miss for the committed hit.
void Machine::shade(const TraceRay& r, uint32_t flags, uint32_t depth, const Committed& best, Payload& payload) {
  const Case& c = *sh_.c;
  const ModelScene& scene = *sh_.scene;
  if (best.valid) {
    if (!(flags & kRaySkipClosestHit)) {
      const SbtRecord* rec = hitRecord(best.instance, best.geometry, r);
      const CHitGroup* grp = groupOf(*sh_.programs, rec);
      if (grp && grp->closest_hit && grp->closest_hit_counts.yes) {
        bump(grp->closest_hit_counts);
        bumpRuns(kRunsClosestHit);
      } else if (grp && grp->closest_hit) {
        HitView hv = viewOf(scene, c, r, best.instance, best.geometry, best.primitive,
                            sh_.need_object_ray);
        setHit(hv, static_cast<float>(best.t), best.kind, best.b1, best.b2);
        bumpRuns(kRunsClosestHit);
        StageEnv env = hitStage(Stage::ClosestHit, rec->data, &payload, r, hv, hv.t, depth);
        exec(*grp->closest_hit, env);
      }
    }
  } else {
    const uint32_t mi = r.miss & 0xFFFF;
    if (mi < default_miss_.size()) {
      const SbtRecord& rec = default_miss_[mi];
      if (rec.group && *rec.group < c.pipeline.miss.size() && sh_.programs->miss_counts[*rec.group].yes) {
        bump(sh_.programs->miss_counts[*rec.group]);
        bumpRuns(kRunsMiss);
      } else if (rec.group && *rec.group < c.pipeline.miss.size()) {
        bumpRuns(kRunsMiss);
        StageEnv env;
        env.stage = Stage::Miss;
        env.record_data = &rec.data;
        env.payload = &payload;
        env.ray = &r;
        env.tmax_view = r.tmax;
        env.depth = depth;
        exec(sh_.programs->miss[*rec.group], env);
      }
    }
  }
}

}  // namespace rayspec
