// Undefined behaviour the model diagnoses (R-UB; results/results.h,
// UndefinedReason). A diagnosis marks the current launch ray once, with the
// first reason and the case field at fault; the model never judges such a ray
// and goes on in a defined way, documented where each is found:
//   RayParameters        trace(): no candidate, a miss
//   NanTriangle          the triangle is never a hit (model_scene.cpp)
//   HitRecordOutOfRange  no shader of that record runs
//   MissRecordOutOfRange no miss shader runs
//   CallableOutOfRange   the call is skipped (stage_interpreter.cpp)
//   DivisionByZero       uint a / 0 = 0xFFFFFFFF, a % 0 = 0
//   RecursionTooDeep     the trace or call is skipped
//   PayloadType          the shader runs on the trace's payload as it is
//   NullShader           no shader runs (as for any all-zero record)
//   CallDataType         the callable runs on the call's data as it is
#include <cmath>
#include <cstdio>
#include <string>

#include "case/flag_names.h"
#include "model/launch_state.h"

namespace rayspec {

namespace {

std::string fieldOf(const CStmt* site, const char* fallback) {
  return site && site->src && !site->src->loc.field.empty() ? site->src->loc.field
                                                            : std::string(fallback);
}

std::string num(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

std::string vec(const Vec3& v) {
  return "(" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + ")";
}

bool finite(const Vec3& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

const char* rayFlagName(uint32_t bit) {
  for (const auto& [name, value] : rayFlagNames())
    if (value == bit) return name;
  return "?";
}

// Two flags of a group of mutually exclusive ray flags, or none.
std::string exclusiveFlags(uint32_t flags) {
  const uint32_t groups[][4] = {
      {kRayOpaque, kRayNoOpaque, kRayCullOpaque, kRayCullNoOpaque},  // R-CULL-OPQ
      {kRayCullBackFacing, kRayCullFrontFacing, 0, 0},               // R-FACE-CULL
      {kRaySkipTriangles, kRaySkipAabbs, 0, 0},                      // R-SKIP-TRI / R-SKIP-AABB
      {kRaySkipTriangles, kRayCullBackFacing, 0, 0},
      {kRaySkipTriangles, kRayCullFrontFacing, 0, 0},
  };
  for (const auto& g : groups) {
    uint32_t first = 0;
    for (uint32_t bit : g) {
      if (!bit || !(flags & bit)) continue;
      if (first) return std::string(rayFlagName(first)) + " and " + rayFlagName(bit) + " together";
      first = bit;
    }
  }
  return {};
}

// The first undefined parameter of a ray: which trace argument, and why.
struct RayProblem {
  int arg = -1;  // CStmt::kOrigin ...; -1: none
  std::string why;
};

RayProblem rayProblem(const TraceRay& r) {
  if (!finite(r.origin)) return {CStmt::kOrigin, vec(r.origin) + " is not finite"};
  if (!finite(r.direction)) return {CStmt::kDirection, vec(r.direction) + " is not finite"};
  if (std::isnan(r.tmin)) return {CStmt::kTmin, "NaN"};
  if (std::isnan(r.tmax)) return {CStmt::kTmax, "NaN"};
  if (r.tmin < 0) return {CStmt::kTmin, num(r.tmin) + " < 0"};
  if (r.tmax < r.tmin) return {CStmt::kTmax, num(r.tmax) + " < tmin " + num(r.tmin)};
  if (std::string both = exclusiveFlags(r.flags); !both.empty()) return {CStmt::kFlags, both};
  return {};
}

const char* const kTraceArgNames[CStmt::kTraceArgs] = {
    "origin",    "direction",  "tmin",       "tmax", "flags",
    "cull_mask", "sbt_offset", "sbt_stride", "miss", "tlas"};

// The common case, without building a message: every parameter defined.
bool defined(const TraceRay& r) {
  const uint32_t opacity =
      r.flags & (kRayOpaque | kRayNoOpaque | kRayCullOpaque | kRayCullNoOpaque);
  const uint32_t facing = r.flags & (kRayCullBackFacing | kRayCullFrontFacing);
  const uint32_t skip = r.flags & (kRaySkipTriangles | kRaySkipAabbs);
  return finite(r.origin) && finite(r.direction) && r.tmin >= 0 && r.tmin <= r.tmax &&
         (opacity & (opacity - 1)) == 0 && (facing & (facing - 1)) == 0 &&
         (skip & (skip - 1)) == 0 && !(facing && (skip & kRaySkipTriangles));
}

}  // namespace

void LaunchState::markUndefined(UndefinedReason why, std::string what) {
  if (ray_undefined) return;
  ray_undefined = true;
  undefined.push_back({index, why, std::move(what)});
}

bool LaunchState::checkRayParameters(const TraceRay& r, const CStmt* site, uint32_t depth) {
  if (defined(r)) return false;
  const RayProblem p = rayProblem(r);
  if (p.arg < 0) return false;
  if (ray_undefined) return true;
  std::string where;
  if (site && site->has[p.arg])
    where = fieldOf(site, "trace") + "." + kTraceArgNames[p.arg];
  else if (depth == 1)  // raygen's trace of the launch ray's own parameter
    where = "rays: launch ray " + std::to_string(index) + " " + kTraceArgNames[p.arg];
  else  // a nested trace takes the rays defaults
    where = std::string("rays.") + kTraceArgNames[p.arg] + " (the default of " +
            fieldOf(site, "a nested trace") + ")";
  markUndefined(UndefinedReason::RayParameters, where + ": " + p.why);
  return true;
}

void LaunchState::hitRecordOutOfRange(uint32_t instance, uint32_t geometry, const TraceRay& r) {
  const Instance& inst = sh_.c->scene.instances[instance];
  markUndefined(UndefinedReason::HitRecordOutOfRange,
                "pipeline.sbt.hit: record " + std::to_string(sbt_.hitIndex(instance, geometry, r)) +
                    ", the hit region has " + std::to_string(sbt_.hitCount()) + " (instance " +
                    std::to_string(instance) + " sbt_offset " +
                    std::to_string(inst.sbt_offset & kInstanceFieldMask) + " + geometry " +
                    std::to_string(geometry) + " x stride " +
                    std::to_string(r.sbt_stride & kTraceSbtFieldMask) + " + sbt_offset " +
                    std::to_string(r.sbt_offset & kTraceSbtFieldMask) + ")");
}

void LaunchState::missRecordOutOfRange(const TraceRay& r) {
  markUndefined(UndefinedReason::MissRecordOutOfRange,
                "pipeline.sbt.miss: miss index " + std::to_string(r.miss & kTraceMissIndexMask) +
                    ", the miss region has " + std::to_string(sbt_.miss().size()));
}

void LaunchState::payloadTypeDiffers(const Payload& p, uint32_t shader_location, const char* list,
                                     uint32_t index, const char* stage) {
  const Pipeline& pipe = sh_.c->pipeline;
  const std::string shader = std::string(list) + "[" + std::to_string(index) + "]" + stage;
  if (pipe.payloadWords(p.location) == pipe.payloadWords(shader_location) &&
      pipe.payloadSized(p.location) == pipe.payloadSized(shader_location))
    return;
  auto type_of = [&](uint32_t location) {
    const size_t sized = pipe.payloadSized(location).size();
    return std::to_string(pipe.payloadWords(location)) + " words" +
           (sized ? ", " + std::to_string(sized) + " sized members" : std::string());
  };
  markUndefined(UndefinedReason::PayloadType,
                shader + ": its incoming payload has the type of location " +
                    std::to_string(shader_location) + " (" + type_of(shader_location) +
                    "), the trace passes location " + std::to_string(p.location) + " (" +
                    type_of(p.location) + ")");
}

void LaunchState::callDataTypeDiffers(const CallData& d, uint32_t callable) {
  if (ray_undefined) return;
  const Pipeline& p = sh_.c->pipeline;
  const uint32_t own = p.callableData(callable);
  markUndefined(UndefinedReason::CallDataType,
                "pipeline.callables[" + std::to_string(callable) +
                    "]: its incoming callable data has the type of location " +
                    std::to_string(own) + " (" + std::to_string(p.callDataWords(own)) +
                    " words), the call passes location " + std::to_string(d.location) + " (" +
                    std::to_string(p.callDataWords(d.location)) + " words)");
}

void LaunchState::nullShaderReached(uint32_t flag, const char* shader, const char* region,
                                    uint32_t record) {
  std::string name = "no_null_*";
  for (const auto& [n, bit] : pipelineFlagNames())
    if (bit == flag) name = n;
  markUndefined(UndefinedReason::NullShader, std::string("pipeline.sbt.") + region + ": record " +
                                                 std::to_string(record) + " is all zero where " +
                                                 shader + " would run, which pipeline.flags " +
                                                 name + " rules out");
}

void LaunchState::divisionByZero(const CExpr& e) {
  if (ray_undefined) return;
  const std::string field =
      e.src && !e.src->loc.field.empty() ? e.src->loc.field : std::string(e.src ? e.src->name : "");
  markUndefined(UndefinedReason::DivisionByZero,
                field + ": uint " + (e.op == Op::Mod ? "modulo" : "division") + " by zero");
}

}  // namespace rayspec
