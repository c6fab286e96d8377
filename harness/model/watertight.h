// Watertight ray/triangle test in double precision (after Woop, Benthin and
// Wald 2013), with an error bound that says whether the decision could flip
// under the float arithmetic a device uses (then the ray is ambiguous).
//
// The bound lives in the translated frame a device computes in: the vertices
// relative to the ray origin (v - o), sheared so the ray runs along z. A
// device rounds each of those differences once, then the shear and the edge
// functions, each relative to its own (translated) magnitude: so the bound
// grows with |v - o| and the edge functions' products, never with the
// absolute coordinates (a triangle at 1e6 seen from nearby is as clear as one
// at the origin). On top come the errors of the device's own view of the
// ray and the vertices (FrameError): the object-space ray a device derives
// from the world ray and the instance transform (model/instance_ray_error.h)
// and the vertices a device derives from a geometry transform.
//
// With, per vertex j, a_j = v_j - o, the shear S = (-d_x/d_z, -d_y/d_z),
// p_j = (a_jx + S_x a_jz, a_jy + S_y a_jz) and the edge function of the edge
// (a, b) e = p_ax p_by - p_ay p_bx, a device's e differs from the model's by
// at most
//   bound = D_x |p_by - p_ay| + D_y |p_bx - p_ax|              (common shift)
//         + |p_ax| E_by + |p_by| E_ax + |p_ay| E_bx + |p_bx| E_ay
//         + D_x (E_ay + E_by) + D_y (E_ax + E_bx) + E_ax E_by + E_ay E_bx
//         + r ((|p_ax| + D_x + E_ax)(|p_by| + D_y + E_by) + (|p_ay| + D_y + E_ay)(|p_bx| + D_x +
//         E_bx))
// where D = the device's origin error carried through the shear (the same
// for the three vertices: it moves the triangle rigidly, so it enters with
// the edge's own extent, exactly), E_j = the per-vertex error (the rounding
// r of v - o and of the shear, the vertex error, the shear's error from the
// direction error times |a_jz|), and r = kFrameRoundings * 2^-24 (a few
// roundings per quantity, with room for other orderings of the same
// arithmetic, such as Moller-Trumbore's).
#pragma once

#include <array>
#include <cstdint>

#include "base/float_steps.h"
#include "base/vec3.h"

namespace rayspec {

enum class TriAmbiguity { None, Edge, Vertex, Degenerate };

struct WatertightHit {
  bool hit = false;  // the double-precision decision (an edge exactly hit: a perturbation decides,
                     // watertight.cpp)
  double t = 0, b1 = 0, b2 = 0;                 // barycentrics: weights of v1 and v2
  TriAmbiguity ambiguity = TriAmbiguity::None;  // near an edge / vertex
  // Bit i: the edge from vertex (i + 1) % 3 to vertex (i + 2) % 3 within its
  // bound (set with `ambiguity`): which edge or vertex the ray is near.
  uint8_t near_edges = 0;
  bool valid = true;  // false: NaN somewhere (never a hit)
  // How far a device's t may lie from `t` (same frame: each vertex's depth
  // error, and the edge functions' errors weighted by how far each vertex's
  // depth lies from t); 0 when there is no t (zero determinant).
  double t_err = 0;
  // A determinant of 0, or within its bound (nearlyInPlane, watertight.cpp)
  // with the line near the plane (lineNearPlane, in_plane.h), with every
  // edge function within its bound; or a determinant within its
  // bound with edge functions clearly of both signs (a device may hit it all
  // the same): the ray's line lies in the triangle's plane, to rounding (no
  // one t, and `hit` false: in_plane.h).
  bool in_plane = false;
};

// Per component, how far a device's object-space ray and vertices may lie
// from the model's (absolute bounds; zero: the device sees exactly them).
struct FrameError {
  DVec3 origin{}, direction{}, vertex{};
};

// Relative tolerance of a device's float pipeline for quantities outside the
// translated frame (t ties, AABB faces): 16 * 2^-24.
constexpr double kDeviceRelTolerance = 16.0 * kUnitRoundoff;
// Roundings a device's translated, sheared quantities and edge functions
// carry (in units of 2^-24).
constexpr double kFrameRoundings = 4.0;

WatertightHit watertightIntersect(const DVec3& o, const DVec3& d, const DVec3& v0, const DVec3& v1,
                                  const DVec3& v2, const FrameError& err = {});

// The part of the test that depends only on the object-space ray and the
// device's error of it (FrameError's origin and direction; the vertex part is
// the geometry's, given per call): the dominant axis, the shear and its
// error. The model computes it once per (ray, instance) (model_scene.cpp);
// the split changes no value: watertightIntersect(o, d, ...) is
// watertightIntersectPrepared(prepareWatertightRay(o, d, err), ..., err.vertex).
struct WatertightRay {
  DVec3 o{}, d{};
  DVec3 origin_err{}, direction_err{};
  bool valid = false;  // false: zero or NaN direction (never a hit)
  int kx = 0, ky = 0, kz = 0;
  double sx = 0, sy = 0, sz = 0;
  double dsx = 0, dsy = 0;          // the shear a device derives from its own direction
  double shift_x = 0, shift_y = 0;  // the device's origin error, sheared
  double dir_err = 0;               // relative error of the depth scale
};
WatertightRay prepareWatertightRay(const DVec3& o, const DVec3& d, const FrameError& err);
WatertightHit watertightIntersectPrepared(const WatertightRay& ray, const DVec3& v0,
                                          const DVec3& v1, const DVec3& v2,
                                          const DVec3& vertex_err);

}  // namespace rayspec
