/* ---- Acceleration structures -------------------------------------------- */

/* One structure of `type` over `geos`, built by its own submission. */
static VkDeviceAddress rs_build(VkAccelerationStructureTypeKHR type,
                                const VkAccelerationStructureGeometryKHR* geos, uint32_t count,
                                const VkAccelerationStructureBuildRangeInfoKHR* ranges,
                                VkAccelerationStructureKHR* out) {
  VkAccelerationStructureBuildGeometryInfoKHR info = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  VkAccelerationStructureBuildSizesInfoKHR sizes = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  VkAccelerationStructureCreateInfoKHR create = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  VkAccelerationStructureDeviceAddressInfoKHR where = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  uint32_t *max_primitives = calloc(count ? count : 1, sizeof(uint32_t)), i;
  rs_buffer storage, scratch;
  VkCommandBuffer cmd;
  for (i = 0; i < count; ++i) max_primitives[i] = ranges[i].primitiveCount;
  info.type = type;
  info.flags = RS_BUILD_FLAGS;
  info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  info.geometryCount = count;
  info.pGeometries = geos;
  rs_build_sizes(rs_device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info, max_primitives,
                 &sizes);
  free(max_primitives);
  storage = rs_make_buffer(sizes.accelerationStructureSize,
                           VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR, NULL);
  scratch = rs_make_buffer(sizes.buildScratchSize + 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, NULL);
  create.buffer = storage.buffer;
  create.size = sizes.accelerationStructureSize;
  create.type = type;
  rs_check(rs_create_as(rs_device, &create, NULL, out), "vkCreateAccelerationStructureKHR");
  info.dstAccelerationStructure = *out;
  info.scratchData.deviceAddress = (scratch.address + 255) & ~(VkDeviceAddress)255;
  cmd = rs_begin();
  rs_cmd_build(cmd, 1, &info, &ranges);
  rs_submit(cmd);
  where.accelerationStructure = *out;
  return rs_as_address(rs_device, &where);
}

static const VkBufferUsageFlags rs_input_usage =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;

static VkDeviceAddress rs_input(const uint8_t* bytes, size_t n) {
  return n ? rs_make_buffer(n, rs_input_usage, bytes).address : 0;
}

static void rs_describe_triangles(VkAccelerationStructureGeometryTrianglesDataKHR* t,
                                  const rs_geometry* g) {
  t->sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
  t->vertexFormat = g->format;
  t->vertexStride = g->stride;
  t->maxVertex = g->max_vertex;
  t->indexType = g->index_type;
  t->vertexData.deviceAddress = rs_input(g->vertices, g->vertex_bytes);
  t->indexData.deviceAddress = rs_input(g->indices, g->index_bytes);
  t->transformData.deviceAddress = rs_input(g->transform, g->transform_bytes);
}

static void rs_describe_aabbs(VkAccelerationStructureGeometryAabbsDataKHR* a,
                              const rs_geometry* g) {
  a->sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
  a->stride = g->stride;
  a->data.deviceAddress = rs_input(g->vertices, g->vertex_bytes);
}

static VkDeviceAddress rs_build_blas(const rs_blas* b) {
  VkAccelerationStructureGeometryKHR geos[RS_MAX_GEOMETRIES];
  VkAccelerationStructureBuildRangeInfoKHR ranges[RS_MAX_GEOMETRIES];
  VkAccelerationStructureKHR as;
  uint32_t i;
  for (i = 0; i < b->geometry_count; ++i) {
    const rs_geometry* g = &rs_geometries[b->first_geometry + i];
    memset(&geos[i], 0, sizeof geos[i]);
    geos[i].sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR;
    geos[i].geometryType = g->type;
    geos[i].flags = g->flags;
    if (g->type == VK_GEOMETRY_TYPE_AABBS_KHR)
      rs_describe_aabbs(&geos[i].geometry.aabbs, g);
    else
      rs_describe_triangles(&geos[i].geometry.triangles, g);
    ranges[i] = g->range;
  }
  return rs_build(VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, geos, b->geometry_count, ranges,
                  &as);
}

/* NotSupported where the device cannot build from a geometry's vertex format. */
static void rs_check_vertex_formats(void) {
  uint32_t i;
  for (i = 0; i < sizeof rs_geometries / sizeof rs_geometries[0]; ++i) {
    VkFormatProperties p;
    if (rs_geometries[i].type != VK_GEOMETRY_TYPE_TRIANGLES_KHR) continue;
    vkGetPhysicalDeviceFormatProperties(rs_physical, rs_geometries[i].format, &p);
    if (p.bufferFeatures & VK_FORMAT_FEATURE_ACCELERATION_STRUCTURE_VERTEX_BUFFER_BIT_KHR) continue;
    printf(
        "NotSupported: triangles.vertex_format %s: the device cannot build acceleration "
        "structures from it\n",
        rs_geometries[i].format_name);
    exit(77);
  }
}

static VkAccelerationStructureKHR rs_build_scene(void) {
  VkDeviceAddress blas[RS_BLAS_COUNT];
  VkAccelerationStructureInstanceKHR instances[RS_INSTANCE_COUNT];
  VkAccelerationStructureGeometryKHR geo = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  VkAccelerationStructureBuildRangeInfoKHR range = {RS_INSTANCE_COUNT, 0, 0, 0};
  VkAccelerationStructureKHR tlas;
  uint32_t i;
  rs_check_vertex_formats();
  for (i = 0; i < RS_BLAS_COUNT; ++i) blas[i] = rs_build_blas(&rs_blases[i]);
  memset(instances, 0, sizeof instances);
  for (i = 0; i < RS_INSTANCE_COUNT; ++i) {
    const rs_instance* in = &rs_instances[i];
    memcpy(&instances[i].transform, in->transform, sizeof in->transform);
    instances[i].instanceCustomIndex = in->custom_index;
    instances[i].mask = in->mask;
    instances[i].instanceShaderBindingTableRecordOffset = in->sbt_offset;
    instances[i].flags = in->flags;
    instances[i].accelerationStructureReference = in->blas == RS_NONE ? 0 : blas[in->blas];
  }
  geo.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geo.geometry.instances.sType =
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  geo.geometry.instances.data.deviceAddress = rs_input((const uint8_t*)instances, sizeof instances);
  rs_build(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, &geo, 1, &range, &tlas);
  return tlas;
}
