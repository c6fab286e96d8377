#include "model/model_scene.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "base/affine.h"
#include "base/error_bounds.h"
#include "base/float_steps.h"
#include "base/slab.h"
#include "case/transform.h"
#include "model/box_bound.h"
#include "model/box_pad.h"
#include "model/exact_interval.h"
#include "model/frame_error.h"
#include "model/in_plane.h"
#include "model/model_trace_context.h"
#include "model/watertight.h"
#include "model/watertight_rejection.h"

namespace rayspec {
namespace {

constexpr float kEmbreeLarge = 1.0e18f;  // Embree drops bounds beyond ~1.8e18

void setInvalidBounds(RTCBounds& b) {
  b.lower_x = b.lower_y = b.lower_z = 1.0f;
  b.upper_x = b.upper_y = b.upper_z = -1.0f;
}

float clampLarge(float x) {
  return std::clamp(x, -kEmbreeLarge, kEmbreeLarge);
}

// Embree's box from its low and high corners.
void setBounds(RTCBounds& b, const float lo[3], const float hi[3]) {
  b.lower_x = lo[0];
  b.lower_y = lo[1];
  b.lower_z = lo[2];
  b.upper_x = hi[0];
  b.upper_y = hi[1];
  b.upper_z = hi[2];
}

void ownTriangleBounds(const RTCBoundsFunctionArguments* args) {
  const auto* g = static_cast<const ModelGeometry*>(args->geometryUserPtr);
  const auto& tri = g->triangles[args->primID];
  RTCBounds& b = *args->bounds_o;
  float lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min({tri[0][k], tri[1][k], tri[2][k]});
    hi[k] = std::max({tri[0][k], tri[1][k], tri[2][k]});
    if (std::isnan(tri[0][k]) || std::isnan(tri[1][k]) || std::isnan(tri[2][k])) {
      const auto it = g->nan_regions.find(args->primID);
      if (it == g->nan_regions.end()) {
        setInvalidBounds(b);  // inactive (R-INACTIVE): never a candidate
        return;
      }
      // NaN in Y or Z: its region, so that every ray crossing it is enumerated
      // (padded by its finite size too: a flat region still has thickness for
      // the BVH, the model's own test decides).
      const std::array<double, 6>& r = it->second;
      double size = kMagnitudeFloor;
      for (double x : r)
        if (std::isfinite(x)) size = std::max(size, std::fabs(x));
      for (int a = 0; a < 3; ++a) {
        lo[a] = clampLarge(static_cast<float>(r[a] - kEnumerationPadRel * size));
        hi[a] = clampLarge(static_cast<float>(r[a + 3] + kEnumerationPadRel * size));
      }
      setBounds(b, lo, hi);
      return;
    }
  }
  // Enlarged so that rays within the ambiguity bound of an edge are enumerated
  // (and rays an instance's rounding may move onto it): model/box_pad.cpp
  // says why this much is enough. Rounded outward to float.
  for (int k = 0; k < 3; ++k) {
    const double m =
        std::max({std::fabs(double(lo[k])), std::fabs(double(hi[k])), kMagnitudeFloor});
    const double pad = kBoxMagnitudeSteps * kUnitRoundoff * m + g->ray_pad + 4 * g->vertex_err[k];
    lo[k] = clampLarge(floatBelow(lo[k] - pad));
    hi[k] = clampLarge(floatAbove(hi[k] + pad));
  }
  setBounds(b, lo, hi);
}

void aabbBounds(const RTCBoundsFunctionArguments* args) {
  const auto* g = static_cast<const ModelGeometry*>(args->geometryUserPtr);
  const auto& a = g->aabbs[args->primID];
  RTCBounds& b = *args->bounds_o;
  if (std::isnan(a[0])) {
    setInvalidBounds(b);
    return;
  }  // R-INACTIVE
  float v[6];
  for (int k = 0; k < 6; ++k)
    v[k] = std::isnan(a[k]) ? (k < 3 ? -kEmbreeLarge : kEmbreeLarge) : a[k];
  for (int k = 0; k < 3; ++k) {
    // Conservative (R-AABB-CONS): a little slack, so grazing rays are enumerated.
    const float pad = boxSlackF(v[k], v[k + 3]) + (g->aabbs_grown ? v[k + 3] - v[k] : 0.0f);
    if (g->box_pad > 0) {  // exact tier: boxes a device may offer (rounded outward)
      v[k] = clampLarge(floatBelow(v[k] - pad - g->box_pad));
      v[k + 3] = clampLarge(floatAbove(v[k + 3] + pad + g->box_pad));
      continue;
    }
    v[k] = clampLarge(v[k] - pad);
    v[k + 3] = clampLarge(v[k + 3] + pad);
  }
  setBounds(b, v, v + 3);
}

TraceContext* traceContext(RTCIntersectContext* ctx) {
  return reinterpret_cast<TraceContext*>(ctx);
}

// The object-space ray of instance `inst` in double, with a device's frame
// error (exact tier), kept for the instance seen last.
const WatertightRay& objectRay(TraceContext& tc, ModelTier tier, uint32_t inst) {
  if (tc.object_instance == inst) return tc.object_ray;
  const auto& mi = tc.scene->instances[inst];
  tc.object_instance = inst;
  FrameError err;
  if (tier == ModelTier::Exact)
    objectRayFrameError(mi.form, mi.inverse, mi.inverse_f, tc.origin, tc.direction, err);
  tc.object_ray = prepareWatertightRay(applyAffine(mi.inverse, tc.origin, 1.0),
                                       applyAffine(mi.inverse, tc.direction, 0.0), err);
  tc.object_exact =
      tier == ModelTier::Exact && objectRayExact(mi.form, mi.src->transform, tc.origin);
  return tc.object_ray;
}

// A triangle whose plane the ray's line lies in (WatertightHit::in_plane):
// its candidate spans where the line runs across it within the trace's
// interval (t its middle, t_err half its length); false where it does not.
// A triangle of no area keeps the watertight test's candidate.
bool placeInPlane(ModelCandidate& c, const TraceContext& tc, const WatertightRay& wr,
                  const DVec3& v0, const DVec3& v1, const DVec3& v2, const DVec3& vertex_err) {
  const std::optional<Span> across = inPlaneSpan(wr, v0, v1, v2, vertex_err);
  if (!across) return true;
  const double t0 = std::max(across->t0, tc.tmin), t1 = std::min(across->t1, tc.tmax);
  if (!(t0 <= t1)) return false;
  c.in_plane = true;
  c.t = 0.5 * (t0 + t1);
  c.t_err = 0.5 * (t1 - t0);
  return true;
}

void ownTriangleIntersect(const RTCIntersectFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto* g = static_cast<const ModelGeometry*>(args->geometryUserPtr);
  TraceContext* tc = traceContext(args->context);
  const uint32_t inst = args->context->instID[0];
  const WatertightRay& wr = objectRay(*tc, g->tier, inst);
  const DVec3& o = wr.o;
  const DVec3& d = wr.d;
  const auto& tri = g->triangles[args->primID];
  if (!g->nan_regions.empty()) {
    if (const auto it = g->nan_regions.find(args->primID); it != g->nan_regions.end()) {
      // R-UB: never a hit; noted when the ray crosses the region in its interval.
      const std::array<double, 6>& box = it->second;
      DVec3 lo, hi;
      for (int k = 0; k < 3; ++k) {
        const double slack = boxSlack(box[k], box[k + 3]);
        lo[k] = box[k] - slack;
        hi[k] = box[k + 3] + slack;
      }
      const Span s = slabSpan(lo, hi, o, d, {tc->tmin, tc->tmax});
      if (s.empty()) return;
      ModelCandidate c;
      c.t = s.t0;
      c.instance = inst;
      c.geometry = args->geomID;
      c.primitive = args->primID;
      c.hit = false;
      c.nan_triangle = true;
      tc->candidates->push_back(c);
      return;
    }
  }
  auto dv = [](const Vec3& v) {
    return DVec3{v[0], v[1], v[2]};
  };
  const DVec3 v0 = dv(tri[0]), v1 = dv(tri[1]), v2 = dv(tri[2]);
  const DVec3 vertex_err = g->tier == ModelTier::Exact ? g->vertex_err : DVec3{};
  if (watertightCertainMiss(wr, v0, v1, v2, vertex_err)) return;  // dropped below too (proof there)
  WatertightHit h = watertightIntersectPrepared(wr, v0, v1, v2, vertex_err);
  if (!h.valid) return;
  if (!h.hit && h.ambiguity == TriAmbiguity::None) return;
  if (g->tier != ModelTier::Exact && !h.hit) return;
  ModelCandidate c;
  c.t = h.t;
  c.instance = inst;
  c.geometry = args->geomID;
  c.primitive = args->primID;
  c.hit = h.hit;
  c.b1 = static_cast<float>(h.b1);
  c.b2 = static_cast<float>(h.b2);
  c.ambiguity = g->tier == ModelTier::Exact ? h.ambiguity : TriAmbiguity::None;
  c.near_edges = g->tier == ModelTier::Exact ? h.near_edges : 0;
  c.t_err = h.t_err;
  if (h.in_plane && g->tier == ModelTier::Exact &&
      !placeInPlane(c, *tc, wr, v0, v1, v2, vertex_err))
    return;
  if (g->tier == ModelTier::Exact && g->vertex_err == DVec3{} && tc->object_exact && !c.in_plane) {
    const ExactEnds ends = exactEnds(o, d, v0, v1, v2, h.t, tc->tmin, tc->tmax);
    c.exact_tmin = ends.tmin;
    c.exact_tmax = ends.tmax;
  }
  tc->candidates->push_back(c);
}

// Whether the ray's interval meets span s.
bool meets(const Span& s, const TraceContext& tc) {
  return !(s.t0 > s.t1 || s.t1 < tc.tmin || s.t0 > tc.tmax);
}

// Exact tier: where the model's object-space ray meets the box grown (sign
// +1) or shrunk (-1) by a device's error bound (model/box_bound.h).
Span boundedSpan(const std::array<float, 6>& a, const WatertightRay& w, double sign) {
  const DVec3 lo{a[0], a[1], a[2]}, hi{a[3], a[4], a[5]};
  const DVec3 bound = boxFaceBounds(lo, hi, w);
  DVec3 blo, bhi;
  for (int k = 0; k < 3; ++k) {
    blo[k] = lo[k] - sign * bound[k];
    bhi[k] = hi[k] + sign * bound[k];
  }
  return slabSpan(blo, bhi, w.o, w.d);
}

void aabbIntersect(const RTCIntersectFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto* g = static_cast<const ModelGeometry*>(args->geometryUserPtr);
  TraceContext* tc = traceContext(args->context);
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
  const DVec3 o{RTCRayN_org_x(ray, args->N, 0), RTCRayN_org_y(ray, args->N, 0),
                RTCRayN_org_z(ray, args->N, 0)};
  const DVec3 d{RTCRayN_dir_x(ray, args->N, 0), RTCRayN_dir_y(ray, args->N, 0),
                RTCRayN_dir_z(ray, args->N, 0)};
  const auto& a = g->aabbs[args->primID];
  const uint32_t inst = args->context->instID[0];
  const bool exact = g->tier == ModelTier::Exact;
  DVec3 lo, hi;  // the box with a little slack
  for (int k = 0; k < 3; ++k) {
    const double slack = boxSlack(a[k], a[k + 3]);
    lo[k] = a[k] - slack;
    hi[k] = a[k + 3] + slack;
  }
  Span s = slabSpan(lo, hi, o, d);
  const bool entered = meets(s, *tc);
  ModelCandidate c;
  if (!entered && g->aabbs_grown) {  // a neighbour's intersection program runs too
    for (int k = 0; k < 3; ++k) {
      const double extent = double(a[k + 3]) - double(a[k]);
      lo[k] -= extent;
      hi[k] += extent;
    }
    s = slabSpan(lo, hi, o, d);
  }
  if (!meets(s, *tc)) {
    // Exact tier: missed, but within a device's error bound of the box
    // (R-AABB-CONS): a device may offer it.
    if (!exact) return;
    s = boundedSpan(a, objectRay(*tc, g->tier, inst), 1.0);
    if (!meets(s, *tc)) return;
    c.outside = c.near_face = true;
  } else if (exact && entered) {
    // Does the ray still cross the box shrunk by the device's error bound,
    // within its interval? If not, it only grazes a face (or passes just
    // outside, within the slack), or its interval only reaches a face: one
    // that ends (or starts) on the box's surface, as a ray of zero length
    // (tmin = tmax) at a face or corner does.
    const Span inner = boundedSpan(a, objectRay(*tc, g->tier, inst), -1.0);
    c.near_face = inner.empty() || !meets(inner, *tc);
    if (!c.near_face) {
      c.inner_t0 = inner.t0;
      c.inner_t1 = inner.t1;
    }
  }
  c.aabb = true;
  c.missed = !entered;
  c.t = std::max(s.t0, tc->tmin);
  c.instance = inst;
  c.geometry = args->geomID;
  c.primitive = args->primID;
  tc->candidates->push_back(c);
}

void triangleFilter(const RTCFilterFunctionNArguments* args) {
  TraceContext* tc = traceContext(args->context);
  ModelCandidate c;
  c.t = RTCRayN_tfar(args->ray, args->N, 0);
  c.instance = RTCHitN_instID(args->hit, args->N, 0, 0);
  c.geometry = RTCHitN_geomID(args->hit, args->N, 0);
  c.primitive = RTCHitN_primID(args->hit, args->N, 0);
  c.b1 = RTCHitN_u(args->hit, args->N, 0);
  c.b2 = RTCHitN_v(args->hit, args->N, 0);
  tc->candidates->push_back(c);
  args->valid[0] = 0;  // keep enumerating: the model decides afterwards
}

}  // namespace

