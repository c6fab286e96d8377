/* ---- The scene built: bottom levels, then the top levels over them ------ */

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

/* BLAS b's geometries in `state`. */
static void rs_describe_blas(uint32_t state, uint32_t b, rs_inputs* in) {
  const rs_blas* blas = &rs_blases[state * RS_BLAS_COUNT + b];
  uint32_t i;
  memset(in, 0, sizeof *in);
  in->count = blas->geometry_count;
  for (i = 0; i < blas->geometry_count; ++i) {
    const rs_geometry* g = &rs_geometries[blas->first_geometry + i];
    in->geos[i].sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR;
    in->geos[i].geometryType = g->type;
    in->geos[i].flags = g->flags;
    if (g->type == VK_GEOMETRY_TYPE_AABBS_KHR)
      rs_describe_aabbs(&in->geos[i].geometry.aabbs, g);
    else
      rs_describe_triangles(&in->geos[i].geometry.triangles, g);
    in->ranges[i] = g->range;
  }
}

/* Top level `level` in `state`: every instance of the state in order, those
   of the other levels (and those without a BLAS) with reference 0. */
static void rs_describe_tlas(uint32_t state, uint32_t level, rs_inputs* in) {
  VkAccelerationStructureInstanceKHR instances[RS_INSTANCE_COUNT];
  uint32_t i;
  memset(instances, 0, sizeof instances);
  for (i = 0; i < RS_INSTANCE_COUNT; ++i) {
    const rs_instance* inst = &rs_instances[state * RS_INSTANCE_COUNT + i];
    memcpy(&instances[i].transform, inst->transform, sizeof inst->transform);
    instances[i].instanceCustomIndex = inst->custom_index;
    instances[i].mask = inst->mask;
    instances[i].instanceShaderBindingTableRecordOffset = inst->sbt_offset;
    instances[i].flags = inst->flags;
    instances[i].accelerationStructureReference =
        inst->tlas == level && inst->blas != RS_NONE ? rs_blas_address[inst->blas] : 0;
  }
  memset(in, 0, sizeof *in);
  in->count = 1;
  in->geos[0].sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR;
  in->geos[0].geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  in->geos[0].geometry.instances.sType =
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  in->geos[0].geometry.instances.data.deviceAddress =
      rs_input((const uint8_t*)instances, sizeof instances);
  in->ranges[0].primitiveCount = RS_INSTANCE_COUNT;
}

/* One level: built, then each update in turn, the queries and the copy where
   scene.build.order puts them (RS_QUERY_AT, RS_COPY_AT: before that update;
   after the last: RS_STATE_COUNT - 1). */
static void rs_run_level(rs_level* l) {
  uint32_t i, k;
  for (i = 0; i < l->count; ++i) rs_build_first(l, i);
  for (k = 0; k < RS_STATE_COUNT; ++k) {
    if (k == RS_QUERY_AT) rs_query_level(l);
    if (k == RS_COPY_AT) rs_copy_structures(l);
    if (k + 1 == RS_STATE_COUNT) break;
    for (i = 0; i < l->count; ++i) rs_update(l, k + 1, i);
  }
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

/* The BLASes some instance of the first state references, then the top
   levels over them as they end up (copied, updated): the top levels'
   structures into `tlas`. */
static void rs_build_scene(VkAccelerationStructureKHR* tlas) {
  static rs_level bottom, top;
  uint32_t i;
  rs_check_vertex_formats();
  bottom.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
  bottom.name = "BLAS";
  bottom.describe = rs_describe_blas;
  for (i = 0; i < RS_BLAS_COUNT; ++i)
    if (rs_blases[i].reached) bottom.index[bottom.count++] = i;
  rs_run_level(&bottom);
  for (i = 0; i < bottom.count; ++i)
    rs_blas_address[bottom.index[i]] = rs_structure_address(bottom.handle[i]);
  top.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
  top.name = "TLAS";
  top.describe = rs_describe_tlas;
  for (i = 0; i < RS_TLAS_COUNT; ++i) top.index[top.count++] = i;
  rs_run_level(&top);
  for (i = 0; i < RS_TLAS_COUNT; ++i) tlas[i] = top.handle[i];
}
