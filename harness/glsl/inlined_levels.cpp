#include "glsl/inlined_levels.h"

#include <algorithm>

#include "case/ray_query_inlining.h"

namespace rayspec {
namespace {

// Names read by built-in spellings (program/builtin_table.h), shared GLSL
// and the statements of emit_stmt.cpp: they take the level's own by #define.
constexpr const char* kLevelState[] = {"rs_rq",
                                       "rs_q_flags",
                                       "rs_q_cull_mask",
                                       "rs_q_sbt_offset",
                                       "rs_q_sbt_stride",
                                       "rs_q_tmax",
                                       "rs_q_done",
                                       "rs_c_kind",
                                       "rs_c_bary",
                                       "rs_c_words",
                                       "rs_current_tmax",
                                       "rs_q_hit_record",
                                       "rs_q_miss_record",
                                       "rs_hit_record_word",
                                       "rs_miss_record_word",
                                       "rs_hit_group"};

}  // namespace

bool hostsInlinedStages(const Case& c, Stage stage, const StageUses& uses) {
  if (stage == Stage::Raygen) return c.pipeline.ray_query;
  return (stage == Stage::ClosestHit || stage == Stage::Miss) && c.pipeline.ray_query_in_hit &&
         uses.trace;
}

bool tracesByRayQuery(const StageContext& ctx) {
  return ctx.inlined || hostsInlinedStages(ctx.c, ctx.stage, ctx.uses);
}

uint32_t inlinedLevels(const StageContext& host) {
  const uint32_t most = std::max<uint32_t>(host.c.pipeline.max_recursion, 1);
  if (host.stage != Stage::Raygen) return std::max<uint32_t>(most - 1, 1);
  return hitOrMissTraces(host.c.pipeline) ? most : 1;
}

std::string atLevel(const std::string& name, uint32_t level) {
  return level <= 1 ? name : name + "_d" + std::to_string(level);
}

void openLevel(uint32_t level, GlslWriter& out) {
  if (level <= 1) return;
  for (const char* name : kLevelState)
    out.raw("#define " + std::string(name) + " " + atLevel(name, level) + "\n");
}

void closeLevel(uint32_t level, GlslWriter& out) {
  if (level <= 1) return;
  for (const char* name : kLevelState) out.raw("#undef " + std::string(name) + "\n");
}

}  // namespace rayspec