bool triangleNanYZ(const std::array<Vec3, 3>& tri) {
  if (triangleInactive(tri)) return false;
  for (const Vec3& v : tri)
    if (std::isnan(v[1]) || std::isnan(v[2])) return true;
  return false;
}

std::array<double, 6> nanTriangleRegion(const std::array<Vec3, 3>& tri,
                                        const std::optional<Transform>& transform) {
  std::array<double, 6> box;
  for (int k = 0; k < 3; ++k) {
    box[k] = INFINITY;
    box[k + 3] = -INFINITY;
    for (const Vec3& v : tri) {
      if (std::isnan(v[k])) {
        box[k] = -INFINITY;
        box[k + 3] = INFINITY;
        break;
      }
      box[k] = std::min<double>(box[k], v[k]);
      box[k + 3] = std::max<double>(box[k + 3], v[k]);
    }
  }
  if (!transform) return box;
  // Interval arithmetic through the affine map (a zero coefficient adds
  // nothing, even to an unbounded component).
  std::array<double, 6> out;
  const Transform& m = *transform;
  for (int row = 0; row < 3; ++row) {
    double lo = m[row * 4 + 3], hi = m[row * 4 + 3];
    for (int k = 0; k < 3; ++k) {
      const double a = m[row * 4 + k];
      if (a == 0) continue;
      lo += a > 0 ? a * box[k] : a * box[k + 3];
      hi += a > 0 ? a * box[k + 3] : a * box[k];
    }
    out[row] = lo;
    out[row + 3] = hi;
  }
  return out;
}

