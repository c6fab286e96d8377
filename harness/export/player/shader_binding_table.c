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

static rs_regions rs_write_sbt(VkPipeline pipeline) {
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rt = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &rt};
  rs_regions out;
  uint8_t* handles;
  VkDeviceSize raygen_stride, miss_stride, hit_stride, miss_at, hit_at, total;
  rs_buffer table;
  vkGetPhysicalDeviceProperties2(rs_physical, &props);
  handles = malloc((size_t)RS_GROUP_COUNT * rt.shaderGroupHandleSize);
  rs_check(rs_group_handles(rs_device, pipeline, 0, RS_GROUP_COUNT,
                            (size_t)RS_GROUP_COUNT * rt.shaderGroupHandleSize, handles),
           "vkGetRayTracingShaderGroupHandlesKHR");
  raygen_stride =
      rs_align(rt.shaderGroupHandleSize + RS_RECORD_DATA_BYTES, rt.shaderGroupHandleAlignment);
  miss_stride = rs_align(rt.shaderGroupHandleSize + RS_RECORD_DATA_BYTES + RS_MISS_PADDING,
                         rt.shaderGroupHandleAlignment);
  hit_stride = rs_align(rt.shaderGroupHandleSize + RS_RECORD_DATA_BYTES + RS_HIT_PADDING,
                        rt.shaderGroupHandleAlignment);
  if (miss_stride > rt.maxShaderGroupStride || hit_stride > rt.maxShaderGroupStride)
    rs_unsupported("an SBT stride within maxShaderGroupStride");
  miss_at = rs_align(raygen_stride, rt.shaderGroupBaseAlignment);
  hit_at = rs_align(miss_at + miss_stride * RS_MISS_RECORDS, rt.shaderGroupBaseAlignment);
  total = hit_at + hit_stride * RS_HIT_RECORDS;
  table = rs_make_buffer(total + rt.shaderGroupBaseAlignment,
                         VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR, NULL);
  {
    VkDeviceAddress base = rs_align(table.address, rt.shaderGroupBaseAlignment);
    uint8_t* bytes = (uint8_t*)table.mapped + (base - table.address);
    out.raygen = rs_region(bytes, base, 0, raygen_stride, &rs_raygen_record, 1, handles,
                           rt.shaderGroupHandleSize);
    out.miss = rs_region(bytes, base, miss_at, miss_stride, rs_miss_records, RS_MISS_RECORDS,
                         handles, rt.shaderGroupHandleSize);
    out.hit = rs_region(bytes, base, hit_at, hit_stride, rs_hit_records, RS_HIT_RECORDS, handles,
                        rt.shaderGroupHandleSize);
    memset(&out.callable, 0, sizeof out.callable);
  }
  free(handles);
  return out;
}

