/* The fixed part of a `rayspec export --format c` reproducer: a generic
 * player of one case, the case's data spliced in by rayspec (export_c.cpp)
 * where the marker line below stands. It creates an instance and a device,
 * builds the bottom levels and the top level from the embedded inputs,
 * creates the ray tracing pipeline from the embedded SPIR-V, writes the
 * shader binding table with the device's handles, binds the buffers, traces,
 * reads the per-ray records and counters back and compares them with the
 * reference model's expectations, embedded. Exit status: 0 PASS, 1 FAIL (the
 * first wrong value: rule, ray, field, expected, observed), 77 NotSupported
 * (the missing feature named), 2 a Vulkan error.
 * This file is compiled only as part of an exported reproducer (C99, the
 * Vulkan loader and libc). */
#include <math.h> /* NAN, INFINITY in the data (macros: no -lm) */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vulkan/vulkan.h>

#define RS_NONE 0xFFFFFFFFu

typedef struct {
  VkShaderStageFlagBits stage;
  const uint32_t* code;
  size_t bytes;
} rs_shader;
typedef struct {
  VkRayTracingShaderGroupTypeKHR type;
  uint32_t general, closest_hit, any_hit, intersection; /* shader indices or RS_NONE */
} rs_group;
typedef struct {
  VkFormat format;
  const char* format_name; /* the case's name of it (triangles.vertex_format) */
  uint32_t stride, max_vertex;
  VkIndexType index_type;
  VkGeometryFlagsKHR flags;
  const uint8_t *vertices, *indices, *transform;
  size_t vertex_bytes, index_bytes, transform_bytes;
  VkAccelerationStructureBuildRangeInfoKHR range;
} rs_geometry;
typedef struct {
  uint32_t first_geometry, geometry_count;
} rs_blas;
typedef struct {
  float transform[12];
  uint32_t custom_index, mask, sbt_offset, flags, blas; /* blas: RS_NONE for none */
} rs_instance;
typedef struct {
  uint32_t group; /* RS_NONE: an all-zero record */
  uint32_t data_words;
  uint32_t data[8];
} rs_record;
enum rs_binding_kind { RS_BIND_TLAS, RS_BIND_RAYS, RS_BIND_RECORDS, RS_BIND_COUNTERS };
typedef struct {
  uint32_t binding;
  enum rs_binding_kind kind;
} rs_binding;
typedef struct {
  const char *name, *rule;
  uint32_t offset, words, is_float, automatic, bit;
  double abs, rel;
} rs_field;
typedef struct {
  uint32_t ray, first_replay, replays;
  const char *reason, *rule;
} rs_ambiguous;
typedef struct {
  const char *name, *rule;
  uint64_t lo, hi;
} rs_counter;

/* RAYSPEC_CASE_DATA */

/* ---- Vulkan plumbing ---------------------------------------------------- */

static PFN_vkGetAccelerationStructureBuildSizesKHR rs_build_sizes;
static PFN_vkCreateAccelerationStructureKHR rs_create_as;
static PFN_vkCmdBuildAccelerationStructuresKHR rs_cmd_build;
static PFN_vkGetAccelerationStructureDeviceAddressKHR rs_as_address;
static PFN_vkCreateRayTracingPipelinesKHR rs_create_pipelines;
static PFN_vkGetRayTracingShaderGroupHandlesKHR rs_group_handles;
static PFN_vkCmdTraceRaysKHR rs_cmd_trace;

static VkInstance rs_instance_handle;
static VkPhysicalDevice rs_physical;
static VkDevice rs_device;
static VkQueue rs_queue;
static uint32_t rs_queue_family;
static VkCommandPool rs_pool;

static void rs_check(VkResult r, const char* what) {
  if (r == VK_SUCCESS) return;
  fprintf(stderr, "Vulkan error %d in %s\n", (int)r, what);
  exit(2);
}

static void rs_unsupported(const char* what) {
  printf("NotSupported: %s\n", what);
  exit(77);
}

