// ray_query statements as GLSL (GL_EXT_ray_query): each a rayQueryEXT of its
// own nesting depth (rs_query_0, rs_query_1, ...), initialized with the
// statement's fields (a trace's defaults), then a rayQueryProceedEXT loop
// whose triangle candidates run the triangle block and AABB candidates the
// aabb block, then the after block. The getters (candidate.*, committed.*,
// query.*; program/builtin_table.h) spell the query as the macro rs_query,
// defined to the innermost query around each block.
#pragma once

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

// RayQuery, Confirm, Generate, TerminateQuery (a Candidates block is only
// written by its RayQuery).
void emitQueryStatement(const Stmt& s, const StageContext& ctx, GlslWriter& out);

}  // namespace rayspec
