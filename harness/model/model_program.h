// Stage programs compiled once per run into the form the model's interpreter
// executes: every name (built-in, op, counter, record field, payload / call
// data field, light) resolved to a number, literals pre-converted, so that the
// hot path compares no strings and allocates nothing.
#pragma once

#include <array>
#include <bit>
#include <bitset>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "case/case.h"
#include "plan/plan.h"
#include "program/builtins.h"
#include "program/ops.h"

namespace rayspec {

struct Val {
  std::array<float, 4> f{};
  // A sized scalar or vector (program/sized_types.h), one component a lane:
  // an integer's value wrapped to its type (program/sized_values.h,
  // wrapToType), a float16's or float64's value as a double's bits.
  std::array<uint64_t, 4> x{};
  uint32_t u = 0;
  bool b = false;
  ValueType sized = ValueType::Bool;  // the sized type x holds (Bool: none), scalar or vector
};

// The sized members a payload, callable data or hit attribute holds
// (program/payload_words.h SizedMembers): each member's lanes (Val::x)
// under its type, in the order written. A member never written reads zero,
// as the GLSL's zeroed members do.
struct SizedSlots {
  std::vector<std::pair<ValueType, std::array<uint64_t, 4>>> members;
  Val read(ValueType t) const {
    Val v;
    v.sized = t;
    for (const auto& [type, lanes] : members)
      if (type == t) v.x = lanes;
    return v;
  }
  void write(ValueType t, const Val& v) {
    for (auto& [type, lanes] : members)
      if (type == t) {
        lanes = v.x;
        return;
      }
    members.emplace_back(t, v.x);
  }
  bool operator==(const SizedSlots&) const = default;
};

inline Val fromVec3(const Vec3& v) {
  Val r;
  r.f = {v[0], v[1], v[2], 0};
  return r;
}
inline Val fromVec4(const std::array<float, 4>& v) {
  Val r;
  r.f = v;
  return r;
}
inline Val fromUint(uint32_t u) {
  Val r;
  r.u = u;
  return r;
}
inline Val fromFloat(float f) {
  Val r;
  r.f[0] = f;
  return r;
}

inline Val fromSized(ValueType t, uint64_t x) {
  Val r;
  r.x[0] = x;
  r.sized = t;
  return r;
}
inline Val fromSizedDouble(ValueType t, double d) {
  return fromSized(t, std::bit_cast<uint64_t>(d));
}
inline double sizedDouble(const Val& v, int lane = 0) {
  return std::bit_cast<double>(v.x[static_cast<size_t>(lane)]);
}

struct CExpr {
  Expr::Kind kind = Expr::Kind::Literal;
  ValueType type = ValueType::Uint;
  uint8_t builtin = kBiUnknown;  // Builtin
  Op op = Op::None;              // Op
  uint32_t index = 0;  // RecordUint/RecordFloat: word; payload/child word; Local: its (first)
                       // slot in the frame
  uint32_t size = 0;   // Local: an array's elements (0: a scalar)
  Val literal;         // Literal
  std::vector<CExpr> args;
  const Expr* src = nullptr;  // for error messages
};

// Sized: a sized member (program/payload_words.h SizedMembers), its type in `word`.
enum class Slot : uint8_t { Color, Value, Position, Normal, Word, Sized, None };
enum class LightKind : uint8_t { Point, Spot, Directional };

struct CAssign {
  int field = -1;  // Record: record field index (-1: unknown or automatic); Let/Set: the slot
  Slot slot = Slot::None;  // SetPayload / SetCall / Call
  uint8_t word = 0;        // Slot::Word: which payload word; Slot::Sized: the member's ValueType
  CExpr value;
};

struct CStmt {
  Stmt::Kind kind = Stmt::Kind::Count;
  int counter = -1;  // Count: index in plan.counters (-1: not kept)
  std::vector<CAssign> assigns;
  CExpr cond, t, hit_kind, call_index;
  bool has_attribute = false;
  CExpr attribute;
  LightKind light = LightKind::Point;
  // Trace: 10 optional arguments (origin, direction, tmin, tmax, flags,
  // cull_mask, sbt_offset, sbt_stride, miss, the top level's index).
  enum {
    kOrigin,
    kDirection,
    kTmin,
    kTmax,
    kFlags,
    kCullMask,
    kSbtOffset,
    kSbtStride,
    kMiss,
    kTlas,  // TraceArgs::tlas_index
    kTraceArgs
  };
  std::array<bool, kTraceArgs> has{};
  std::array<CExpr, kTraceArgs> args;
  // Control flow: Array/Store/Repeat: the local's slot (Repeat: -1 without a
  // variable); Array/Store: elements; Case: the label; Invoke: the frame's slots;
  // RayQuery: 1 when its candidate blocks hold terminate_query.
  int slot = -1;
  uint32_t size = 0;
  CExpr count, from, index;  // Repeat, Store
  // Store to payload.words / call.words (size: its words); nullopt: to a local.
  std::optional<WordArray> words;
  std::vector<CStmt> then_, else_;
  const Stmt* src = nullptr;  // for the case field a diagnosis names
  // RayQuery: its candidate blocks may depend on the order candidates
  // arrive in (model/order_dependence.h); RayQueries: its queries' blocks
  // share what they read or write (steppedQueriesShare), so the interleaving
  // of their candidates may decide.
  bool order_dependent = false;
};

using CProgram = std::vector<CStmt>;

// A program of nothing but `count` statements: the counters it bumps (a
// closest-hit or miss like that runs without a stage environment).
struct CountsOnly {
  bool yes = false;
  std::vector<int> counters;  // kept counters only
};
CountsOnly countsOnly(const CProgram& p);
// The counters the `count` statements a program starts with bump (kept
// counters only, once per statement): every run of it bumps each so, whatever
// it does next (model/counter_floors.cpp).
std::vector<int> leadingCounts(const CProgram& p);
// An intersection program's leading report: the first statement after its
// leading counts, when a report whose t reads nothing an order decides (no
// ray_tmax): every run of the program makes it at one t (counter_floors.cpp);
// null otherwise.
const CStmt* leadingReport(const CProgram& p);
// Whether a ray_query's candidate blocks (its then_) may end or restart its
// traversal early: a break, return, terminate_query or restart_query anywhere
// in them (conservative: a break inside a repeat only leaves the repeat).
bool queryBlocksMayEnd(const CStmt& query);

struct CHitGroup {
  const CProgram* closest_hit = nullptr;
  const CProgram* any_hit = nullptr;
  const CProgram* intersection = nullptr;
  CountsOnly closest_hit_counts;
  std::vector<int> any_hit_leading, intersection_leading;  // leadingCounts of each
  const CStmt* leading_report = nullptr;                   // leadingReport(*intersection)
  bool any_hit_terminates = false;  // the any-hit has a `terminate` (R-ORDER-UNSPEC)
  uint32_t payload = 0;             // HitGroup::payload: the location whose type it takes
};
// Does the program hold a `terminate` statement (at any nesting)?
bool hasTerminate(const CProgram& p);

struct CPipeline {
  CProgram raygen;
  std::vector<CProgram> miss, callables;
  std::vector<CountsOnly> miss_counts;
  std::vector<CProgram> hit_programs;  // storage for the groups' programs
  std::vector<CHitGroup> groups;
  std::bitset<kBiCount> read_bits;  // every built-in any program reads
  BuiltinNeeds needs = 0;           // every need of the built-ins read (program/builtins.h)
  bool reads_sphere = false;        // sphere_* ops (read the object-space ray and the box)
  // A built-in a hit on a triangle the ray runs in the plane of leaves free
  // (ModelCandidate::in_plane: its t anywhere across the triangle, either
  // face; isInPlaneFree) is read other than straight into its own record
  // field of bounded t (hit_t, ray_tmax, hit_position: a replay's record
  // holds those to the ray's t bound): such a ray keeps no replays.
  bool reads_in_plane_free = false;
  // The hit's t or what follows from it (hit_t, ray_tmax, hit_position, a
  // query's t) is read other than straight into its own record field: a
  // ray whose t a device may round past hit_t's tolerance (a sphere root
  // from a far origin, TraceClassifier::noteRootTFree) keeps no replays.
  bool reads_root_t_free = false;
  bool any_hit_terminates = false;  // some group's any-hit has a `terminate`
  // Its any-hit or intersection programs may depend on the order candidates
  // arrive in (model/order_dependence.h).
  bool order_dependent = false;
  bool order_ties_only = false;  // only through reports that tie (OrderDependence::ties_only)
  bool reads(Builtin b) const { return read_bits.test(b); }
};

CPipeline compilePipeline(const Case& c, const Plan& plan);

}  // namespace rayspec
