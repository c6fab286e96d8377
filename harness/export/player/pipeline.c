/* ---- The ray tracing pipeline ------------------------------------------- */

/* NotSupported where the case recurses deeper than the device allows. */
static void rs_check_recursion(void) {
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rt = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &rt};
  vkGetPhysicalDeviceProperties2(rs_physical, &props);
  if (RS_MAX_RECURSION > rt.maxRayRecursionDepth) {
    printf("NotSupported: max_recursion %u > device maxRayRecursionDepth %u\n",
           (unsigned)RS_MAX_RECURSION, (unsigned)rt.maxRayRecursionDepth);
    exit(77);
  }
}

static VkPipeline rs_create_pipeline(VkPipelineLayout layout) {
  VkPipelineShaderStageCreateInfo stages[RS_SHADER_COUNT];
  VkRayTracingShaderGroupCreateInfoKHR groups[RS_GROUP_COUNT];
  VkRayTracingPipelineCreateInfoKHR info = {VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
  VkPipeline pipeline;
  uint32_t i;
  rs_check_recursion();
  for (i = 0; i < RS_SHADER_COUNT; ++i) {
    VkShaderModuleCreateInfo module = {VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    memset(&stages[i], 0, sizeof stages[i]);
    module.codeSize = rs_shaders[i].bytes;
    module.pCode = rs_shaders[i].code;
    stages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[i].stage = rs_shaders[i].stage;
    stages[i].pName = "main";
    rs_check(vkCreateShaderModule(rs_device, &module, NULL, &stages[i].module),
             "vkCreateShaderModule");
  }
  for (i = 0; i < RS_GROUP_COUNT; ++i) {
    memset(&groups[i], 0, sizeof groups[i]);
    groups[i].sType = VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR;
    groups[i].type = rs_groups[i].type;
    groups[i].generalShader =
        rs_groups[i].general == RS_NONE ? VK_SHADER_UNUSED_KHR : rs_groups[i].general;
    groups[i].closestHitShader =
        rs_groups[i].closest_hit == RS_NONE ? VK_SHADER_UNUSED_KHR : rs_groups[i].closest_hit;
    groups[i].anyHitShader =
        rs_groups[i].any_hit == RS_NONE ? VK_SHADER_UNUSED_KHR : rs_groups[i].any_hit;
    groups[i].intersectionShader =
        rs_groups[i].intersection == RS_NONE ? VK_SHADER_UNUSED_KHR : rs_groups[i].intersection;
  }
  info.stageCount = RS_SHADER_COUNT;
  info.pStages = stages;
  info.groupCount = RS_GROUP_COUNT;
  info.pGroups = groups;
  info.maxPipelineRayRecursionDepth = RS_MAX_RECURSION;
  info.layout = layout;
  rs_check(
      rs_create_pipelines(rs_device, VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &info, NULL, &pipeline),
      "vkCreateRayTracingPipelinesKHR");
  return pipeline;
}

/* Raygen as a compute shader (pipeline.traces: ray_query_compute): a compute
   pipeline of the one stage. */
static VkPipeline rs_create_compute_pipeline(VkPipelineLayout layout) {
  VkShaderModuleCreateInfo module = {VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  VkComputePipelineCreateInfo info = {VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  VkPipeline pipeline;
  module.codeSize = rs_shaders[0].bytes;
  module.pCode = rs_shaders[0].code;
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.pName = "main";
  rs_check(vkCreateShaderModule(rs_device, &module, NULL, &info.stage.module),
           "vkCreateShaderModule");
  info.layout = layout;
  rs_check(vkCreateComputePipelines(rs_device, VK_NULL_HANDLE, 1, &info, NULL, &pipeline),
           "vkCreateComputePipelines");
  return pipeline;
}
