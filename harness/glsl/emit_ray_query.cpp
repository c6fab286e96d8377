#include "glsl/emit_ray_query.h"

#include <string>

#include "case/flag_names.h"
#include "glsl/bindings.h"
#include "glsl/emit_call_data.h"
#include "glsl/emit_control.h"
#include "glsl/emit_payloads.h"
#include "glsl/emit_stage.h"
#include "glsl/emit_stmt.h"
#include "glsl/emit_trace.h"
#include "glsl/glsl_literal.h"
#include "glsl/inlined_functions.h"
#include "glsl/inlined_levels.h"
#include "glsl/stage_prologue.h"
#include "program/builtins.h"
#include "program/walk_program.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

std::string str(uint32_t v) {
  return std::to_string(v);
}

// The one payload type (case/ray_query_inlining.h refuses several).
std::string payloadType(const Case& c) {
  return payloadTypeOf(c.pipeline, 0);
}

uint32_t attributeWords(const Pipeline& p, const HitGroup& h) {
  return h.intersection ? p.attribute_words : 0;
}

std::string attributeType(uint32_t words) {
  return words ? "RsAttr" : "vec2";
}

// The attribute a group's stages receive from barycentrics `bary` and, for a
// procedural group, the words `words` (GLSL of a uint[N]).
std::string attributeValue(uint32_t group_words, const std::string& bary,
                           const std::string& words) {
  return group_words ? "RsAttr(" + bary + ", " + words + ")" : bary;
}

std::string zeroWords(uint32_t n) {
  std::string s = "uint[" + str(n) + "](";
  for (uint32_t i = 0; i < n; ++i) s += i ? ", 0u" : "0u";
  return s + ")";
}

// A built-in of the query's candidate (program/builtin_table.h).
std::string candidate(Builtin b) {
  return rayQuerySpelling(builtins()[b], false);
}

StageContext inlinedContext(const StageContext& host, Stage stage, uint32_t index,
                            const Program& program, uint32_t words, uint32_t level) {
  StageContext ctx{host.c, host.plan, stage, Pipeline::shaderName(stage, index),
                   findStageUses(program, stage, host.plan)};
  ctx.attribute_words = words;
  ctx.inlined = true;
  ctx.group = index;
  ctx.level = level;
  ctx.levels = inlinedLevels(host);
  ctx.compute = host.compute;
  return ctx;
}

bool invokes(const Program& program) {
  bool found = false;
  walkStatements(program, [&](const Stmt& s) { found = found || s.kind == Stmt::Kind::Invoke; });
  return found;
}

// An inlined program's function: its stage's run count and any-hit slot as
// the stage's main() has them, zero child and callee data, then the program.
void inlinedBody(const StageContext& ctx, const Program& program, GlslWriter& out) {
  if (ctx.stage == Stage::AnyHit && invokes(program))
    out.line("uint rs_ah_verdict = kRsAccept;  // an invoked function's ignore or terminate");
  emitStagePrologue(ctx, {candidate(kBiInstance), candidate(kBiGeometry), candidate(kBiPrimitive)},
                    out);
  if (ctx.uses.reads_child || ctx.uses.trace) {
    out.line(resultPayloadType(ctx.c.pipeline) + " child;");
    emitPayloadStart(ctx, out);
  }
  if (ctx.uses.call || ctx.uses.reads_callee) {
    out.line(resultCallDataType(ctx.c.pipeline) + " callee;");
    emitCallDataStart(ctx, out);
  }
  emitProgram(program, ctx, out);
}

// The host declares the hit attribute's struct itself: a procedural group's
// closest-hit that hosts (glsl/emit_stage.cpp's interface variables).
bool hostDeclaresAttribute(const StageContext& host) {
  return host.attribute_words && host.uses.hit_attribute && host.stage == Stage::ClosestHit;
}

