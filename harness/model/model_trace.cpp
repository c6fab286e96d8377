// traceRayEXT in the model: Embree enumerates, the model decides (see the
// order documented in model_backend.h), then closest-hit or miss runs.
#include <algorithm>
#include <cmath>
#include <limits>

#include "model/model_machine.h"
#include "model/watertight.h"

namespace rayspec {

struct Committed {
  bool valid = false;
  double t = 0;
  uint32_t instance = 0, geometry = 0, primitive = 0, kind = 0;
  float b1 = 0, b2 = 0;
};

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
  const HitGroup* cur_group = nullptr;
  const ModelCandidate* cur = nullptr;

  Traversal(Machine& machine, const TraceRay& r) : m(machine), ray(r) {}
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

const HitGroup* groupOf(const Case& c, const SbtRecord* rec) {
  if (!rec || !rec->group || *rec->group >= c.pipeline.hit_groups.size()) return nullptr;
  return &c.pipeline.hit_groups[*rec->group];
}

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

HitView viewOf(const ModelScene& s, const Case& c, const TraceRay& ray, uint32_t instance, uint32_t geometry,
               uint32_t primitive) {
  HitView hv;
  const ModelInstance& mi = s.instances[instance];
  hv.instance = instance;
  hv.custom_index = c.scene.instances[instance].custom_index & 0xFFFFFF;
  hv.geometry = geometry;
  hv.primitive = primitive;
  hv.object_origin = xform(mi.inverse_f, ray.origin, 1);
  hv.object_direction = xform(mi.inverse_f, ray.direction, 0);
  const ModelGeometry& g = s.blases[mi.blas].geometries[geometry];
  if (g.kind == Geometry::Kind::Aabbs) {
    const auto& a = g.aabbs[primitive];
    hv.aabb_min = {a[0], a[1], a[2]};
    hv.aabb_max = {a[3], a[4], a[5]};
  }
  return hv;
}

}  // namespace