static int rs_has_extension(VkPhysicalDevice p, const char* name) {
  uint32_t n = 0, i;
  int found = 0;
  VkExtensionProperties* props;
  vkEnumerateDeviceExtensionProperties(p, NULL, &n, NULL);
  props = calloc(n ? n : 1, sizeof *props);
  vkEnumerateDeviceExtensionProperties(p, NULL, &n, props);
  for (i = 0; i < n; ++i) found = found || strcmp(props[i].extensionName, name) == 0;
  free(props);
  return found;
}

static int rs_has_layer(const char* name) {
  uint32_t n = 0, i;
  int found = 0;
  VkLayerProperties* props;
  vkEnumerateInstanceLayerProperties(&n, NULL);
  props = calloc(n ? n : 1, sizeof *props);
  vkEnumerateInstanceLayerProperties(&n, props);
  for (i = 0; i < n; ++i) found = found || strcmp(props[i].layerName, name) == 0;
  free(props);
  return found;
}

static void rs_create_instance(void) {
  VkApplicationInfo app = {VK_STRUCTURE_TYPE_APPLICATION_INFO};
  VkInstanceCreateInfo info = {VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  const char* layer = "VK_LAYER_KHRONOS_validation";
  app.pApplicationName = "rayspec-export";
  app.apiVersion = VK_API_VERSION_1_2;
  info.pApplicationInfo = &app;
#ifdef RAYSPEC_VALIDATION
  if (rs_has_layer(layer)) {
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
  } else {
    fprintf(stderr, "note: %s is not installed; running without it\n", layer);
  }
#else
  (void)layer;
  (void)rs_has_layer;
#endif
  rs_check(vkCreateInstance(&info, NULL, &rs_instance_handle), "vkCreateInstance");
}

/* The device argv names (an index, or a part of its name), else the first
 * with VK_KHR_ray_tracing_pipeline. */
static void rs_pick_device(int argc, char** argv) {
  uint32_t n = 0, i;
  VkPhysicalDevice* all;
  const char* want = argc > 1 ? argv[1] : NULL;
  char* end = NULL;
  long index = want ? strtol(want, &end, 10) : -1;
  int by_index = want && end && *end == 0;
  vkEnumeratePhysicalDevices(rs_instance_handle, &n, NULL);
  all = calloc(n ? n : 1, sizeof *all);
  vkEnumeratePhysicalDevices(rs_instance_handle, &n, all);
  for (i = 0; i < n && !rs_physical; ++i) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(all[i], &p);
    if (by_index ? (long)i != index : want && !strstr(p.deviceName, want)) continue;
    if (!rs_has_extension(all[i], VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME)) {
      if (want) rs_unsupported("the device named has no VK_KHR_ray_tracing_pipeline");
      continue;
    }
    rs_physical = all[i];
    printf("device: %s\n", p.deviceName);
  }
  free(all);
  if (!rs_physical) rs_unsupported("no device with VK_KHR_ray_tracing_pipeline (or none named so)");
}