// What every level shares: the any-hit verdicts, the attribute struct, the
// SBT tables (their buffer and offsets) and the group of a candidate's or committed record.
void sharedState(const StageContext& host, GlslWriter& out) {
  const Pipeline& p = host.c.pipeline;
  const uint32_t words = p.attribute_words;
  out.line("");
  out.line("// ---- what every level of ray queries shares (glsl/emit_ray_query.h) ----");
  out.line("const uint kRsIgnore = 0u, kRsAccept = 1u, kRsTerminate = 2u;  // any-hit verdicts");
  if (words && !hostDeclaresAttribute(host))
    out.line("struct RsAttr { vec2 bary; uint words[" + str(words) + "]; };");
  const SbtTables tables = packSbtTables(p);
  out.line("// The SBT as tables, laid out by packSbtTables (glsl/bindings.h).");
  out.line(
      "layout(set = 0, binding = RS_BINDING_SBT_TABLES, std430) readonly buffer RsSbtTables "
      "{ uint rs_sbt_tables[]; };");
  out.line("const uint kRsHitRecords = " + str(tables.hit_records) + "u, kRsMissRecords = " +
           str(tables.miss_records) + "u, kRsRecordWords = " + str(tables.record_words) + "u;");
  out.line("const uint kRsHitGroups = " + str(tables.hit_groups) + "u, kRsMissGroups = " +
           str(tables.miss_groups) + "u, kRsHitData = " + str(tables.hit_data) +
           "u, kRsMissData = " + str(tables.miss_data) + "u;");
  out.line(
      "#define rs_hit_group_of(c) rs_hit_group("
      "rayQueryGetIntersectionInstanceShaderBindingTableRecordOffsetEXT(rs_rq, c), "
      "uint(rayQueryGetIntersectionGeometryIndexEXT(rs_rq, c)))");
}

// One level's query and what its loop keeps: the trace's arguments the
// inlined programs read, and the attribute and kind of a generated
// intersection. Level 1's query is declared before the shared GLSL.
void queryState(const StageContext& host, uint32_t level, GlslWriter& out) {
  const uint32_t words = host.c.pipeline.attribute_words;
  out.line("");
  out.line("// ---- the ray query of level " + str(level) + " and its state ----");
  if (level > 1) out.line("rayQueryEXT rs_rq;");
  out.line("uint rs_q_flags, rs_q_cull_mask, rs_q_sbt_offset, rs_q_sbt_stride;");
  out.line("float rs_q_tmax;");
  out.line("bool rs_q_done;  // an any-hit terminated inside a report");
  out.line("uint rs_c_kind;  // the committed generated intersection's kind and attribute");
  out.line("vec2 rs_c_bary;");
  if (words) out.line("uint rs_c_words[" + str(words) + "];");
  out.open("float rs_current_tmax() {  // gl_RayTmaxEXT in an intersection shader");
  out.line(
      "return rayQueryGetIntersectionTypeEXT(rs_rq, true) == "
      "gl_RayQueryCommittedIntersectionNoneEXT ? rs_q_tmax : "
      "rayQueryGetIntersectionTEXT(rs_rq, true);");
  out.close();
}

// The word i of the record an inlined stage runs for (its shader_record_uint
// / _float reads): rs_q_<region>_record, set where the record is chosen.
void recordWord(const std::string& region, const std::string& table, GlslWriter& out) {
  const std::string record = "rs_q_" + region + "_record";
  out.line("uint " + record + ";");
  out.open("uint rs_" + region + "_record_word(uint i) {");
  out.line("return " + record + " < kRs" + table +
           "Records && i < kRsRecordWords ? rs_sbt_tables[kRs" + table + "Data + " + record +
           " * kRsRecordWords + i] : 0u;");
  out.close();
}

// The group of the candidate's or committed intersection's hit record
// (R-SBT-HIT), 0xFFFFFFFF for an all-zero record or one beyond the region;
// rs_hit_group_of(c) calls it with the query's values (c: committed, a
// constant, as the getters want).
void hitGroupFunction(GlslWriter& out) {
  out.open("uint rs_hit_group(uint instance_offset, uint geometry) {");
  // R-SBT-HIT, with the widths of case/bit_widths.h.
  out.line("const uint record = (instance_offset & " + glslHexUint(kInstanceFieldMask) +
           ") + geometry * (rs_q_sbt_stride & " + glslHexUint(kTraceSbtFieldMask) +
           ") + (rs_q_sbt_offset & " + glslHexUint(kTraceSbtFieldMask) + ");");
  out.line("rs_q_hit_record = record;");
  out.line("return record < kRsHitRecords ? rs_sbt_tables[kRsHitGroups + record] : " +
           str(kSbtNoGroup) + "u;");
  out.close();
}

