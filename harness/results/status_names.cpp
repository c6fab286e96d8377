// The stable names of the typed statuses and reasons in results/results.h.
#include "results/results.h"

namespace rayspec {
namespace {

template <typename E, size_t N>
bool parseByName(const std::string& name, E* out, const E (&all)[N], const char* (*name_of)(E)) {
  for (E e : all)
    if (name == name_of(e)) {
      *out = e;
      return true;
    }
  return false;
}

}  // namespace

const char* sideStatusName(SideStatus s) {
  switch (s) {
    case SideStatus::Ok:
      return "ok";
    case SideStatus::NotSupported:
      return "NotSupported";
    case SideStatus::Crash:
      return "Crash";
    case SideStatus::Timeout:
      return "Timeout";
    case SideStatus::Refused:
      return "Refused";
    case SideStatus::InvalidShader:
      return "InvalidShader";
  }
  return "Crash";
}

bool parseSideStatus(const std::string& name, SideStatus* out) {
  static const SideStatus all[] = {SideStatus::Ok,      SideStatus::NotSupported,
                                   SideStatus::Crash,   SideStatus::Timeout,
                                   SideStatus::Refused, SideStatus::InvalidShader};
  return parseByName(name, out, all, sideStatusName);
}

std::string Results::statusText() const {
  if (status == SideStatus::Ok) return "ok";
  return std::string(sideStatusName(status)) + ": " + status_detail;
}

const char* ambiguityReasonName(AmbiguityReason r) {
  switch (r) {
    case AmbiguityReason::Edge:
      return "edge";
    case AmbiguityReason::Vertex:
      return "vertex";
    case AmbiguityReason::TmaxTie:
      return "tmax-tie";
    case AmbiguityReason::TminTie:
      return "tmin-tie";
    case AmbiguityReason::TTie:
      return "t-tie";
    case AmbiguityReason::FirstHit:
      return "first-hit";
    case AmbiguityReason::Order:
      return "order";
    case AmbiguityReason::AabbFace:
      return "aabb-face";
    case AmbiguityReason::ShaderArith:
      return "shader-arith";
  }
  return "edge";
}

bool parseAmbiguityReason(const std::string& name, AmbiguityReason* out) {
  static const AmbiguityReason all[] = {
      AmbiguityReason::Edge,    AmbiguityReason::Vertex,   AmbiguityReason::TmaxTie,
      AmbiguityReason::TminTie, AmbiguityReason::TTie,     AmbiguityReason::FirstHit,
      AmbiguityReason::Order,   AmbiguityReason::AabbFace, AmbiguityReason::ShaderArith};
  return parseByName(name, out, all, ambiguityReasonName);
}

const char* ruleForAmbiguity(AmbiguityReason r) {
  switch (r) {
    case AmbiguityReason::Edge:
    case AmbiguityReason::Vertex:
      return "R-WATERTIGHT";
    case AmbiguityReason::TmaxTie:
    case AmbiguityReason::TminTie:
    case AmbiguityReason::TTie:
      return "R-TIE";
    case AmbiguityReason::FirstHit:
      return "R-TOFH";
    case AmbiguityReason::Order:
      return "R-ORDER-UNSPEC";
    case AmbiguityReason::AabbFace:
      return "R-AABB-CONS";
    case AmbiguityReason::ShaderArith:
      return "R-PREC";
  }
  return "R-PREC";
}

const char* undefinedReasonName(UndefinedReason r) {
  switch (r) {
    case UndefinedReason::RayParameters:
      return "ray-parameters";
    case UndefinedReason::NanTriangle:
      return "nan-triangle";
    case UndefinedReason::HitRecordOutOfRange:
      return "hit-record-out-of-range";
    case UndefinedReason::MissRecordOutOfRange:
      return "miss-record-out-of-range";
    case UndefinedReason::CallableOutOfRange:
      return "callable-out-of-range";
    case UndefinedReason::DivisionByZero:
      return "division-by-zero";
    case UndefinedReason::RecursionTooDeep:
      return "recursion-too-deep";
    case UndefinedReason::PayloadType:
      return "payload-type";
    case UndefinedReason::NullShader:
      return "null-shader";
    case UndefinedReason::CallDataType:
      return "call-data-type";
  }
  return "ray-parameters";
}

bool parseUndefinedReason(const std::string& name, UndefinedReason* out) {
  static const UndefinedReason all[] = {
      UndefinedReason::RayParameters,       UndefinedReason::NanTriangle,
      UndefinedReason::HitRecordOutOfRange, UndefinedReason::MissRecordOutOfRange,
      UndefinedReason::CallableOutOfRange,  UndefinedReason::DivisionByZero,
      UndefinedReason::RecursionTooDeep,    UndefinedReason::PayloadType,
      UndefinedReason::NullShader,          UndefinedReason::CallDataType};
  return parseByName(name, out, all, undefinedReasonName);
}

}  // namespace rayspec