bool needsOwnTriangleTest(const std::array<Vec3, 3>& tri) {
  if (triangleInactive(tri)) return false;
  for (const Vec3& v : tri)
    for (float x : v)
      if (std::isnan(x) || std::fabs(x) > kEmbreeLarge) return true;
  return false;
}

ModelScene::~ModelScene() {
  for (RTCScene t : tops)
    if (t) rtcReleaseScene(t);
  for (ModelBlas& b : blases)
    if (b.scene) rtcReleaseScene(b.scene);
  if (device) rtcReleaseDevice(device);
}

namespace {

Result<RTCDevice> newEmbreeDevice() {
  RTCDevice device = rtcNewDevice(nullptr);
  if (device) return device;
  const RTCError e = rtcGetDeviceError(nullptr);
  return errorMessage(
      e == RTC_ERROR_OUT_OF_MEMORY
          ? "rtcNewDevice failed: out of memory (a --memory-limit too low for Embree?)"
          : "rtcNewDevice failed (Embree error " + std::to_string(int(e)) + ")");
}

// Per-primitive triangles (geometry transform applied), classified on the
// vertices as given: inactive (NaN X), NaN in Y or Z (its region kept), or
// beyond Embree's range (the model's own test).
void fillTriangles(ModelGeometry& mg, const Geometry& g) {
  mg.triangles.resize(mg.count);
  for (uint32_t p = 0; p < mg.count; ++p) {
    std::array<Vec3, 3> raw;
    for (int k = 0; k < 3; ++k) {
      const uint32_t idx = g.indices.empty() ? p * 3 + k : g.indices[p * 3 + k];
      raw[k] = idx < g.vertices.size() ? g.vertices[idx] : Vec3{NAN, NAN, NAN};
      mg.triangles[p][k] = g.transform ? applyAffine(*g.transform, raw[k], 1.0f) : raw[k];
    }
    if (triangleInactive(raw)) {
      mg.triangles[p][0][0] = NAN;  // stays inactive whatever the transform made of it
    } else if (triangleNanYZ(raw)) {
      mg.nan_regions[p] = nanTriangleRegion(raw, g.transform);
      mg.own_triangles = true;
    } else if (needsOwnTriangleTest(mg.triangles[p])) {
      mg.own_triangles = true;
    }
  }
}

// Whether Embree can take the geometry's index buffer as it is: every index
// in range.
bool indexBufferUsable(const Geometry& g, uint32_t n) {
  if (g.indices.empty() || g.indices.size() < 3 * size_t{n}) return false;
  uint32_t max_index = 0;  // one pass, no early exit: vectorizes
  for (size_t i = 0; i < 3 * size_t{n}; ++i) max_index = std::max(max_index, g.indices[i]);
  return n == 0 || size_t{max_index} < g.vertices.size();
}

// Whether every vertex (transformed) is ordinary: no NaN, nothing Embree
// would drop.
bool verticesOrdinary(const Geometry& g) {
  bool ordinary = true;
  for (size_t v = 0; ordinary && v < g.vertices.size(); ++v) {
    const Vec3 x = g.transform ? applyAffine(*g.transform, g.vertices[v], 1.0f) : g.vertices[v];
    for (float f : x) ordinary = ordinary && !std::isnan(f) && std::fabs(f) <= kEmbreeLarge;
  }
  return ordinary;
}

// Exact tier: per component, how far a device's vertices may lie from the
// model's: the decode of normalized codes (vertexDecodeError: c / (2^b - 1)
// is no float, and a device may round it another way), carried through the
// geometry transform, and that transform's own roundings.
DVec3 deviceVertexError(const Geometry& g) {
  const double decode = vertexDecodeError(g.vertex_format);
  const uint32_t n = vertexComponents(g.vertex_format);
  DVec3 e{};
  if (!g.transform) {
    for (uint32_t k = 0; k < n; ++k) e[k] = decode;
    return e;
  }
  const Transform& m = *g.transform;
  e = geometryVertexError(m, g.vertices);
  for (int k = 0; k < 3; ++k)
    for (uint32_t j = 0; j < n; ++j) e[k] += std::fabs(double(m[k * 4 + j])) * decode;
  return e;
}

// The model's view of one geometry of BLAS bi; its per-primitive triangles
// only where someone reads them (candidates, own tests, an unusable index
// buffer).
void describeGeometry(ModelGeometry& mg, const Geometry& g, size_t bi, size_t gi, ModelTier tier,
                      double ray_pad, bool keep_triangles, bool filters, bool grown) {
  mg.kind = g.kind;
  mg.flags = g.flags;
  mg.transform = g.transform;
  mg.blas = static_cast<uint32_t>(bi);
  mg.index = static_cast<uint32_t>(gi);
  mg.tier = tier;
  mg.ray_pad = ray_pad;
  mg.aabbs_grown = grown;
  if (tier == ModelTier::Exact) mg.vertex_err = deviceVertexError(g);
  if (g.kind == Geometry::Kind::Aabbs) {
    mg.aabbs = g.aabbs;
    mg.count = static_cast<uint32_t>(g.aabbs.size());
    return;
  }
  mg.count = g.primitiveCount();
  mg.indexed = indexBufferUsable(g, mg.count);
  const bool ordinary = mg.indexed && verticesOrdinary(g);
  mg.own_triangles = tier == ModelTier::Exact;
  if (keep_triangles || filters || !ordinary || mg.own_triangles) fillTriangles(mg, g);
}

// Embree's triangle geometry: the case's own vertex sharing where it can
// (fewer vertices to build from), else three vertices a triangle.
RTCGeometry embreeTriangles(RTCDevice device, const ModelGeometry& mg, const Geometry& g,
                            bool filters) {
  const uint32_t n = mg.count;
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  const size_t nv = mg.indexed ? g.vertices.size() : 3 * size_t{n};
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                         RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
  auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
  if (mg.indexed) {
    for (size_t v = 0; v < nv; ++v) {
      const Vec3 x = g.transform ? applyAffine(*g.transform, g.vertices[v], 1.0f) : g.vertices[v];
      for (int a = 0; a < 3; ++a) vb[v * 3 + a] = x[a];
    }
    std::copy(g.indices.begin(), g.indices.begin() + 3 * size_t{n}, ib);
  } else {
    for (uint32_t p = 0; p < n; ++p)
      for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 3; ++a) vb[(p * 3 + k) * 3 + a] = mg.triangles[p][k][a];
        ib[p * 3 + k] = p * 3 + k;
      }
  }
  rtcSetGeometryMask(geom, kMaskTriangles);
  if (filters) rtcSetGeometryIntersectFilterFunction(geom, triangleFilter);
  return geom;
}