// A procedural group's report: the reported t in [tmin, committed t], the
// any-hit's verdict (none for an opaque box), then the generated intersection.
void reportFunction(const StageContext& host, uint32_t g, uint32_t level, GlslWriter& out) {
  const HitGroup& h = host.c.pipeline.hit_groups[g];
  const uint32_t words = attributeWords(host.c.pipeline, h);
  out.open("bool " + atLevel("rs_report_" + str(g), level) + "(inout " + payloadType(host.c) +
           " rs_ah_payload, float rs_t, uint rs_kind, " + attributeType(words) + " rs_attr) {");
  out.line("if (rs_t < rayQueryGetRayTMinEXT(rs_rq) || rs_t > rs_current_tmax()) return false;");
  out.line("uint rs_verdict = kRsAccept;");
  if (anyHitRuns(host.plan, h))
    out.line("if (!rayQueryGetIntersectionCandidateAABBOpaqueEXT(rs_rq)) rs_verdict = " +
             atLevel("rs_any_hit_" + str(g), level) + "(rs_ah_payload, rs_attr, rs_t, rs_kind);");
  out.line("if (rs_verdict == kRsIgnore) return false;");
  out.line("rayQueryGenerateIntersectionEXT(rs_rq, rs_t);");
  out.line("rs_c_kind = rs_kind;");
  out.line(words ? "rs_c_bary = rs_attr.bary;" : "rs_c_bary = rs_attr;");
  if (words) out.line("rs_c_words = rs_attr.words;");
  out.open(
      "if (rs_verdict == kRsTerminate || (rs_q_flags & gl_RayFlagsTerminateOnFirstHitEXT) != 0u) "
      "{");
  out.line("rayQueryTerminateEXT(rs_rq);");
  out.line("rs_q_done = true;");
  out.close();
  out.line("return true;");
  out.close();
}

// Group g's any-hit, report, intersection and closest-hit functions at `level`.
void hitGroupFunctions(const StageContext& host, uint32_t g, uint32_t level, GlslWriter& out) {
  const HitGroup& h = host.c.pipeline.hit_groups[g];
  const uint32_t words = attributeWords(host.c.pipeline, h);
  const std::string payload = "inout " + payloadType(host.c) + " payload";
  const std::string hit_args =
      payload + ", " + attributeType(words) + " rs_attr, float rs_hit_t, uint rs_hit_kind) {";
  auto context = [&](Stage stage, const Program& program) {
    return inlinedContext(host, stage, g, program, words, level);
  };
  if (anyHitRuns(host.plan, h)) {
    const StageContext ctx = context(Stage::AnyHit, *h.any_hit);
    emitFunctions(*h.any_hit, ctx, out);
    out.open("uint " + atLevel("rs_any_hit_" + str(g), level) + "(" + hit_args);
    inlinedBody(ctx, *h.any_hit, out);
    out.line("return kRsAccept;");
    out.close();
  }
  if (intersectionRuns(host.plan, h)) {
    reportFunction(host, g, level, out);
    const StageContext ctx = context(Stage::Intersection, *h.intersection);
    emitFunctions(*h.intersection, ctx, out);
    out.open("void " + atLevel("rs_intersection_" + str(g), level) + "(inout " +
             payloadType(host.c) + " rs_ah_payload) {");
    out.line(attributeType(words) +
             " rs_attr = " + attributeValue(words, "vec2(0.0)", zeroWords(words)) + ";");
    inlinedBody(ctx, *h.intersection, out);
    out.close();
  }
  if (h.closest_hit) {
    const StageContext ctx = context(Stage::ClosestHit, *h.closest_hit);
    emitFunctions(*h.closest_hit, ctx, out);
    out.open("void " + atLevel("rs_closest_hit_" + str(g), level) + "(" + hit_args);
    inlinedBody(ctx, *h.closest_hit, out);
    out.close();
  }
}

