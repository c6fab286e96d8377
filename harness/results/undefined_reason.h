// Why a ray's behaviour is undefined by the specification (R-UB), on its own:
// the case parser names the reason where it finds it, results carry it.
#pragma once

#include <string>

namespace rayspec {

// Such rays are never judged; the device only has to survive them.
enum class UndefinedReason {
  RayParameters,  // non-finite origin/direction, NaN, tmin < 0, tmax < tmin
  NanTriangle,    // a candidate triangle has NaN in Y or Z (not X: that one is inactive)
  HitRecordOutOfRange,
  MissRecordOutOfRange,
  CallableOutOfRange,
  DivisionByZero,    // integer division or modulo by zero in a stage program
  RecursionTooDeep,  // traceRay beyond max_recursion, or callables nested too deeply
  PayloadType,       // the shader reached declares another incoming payload type than the trace's
  NullShader,        // a NO_NULL_*_SHADERS pipeline reaches an all-zero record for that shader
  CallDataType,      // the callable reached declares another incoming data type than the call's
};
const char* undefinedReasonName(UndefinedReason r);
bool parseUndefinedReason(const std::string& name, UndefinedReason* out);

}  // namespace rayspec
