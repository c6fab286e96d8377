#include "glsl/emit_query.h"

#include <string>

#include "glsl/emit_expr.h"
#include "glsl/emit_stmt.h"
#include "glsl/emit_trace.h"
#include "glsl/glsl_literal.h"

namespace rayspec {
namespace {

// The nesting depth of the ray_query being written. Emission is recursive on
// one thread, so the depth is that thread's: each query names its variable
// by it and gives rs_query back to its parent when it ends.
thread_local uint32_t t_query_depth = 0;

std::string queryVariable(uint32_t depth) {
  return "rs_query_" + std::to_string(depth);
}

// rs_query, the name the getters read, as the query of `depth`.
void nameQuery(uint32_t depth, bool defined, GlslWriter& out) {
  if (defined) out.raw("#undef rs_query\n");
  out.raw("#define rs_query " + queryVariable(depth) + "\n");
}

// One field of the query: the case's expression, else the trace's default
// (the launch ray in raygen, rays.defaults elsewhere).
void field(const char* type, const char* local, const std::vector<Expr>& given,
           const std::string& fallback, const StageContext& ctx, GlslWriter& out) {
  std::string value = given.empty() ? fallback : emitExpr(given.front(), ctx);
  if (value.empty()) {
    out.raw(std::string("#error rayspec: a ray_query outside raygen needs ") + (local + 3) + "\n");
    value = "vec3(0.0)";
  }
  out.line(std::string(type) + " " + local + " = " + value + ";");
}

void fields(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  const TraceArgs& t = s.trace;
  const Ray& d = ctx.c.rays.defaults;
  const bool raygen = ctx.stage == Stage::Raygen;
  auto def = [&](const std::string& launch, const std::string& nested) {
    return raygen ? launch : nested;
  };
  field("uint", "rs_flags", t.flags, def("rs_ray.flags", glslUint(d.flags)), ctx, out);
  field("uint", "rs_cull_mask", t.cull_mask, def("rs_ray.cull_mask", glslUint(d.cull_mask)), ctx,
        out);
  field("vec3", "rs_origin", t.origin, def("rs_ray.origin", ""), ctx, out);
  field("float", "rs_tmin", t.tmin, def("rs_ray.tmin", glslFloat(d.tmin)), ctx, out);
  field("vec3", "rs_direction", t.direction, def("rs_ray.direction", ""), ctx, out);
  field("float", "rs_tmax", t.tmax, def("rs_ray.tmax", glslFloat(d.tmax)), ctx, out);
}

const Program* candidateBlock(const Stmt& s, uint32_t which) {
  for (const Stmt& c : s.then_)
    if (c.kind == Stmt::Kind::Candidates && c.size == which) return &c.then_;
  return nullptr;
}

void rayQuery(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  const uint32_t depth = t_query_depth;
  const std::string q = queryVariable(depth);
  out.open("{  // ray_query");
  fields(s, ctx, out);
  tlasIndexLocal(s.trace, ctx, out);
  out.line("rayQueryEXT " + q + ";");
  nameQuery(depth, depth > 0, out);
  out.line("rayQueryInitializeEXT(" + q + ", " + tlasOperand(s.trace, ctx) +
           ", rs_flags, rs_cull_mask, rs_origin, rs_tmin, rs_direction, rs_tmax);");
  ++t_query_depth;
  out.open("while (rayQueryProceedEXT(" + q + ")) {");
  out.open("if (rayQueryGetIntersectionTypeEXT(" + q +
           ", false) == gl_RayQueryCandidateIntersectionTriangleEXT) {");
  if (const Program* p = candidateBlock(s, 0)) emitProgram(*p, ctx, out);
  out.reopen("} else {");
  if (const Program* p = candidateBlock(s, 1)) emitProgram(*p, ctx, out);
  out.close();
  out.close();
  emitProgram(s.else_, ctx, out);  // after: the committed intersection stays readable
  --t_query_depth;
  out.close();
  // The enclosing query's getters read the enclosing query again.
  if (depth > 0)
    nameQuery(depth - 1, true, out);
  else
    out.raw("#undef rs_query\n");
}

}  // namespace

void emitQueryStatement(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  switch (s.kind) {
    case Stmt::Kind::RayQuery:
      rayQuery(s, ctx, out);
      return;
    case Stmt::Kind::Confirm:
      out.line("rayQueryConfirmIntersectionEXT(rs_query);");
      return;
    case Stmt::Kind::Generate:
      out.line("rayQueryGenerateIntersectionEXT(rs_query, " + emitExpr(s.t, ctx) + ");");
      return;
    case Stmt::Kind::TerminateQuery:
      out.line("rayQueryTerminateEXT(rs_query);");
      return;
    default:
      out.raw("#error rayspec: a ray_query's candidate block outside its ray_query\n");
      return;
  }
}

}  // namespace rayspec
