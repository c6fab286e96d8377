#include "glsl/emit_query.h"

#include <string>
#include <utility>
#include <vector>

#include "glsl/emit_expr.h"
#include "glsl/emit_stmt.h"
#include "glsl/emit_trace.h"
#include "glsl/glsl_literal.h"
#include "glsl/tlas_function.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

// The nesting depth of the ray_query being written, and what rs_query (and
// rs_restarts, its restart count) name at each depth. Emission is recursive
// on one thread, so both are that thread's: each query names its variable
// by its depth and gives rs_query back to its parent when it ends.
thread_local uint32_t t_query_depth = 0;
thread_local std::vector<std::pair<std::string, std::string>> t_named;

std::string queryVariable(uint32_t depth) {
  return "rs_query_" + std::to_string(depth);
}

void defineQuery(const std::pair<std::string, std::string>& named, bool defined, GlslWriter& out) {
  if (defined) out.raw("#undef rs_query\n#undef rs_restarts\n");
  out.raw("#define rs_query " + named.first + "\n#define rs_restarts " + named.second + "\n");
}

// rs_query, the name the getters read, as `query` (its restart count
// `restarts`) until unnameQuery.
void nameQuery(const std::string& query, const std::string& restarts, GlslWriter& out) {
  t_named.emplace_back(query, restarts);
  defineQuery(t_named.back(), t_named.size() > 1, out);
}

// rs_query as the enclosing query's again (none: undefined).
void unnameQuery(GlslWriter& out) {
  t_named.pop_back();
  if (t_named.empty())
    out.raw("#undef rs_query\n#undef rs_restarts\n");
  else
    defineQuery(t_named.back(), true, out);
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

// Whether a query's candidate blocks may restart it (a restart count to keep).
bool restarts(const Stmt& s) {
  bool found = false;
  for (const Stmt& c : s.then_)
    walkStatements(c.then_,
                   [&](const Stmt& x) { found = found || x.kind == Stmt::Kind::RestartQuery; });
  return found;
}

// rayQueryInitializeEXT of rs_query with s's fields (declared in a scope
// of their own).
void initialize(const Stmt& s, const std::string& query, const StageContext& ctx, GlslWriter& out) {
  fields(s, ctx, out);
  tlasIndexLocal(s.trace, ctx, out);
  out.line(queryInitCall(ctx, query, tlasOperand(s.trace, ctx)));
}

// The body of a proceed loop for its candidate: the triangle block or the
// aabb block, by the candidate's type.
void candidateBlocks(const Stmt& s, const std::string& query, const StageContext& ctx,
                     GlslWriter& out) {
  out.open("if (rayQueryGetIntersectionTypeEXT(" + query +
           ", false) == gl_RayQueryCandidateIntersectionTriangleEXT) {");
  if (const Program* p = candidateBlock(s, 0)) emitProgram(*p, ctx, out);
  out.reopen("} else {");
  if (const Program* p = candidateBlock(s, 1)) emitProgram(*p, ctx, out);
  out.close();
}

void rayQuery(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  const uint32_t depth = t_query_depth;
  const std::string q = queryVariable(depth);
  const std::string count = "rs_restarts_" + std::to_string(depth);
  out.open("{  // ray_query");
  out.line("rayQueryEXT " + q + ";");
  if (restarts(s)) out.line("uint " + count + " = 0u;");
  initialize(s, q, ctx, out);  // its fields may read the enclosing query
  nameQuery(q, count, out);
  ++t_query_depth;
  out.open("while (rayQueryProceedEXT(" + q + ")) {");
  candidateBlocks(s, q, ctx, out);
  out.close();
  emitProgram(s.else_, ctx, out);  // after: the committed intersection stays readable
  --t_query_depth;
  out.close();
  unnameQuery(out);  // the enclosing query's getters read the enclosing query again
}

// ray_queries: one array of rayQueryEXT, each initialized in order; then,
// while any is live, each live query in turn (a loop index, a dynamic
// index) proceeds once and runs its own blocks for its candidate; then each
// one's after. A continue (or a restart) in a block goes on to the next
// query's step.
void rayQueries(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  const std::string d = std::to_string(t_query_depth);
  const std::string n = std::to_string(s.then_.size());
  const std::string qs = "rs_queries_" + d, step = "rs_step_" + d, live = "rs_live_" + d,
                    count = "rs_restarts_" + d;
  out.open("{  // ray_queries");
  out.line("rayQueryEXT " + qs + "[" + n + "];");
  bool any_restarts = false;
  for (const Stmt& q : s.then_) any_restarts = any_restarts || restarts(q);
  if (any_restarts) out.line("uint " + count + "[" + n + "];");
  for (size_t k = 0; k < s.then_.size(); ++k) {
    out.open("{");
    initialize(s.then_[k], qs + "[" + std::to_string(k) + "]", ctx, out);
    if (any_restarts) out.line(count + "[" + std::to_string(k) + "] = 0u;");
    out.close();
  }
  out.line("uint " + live + " = " + glslUint((1u << s.then_.size()) - 1u) + ";");
  ++t_query_depth;
  nameQuery(qs + "[" + step + "]", count + "[" + step + "]", out);
  out.open("while (" + live + " != 0u) {");
  out.open("for (uint " + step + " = 0u; " + step + " < " + n + "u; ++" + step + ") {");
  out.line("if ((" + live + " & (1u << " + step + ")) == 0u) continue;");
  out.open("if (!rayQueryProceedEXT(rs_query)) {");
  out.line(live + " &= ~(1u << " + step + ");");
  out.line("continue;");
  out.close();
  for (size_t k = 0; k < s.then_.size(); ++k) {
    const std::string which = "if (" + step + " == " + std::to_string(k) + "u) {";
    if (k == 0)
      out.open(which);
    else
      out.reopen("} else " + which);
    candidateBlocks(s.then_[k], "rs_query", ctx, out);
  }
  out.close();  // the queries' blocks
  out.close();  // for
  out.close();  // while
  unnameQuery(out);
  for (size_t k = 0; k < s.then_.size(); ++k) {
    const std::string i = "[" + std::to_string(k) + "]";
    nameQuery(qs + i, count + i, out);
    out.open("{  // after" + i);
    emitProgram(s.then_[k].else_, ctx, out);
    out.close();
    unnameQuery(out);
  }
  --t_query_depth;
  out.close();
}

// restart_query: rayQueryInitializeEXT of the innermost query with the
// statement's fields, then on to its next proceed (at most
// kMaxQueryRestarts times a run of the query: past them it does nothing).
void restartQuery(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  out.open("if (rs_restarts < " + glslUint(kMaxQueryRestarts) + ") {  // restart_query");
  out.line("rs_restarts += 1u;");
  initialize(s, "rs_query", ctx, out);
  out.line("continue;");
  out.close();
}

}  // namespace

void emitQueryStatement(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  switch (s.kind) {
    case Stmt::Kind::RayQuery:
      rayQuery(s, ctx, out);
      return;
    case Stmt::Kind::RayQueries:
      rayQueries(s, ctx, out);
      return;
    case Stmt::Kind::RestartQuery:
      restartQuery(s, ctx, out);
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
