// The stage vocabulary: what an any-hit, closest-hit, miss, intersection,
// callable or ray generation stage does, as a small typed tree. The Vulkan side
// turns it into GLSL (harness/glsl); the model interprets it (harness/model).
// The meaning of every node is defined here, once; both executions follow it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/enum_names.h"
#include "base/source_loc.h"
#include "program/builtin_table.h"
#include "program/op_table.h"
#include "program/sized_types.h"

namespace rayspec {

// clang-format off
#define RAYSPEC_STAGES(X)           \
  X(Raygen, "raygen")               \
  X(Miss, "miss")                   \
  X(ClosestHit, "closest_hit")      \
  X(AnyHit, "any_hit")              \
  X(Intersection, "intersection")   \
  X(Callable, "callable")
// clang-format on
enum class Stage { RAYSPEC_STAGES(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(Stage, RAYSPEC_STAGES);
inline const char* stageName(Stage s) {
  return nameOf(s);
}

// Value types of expressions. Bool only appears in conditions.
// Rows: X(ValueType, "name", "the case's spelling", components, "GLSL").
// clang-format off
#define RAYSPEC_VALUE_TYPES(X)                                      \
  X(Bool, "Bool", "bool", 1, "bool")                                \
  X(Uint, "Uint", "uint", 1, "uint")                                \
  X(Float, "Float", "float", 1, "float")                            \
  X(Vec2, "Vec2", "vec2", 2, "vec2")                                \
  X(Vec3, "Vec3", "vec3", 3, "vec3")                                \
  X(Vec4, "Vec4", "vec4", 4, "vec4")                                \
  RAYSPEC_SIZED_TYPES(RAYSPEC_SIZED_AS_VALUE_TYPE, X)              \
  RAYSPEC_VECTOR_ROWS(RAYSPEC_SIZED_VECTORS_AS_VALUE_TYPES, X)

// clang-format on
enum class ValueType { RAYSPEC_VALUE_TYPES(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(ValueType, RAYSPEC_VALUE_TYPES);
static_assert(
    static_cast<int>(ValueType::Float64Vec4) - static_cast<int>(ValueType::Int8Vec2) ==
            3 * (static_cast<int>(ValueType::Float64) - static_cast<int>(ValueType::Int8)) + 2 &&
        static_cast<int>(ValueType::Int8Vec2) == static_cast<int>(ValueType::Float64) + 1 &&
        static_cast<int>(ValueType::UintVec2) == static_cast<int>(ValueType::Float64Vec4) + 1,
    "the sized scalars, then their vectors (2, 3, 4 each) in the same order, then uint's");
inline const char* valueTypeName(ValueType t) {
  return nameOf(t);
}
const char* valueTypeSpelling(ValueType t);  // "bool", "uint", ..., "vec4", "int8", ...
const char* valueTypeGlsl(ValueType t);      // "bool", ..., "int8_t", ..., "float64_t"
int componentCount(ValueType t);             // Bool/Uint/Float 1, Vec2 2, I8Vec3 3, ...

// A sized scalar's row of RAYSPEC_SIZED_TYPES.
enum class SizedKind : uint8_t { Signed, Unsigned, Floating };
struct SizedType {
  ValueType type;
  int bits;
  SizedKind kind;
  const char* extension;  // the #extension its GLSL needs
  const char* feature;    // the device feature (NotSupported names it)
};
// Its row (a sized vector's: its component's; uvec2 .. uvec4: uint's row of
// RAYSPEC_UINT_VECTORS), or null for Bool, Uint, Float and Vec2..Vec4.
const SizedType* sizedType(ValueType t);
inline bool isSized(ValueType t) {  // a sized scalar or a sized vector (uvecs included)
  return sizedType(t) != nullptr;
}
bool isSizedVector(ValueType t);  // i8vec2 .. f64vec4, uvec2 .. uvec4
inline bool isSizedScalar(ValueType t) {
  return isSized(t) && !isSizedVector(t);
}
bool isSizedInteger(ValueType t);  // int8 .. uint64, scalar or vector
bool isSizedFloat(ValueType t);    // float16, float64, scalar or vector
// A sized vector's component type (Int8 for Int8Vec3, Uint for UintVec3); any
// other type itself.
ValueType sizedComponent(ValueType t);
// The sized scalar s's (or Uint's) vector of n (2..4) components.
ValueType sizedVectorOf(ValueType s, int n);
// The spellings of the types an array may hold, joined by ", " (messages).
std::string arrayTypeSpellings();

// An expression, written in YAML as
//   a number            -> literal (Uint if written without '.', 'e', or sign
//                          and >= 0; otherwise Float), or a list of 2..4
//                          numbers -> Vec2/Vec3/Vec4 literal;
//   true / false        -> Bool literal;
//   a built-in name     -> Builtin (see builtins.h: "primitive_id", "hit_t",
//                          "payload.color", ...);
//   {op: arg} / {op: [args]} -> Op (see ops.h: add, eq, odd, sphere_near, ...).
struct Expr {
  // Local: `var.NAME`, Constant: `const.NAME` (a specialization constant),
  // RecordMember: `shader_record.NAME` (a member of the shader record block,
  // pipeline.sbt.record_layout); name NAME.
  enum class Kind { Literal, Builtin, Op, Local, Constant, RecordMember };
  Kind kind = Kind::Literal;
  ValueType type = ValueType::Uint;  // filled by the type checker
  std::vector<double> literal;       // Literal: 1..4 components
  // Literal: an integer over 32 bits written in the case, exactly (literal[0]
  // holds it rounded); only an int64 or uint64 place takes one. 0: none.
  uint64_t wide = 0;
  std::string name;              // Builtin or Op: its spelling (for messages)
  Op op = Op::None;              // Op: the operator the name spells, resolved once by
                                 // the parser (or opExpr / setOp in program/ops.h)
  Builtin builtin = kBiUnknown;  // Builtin: the row the name reads, resolved once by
                                 // the parser (or builtinExpr / setBuiltin in
                                 // program/builtins.h)
  uint32_t word = 0;             // Builtin of a word<i> family (payload.word3): i
  std::vector<Expr> args;        // Op arguments
  SourceLoc loc;
};

// The arguments of a traceRayEXT call. Every field is optional: an empty Expr
// list means "take it from the case's ray for this launch" in raygen, and is an
// error elsewhere for origin/direction; flags/cull_mask/sbt_* /miss/tmin/tmax
// default to the case's ray defaults (rays.defaults) outside raygen.
struct TraceArgs {
  std::vector<Expr> origin, direction, tmin, tmax;  // 0 or 1 element each
  std::vector<Expr> flags, cull_mask, sbt_offset, sbt_stride, miss;
  uint32_t tlas = 0;  // which top level (a constant: Instance::tlas)
  // ... or 0 or 1 Uint expressions: the top level of index tlas_index % the
  // scene's top levels (a dynamically indexed descriptor array, nonuniformEXT).
  std::vector<Expr> tlas_index;
  SourceLoc tlas_loc;
  uint32_t location = 0;  // the payload location passed (a constant: Pipeline::payload_words)
  SourceLoc location_loc;
  // Trace: `hit_object: true`, hitObjectTraceRayNV into the stage's hit object
  // (GL_NV_shader_invocation_reorder): any-hit and intersection run, closest-hit
  // and miss do not; `execute` runs them later.
  bool hit_object = false;
};

struct Stmt {
  enum class Kind {
    Count,       // counter += 1 (global, atomic), name in `counter`
    Record,      // per-ray record fields of this launch: assigns[i] = (field, value)
    SetPayload,  // incoming payload (hit/miss/any-hit) fields: "color", "value", "word<i>"
    SetCall,     // incoming callable data (callable stage): "color", "value"
    Ignore,      // ignoreIntersectionEXT (any-hit only)
    Terminate,   // terminateRayEXT (any-hit only)
    Report,      // reportIntersectionEXT(t, kind) (intersection only);
                 // then_ runs if it returned true, else_ if false
    Trace,       // traceRayEXT with `trace`, the payload starting as `assigns`
                 // ("color", "value"; zero where not given) evaluated before
                 // the trace; the result readable as child.* (payload.* in raygen)
    Call,        // executeCallableEXT(call_index) with data fields `assigns`
                 // ("position", "normal", "value", "color"); result as callee.*
    Light,       // callable only: call.color = light_<light>(call.position,
                 // call.normal, shader record floats) from shaders/lights.glsl
    // Ray queries (GLSL_EXT_ray_query, cases/README.md "Ray queries"):
    RayQuery,        // rayQueryInitializeEXT with `trace` (origin .. cull_mask, tlas),
                     // then while rayQueryProceedEXT: a triangle candidate runs
                     // then_[0]'s body, an AABB candidate then_[1]'s; else_ runs
                     // after the loop ("after"). Its getters read the innermost query.
    Candidates,      // a RayQuery's candidate block: size 0 triangles, 1 AABBs; body in then_
    Confirm,         // rayQueryConfirmIntersectionEXT (a triangle block)
    Generate,        // rayQueryGenerateIntersectionEXT(t) (an AABB block)
    TerminateQuery,  // rayQueryTerminateEXT (a candidate block)
    RayQueries,      // ray_queries: the RayQuery statements in then_, all alive at once
                     // (one GLSL array of rayQueryEXT): each initialized in order, then
                     // stepped in turn (one rayQueryProceedEXT each, its block for its
                     // candidate) until all are done, then each one's `after` in order
    RestartQuery,    // restart_query: rayQueryInitializeEXT of the innermost query with
                     // `trace` (a candidate block; the block ends, the loop goes on
                     // with the new ray: nothing committed)
    // Hit objects (GL_NV_shader_invocation_reorder, cases/README.md "Hit objects"):
    // each stage that uses them holds one, empty at its start.
    ExecuteHitObject,  // hitObjectExecuteShaderNV: the hit object's closest-hit or miss runs
                       // with the payload (location `trace.location`) starting as `assigns`
                       // (as a trace's); the result readable as a trace's
    RecordMiss,        // hitObjectRecordMissNV: miss index `trace.miss`, the ray of `trace`
                       // (origin, direction, tmin, tmax; defaulted as a trace's)
    RecordEmpty,       // hitObjectRecordEmptyNV
    RecordHit,         // hitObjectRecordHitNV (size 0: SBT record of the instance's offset and
                       // `trace.sbt_offset` / `sbt_stride`) or hitObjectRecordHitWithIndexNV
                       // (size 1: the record index given): assigns "instance", "primitive",
                       // "geometry", "hit_kind", "attributes" (a Vec2) and, size 1,
                       // "sbt_index"; the ray of `trace` (program/hit_object.h)
    Reorder,           // reorderThreadNV: with the hit object when `size` is 1, with the
                       // assigns ("hint", "bits": the hint and how many of its low bits
                       // count) when given (raygen only)
    If,                // if (cond) then_ else else_
    // Control flow and local variables (cases/README.md, "Control flow"); kept
    // last: the model's compiler tells them by order (Kind >= Let).
    Let,       // declare locals: assigns[i] = (name, initial value)
    Set,       // assign declared locals: assigns[i] = (name, value)
    Array,     // declare `local`: an array of `size` elements of `local_type`, all zero
    Store,     // local[index % size] = assigns[0].second
    Struct,    // declare `local`: a struct of the members `params` (name, type), each
               // zero; a member is the local `local.member` (set: {s.a: ..}, var.s.a)
    Repeat,    // for k in 0 .. min(count, kMaxLoopTrips)-1: local := from + k; then_
    Break,     // leave the innermost repeat
    Continue,  // next iteration of the innermost repeat
    Switch,    // switch (cond): then_ holds Case statements, else_ the default
    Case,      // one label of a switch (`size`), its body in then_
    Invoke,    // call function `local` with arguments assigns (params' order); the
               // function's body, copied at parse time, in then_
    Return,    // leave the function (in a stage's own program: end the stage)
  };
  Kind kind = Kind::Count;
  std::string counter;                                // Count
  std::vector<std::pair<std::string, Expr>> assigns;  // Record/SetPayload/SetCall/Call/Trace
  Expr cond;                                          // If
  Expr t, hit_kind;                                   // Report; Generate: t
  std::vector<Expr> attribute;                        // Report: optional Vec2 hit
                                                      // attribute; vec2(0) when absent
  Expr call_index;                                    // Call
  uint32_t call_location = 0;  // Call: the callable data location passed (a constant:
                               // Pipeline::call_data_words)
  SourceLoc call_location_loc;
  std::string light;  // Light: point|spot|directional
  TraceArgs trace;    // Trace; RayQuery, RestartQuery (origin .. cull_mask, tlas)
  std::string local;  // Array, Store: the array; Repeat: its variable (optional);
                      // Invoke: the function
  ValueType local_type = ValueType::Uint;  // Array: the element type
  uint32_t size = 0;        // Array: elements; Case: the label; RayQuery: 1 when declared
                            // order_dependent (model/order_dependence.h)
  Expr count, from, index;  // Repeat: trip count, first value; Store: index
  std::vector<std::pair<std::string, ValueType>> params;  // Invoke: the function's parameters;
                                                          // Struct: its members
  bool query_param = false;  // Invoke: the function takes the caller's innermost ray query
                             // (pipeline.functions' `query: true`; GLSL: a rayQueryEXT parameter)
  std::vector<Stmt> then_, else_;  // If, Report, Repeat (body), Switch (cases, default),
                                   // Case and Invoke (body)
  SourceLoc loc;
};

using Program = std::vector<Stmt>;

// A specialization constant (pipeline.constants): constant_id is its index;
// its value in a shader is pipeline.specialize's for that shader, else this
// default. Uint, Float or Bool.
struct SpecConstant {
  std::string name;
  ValueType type = ValueType::Uint;
  double value = 0;
  SourceLoc loc;
};

// The shader record block's members (pipeline.sbt.record_layout), in the
// order declared, each Uint, Float or a vector, at the byte offset the block's
// layout gives it (std430 or scalar; shader_record_layout.h lays them out).
struct RecordMember {
  std::string name;
  ValueType type = ValueType::Uint;
  uint32_t offset = 0;
  SourceLoc loc;
};
struct ShaderRecordLayout {
  bool scalar = false;  // GL_EXT_scalar_block_layout's scalar, else std430
  std::vector<RecordMember> members;
  uint32_t bytes = 0;  // the end of the last member
  bool declared() const { return !members.empty(); }
  const RecordMember* find(const std::string& name) const {
    for (const RecordMember& m : members)
      if (m.name == name) return &m;
    return nullptr;
  }
};

// Bounds of the control-flow vocabulary, the same on both sides: a repeat runs
// at most kMaxLoopTrips times (a larger count is clamped), an array holds at
// most kMaxArrayElements, functions nest at most kMaxFunctionNesting deep.
constexpr uint32_t kMaxLoopTrips = 1024;
constexpr uint32_t kMaxArrayElements = 128;
constexpr uint32_t kMaxFunctionNesting = 8;
// A struct local holds 1 to this many members.
constexpr uint32_t kMaxStructMembers = 16;
// ray_query statements nest at most this deep (one GLSL query variable each).
constexpr uint32_t kMaxQueryNesting = 4;
// A ray_queries statement steps 2 to this many queries in turn.
constexpr uint32_t kMaxSteppedQueries = 8;
// A query restarts (restart_query) at most this many times in one run of its
// ray_query; a further restart_query does nothing on both sides (the GLSL
// counts them) and the model names it a case error (endless restarts).
constexpr uint32_t kMaxQueryRestarts = 8;

}  // namespace rayspec