// A switch over the hit groups that have `has`, each case `call(g)`.
template <typename Has, typename Call>
void groupSwitch(const StageContext& ctx, const std::string& on, Has has, Call call,
                 GlslWriter& out) {
  out.open("switch (" + on + ") {");
  const std::vector<HitGroup>& groups = ctx.c.pipeline.hit_groups;
  for (uint32_t g = 0; g < groups.size(); ++g)
    if (has(groups[g])) out.line("case " + str(g) + "u: " + call(g) + " break;");
  out.line("default: break;");
  out.close();
}

// The box candidate the scene reads of an inlined intersection take
// (aabb_min, sphere_*: shaders/scene.glsl through emitCandidateMacros): the
// level's query is not the one the shared functions were written with.
void candidateBox(GlslWriter& out) {
  out.line("rs_cand_instance = " + candidate(kBiInstance) + ";");
  out.line("rs_cand_geometry = " + candidate(kBiGeometry) + ";");
  out.line("rs_cand_primitive = " + candidate(kBiPrimitive) + ";");
  out.line("rs_cand_origin = " + candidate(kBiObjectOrigin) + ";");
  out.line("rs_cand_direction = " + candidate(kBiObjectDirection) + ";");
}

// The loop: each candidate decided by its group's any-hit or intersection.
void candidateLoop(const StageContext& host, uint32_t level, GlslWriter& out) {
  const Pipeline& p = host.c.pipeline;
  const std::string payload = "rs_trace_payload";
  out.open("while (rayQueryProceedEXT(rs_rq)) {");
  out.line("const uint rs_group = rs_hit_group_of(false);");
  out.open(
      "if (rayQueryGetIntersectionTypeEXT(rs_rq, false) == "
      "gl_RayQueryCandidateIntersectionTriangleEXT) {");
  out.line("const vec2 rs_bary = rayQueryGetIntersectionBarycentricsEXT(rs_rq, false);");
  out.line("const float rs_t = rayQueryGetIntersectionTEXT(rs_rq, false);");
  out.line(
      "const uint rs_kind = rayQueryGetIntersectionFrontFaceEXT(rs_rq, false) ? 0xFEu : "
      "0xFFu;");
  out.line("uint rs_verdict = kRsAccept;");
  groupSwitch(
      host, "rs_group", [&](const HitGroup& h) { return anyHitRuns(host.plan, h); },
      [&](uint32_t g) {
        const uint32_t words = attributeWords(p, p.hit_groups[g]);
        return "rs_verdict = " + atLevel("rs_any_hit_" + str(g), level) + "(" + payload + ", " +
               attributeValue(words, "rs_bary", zeroWords(words)) + ", rs_t, rs_kind);";
      },
      out);
  out.line("if (rs_verdict != kRsIgnore) rayQueryConfirmIntersectionEXT(rs_rq);");
  out.line("if (rs_verdict == kRsTerminate) rayQueryTerminateEXT(rs_rq);");
  out.reopen("} else {");
  if (host.uses.scene) candidateBox(out);
  groupSwitch(
      host, "rs_group", [&](const HitGroup& h) { return intersectionRuns(host.plan, h); },
      [&](uint32_t g) {
        return atLevel("rs_intersection_" + str(g), level) + "(" + payload + ");";
      },
      out);
  out.close();
  out.close();
}

