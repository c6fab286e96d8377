#include <algorithm>

#include "compare/compare_parts.h"
#include "program/builtins.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

// The bound the model widens a built-in's own record field by (hit_t and
// ray_tmax: t, object_ray_origin: origin, hit_position: t through the
// direction); NoBound for every other built-in.
FieldBound boundOfBuiltin(const Expr& e) {
  if (e.kind != Expr::Kind::Builtin || e.builtin == kBiUnknown) return FieldBound::NoBound;
  const RecordField* f = findRecordField(builtins()[e.builtin].name);
  return f ? f->bound : FieldBound::NoBound;
}

// Reads of bounded built-ins in p, less those recorded straight into their
// own field (`record: {hit_t: hit_t}`, which the bound widens already).
int carriedReads(const Program& p) {
  int reads = 0;
  walkExpressions(p, [&](const Expr& e) { reads += boundOfBuiltin(e) != FieldBound::NoBound; });
  walkStatements(p, [&](const Stmt& s) {
    if (s.kind != Stmt::Kind::Record) return;
    for (const auto& [field, value] : s.assigns)
      if (boundOfBuiltin(value) != FieldBound::NoBound && field == builtins()[value.builtin].name)
        --reads;
  });
  return reads;
}

}  // namespace

bool carriesBoundedBuiltins(const Case& c) {
  const Pipeline& pipe = c.pipeline;
  int reads = carriedReads(pipe.raygen);
  for (const Program& p : pipe.other_raygens) reads += carriedReads(p);
  for (const Program& p : pipe.miss) reads += carriedReads(p);
  for (const Program& p : pipe.callables) reads += carriedReads(p);
  for (const HitGroup& g : pipe.hit_groups)
    for (const auto* p : {&g.closest_hit, &g.any_hit, &g.intersection})
      if (*p) reads += carriedReads(**p);
  return reads > 0;
}

float carriedBound(const RayBounds& b) {
  return std::max({b.t, b.object_origin, b.position});
}

}  // namespace rayspec
