/* ---- Acceleration structures -------------------------------------------- */

/* The structures of one level, bottom or top, as rayspec's builds make them
   (harness/vulkan/level_builds.cpp): each built from the scene as
   first built, then updated to each later state (scene.update) and copied
   (scene.build.copy) where the case orders it. */
#define RS_MAX_LEVEL (RS_BLAS_COUNT > RS_TLAS_COUNT ? RS_BLAS_COUNT : RS_TLAS_COUNT)
typedef struct {
  VkAccelerationStructureGeometryKHR geos[RS_MAX_GEOMETRIES];
  VkAccelerationStructureBuildRangeInfoKHR ranges[RS_MAX_GEOMETRIES];
  uint32_t count;
} rs_inputs;
typedef struct {
  VkAccelerationStructureTypeKHR type;
  const char* name;             /* "BLAS", "TLAS" */
  uint32_t count;               /* its structures */
  uint32_t index[RS_MAX_LEVEL]; /* each one's BLAS or top level */
  VkAccelerationStructureKHR handle[RS_MAX_LEVEL];
  VkDeviceSize built[RS_MAX_LEVEL]; /* accelerationStructureSize as first built */
  VkDeviceSize size[RS_MAX_LEVEL];  /* the size the current structure was created with */
  VkDeviceSize room[RS_MAX_LEVEL];  /* room for a build: 0 in a compacted copy */
  VkDeviceSize build_scratch[RS_MAX_LEVEL], update_scratch[RS_MAX_LEVEL];
  /* the inputs of structure `index` in state `state` (0: as first built) */
  void (*describe)(uint32_t state, uint32_t index, rs_inputs* in);
} rs_level;

/* Each BLAS's address once the bottom levels are final (0: not built). */
static VkDeviceAddress rs_blas_address[RS_BLAS_COUNT];

/* A structure of `size` bytes over a buffer of its own. */
static VkAccelerationStructureKHR rs_create_structure(VkAccelerationStructureTypeKHR type,
                                                      VkDeviceSize size) {
  VkAccelerationStructureCreateInfoKHR create = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  VkAccelerationStructureKHR as;
  rs_buffer storage =
      rs_make_buffer(size, VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR, NULL);
  create.buffer = storage.buffer;
  create.size = size;
  create.type = type;
  rs_check(rs_create_as(rs_device, &create, NULL, &as), "vkCreateAccelerationStructureKHR");
  return as;
}

static VkDeviceAddress rs_structure_address(VkAccelerationStructureKHR as) {
  VkAccelerationStructureDeviceAddressInfoKHR where = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  where.accelerationStructure = as;
  return rs_as_address(rs_device, &where);
}

static VkAccelerationStructureBuildGeometryInfoKHR rs_build_info(
    VkAccelerationStructureTypeKHR type, const rs_inputs* in) {
  VkAccelerationStructureBuildGeometryInfoKHR info = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  info.type = type;
  info.flags = RS_BUILD_FLAGS;
  info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  info.geometryCount = in->count;
  info.pGeometries = in->geos;
  return info;
}

/* One build (src VK_NULL_HANDLE) or update (MODE_UPDATE from src) into dst,
   by its own submission, in scratch of scratch_size bytes. */
static void rs_build_into(VkAccelerationStructureTypeKHR type, VkAccelerationStructureKHR src,
                          VkAccelerationStructureKHR dst, const rs_inputs* in,
                          VkDeviceSize scratch_size) {
  VkAccelerationStructureBuildGeometryInfoKHR info = rs_build_info(type, in);
  const VkAccelerationStructureBuildRangeInfoKHR* ranges = in->ranges;
  rs_buffer scratch = rs_make_buffer(scratch_size + 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, NULL);
  VkCommandBuffer cmd;
  if (src != VK_NULL_HANDLE) info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR;
  info.srcAccelerationStructure = src;
  info.dstAccelerationStructure = dst;
  info.scratchData.deviceAddress = (scratch.address + 255) & ~(VkDeviceAddress)255;
  cmd = rs_begin();
  rs_cmd_build(cmd, 1, &info, &ranges);
  rs_submit(cmd);
}

/* Structure i of the level built from the first state: created at the size
   the device asks for, its scratch sizes kept for its updates. */
static void rs_build_first(rs_level* l, uint32_t i) {
  VkAccelerationStructureBuildSizesInfoKHR sizes = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  VkAccelerationStructureBuildGeometryInfoKHR info;
  uint32_t max_primitives[RS_MAX_GEOMETRIES], g;
  rs_inputs in;
  l->describe(0, l->index[i], &in);
  for (g = 0; g < in.count; ++g) max_primitives[g] = in.ranges[g].primitiveCount;
  info = rs_build_info(l->type, &in);
  rs_build_sizes(rs_device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info, max_primitives,
                 &sizes);
  l->built[i] = l->size[i] = l->room[i] = sizes.accelerationStructureSize;
  l->build_scratch[i] = sizes.buildScratchSize;
  l->update_scratch[i] = sizes.updateScratchSize;
  l->handle[i] = rs_create_structure(l->type, sizes.accelerationStructureSize);
  rs_build_into(l->type, VK_NULL_HANDLE, l->handle[i], &in, sizes.buildScratchSize);
}

/* Structure i updated to `state` (R-AS-UPDATE): in place, or into a new
   structure (scene.build.update_into other); a top level rebuilt instead
   (scene.build.tlas_update rebuild, MODE_BUILD), into a new structure of its
   build size where it has no room for a build (a compacted copy). */
static void rs_update(rs_level* l, uint32_t state, uint32_t i) {
  const int rebuild = RS_TLAS_REBUILT && l->type == VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
  VkAccelerationStructureKHR dst = l->handle[i];
  rs_inputs in;
  l->describe(state, l->index[i], &in);
  if (RS_UPDATE_INTO_OTHER || (rebuild && l->room[i] < l->built[i])) {
    dst = rs_create_structure(l->type, l->built[i]);
    l->size[i] = l->room[i] = l->built[i];
  }
  rs_build_into(l->type, rebuild ? VK_NULL_HANDLE : l->handle[i], dst, &in,
                rebuild ? l->build_scratch[i] : l->update_scratch[i]);
  l->handle[i] = dst;
}

static const VkBufferUsageFlags rs_input_usage =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;

static VkDeviceAddress rs_input(const uint8_t* bytes, size_t n) {
  return n ? rs_make_buffer(n, rs_input_usage, bytes).address : 0;
}