static void rs_create_device(void) {
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR, &as};
  VkPhysicalDeviceVulkan12Features v12 = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                          &rt};
  VkPhysicalDeviceFeatures2 have = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v12};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as_on = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt_on = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR, &as_on};
  VkPhysicalDeviceVulkan12Features v12_on = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                             &rt_on};
  VkPhysicalDeviceFeatures2 on = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v12_on};
  const char* extensions[] = {VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
                              VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                              VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queue = {VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  VkDeviceCreateInfo info = {VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &on};
  VkQueueFamilyProperties families[16];
  uint32_t count = 16;
  vkGetPhysicalDeviceFeatures2(rs_physical, &have);
  if (!rt.rayTracingPipeline) rs_unsupported("rayTracingPipeline");
  if (!as.accelerationStructure) rs_unsupported("accelerationStructure");
  if (!v12.bufferDeviceAddress) rs_unsupported("bufferDeviceAddress");
  rt_on.rayTracingPipeline = as_on.accelerationStructure = v12_on.bufferDeviceAddress = VK_TRUE;
  v12_on.scalarBlockLayout = v12.scalarBlockLayout;
  v12_on.vulkanMemoryModel = v12.vulkanMemoryModel;
  v12_on.vulkanMemoryModelDeviceScope = v12.vulkanMemoryModelDeviceScope;
  on.features.shaderInt64 = have.features.shaderInt64;
  vkGetPhysicalDeviceQueueFamilyProperties(rs_physical, &count, families);
  for (rs_queue_family = 0; rs_queue_family < count; ++rs_queue_family)
    if (families[rs_queue_family].queueFlags & VK_QUEUE_COMPUTE_BIT) break;
  if (rs_queue_family == count) rs_unsupported("a queue family with compute");
  queue.queueFamilyIndex = rs_queue_family;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = 3;
  info.ppEnabledExtensionNames = extensions;
  rs_check(vkCreateDevice(rs_physical, &info, NULL, &rs_device), "vkCreateDevice");
  vkGetDeviceQueue(rs_device, rs_queue_family, 0, &rs_queue);
}

#define RS_PROC(var, type, name)                    \
  var = (type)vkGetDeviceProcAddr(rs_device, name); \
  if (!var) rs_unsupported(name)

static void rs_load_functions(void) {
  VkCommandPoolCreateInfo pool = {VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  RS_PROC(rs_build_sizes, PFN_vkGetAccelerationStructureBuildSizesKHR,
          "vkGetAccelerationStructureBuildSizesKHR");
  RS_PROC(rs_create_as, PFN_vkCreateAccelerationStructureKHR, "vkCreateAccelerationStructureKHR");
  RS_PROC(rs_cmd_build, PFN_vkCmdBuildAccelerationStructuresKHR,
          "vkCmdBuildAccelerationStructuresKHR");
  RS_PROC(rs_as_address, PFN_vkGetAccelerationStructureDeviceAddressKHR,
          "vkGetAccelerationStructureDeviceAddressKHR");
  RS_PROC(rs_create_pipelines, PFN_vkCreateRayTracingPipelinesKHR,
          "vkCreateRayTracingPipelinesKHR");
  RS_PROC(rs_group_handles, PFN_vkGetRayTracingShaderGroupHandlesKHR,
          "vkGetRayTracingShaderGroupHandlesKHR");
  RS_PROC(rs_cmd_trace, PFN_vkCmdTraceRaysKHR, "vkCmdTraceRaysKHR");
  pool.queueFamilyIndex = rs_queue_family;
  rs_check(vkCreateCommandPool(rs_device, &pool, NULL, &rs_pool), "vkCreateCommandPool");
}

/* Every buffer host-visible and coherent, with a device address. */
typedef struct {
  VkBuffer buffer;
  VkDeviceMemory memory;
  void* mapped;
  VkDeviceAddress address;
} rs_buffer;

static uint32_t rs_memory_type(uint32_t bits, VkMemoryPropertyFlags want) {
  VkPhysicalDeviceMemoryProperties mp;
  uint32_t i;
  vkGetPhysicalDeviceMemoryProperties(rs_physical, &mp);
  for (i = 0; i < mp.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
  rs_unsupported("host-visible coherent memory for a buffer");
  return 0;
}

static rs_buffer rs_make_buffer(VkDeviceSize bytes, VkBufferUsageFlags usage, const void* data) {
  rs_buffer b;
  VkBufferCreateInfo info = {VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  VkMemoryAllocateFlagsInfo flags = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  VkMemoryAllocateInfo alloc = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, &flags};
  VkBufferDeviceAddressInfo where = {VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
  VkMemoryRequirements req;
  info.size = bytes ? bytes : 16;
  info.usage = usage | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  rs_check(vkCreateBuffer(rs_device, &info, NULL, &b.buffer), "vkCreateBuffer");
  vkGetBufferMemoryRequirements(rs_device, b.buffer, &req);
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex =
      rs_memory_type(req.memoryTypeBits,
                     VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  rs_check(vkAllocateMemory(rs_device, &alloc, NULL, &b.memory), "vkAllocateMemory");
  rs_check(vkBindBufferMemory(rs_device, b.buffer, b.memory, 0), "vkBindBufferMemory");
  rs_check(vkMapMemory(rs_device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
  memset(b.mapped, 0, (size_t)info.size);
  if (data && bytes) memcpy(b.mapped, data, (size_t)bytes);
  where.buffer = b.buffer;
  b.address = vkGetBufferDeviceAddress(rs_device, &where);
  return b;
}

/* Everything before (earlier submissions included) made visible to `stage`. */
static void rs_barrier(VkCommandBuffer cmd, VkPipelineStageFlags stage, VkAccessFlags access) {
  VkMemoryBarrier m = {VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  m.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  m.dstAccessMask = access;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, stage, 0, 1, &m, 0, NULL, 0, NULL);
}

static VkCommandBuffer rs_begin(void) {
  VkCommandBufferAllocateInfo alloc = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  VkCommandBufferBeginInfo begin = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  VkCommandBuffer cmd;
  alloc.commandPool = rs_pool;
  alloc.commandBufferCount = 1;
  rs_check(vkAllocateCommandBuffers(rs_device, &alloc, &cmd), "vkAllocateCommandBuffers");
  rs_check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  rs_barrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
             VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
  return cmd;
}

static void rs_submit(VkCommandBuffer cmd) {
  VkSubmitInfo submit = {VK_STRUCTURE_TYPE_SUBMIT_INFO};
  rs_barrier(cmd, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  rs_check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  rs_check(vkQueueSubmit(rs_queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
  rs_check(vkQueueWaitIdle(rs_queue), "vkQueueWaitIdle");
}

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

static VkDeviceAddress rs_build_blas(const rs_blas* b) {
  VkAccelerationStructureGeometryKHR geos[RS_MAX_GEOMETRIES];
  VkAccelerationStructureBuildRangeInfoKHR ranges[RS_MAX_GEOMETRIES];
  VkAccelerationStructureKHR as;
  uint32_t i;
  for (i = 0; i < b->geometry_count; ++i) {
    const rs_geometry* g = &rs_geometries[b->first_geometry + i];
    VkAccelerationStructureGeometryTrianglesDataKHR* t = &geos[i].geometry.triangles;
    memset(&geos[i], 0, sizeof geos[i]);
    geos[i].sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR;
    geos[i].geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
    geos[i].flags = g->flags;
    t->sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
    t->vertexFormat = g->format;
    t->vertexStride = g->stride;
    t->maxVertex = g->max_vertex;
    t->indexType = g->index_type;
    t->vertexData.deviceAddress = rs_input(g->vertices, g->vertex_bytes);
    t->indexData.deviceAddress = rs_input(g->indices, g->index_bytes);
    t->transformData.deviceAddress = rs_input(g->transform, g->transform_bytes);
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

/* ---- Pipeline, shader binding table, descriptors ------------------------ */

static VkPipeline rs_create_pipeline(VkPipelineLayout layout) {
  VkPipelineShaderStageCreateInfo stages[RS_SHADER_COUNT];
  VkRayTracingShaderGroupCreateInfoKHR groups[RS_GROUP_COUNT];
  VkRayTracingPipelineCreateInfoKHR info = {VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
  VkPipeline pipeline;
  uint32_t i;
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

typedef struct {
  rs_buffer rays, records, records_ref, counters;
} rs_io;

static VkDescriptorSet rs_bind(VkDescriptorSetLayout* set_layout, VkAccelerationStructureKHR tlas,
                               const rs_io* io) {
  VkDescriptorSetLayoutBinding b[RS_BINDING_COUNT];
  VkWriteDescriptorSet w[RS_BINDING_COUNT];
  VkDescriptorBufferInfo buffers[RS_BINDING_COUNT];
  VkWriteDescriptorSetAccelerationStructureKHR as = {
      VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
  VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1},
                                   {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, RS_BINDING_COUNT}};
  VkDescriptorSetLayoutCreateInfo layout = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  VkDescriptorPoolCreateInfo pool = {VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  VkDescriptorSetAllocateInfo alloc = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  VkDescriptorPool pool_handle;
  VkDescriptorSet set;
  uint32_t i;
  as.accelerationStructureCount = 1;
  as.pAccelerationStructures = &tlas;
  for (i = 0; i < RS_BINDING_COUNT; ++i) {
    const rs_buffer* src = rs_bindings[i].kind == RS_BIND_RAYS      ? &io->rays
                           : rs_bindings[i].kind == RS_BIND_RECORDS ? &io->records_ref
                                                                    : &io->counters;
    int is_tlas = rs_bindings[i].kind == RS_BIND_TLAS;
    memset(&b[i], 0, sizeof b[i]);
    memset(&w[i], 0, sizeof w[i]);
    b[i].binding = w[i].dstBinding = rs_bindings[i].binding;
    b[i].descriptorType = w[i].descriptorType =
        is_tlas ? VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    b[i].descriptorCount = w[i].descriptorCount = 1;
    b[i].stageFlags = VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR |
                      VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_ANY_HIT_BIT_KHR |
                      VK_SHADER_STAGE_INTERSECTION_BIT_KHR | VK_SHADER_STAGE_CALLABLE_BIT_KHR;
    w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    buffers[i].buffer = src->buffer;
    buffers[i].offset = 0;
    buffers[i].range = VK_WHOLE_SIZE;
    if (is_tlas)
      w[i].pNext = &as;
    else
      w[i].pBufferInfo = &buffers[i];
  }
  layout.bindingCount = RS_BINDING_COUNT;
  layout.pBindings = b;
  rs_check(vkCreateDescriptorSetLayout(rs_device, &layout, NULL, set_layout),
           "vkCreateDescriptorSetLayout");
  pool.maxSets = 1;
  pool.poolSizeCount = 2;
  pool.pPoolSizes = sizes;
  rs_check(vkCreateDescriptorPool(rs_device, &pool, NULL, &pool_handle), "vkCreateDescriptorPool");
  alloc.descriptorPool = pool_handle;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = set_layout;
  rs_check(vkAllocateDescriptorSets(rs_device, &alloc, &set), "vkAllocateDescriptorSets");
  for (i = 0; i < RS_BINDING_COUNT; ++i) w[i].dstSet = set;
  vkUpdateDescriptorSets(rs_device, RS_BINDING_COUNT, w, 0, NULL);
  return set;
}

/* ---- The comparison ----------------------------------------------------- */

static float rs_float(uint32_t w) {
  float f;
  memcpy(&f, &w, 4);
  return f;
}

static double rs_abs(double v) {
  return v < 0 ? -v : v;
}
static int rs_nan(float v) {
  return v != v;
}

static int rs_written(const uint32_t* rec, const rs_field* f) {
  return f->automatic || ((rec[f->bit / 32] >> (f->bit % 32)) & 1u);
}

/* One field of a record as the expected one has it (the judge's sameField). */
static int rs_same(const rs_field* f, const uint32_t* d, const uint32_t* m) {
  uint32_t k;
  if (rs_written(d, f) != rs_written(m, f)) return 0;
  if (!rs_written(d, f)) return 1;
  for (k = 0; k < f->words; ++k) {
    uint32_t dw = d[f->offset + k], mw = m[f->offset + k];
    if (!f->is_float) {
      if (dw != mw) return 0;
    } else {
      float df = rs_float(dw), mf = rs_float(mw);
      double diff = rs_abs((double)df - (double)mf), scale = rs_abs((double)mf);
      if (rs_nan(df) || rs_nan(mf)) {
        if (!(rs_nan(df) && rs_nan(mf))) return 0;
      } else if (df != mf && diff > f->abs + f->rel * (scale > 1.0 ? scale : 1.0)) {
        return 0;
      }
    }
  }
  return 1;
}

static void rs_print_value(const rs_field* f, const uint32_t* rec) {
  uint32_t k;
  if (!rs_written(rec, f)) {
    printf("(not written)");
    return;
  }
  for (k = 0; k < f->words; ++k) {
    if (f->is_float)
      printf(k ? " %.9g" : "%.9g", (double)rs_float(rec[f->offset + k]));
    else
      printf(k ? " %u" : "%u", rec[f->offset + k]);
  }
}

/* The counts as variables: a loop up to a count of 0 draws no warning. */
static const uint32_t rs_ambiguous_count = RS_AMBIGUOUS_COUNT;
static const uint32_t rs_counter_count = RS_COUNTER_COUNT;
static const uint32_t rs_ray_count = RS_RAY_COUNT;

static const rs_ambiguous* rs_ambiguity(uint32_t ray) {
  uint32_t i;
  for (i = 0; i < rs_ambiguous_count; ++i)
    if (rs_ambiguous_rays[i].ray == ray) return &rs_ambiguous_rays[i];
  return NULL;
}

/* The first field of `d` that differs from `m`, or NULL. */
static const rs_field* rs_differs(const uint32_t* d, const uint32_t* m) {
  uint32_t i;
  for (i = 0; i < RS_FIELD_COUNT; ++i)
    if (!rs_same(&rs_fields[i], d, m)) return &rs_fields[i];
  return NULL;
}

static int rs_check_ray(uint32_t ray, const uint32_t* d) {
  const rs_ambiguous* a = rs_ambiguity(ray);
  const rs_field* f;
  uint32_t i;
  if (!a) {
    f = rs_differs(d, rs_expected + (size_t)ray * RS_RECORD_WORDS);
    if (!f) return 1;
    printf("FAIL: %s: ray %u: field '%s': expected ", f->rule, ray, f->name);
    rs_print_value(f, rs_expected + (size_t)ray * RS_RECORD_WORDS);
    printf(", observed ");
    rs_print_value(f, d);
    printf("\n");
    return 0;
  }
  for (i = 0; i < a->replays; ++i)
    if (!rs_differs(d, rs_replays + (size_t)(a->first_replay + i) * RS_RECORD_WORDS)) return 1;
  f = rs_differs(d, rs_replays + (size_t)a->first_replay * RS_RECORD_WORDS);
  printf(
      "FAIL: %s: ray %u (numerically ambiguous: %s): the record is none of its %u legal answers; "
      "field '%s' of the first: expected ",
      a->rule, ray, a->reason, a->replays, f->name);
  rs_print_value(f, rs_replays + (size_t)a->first_replay * RS_RECORD_WORDS);
  printf(", observed ");
  rs_print_value(f, d);
  printf("\n");
  return 0;
}

static int rs_compare(const uint32_t* records, const uint32_t* counters) {
  uint32_t ray, i;
  int failures = 0;
  for (ray = 0; ray < rs_ray_count; ++ray)
    if (!rs_undefined[ray] && !rs_check_ray(ray, records + (size_t)ray * RS_RECORD_WORDS))
      ++failures;
  for (i = 0; i < rs_counter_count; ++i) {
    const rs_counter* c = &rs_counters[i];
    if (counters[i] >= c->lo && counters[i] <= c->hi) continue;
    printf("FAIL: %s: counter '%s': expected %llu..%llu, observed %u\n", c->rule, c->name,
           (unsigned long long)c->lo, (unsigned long long)c->hi, counters[i]);
    ++failures;
  }
  return failures;
}

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
  io.rays = rs_make_buffer(sizeof rs_rays, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, rs_rays);
  io.records = rs_make_buffer((VkDeviceSize)RS_RAY_COUNT * RS_RECORD_WORDS * 4,
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, NULL);
  io.records_ref = rs_make_buffer(8, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, &io.records.address);
  io.counters = rs_make_buffer(4 * (RS_COUNTER_COUNT ? RS_COUNTER_COUNT : 1),
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, NULL);
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
  printf("PASS: %u rays and %u counters as the reference model expects\n", (unsigned)RS_RAY_COUNT,
         (unsigned)RS_COUNTER_COUNT);
  return 0;
}