// A user geometry the model intersects itself: AABBs, or triangles under its
// own test.
RTCGeometry embreeUserGeometry(RTCDevice device, ModelGeometry& mg) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geom, mg.count);
  rtcSetGeometryUserData(geom, &mg);
  if (mg.kind == Geometry::Kind::Aabbs) {
    rtcSetGeometryBoundsFunction(geom, aabbBounds, nullptr);
    rtcSetGeometryIntersectFunction(geom, aabbIntersect);
    rtcSetGeometryMask(geom, kMaskAabbs);
  } else {
    rtcSetGeometryBoundsFunction(geom, ownTriangleBounds, nullptr);
    rtcSetGeometryIntersectFunction(geom, ownTriangleIntersect);
    rtcSetGeometryMask(geom, kMaskTriangles);
  }
  return geom;
}

// One BLAS as an Embree scene of its geometries.
void commitBlas(ModelScene& s, const Case& c, size_t bi, RTCSceneFlags scene_flags) {
  ModelBlas& mb = s.blases[bi];
  mb.scene = rtcNewScene(s.device);
  rtcSetSceneFlags(mb.scene, scene_flags);
  for (ModelGeometry& mg : mb.geometries) {
    if (mg.count == 0) continue;
    RTCGeometry geom =
        mg.kind == Geometry::Kind::Triangles && !mg.own_triangles
            ? embreeTriangles(s.device, mg, c.scene.blases[mg.blas].geometries[mg.index], s.filters)
            : embreeUserGeometry(s.device, mg);
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(mb.scene, geom, mg.index);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(mb.scene);
}

// Each TLAS as an Embree scene of its instances (a null BLAS, or an
// instance of another level: inactive there, kept for its index but not
// attached).
void commitInstances(ModelScene& s, const Case& c, RTCSceneFlags scene_flags) {
  s.tops.resize(c.scene.tlasCount());
  for (RTCScene& top : s.tops) {
    top = rtcNewScene(s.device);
    rtcSetSceneFlags(top, scene_flags);
  }
  s.instances.resize(c.scene.instances.size());
  for (size_t ii = 0; ii < c.scene.instances.size(); ++ii) {
    const Instance& inst = c.scene.instances[ii];
    ModelInstance& mi = s.instances[ii];
    mi.src = &inst;
    mi.inverse = invertTransform(inst.transform);
    mi.form = instanceForm(inst.transform);
    for (int k = 0; k < 12; ++k) mi.inverse_f[k] = static_cast<float>(mi.inverse[k]);
    if (!inst.blas || *inst.blas >= s.blases.size()) continue;  // R-INACTIVE: null BLAS
    mi.blas = static_cast<int>(*inst.blas);
    RTCGeometry geom = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geom, s.blases[mi.blas].scene);
    rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, inst.transform.data());
    rtcSetGeometryMask(geom, inst.mask & kVisibilityMask);
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(s.tops[inst.tlas], geom, static_cast<unsigned>(ii));
    rtcReleaseGeometry(geom);
  }
  for (RTCScene top : s.tops) rtcCommitScene(top);
}

}  // namespace

