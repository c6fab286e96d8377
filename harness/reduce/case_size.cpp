#include "reduce/case_size.h"

namespace rayspec {
namespace {

// Statements of a program, those nested in bodies included.
size_t statementCount(const Program& p) {
  size_t n = 0;
  for (const Stmt& s : p) n += 1 + statementCount(s.then_) + statementCount(s.else_);
  return n;
}

size_t pipelineStatements(const Pipeline& p) {
  size_t n = statementCount(p.raygen);
  for (const Program& r : p.other_raygens) n += statementCount(r);
  for (const Program& m : p.miss) n += statementCount(m);
  for (const Program& c : p.callables) n += statementCount(c);
  for (const HitGroup& g : p.hit_groups)
    for (const std::optional<Program>* stage : {&g.closest_hit, &g.any_hit, &g.intersection})
      if (*stage) n += statementCount(**stage);
  return n;
}

}  // namespace

CaseSize caseSize(const Case& c) {
  CaseSize s;
  s.rays = c.rays.launchRays();
  s.instances = c.scene.instances.size();
  for (const Blas& b : c.scene.blases) {
    s.geometries += b.geometries.size();
    for (const Geometry& g : b.geometries) s.primitives += g.primitiveCount();
  }
  s.statements = pipelineStatements(c.pipeline);
  return s;
}

std::string sizeChange(const CaseSize& before, const CaseSize& after) {
  const auto one = [](const char* name, size_t a, size_t b) {
    return std::string(name) + " " + std::to_string(a) + " -> " + std::to_string(b);
  };
  return one("rays", before.rays, after.rays) + ", " +
         one("instances", before.instances, after.instances) + ", " +
         one("geometries", before.geometries, after.geometries) + ", " +
         one("primitives", before.primitives, after.primitives) + ", " +
         one("statements", before.statements, after.statements);
}

}  // namespace rayspec