// After the loop: the committed intersection's closest-hit, or the miss.
void committedStage(const StageContext& host, uint32_t level, GlslWriter& out) {
  const Pipeline& p = host.c.pipeline;
  const std::string payload = "rs_trace_payload";
  out.line("const uint rs_committed = rayQueryGetIntersectionTypeEXT(rs_rq, true);");
  out.open("if (rs_committed == gl_RayQueryCommittedIntersectionNoneEXT) {");
  out.line("rs_q_miss_record = rs_miss & " + glslHexUint(kTraceMissIndexMask) +
           ";  // R-SBT-MISS: the low 16 bits");
  out.line(
      "const uint rs_miss_program = rs_q_miss_record < kRsMissRecords ? "
      "rs_sbt_tables[kRsMissGroups + rs_q_miss_record] : " +
      str(kSbtNoGroup) + "u;");
  out.open("switch (rs_miss_program) {");
  for (uint32_t m = 0; m < p.miss.size(); ++m)
    out.line("case " + str(m) + "u: " + atLevel("rs_miss_" + str(m), level) + "(" + payload +
             "); break;");
  out.line("default: break;");
  out.close();
  out.reopen("} else if ((rs_flags & gl_RayFlagsSkipClosestHitShaderEXT) == 0u) {");
  out.line("const uint rs_group = rs_hit_group_of(true);");
  out.line("const float rs_t = rayQueryGetIntersectionTEXT(rs_rq, true);");
  out.line("const bool rs_triangle = rs_committed == gl_RayQueryCommittedIntersectionTriangleEXT;");
  out.line(
      "const vec2 rs_bary = rs_triangle ? rayQueryGetIntersectionBarycentricsEXT(rs_rq, true) "
      ": rs_c_bary;");
  out.line(
      "const uint rs_kind = rs_triangle ? (rayQueryGetIntersectionFrontFaceEXT(rs_rq, true) ? "
      "0xFEu : 0xFFu) : rs_c_kind;");
  groupSwitch(
      host, "rs_group", [](const HitGroup& h) { return h.closest_hit.has_value(); },
      [&](uint32_t g) {
        const uint32_t words = attributeWords(p, p.hit_groups[g]);
        const std::string w = words ? "rs_triangle ? " + zeroWords(words) + " : rs_c_words" : "";
        return atLevel("rs_closest_hit_" + str(g), level) + "(" + payload + ", " +
               attributeValue(words, "rs_bary", w) + ", rs_t, rs_kind);";
      },
      out);
  out.close();
}

// rayQueryInitializeEXT on the trace's top level: with several, a switch
// over the constant index the trace passes (rs_tlas_index).
void initializeQuery(const StageContext& host, const std::string& flags, GlslWriter& out) {
  const std::string rest =
      ", " + flags + ", rs_cull_mask, rs_origin, rs_tmin, rs_direction, rs_tmax);";
  const uint32_t n = host.c.scene.tlasCount();
  if (n <= 1) {
    out.line("rayQueryInitializeEXT(rs_rq, rs_tlas" + rest);
    return;
  }
  out.open("switch (rs_tlas_index) {");
  for (uint32_t t = 0; t < n; ++t)
    out.line("case " + str(t) + "u: rayQueryInitializeEXT(rs_rq, rs_tlas[" + str(t) + "]" + rest +
             " break;");
  out.line("default: break;");
  out.close();
}

// The trace of `level`: its arguments kept for the inlined programs, the
// query initialised, the loop and the committed intersection's stage.
void traceFunction(const StageContext& host, uint32_t level, GlslWriter& out) {
  out.open("void " + atLevel("rs_trace", level) + "(inout " + payloadType(host.c) +
           " rs_trace_payload, " + (host.c.scene.tlasCount() > 1 ? "uint rs_tlas_index, " : "") +
           "uint rs_flags, uint rs_cull_mask, uint rs_sbt_offset, uint rs_sbt_stride, uint "
           "rs_miss, vec3 rs_origin, float rs_tmin, vec3 rs_direction, float rs_tmax) {");
  out.line("rs_q_flags = rs_flags;");
  out.line("rs_q_cull_mask = rs_cull_mask;");
  out.line("rs_q_sbt_offset = rs_sbt_offset;");
  out.line("rs_q_sbt_stride = rs_sbt_stride;");
  out.line("rs_q_tmax = rs_tmax;");
  out.line("rs_q_done = false;");
  // skip_closest_hit is the loop's to honour, not the query's; the pipeline's
  // skip_triangles / skip_aabbs, which act on traceRayEXT alone, become the
  // query's ray flags (gl_IncomingRayFlagsEXT stays the trace's: rs_q_flags).
  const uint32_t p_flags = host.c.pipeline.flags;
  const uint32_t skip = (p_flags & kPipelineSkipTriangles ? kRaySkipTriangles : 0u) |
                        (p_flags & kPipelineSkipAabbs ? kRaySkipAabbs : 0u);
  initializeQuery(host,
                  "(rs_flags & ~gl_RayFlagsSkipClosestHitShaderEXT)" +
                      (skip ? " | " + str(skip) + "u" : std::string()),
                  out);
  candidateLoop(host, level, out);
  committedStage(host, level, out);
  out.close();
}

