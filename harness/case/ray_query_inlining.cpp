#include "case/ray_query_inlining.h"

#include <algorithm>

#include "program/hit_object.h"
#include "program/ops.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

// What a program holds that its inlined form cannot express, or "".
std::string notInlinable(const Program& program) {
  std::string why;
  walkExpressions(program, [&](const Expr& e) {
    if (e.kind == Expr::Kind::RecordMember)
      why = "it reads shader record members (pipeline.sbt.record_layout)";
    if (e.kind == Expr::Kind::Op && isLightOp(e.op))
      why = "a hit or miss stage lights (light_* reads its shader record)";
  });
  walkStatements(program, [&](const Stmt& s) {
    if (s.kind == Stmt::Kind::Light) why = "a stage reads shader record data (light)";
  });
  return why;
}

// The first reason `check` gives for a hit group or miss program (the ones
// inlined), or "".
template <typename Check>
std::string firstInlinedReason(const Pipeline& p, Check check) {
  for (const Program& m : p.miss)
    if (std::string why = check(m); !why.empty()) return why;
  for (const HitGroup& h : p.hit_groups)
    for (const auto* program : {&h.closest_hit, &h.any_hit, &h.intersection})
      if (*program)
        if (std::string why = check(**program); !why.empty()) return why;
  return "";
}

std::string notInlinable(const Pipeline& p) {
  return firstInlinedReason(p, [](const Program& q) { return notInlinable(q); });
}

// What raygen as a compute shader cannot do, in the program it runs or the
// programs it inlines: a callable (executeCallableEXT is a ray tracing
// stage's), shader record members or lights (they read a shaderRecordEXT
// block; plain shader_record_* words are given as constants).
std::string notComputable(const Program& program) {
  std::string why;
  walkExpressions(program, [&](const Expr& e) {
    if (e.kind == Expr::Kind::RecordMember)
      why = "raygen reads shader record members, which a compute shader has no record for";
    if (e.kind == Expr::Kind::Op && isLightOp(e.op))
      why = "raygen lights (light_* reads a shader record)";
  });
  walkStatements(program, [&](const Stmt& s) {
    if (s.kind == Stmt::Kind::Call)
      why = "a stage calls a callable (executeCallableEXT has no compute form)";
  });
  return why;
}

std::string computeObstacle(const Pipeline& p) {
  if (std::string why = notComputable(p.raygen); !why.empty()) return why;
  return firstInlinedReason(p, notComputable);
}

// The trace statements of a program, each invoke's function counted at the
// invoke (a compiler inlines every call).
uint64_t traceSites(const Program& p) {
  uint64_t n = 0;
  walkStatements(p, [&](const Stmt& s) { n += s.kind == Stmt::Kind::Trace; });
  return n;
}

// Every closest-hit and miss program's trace sites: a level's inlined
// programs hold this many calls of the next level's trace.
uint64_t nestedSites(const Pipeline& p) {
  uint64_t n = 0;
  for (const Program& m : p.miss) n += traceSites(m);
  for (const HitGroup& h : p.hit_groups)
    if (h.closest_hit) n += traceSites(*h.closest_hit);
  return n;
}

// Copies of the inlined programs a host with `sites` traces holds once its
// calls are inlined: 1 + T + ... + T^(levels - 1) per site, T the nested
// sites (glsl/inlined_levels.h); "" when within kMaxInlinedCopies.
std::string tooManyCopies(uint64_t sites, uint64_t nested, uint32_t levels) {
  uint64_t copies = 0, level_copies = sites;
  for (uint32_t l = 0; l < levels && copies <= kMaxInlinedCopies; ++l) {
    copies += level_copies;
    level_copies *= nested;
  }
  if (copies <= kMaxInlinedCopies) return "";
  return "its nested traces inline more than " + std::to_string(kMaxInlinedCopies) +
         " copies of the hit and miss programs (" + std::to_string(nested) +
         " trace sites in closest-hit and miss over " + std::to_string(levels) +
         " levels of max_recursion; GLSL has no recursion)";
}

// Whether a stage of the pipeline uses a hit object (program/hit_object.h),
// which has no ray query form.
bool usesHitObjects(const Pipeline& p) {
  bool uses = usesHitObject(p.raygen);
  for (const Program& g : p.other_raygens) uses = uses || usesHitObject(g);
  for (const Program& m : p.miss) uses = uses || usesHitObject(m);
  for (const HitGroup& h : p.hit_groups)
    if (h.closest_hit) uses = uses || usesHitObject(*h.closest_hit);
  return uses;
}

// What both forms refuse.
std::string commonObstacle(const Case& c, bool own) {
  const Pipeline& p = c.pipeline;
  if (usesHitObjects(p)) return "it uses hit objects (VK_NV_ray_tracing_invocation_reorder)";
  if ((p.ray_query || p.ray_query_in_hit) && !own) return "the case traces by ray query itself";
  if (!c.expected_rejections.empty()) return "the case expects a shader to be rejected";
  // The SBT tables the forms read are bound in set 0 (glsl/bindings.h).
  if (p.empty_layout) return "its pipeline layout is empty (pipeline.layout)";
  if (p.payload_words.size() > 1) return "it declares several payload types";
  if (!p.allPayloadSized().empty() || !p.allCallDataSized().empty() || !p.attribute_sized.empty())
    return "it declares sized payload, callable data or hit attribute members";
  // The inlined programs read the host's constants; callables stay stages.
  for (const auto& [shader, values] : p.specialize)
    if (shader.rfind("miss", 0) == 0 || shader.rfind("hit", 0) == 0)
      return "it specializes a constant for " + shader + " alone";
  return notInlinable(p);
}

}  // namespace

bool hitOrMissTraces(const Pipeline& p) {
  auto traces = [](const Program& program) {
    bool found = false;
    walkStatements(program, [&](const Stmt& s) { found = found || s.kind == Stmt::Kind::Trace; });
    return found;
  };
  for (const Program& m : p.miss)
    if (traces(m)) return true;
  for (const HitGroup& h : p.hit_groups)
    if (h.closest_hit && traces(*h.closest_hit)) return true;
  return false;
}

std::string rayQueryObstacle(const Case& c, bool own) {
  if (std::string why = commonObstacle(c, own); !why.empty()) return why;
  const Pipeline& p = c.pipeline;
  if (p.from_compute)
    if (std::string why = computeObstacle(p); !why.empty()) return why;
  const uint64_t nested = nestedSites(p);
  if (!nested) return "";  // one copy, the loops at raygen's traces as before
  return tooManyCopies(traceSites(p.raygen), nested, std::max<uint32_t>(p.max_recursion, 1));
}

std::string computeRayQueryObstacle(const Case& c) {
  if (std::string why = rayQueryObstacle(c); !why.empty()) return why;
  return computeObstacle(c.pipeline);
}

std::string rayQueryInHitObstacle(const Case& c, bool own) {
  if (std::string why = commonObstacle(c, own); !why.empty()) return why;
  const Pipeline& p = c.pipeline;
  const uint64_t nested = nestedSites(p);
  if (!nested) return "no closest-hit or miss traces";
  const uint32_t levels = std::max<uint32_t>(p.max_recursion, 2) - 1;
  for (const Program& m : p.miss)
    if (std::string why = tooManyCopies(traceSites(m), nested, levels); !why.empty()) return why;
  for (const HitGroup& h : p.hit_groups)
    if (h.closest_hit)
      if (std::string why = tooManyCopies(traceSites(*h.closest_hit), nested, levels); !why.empty())
        return why;
  return "";
}

}  // namespace rayspec
