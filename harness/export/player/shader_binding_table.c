/* ---- The shader binding table ------------------------------------------- */

static VkDeviceSize rs_align(VkDeviceSize v, VkDeviceSize a) {
  return (v + a - 1) / a * a;
}

typedef struct {
  VkStridedDeviceAddressRegionKHR raygen, miss, hit, callable;
} rs_regions;

/* Writes one region's records at `offset` of the table; the region it makes. */
static VkStridedDeviceAddressRegionKHR rs_region(uint8_t* table, VkDeviceAddress base,
                                                 VkDeviceSize offset, VkDeviceSize stride,
                                                 const rs_record* records, uint32_t count,
                                                 const uint8_t* handles, uint32_t handle_size) {
  VkStridedDeviceAddressRegionKHR r = {0, 0, 0};
  uint32_t i;
  if (!count) return r;
  for (i = 0; i < count; ++i) {
    uint8_t* at = table + offset + i * stride;
    if (records[i].group == RS_NONE) continue;
    memcpy(at, handles + (size_t)records[i].group * handle_size, handle_size);
    memcpy(at + handle_size, records[i].data, records[i].data_words * 4u);
  }
  r.deviceAddress = base + offset;
  r.stride = stride;
  r.size = stride * count;
  return r;
}

/* The regions in table order (raygen, miss, hit, callable): each one's
   records and padding. The raygen region holds one record, unpadded. */
typedef struct {
  const rs_record* records;
  uint32_t count, padding;
} rs_region_records;

static rs_regions rs_write_sbt(VkPipeline pipeline) {
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rt = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &rt};
  const rs_region_records regions[4] = {
      {&rs_raygen_record, 1, 0},
      {rs_miss_records, RS_MISS_RECORDS, RS_MISS_PADDING},
      {rs_hit_records, RS_HIT_RECORDS, RS_HIT_PADDING},
      {rs_callable_records, RS_CALLABLE_RECORDS, RS_CALLABLE_PADDING}};
  VkStridedDeviceAddressRegionKHR* made[4];
  VkDeviceSize stride[4], at[4], end = 0;
  rs_regions out;
  uint8_t *handles, *bytes;
  VkDeviceAddress base;
  rs_buffer table;
  uint32_t r;
  vkGetPhysicalDeviceProperties2(rs_physical, &props);
  handles = malloc((size_t)RS_GROUP_COUNT * rt.shaderGroupHandleSize);
  rs_check(rs_group_handles(rs_device, pipeline, 0, RS_GROUP_COUNT,
                            (size_t)RS_GROUP_COUNT * rt.shaderGroupHandleSize, handles),
           "vkGetRayTracingShaderGroupHandlesKHR");
  for (r = 0; r < 4; ++r) {
    stride[r] = rs_align(rt.shaderGroupHandleSize + RS_RECORD_DATA_BYTES + regions[r].padding,
                         rt.shaderGroupHandleAlignment);
    if (r && stride[r] > rt.maxShaderGroupStride)
      rs_unsupported("an SBT stride within maxShaderGroupStride");
    at[r] = rs_align(end, rt.shaderGroupBaseAlignment);
    end = at[r] + stride[r] * regions[r].count;
  }
  table = rs_make_buffer(end + rt.shaderGroupBaseAlignment,
                         VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR, NULL);
  base = rs_align(table.address, rt.shaderGroupBaseAlignment);
  bytes = (uint8_t*)table.mapped + (base - table.address);
  made[0] = &out.raygen;
  made[1] = &out.miss;
  made[2] = &out.hit;
  made[3] = &out.callable;
  for (r = 0; r < 4; ++r)
    *made[r] = rs_region(bytes, base, at[r], stride[r], regions[r].records, regions[r].count,
                         handles, rt.shaderGroupHandleSize);
  free(handles);
  return out;
}