// One level's block: its state, every inlined program at that level, and
// its trace function.
void levelBlock(const StageContext& host, uint32_t level, GlslWriter& out) {
  const Pipeline& p = host.c.pipeline;
  openLevel(level, out);
  queryState(host, level, out);
  recordWord("hit", "Hit", out);
  recordWord("miss", "Miss", out);
  hitGroupFunction(out);
  out.line("");
  out.line("// ---- the hit group and miss programs, inlined at level " + str(level) + " ----");
  for (uint32_t g = 0; g < p.hit_groups.size(); ++g) hitGroupFunctions(host, g, level, out);
  for (uint32_t m = 0; m < p.miss.size(); ++m) {
    const StageContext ctx = inlinedContext(host, Stage::Miss, m, p.miss[m], 0, level);
    emitFunctions(p.miss[m], ctx, out);
    out.open("void " + atLevel("rs_miss_" + str(m), level) + "(inout " + payloadType(host.c) +
             " payload) {");
    inlinedBody(ctx, p.miss[m], out);
    out.close();
  }
  traceFunction(host, level, out);
  closeLevel(level, out);
}

}  // namespace

void emitCandidateMacros(GlslWriter& out) {
  out.line("uint rs_cand_instance, rs_cand_geometry, rs_cand_primitive;  // set by each loop");
  out.line("vec3 rs_cand_origin, rs_cand_direction;");
  out.line("#define RS_HIT_INSTANCE rs_cand_instance");
  out.line("#define RS_HIT_GEOMETRY rs_cand_geometry");
  out.line("#define RS_HIT_PRIMITIVE rs_cand_primitive");
  out.line("#define RS_OBJECT_RAY_ORIGIN rs_cand_origin");
  out.line("#define RS_OBJECT_RAY_DIRECTION rs_cand_direction");
}

void addInlinedUses(StageContext& host) {
  const Pipeline& p = host.c.pipeline;
  auto add = [&](Stage stage, const Program& program) {
    const StageUses u = findStageUses(program, stage, host.plan);
    StageUses& r = host.uses;
    r.counters = r.counters || u.counters;
    r.record_fields.insert(u.record_fields.begin(), u.record_fields.end());
    addPrologueFields(host.plan, stage, r);
    r.call = r.call || u.call;
    r.call_locations.insert(u.call_locations.begin(), u.call_locations.end());
    r.scene = r.scene || u.scene;
    r.sphere = r.sphere || u.sphere;
    r.query_sphere = r.query_sphere || u.query_sphere;
    r.query_position_fetch = r.query_position_fetch || u.position_fetch;
  };
  for (const Program& m : p.miss) add(Stage::Miss, m);
  for (const HitGroup& h : p.hit_groups) {
    if (h.closest_hit) add(Stage::ClosestHit, *h.closest_hit);
    if (anyHitRuns(host.plan, h)) add(Stage::AnyHit, *h.any_hit);
    if (intersectionRuns(host.plan, h)) add(Stage::Intersection, *h.intersection);
  }
  // The host's any-hit fields whether or not an any-hit is inlined (its
  // shared functions name them).
  addAnyHitSlotFields(host.plan, host.uses);
}

void emitInlinedStages(const StageContext& host, GlslWriter& out) {
  if (!host.uses.trace) return;  // nothing calls them (and no rs_tlas is bound)
  sharedState(host, out);
  // The deepest level first: a level's programs call the trace of the next.
  for (uint32_t level = inlinedLevels(host); level >= 1; --level) levelBlock(host, level, out);
}

bool emitRayQueryTrace(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  const uint32_t level = ctx.inlined ? ctx.level + 1 : 1;
  if (ctx.inlined && ctx.level >= ctx.levels) {
    out.line("// beyond pipeline.max_recursion: undefined (R-RECURSION, R-UB); skipped, as the");
    out.line("// model skips it");
    return false;
  }
  out.line(atLevel("rs_trace", level) + "(" + outgoingPayload(s.trace.location) + ", " +
           (ctx.c.scene.tlasCount() > 1 ? tlasIndex(s.trace, ctx) + ", " : "") +
           "rs_flags, rs_cull_mask, rs_sbt_offset, rs_sbt_stride, rs_miss, rs_origin, rs_tmin, "
           "rs_direction, rs_tmax);");
  return true;
}

}  // namespace rayspec
