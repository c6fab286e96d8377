// Why a ray's behaviour is undefined by the specification (R-UB), on its own:
// the case parser names the reason where it finds it, results carry it.
#pragma once

#include <string>

#include "base/enum_names.h"

namespace rayspec {

// Such rays are never judged; the device only has to survive them.
#define RAYSPEC_UNDEFINED_REASONS(X)                                                 \
  /* non-finite origin/direction, NaN, tmin < 0, tmax < tmin */                      \
  X(RayParameters, "ray-parameters")                                                 \
  /* a candidate triangle has NaN in Y or Z (not X: that one is inactive) */         \
  X(NanTriangle, "nan-triangle")                                                     \
  X(HitRecordOutOfRange, "hit-record-out-of-range")                                  \
  X(MissRecordOutOfRange, "miss-record-out-of-range")                                \
  X(CallableOutOfRange, "callable-out-of-range")                                     \
  /* integer division or modulo by zero in a stage program */                        \
  X(DivisionByZero, "division-by-zero")                                              \
  /* traceRay beyond max_recursion, or callables nested too deeply */                \
  X(RecursionTooDeep, "recursion-too-deep")                                          \
  /* the shader reached declares another incoming payload type than the trace's */   \
  X(PayloadType, "payload-type")                                                     \
  /* a NO_NULL_*_SHADERS pipeline reaches an all-zero record for that shader */      \
  X(NullShader, "null-shader")                                                       \
  /* the callable reached declares another incoming data type than the call's */     \
  X(CallDataType, "call-data-type")                                                  \
  /* rayQueryGenerateIntersectionEXT at a t outside [tmin, committed t] */           \
  X(GenerateOutsideInterval, "generate-outside-interval")                            \
  /* a ray query's committed value read with nothing committed */                    \
  X(QueryNothingCommitted, "query-nothing-committed")                                \
  /* a ray query's vertex positions read of a box (a candidate or committed AABB) */ \
  X(QueryPositionsOfBox, "query-positions-of-box")                                   \
  /* a hit recorded by hand (hitObjectRecordHitNV) of an instance, geometry or */    \
  /* primitive outside the top level, or by an SBT record index of 16 or more */     \
  X(HitObjectRecordOutsideScene, "hit-object-record-outside-scene")
enum class UndefinedReason { RAYSPEC_UNDEFINED_REASONS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(UndefinedReason, RAYSPEC_UNDEFINED_REASONS);
inline const char* undefinedReasonName(UndefinedReason r) {
  return nameOf(r);
}
inline bool parseUndefinedReason(const std::string& name, UndefinedReason* out) {
  return parseEnumName(name, out);
}

}  // namespace rayspec
