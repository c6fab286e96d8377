#include "case/ray_query_inlining.h"

#include "program/walk_program.h"

namespace rayspec {
namespace {

// What a program holds that its inlined form cannot express, or "".
std::string notInlinable(const Program& program) {
  std::string why;
  walkExpressions(program, [&](const Expr& e) {
    if (e.kind == Expr::Kind::RecordMember)
      why = "it reads shader record members (pipeline.sbt.record_layout)";
    if (e.kind == Expr::Kind::Op && e.name.rfind("light_", 0) == 0)
      why = "a hit or miss stage lights (light_* reads its shader record)";
    if (e.kind == Expr::Kind::Builtin && e.name.rfind("vertex_position", 0) == 0)
      why = "it reads vertex positions (position fetch is not generated for ray queries yet)";
  });
  walkStatements(program, [&](const Stmt& s) {
    if (s.kind == Stmt::Kind::Trace)
      why = "a closest-hit or miss traces (nested ray queries are not generated yet)";
    if (s.kind == Stmt::Kind::Invoke) why = "a hit or miss stage calls a function";
    if (s.kind == Stmt::Kind::Light) why = "a stage reads shader record data (light)";
  });
  return why;
}

// The hit group and miss programs, the ones inlined.
std::string notInlinable(const Pipeline& p) {
  for (const Program& m : p.miss)
    if (std::string why = notInlinable(m); !why.empty()) return why;
  for (const HitGroup& h : p.hit_groups)
    for (const auto* program : {&h.closest_hit, &h.any_hit, &h.intersection})
      if (*program)
        if (std::string why = notInlinable(**program); !why.empty()) return why;
  return "";
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
    if (e.kind == Expr::Kind::Op && e.name.rfind("light_", 0) == 0)
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
  for (const Program& m : p.miss)
    if (std::string why = notComputable(m); !why.empty()) return why;
  for (const HitGroup& h : p.hit_groups)
    for (const auto* program : {&h.closest_hit, &h.any_hit, &h.intersection})
      if (*program)
        if (std::string why = notComputable(**program); !why.empty()) return why;
  return "";
}

}  // namespace

std::string rayQueryObstacle(const Case& c, bool own) {
  const Pipeline& p = c.pipeline;
  if (p.ray_query && !own) return "the case traces by ray query itself";
  if (!c.expected_rejections.empty()) return "the case expects a shader to be rejected";
  if (p.payload_words.size() > 1) return "it declares several payload types";
  for (const auto& [shader, values] : p.specialize)
    if (shader.rfind("raygen", 0) != 0) return "it specializes a constant for " + shader + " alone";
  if (std::string why = notInlinable(p); !why.empty()) return why;
  return p.from_compute ? computeObstacle(p) : "";
}

std::string computeRayQueryObstacle(const Case& c) {
  if (std::string why = rayQueryObstacle(c); !why.empty()) return why;
  return computeObstacle(c.pipeline);
}

}  // namespace rayspec