Result<void> buildModelScene(ModelScene& s, const Case& c, ModelTier tier, bool filters,
                             bool keep_triangles) {
  s.tier = tier;
  RAYSPEC_TRY(RTCDevice device, newEmbreeDevice());
  s.device = device;
  s.blases.resize(c.scene.blases.size());
  // Exact tier: how far a device's and Embree's object-space rays may be off
  // and how far the exact test's ambiguity reaches, per BLAS (box_pad.h).
  const std::vector<double> ray_pad =
      tier == ModelTier::Exact ? blasRayPads(c) : std::vector<double>();
  const std::vector<double> box_pad =
      tier == ModelTier::Exact ? blasBoxPads(c) : std::vector<double>();
  bool any_own = false;
  for (size_t bi = 0; bi < c.scene.blases.size(); ++bi) {
    const Blas& src = c.scene.blases[bi];
    s.blases[bi].geometries.resize(src.geometries.size());
    for (size_t gi = 0; gi < src.geometries.size(); ++gi) {
      ModelGeometry& mg = s.blases[bi].geometries[gi];
      describeGeometry(mg, src.geometries[gi], bi, gi, tier,
                       tier == ModelTier::Exact ? ray_pad[bi] : 0.0, keep_triangles, filters,
                       s.aabbs_grown);
      if (mg.kind == Geometry::Kind::Aabbs && tier == ModelTier::Exact) mg.box_pad = box_pad[bi];
      if (mg.kind == Geometry::Kind::Triangles) s.blases[bi].triangles = true;
      any_own = any_own || mg.own_triangles;
    }
  }
  // Own triangle tests mean the collect-then-process path: Embree's triangles
  // report to it too, and their candidates need the per-primitive triangles.
  if (any_own && !filters) {
    filters = true;
    for (size_t bi = 0; bi < c.scene.blases.size(); ++bi)
      for (ModelGeometry& mg : s.blases[bi].geometries)
        if (mg.kind == Geometry::Kind::Triangles && mg.triangles.size() != mg.count)
          fillTriangles(mg, c.scene.blases[bi].geometries[mg.index]);
  }
  s.filters = filters;
  const RTCSceneFlags scene_flags =
      tier == ModelTier::Fast ? RTC_SCENE_FLAG_NONE : RTC_SCENE_FLAG_ROBUST;
  for (size_t bi = 0; bi < c.scene.blases.size(); ++bi) commitBlas(s, c, bi, scene_flags);
  commitInstances(s, c, scene_flags);
  return {};
}

}  // namespace rayspec
