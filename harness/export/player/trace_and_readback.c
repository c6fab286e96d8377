/* ---- main: build, trace, read back, compare ----------------------------- */

int main(int argc, char** argv) {
  rs_io io;
  VkAccelerationStructureKHR tlas;
  VkDescriptorSetLayout set_layout;
  VkPipelineLayoutCreateInfo layout_info = {VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  VkPipelineLayout layout;
  VkPipeline pipeline;
  VkDescriptorSet set;
  VkCommandBuffer cmd;
  rs_regions sbt;
  int failures;
  printf("case: %s\n", RS_CASE_NAME);
  rs_create_instance();
  rs_pick_device(argc, argv);
  rs_create_device();
  rs_load_functions();
  tlas = rs_build_scene();
  io = rs_make_io();
  set = rs_bind(&set_layout, tlas, &io);
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  rs_check(vkCreatePipelineLayout(rs_device, &layout_info, NULL, &layout),
           "vkCreatePipelineLayout");
  pipeline = rs_create_pipeline(layout);
  sbt = rs_write_sbt(pipeline);
  cmd = rs_begin();
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, layout, 0, 1, &set, 0, NULL);
  rs_cmd_trace(cmd, &sbt.raygen, &sbt.miss, &sbt.hit, &sbt.callable, RS_LAUNCH_WIDTH,
               RS_LAUNCH_HEIGHT, RS_LAUNCH_DEPTH);
  rs_submit(cmd);
  failures = rs_compare((const uint32_t*)io.records.mapped, (const uint32_t*)io.counters.mapped);
  vkDeviceWaitIdle(rs_device);
  if (failures) {
    printf("FAIL: %d of the checks differ from the reference model\n", failures);
    return 1;
  }
  printf("PASS: %u rays and %u counters as the reference model expects\n", (unsigned)rs_ray_count,
         (unsigned)RS_COUNTER_COUNT);
  return 0;
}
