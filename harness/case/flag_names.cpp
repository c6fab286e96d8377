// Names of the Vulkan flag bits as written in cases.
#include "case/flag_names.h"

#include "case/case.h"

namespace rayspec {

const FlagTable& geometryFlagNames() {
  static const FlagTable t = {{"opaque", kGeometryOpaque},
                              {"no_duplicate_any_hit", kGeometryNoDuplicateAnyHit}};
  return t;
}

const FlagTable& instanceFlagNames() {
  static const FlagTable t = {
      {"triangle_facing_cull_disable", kInstanceFacingCullDisable},
      {"triangle_flip_facing", kInstanceFlipFacing},
      {"force_opaque", kInstanceForceOpaque},
      {"force_no_opaque", kInstanceForceNoOpaque},
      {"force_opacity_micromap_2_state", kInstanceForceOpacityMicromap2State},
      {"disable_opacity_micromaps", kInstanceDisableOpacityMicromaps}};
  return t;
}

const FlagTable& rayFlagNames() {
  static const FlagTable t = {{"opaque", kRayOpaque},
                              {"no_opaque", kRayNoOpaque},
                              {"terminate_on_first_hit", kRayTerminateOnFirstHit},
                              {"skip_closest_hit", kRaySkipClosestHit},
                              {"cull_back_facing", kRayCullBackFacing},
                              {"cull_front_facing", kRayCullFrontFacing},
                              {"cull_opaque", kRayCullOpaque},
                              {"cull_no_opaque", kRayCullNoOpaque},
                              {"skip_triangles", kRaySkipTriangles},
                              {"skip_aabbs", kRaySkipAabbs}};
  return t;
}

const FlagTable& pipelineFlagNames() {
  static const FlagTable t = {
      {"skip_triangles", kPipelineSkipTriangles},
      {"skip_aabbs", kPipelineSkipAabbs},
      {"no_null_any_hit", kPipelineNoNullAnyHit},
      {"no_null_closest_hit", kPipelineNoNullClosestHit},
      {"no_null_miss", kPipelineNoNullMiss},
      {"no_null_intersection", kPipelineNoNullIntersection},
      {"link_time_optimization", kPipelineLinkTimeOptimization},
      {"retain_link_time_optimization_info", kPipelineRetainLinkTimeOptimizationInfo}};
  return t;
}

const FlagTable& buildFlagNames() {
  static const FlagTable t = {{"allow_update", kBuildAllowUpdate},
                              {"allow_compaction", kBuildAllowCompaction},
                              {"prefer_fast_trace", kBuildPreferFastTrace},
                              {"prefer_fast_build", kBuildPreferFastBuild},
                              {"low_memory", kBuildLowMemory},
                              {"allow_data_access", kBuildAllowDataAccess}};
  return t;
}

}  // namespace rayspec