Flow Machine::report(const Stmt& s, StageEnv& env) {
  Traversal* tr = env.traversal;
  if (!tr || !tr->cur) return Flow::Continue;
  const Val tv = eval(s.t, env);
  const float t = s.t.type == ValueType::Uint ? static_cast<float>(tv.u) : tv.f[0];
  const uint32_t kind = eval(s.hit_kind, env).u;
  Val attr;
  if (!s.attribute.empty()) attr = eval(s.attribute[0], env);
  bool accepted = false;
  Flow flow = Flow::Continue;
  // R-ISECT-REPORT, R-CAND-AABB-CLOSED: tmin <= t <= current tmax.
  if (t >= tr->ray.tmin && static_cast<double>(t) <= tr->tmax_cur) {
    HitView hv = *env.hit;
    hv.t = t;
    hv.hit_kind = kind;
    hv.b1 = attr.f[0];
    hv.b2 = attr.f[1];
    Flow ah = Flow::Continue;
    if (!tr->cur_opaque && tr->cur_group && tr->cur_group->any_hit) {
      bumpRuns(kRunsAnyHit);
      StageEnv a;
      a.stage = Stage::AnyHit;
      a.record_data = &tr->cur_rec->data;
      a.payload = tr->payload;
      a.ray = &tr->ray;
      a.hit = &hv;
      a.tmax_view = t;  // R-TMAX-VIEW: any-hit sees the candidate's t
      a.depth = tr->depth;
      ah = exec(*tr->cur_group->any_hit, a);
    }
    if (ah != Flow::Ignore) {
      accepted = true;
      tr->best = {true, static_cast<double>(t), hv.instance, hv.geometry, hv.primitive, kind, hv.b1, hv.b2};
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
  const Case& c = *sh_.c;
  const ModelScene& scene = *sh_.scene;
  Traversal tr(*this, r);
  tr.flags = r.flags;
  if (c.pipeline.flags & 0x1000) tr.flags |= kRaySkipTriangles;
  if (c.pipeline.flags & 0x2000) tr.flags |= kRaySkipAabbs;
  tr.depth = depth;
  tr.tmin = r.tmin;
  tr.tmax_cur = r.tmax;
  tr.exact = scene.tier == ModelTier::Exact;
  Payload payload;
  payload.depth = depth;
  tr.payload = &payload;

  RTCRayHit rh;
  rh.ray.org_x = r.origin[0]; rh.ray.org_y = r.origin[1]; rh.ray.org_z = r.origin[2];
  rh.ray.dir_x = r.direction[0]; rh.ray.dir_y = r.direction[1]; rh.ray.dir_z = r.direction[2];
  rh.ray.time = 0;
  rh.ray.mask = (r.cull_mask & 0xFF) | ((tr.flags & kRaySkipTriangles) ? 0u : kMaskTriangles) |
                ((tr.flags & kRaySkipAabbs) ? 0u : kMaskAabbs);
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  const bool validRay = r.tmin <= r.tmax && (rh.ray.mask & 0xFF) != 0;

  std::vector<ModelCandidate>* cands = nullptr;
  if (validRay && sh_.direct) {
    // Embree's own closest hit; the open interval by moving Embree's ends.
    rh.ray.tnear = scene.tier == ModelTier::Robust ? std::nextafter(r.tmin, INFINITY) : r.tmin;
    rh.ray.tfar = std::nextafter(r.tmax, -INFINITY);
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    rtcIntersect1(scene.top, &ctx, &rh);
    if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
      ModelCandidate cand;
      cand.instance = rh.hit.instID[0];
      cand.geometry = rh.hit.geomID;
      cand.primitive = rh.hit.primID;
      const Facing f = facing(scene, cand, r, tr.flags);
      tr.best = {true, rh.ray.tfar, cand.instance, cand.geometry, cand.primitive, f.kind, rh.hit.u, rh.hit.v};
    }
  } else if (validRay) {
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
    for (const ModelCandidate& cand : *cands) {
      if (tr.stop) break;
      const ModelInstance& mi = scene.instances[cand.instance];
      const ModelGeometry& g = scene.blases[mi.blas].geometries[cand.geometry];
      const bool opaque = resolveOpaque(g.flags, mi.src->flags, tr.flags);
      if ((tr.flags & kRayCullOpaque) && opaque) continue;
      if ((tr.flags & kRayCullNoOpaque) && !opaque) continue;
      const SbtRecord* rec = hitRecord(cand.instance, cand.geometry, r);
      const HitGroup* grp = groupOf(c, rec);
      if (cand.aabb) {
        if (cand.t > tr.tmax_cur) continue;
        if (!grp || !grp->intersection) continue;
        HitView hv = viewOf(scene, c, r, cand.instance, cand.geometry, cand.primitive);
        tr.cur = &cand;
        tr.cur_opaque = opaque;
        tr.cur_rec = rec;
        tr.cur_group = grp;
        bumpRuns(kRunsIntersection);
        StageEnv env;
        env.stage = Stage::Intersection;
        env.record_data = &rec->data;
        env.ray = &r;
        env.hit = &hv;
        env.tmax_view = static_cast<float>(tr.tmax_cur);  // R-TMAX-VIEW: closest so far
        env.depth = depth;
        env.traversal = &tr;
        exec(*grp->intersection, env);
        tr.cur = nullptr;
        continue;
      }
      if (!cand.hit) continue;
      bool inside = cand.t > tr.tmin && cand.t < tr.tmax_cur;
      // Exact tier, R-TIE: a tie with the committed hit goes to the smaller key.
      if (!inside && tr.exact && tr.best.valid && std::fabs(cand.t - tr.best.t) <= tr.tol(cand.t) &&
          keyLess(cand.instance, cand.geometry, cand.primitive, tr.best.instance, tr.best.geometry,
                  tr.best.primitive))
        inside = true;
      if (!inside) continue;
      const Facing f = facing(scene, cand, r, tr.flags);
      if (f.culled) continue;
      Flow ah = Flow::Continue;
      if (!opaque && grp && grp->any_hit) {
        HitView hv = viewOf(scene, c, r, cand.instance, cand.geometry, cand.primitive);
        hv.t = static_cast<float>(cand.t);
        hv.hit_kind = f.kind;
        hv.b1 = cand.b1;
        hv.b2 = cand.b2;
        bumpRuns(kRunsAnyHit);
        StageEnv a;
        a.stage = Stage::AnyHit;
        a.record_data = &rec->data;
        a.payload = &payload;
        a.ray = &r;
        a.hit = &hv;
        a.tmax_view = hv.t;
        a.depth = depth;
        ah = exec(*grp->any_hit, a);
        if (ah == Flow::Ignore) continue;
      }
      tr.best = {true, cand.t, cand.instance, cand.geometry, cand.primitive, f.kind, cand.b1, cand.b2};
      tr.tmax_cur = cand.t;
      if (ah == Flow::Terminate || (tr.flags & kRayTerminateOnFirstHit)) tr.stop = true;
    }
  }

  // Exact tier: is this trace's answer numerically clear?
  if (cands && tr.exact && !ray_ambiguous_) {
    RayAmbiguity amb;
    amb.ray = index_;
    const double finalT = tr.best.valid ? tr.best.t : INFINITY;
    auto add = [&](bool hit, uint32_t i, uint32_t g, uint32_t p) {
      for (const Candidate& k : amb.candidates)
        if (k.hit == hit && (!hit || (k.instance == i && k.geometry == g && k.primitive == p))) return;
      amb.candidates.push_back({hit, i, g, p});
    };
    const ModelCandidate* fallback = nullptr;
    for (const ModelCandidate& cand : *cands) {
      if (cand.aabb) continue;
      const ModelInstance& mi = scene.instances[cand.instance];
      const ModelGeometry& g = scene.blases[mi.blas].geometries[cand.geometry];
      const bool opaque = resolveOpaque(g.flags, mi.src->flags, tr.flags);
      if (((tr.flags & kRayCullOpaque) && opaque) || ((tr.flags & kRayCullNoOpaque) && !opaque)) continue;
      if (facing(scene, cand, r, tr.flags).culled) continue;
      const double tl = tr.tol(cand.t);
      if (cand.t < r.tmin - tl || cand.t > r.tmax + tl) continue;
      const char* why = nullptr;
      if (cand.ambiguity != TriAmbiguity::None && cand.t <= finalT + tl)
        why = cand.ambiguity == TriAmbiguity::Vertex ? "vertex" : "edge";
      else if (cand.hit && std::fabs(cand.t - r.tmin) <= tl) why = "tmin-tie";
      else if (cand.hit && std::fabs(cand.t - r.tmax) <= tl) why = "tmax-tie";
      else if (cand.hit && tr.best.valid && std::fabs(cand.t - tr.best.t) <= tl &&
               (cand.instance != tr.best.instance || cand.geometry != tr.best.geometry ||
                cand.primitive != tr.best.primitive))
        why = "tmax-tie";
      if (why) {
        if (amb.reason.empty()) amb.reason = why;
        add(true, cand.instance, cand.geometry, cand.primitive);
      } else if (cand.hit && !fallback && cand.t > r.tmin && cand.t < r.tmax) {
        fallback = &cand;
      }
    }
    if (!amb.reason.empty()) {
      if (tr.best.valid) add(true, tr.best.instance, tr.best.geometry, tr.best.primitive);
      else add(false, 0, 0, 0);
      if (fallback) add(true, fallback->instance, fallback->geometry, fallback->primitive);
      else add(false, 0, 0, 0);
      ambiguous.push_back(std::move(amb));
      ray_ambiguous_ = true;
    }
  }

  // R-MISS-XOR-CHIT
  if (tr.best.valid) {
    if (!(tr.flags & kRaySkipClosestHit)) {
      const SbtRecord* rec = hitRecord(tr.best.instance, tr.best.geometry, r);
      const HitGroup* grp = groupOf(c, rec);
      if (grp && grp->closest_hit) {
        HitView hv = viewOf(scene, c, r, tr.best.instance, tr.best.geometry, tr.best.primitive);
        hv.t = static_cast<float>(tr.best.t);
        hv.hit_kind = tr.best.kind;
        hv.b1 = tr.best.b1;
        hv.b2 = tr.best.b2;
        bumpRuns(kRunsClosestHit);
        StageEnv env;
        env.stage = Stage::ClosestHit;
        env.record_data = &rec->data;
        env.payload = &payload;
        env.ray = &r;
        env.hit = &hv;
        env.tmax_view = hv.t;
        env.depth = depth;
        exec(*grp->closest_hit, env);
      }
    }
  } else {
    const uint32_t mi = r.miss & 0xFFFF;
    if (mi < default_miss_.size()) {
      const SbtRecord& rec = default_miss_[mi];
      if (rec.group && *rec.group < c.pipeline.miss.size()) {
        bumpRuns(kRunsMiss);
        StageEnv env;
        env.stage = Stage::Miss;
        env.record_data = &rec.data;
        env.payload = &payload;
        env.ray = &r;
        env.tmax_view = r.tmax;
        env.depth = depth;
        exec(c.pipeline.miss[*rec.group], env);
      }
    }
  }
  return payload;
}

}  // namespace rayspec
