// Runs checkProgram (program/ops.h) on every stage program of a case, and the
// checks that need the whole pipeline (recursion depth of nested traces).
#include "parse/parse_parts.h"
#include "program/builtins.h"
#include "program/ops.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

const Stmt* findTrace(const Program& p) {
  const Stmt* trace = nullptr;
  walkStatements(p, [&](const Stmt& s) {
    if (!trace && s.kind == Stmt::Kind::Trace) trace = &s;
  });
  return trace;
}

// A read of vertex_position<i> (gl_HitTriangleVertexPositionsEXT), or nullptr.
const Expr* findPositionFetch(const Program& p) {
  const Expr* found = nullptr;
  walkExpressions(p, [&](const Expr& e) {
    if (!found && e.kind == Expr::Kind::Builtin && isHitVertexPosition(e.builtin)) found = &e;
  });
  return found;
}

// Vulkan allows gl_HitTriangleVertexPositionsEXT only where the hit kind is a
// triangle's (VUID-HitTriangleVertexPositionsKHR-08750): never in a hit group
// with an intersection shader, whose hits are boxes'.
void checkPositionFetch(YamlReader& r, const HitGroup& g, const std::string& field) {
  if (!g.intersection) return;
  for (const Program* prog :
       {g.closest_hit ? &*g.closest_hit : nullptr, g.any_hit ? &*g.any_hit : nullptr}) {
    const Expr* e = prog ? findPositionFetch(*prog) : nullptr;
    if (!e) continue;
    SourceLoc loc = e->loc;
    if (loc.file.empty()) loc.file = r.file();
    if (loc.field.empty()) loc.field = field;
    r.error(loc, e->name +
                     ": a group with an intersection shader hits boxes, and vertex positions "
                     "exist only for triangle hits (VUID-HitTriangleVertexPositionsKHR-08750)");
    return;
  }
}

// Every shader of expect_rejected exists and uses what its stage cannot.
void checkRejectionsFound(YamlReader& r, const Case& c, const std::vector<bool>& found) {
  for (size_t k = 0; k < c.expected_rejections.size(); ++k) {
    const ExpectedRejection& e = c.expected_rejections[k];
    if (!found[k])
      r.error(e.loc, "'" + e.shader +
                         "' is no shader of this pipeline (names as `rayspec show` gives them: "
                         "raygen, miss0, hit1.intersection, callable2, ...)");
    else if (e.uses.empty())
      r.error(e.loc, "'" + e.shader +
                         "' uses nothing its stage cannot declare (the payload in an "
                         "intersection shader, the hit attribute in a miss shader)");
  }
}

}  // namespace

void checkPrograms(YamlReader& r, Case& c, const YAML::Node& /*pipeline_node*/) {
  Pipeline& p = c.pipeline;
  std::vector<bool> found(c.expected_rejections.size(), false);
  auto check = [&](Program& prog, Stage stage, const std::string& field, size_t index) {
    const std::string name = Pipeline::shaderName(stage, index, field == "pipeline.raygens");
    std::vector<InterfaceUse>* uses = nullptr;
    for (size_t k = 0; k < c.expected_rejections.size(); ++k)
      if (c.expected_rejections[k].shader == name) {
        uses = &c.expected_rejections[k].uses;
        found[k] = true;
      }
    if (r.isBadProgram(field)) return;
    if (auto e = checkProgram(prog, stage, c.outputs.counters, c.outputs.per_ray,
                              c.pipeline.constants, &c.pipeline.record_layout, uses)) {
      SourceLoc loc = e->loc;
      if (loc.file.empty()) loc.file = r.file();
      if (loc.field.empty()) loc.field = field;
      r.error(loc, e->message);
      return;
    }
    if (stage == Stage::Miss || stage == Stage::ClosestHit)
      if (const Stmt* t = findTrace(prog); t && p.max_recursion < 2)
        r.error(t->loc, std::string("a trace in ") + stageName(stage) +
                            " needs pipeline.max_recursion >= 2 (it is " +
                            std::to_string(p.max_recursion) + ")");
  };
  check(p.raygen, Stage::Raygen, "pipeline.raygen", 0);
  for (size_t i = 0; i < p.other_raygens.size(); ++i)
    check(p.other_raygens[i], Stage::Raygen, "pipeline.raygens", i);
  for (size_t i = 0; i < p.miss.size(); ++i)
    check(p.miss[i], Stage::Miss, "pipeline.miss[" + std::to_string(i) + "]", i);
  for (size_t i = 0; i < p.hit_groups.size(); ++i) {
    HitGroup& g = p.hit_groups[i];
    const std::string f = "pipeline.hit_groups[" + std::to_string(i) + "].";
    if (g.closest_hit) check(*g.closest_hit, Stage::ClosestHit, f + "closest_hit", i);
    if (g.any_hit) check(*g.any_hit, Stage::AnyHit, f + "any_hit", i);
    if (g.intersection) check(*g.intersection, Stage::Intersection, f + "intersection", i);
    checkPositionFetch(r, g, "pipeline.hit_groups[" + std::to_string(i) + "]");
  }
  for (size_t i = 0; i < p.callables.size(); ++i)
    check(p.callables[i], Stage::Callable, "pipeline.callables[" + std::to_string(i) + "]", i);
  checkRejectionsFound(r, c, found);
}

}  // namespace rayspec
