/* ---- Instance, device selection, device functions ----------------------- */

static PFN_vkGetAccelerationStructureBuildSizesKHR rs_build_sizes;
static PFN_vkCreateAccelerationStructureKHR rs_create_as;
static PFN_vkCmdBuildAccelerationStructuresKHR rs_cmd_build;
static PFN_vkGetAccelerationStructureDeviceAddressKHR rs_as_address;
static PFN_vkCreateRayTracingPipelinesKHR rs_create_pipelines;
static PFN_vkGetRayTracingShaderGroupHandlesKHR rs_group_handles;
static PFN_vkCmdTraceRaysKHR rs_cmd_trace;
static PFN_vkCmdWriteAccelerationStructuresPropertiesKHR rs_cmd_write_properties;
static PFN_vkCmdCopyAccelerationStructureKHR rs_cmd_copy;
static PFN_vkCmdCopyAccelerationStructureToMemoryKHR rs_cmd_copy_to_memory;
static PFN_vkCmdCopyMemoryToAccelerationStructureKHR rs_cmd_copy_from_memory;
static PFN_vkGetDeviceAccelerationStructureCompatibilityKHR rs_compatibility;

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

/* VK_KHR_ray_query's rayQuery chained onto `on`, where the case's stages run
 * ray queries; NotSupported where the device lacks it. */
static void rs_chain_ray_query(VkPhysicalDeviceRayQueryFeaturesKHR* on_rq,
                               VkPhysicalDeviceFeatures2* on) {
  VkPhysicalDeviceRayQueryFeaturesKHR rq = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceFeatures2 have = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &rq};
  if (!RS_NEEDS_RAY_QUERY) return;
  if (!rs_has_extension(rs_physical, VK_KHR_RAY_QUERY_EXTENSION_NAME))
    rs_unsupported("ray queries: the device lacks VK_KHR_ray_query");
  vkGetPhysicalDeviceFeatures2(rs_physical, &have);
  if (!rq.rayQuery) rs_unsupported("ray queries: the device lacks VK_KHR_ray_query's rayQuery");
  on_rq->rayQuery = VK_TRUE;
  on_rq->pNext = on->pNext;
  on->pNext = on_rq;
}

/* VK_KHR_ray_tracing_maintenance1's feature chained onto `on`, where the
 * case queries a structure's size or its bottom-level pointers; NotSupported
 * where the device lacks it. */
static void rs_chain_maintenance1(VkPhysicalDeviceRayTracingMaintenance1FeaturesKHR* on_m1,
                                  VkPhysicalDeviceFeatures2* on) {
  VkPhysicalDeviceRayTracingMaintenance1FeaturesKHR m1 = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_MAINTENANCE_1_FEATURES_KHR};
  VkPhysicalDeviceFeatures2 have = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &m1};
  if (!RS_NEEDS_MAINTENANCE1) return;
  if (!rs_has_extension(rs_physical, VK_KHR_RAY_TRACING_MAINTENANCE_1_EXTENSION_NAME))
    rs_unsupported(
        "scene.build.queries size, bottom_level_pointers: the device lacks "
        "VK_KHR_ray_tracing_maintenance1");
  vkGetPhysicalDeviceFeatures2(rs_physical, &have);
  if (!m1.rayTracingMaintenance1)
    rs_unsupported("scene.build.queries size, bottom_level_pointers: rayTracingMaintenance1");
  on_m1->rayTracingMaintenance1 = VK_TRUE;
  on_m1->pNext = on->pNext;
  on->pNext = on_m1;
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
  VkPhysicalDeviceRayQueryFeaturesKHR rq_on = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceRayTracingMaintenance1FeaturesKHR m1_on = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_MAINTENANCE_1_FEATURES_KHR};
  const char* extensions[5] = {VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
                               VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                               VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
  uint32_t extension_count = 3;
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
  if (RS_NEEDS_SCALAR_LAYOUT && !v12.scalarBlockLayout)
    rs_unsupported(
        "pipeline.sbt.record_layout: a scalar shader record block needs "
        "scalarBlockLayout");
  v12_on.scalarBlockLayout = v12.scalarBlockLayout;
  v12_on.vulkanMemoryModel = v12.vulkanMemoryModel;
  v12_on.vulkanMemoryModelDeviceScope = v12.vulkanMemoryModelDeviceScope;
  on.features.shaderInt64 = have.features.shaderInt64;
  /* the sized scalars a case's locals may use (harness/program/sized_types.h) */
  on.features.shaderInt16 = have.features.shaderInt16;
  on.features.shaderFloat64 = have.features.shaderFloat64;
  v12_on.shaderInt8 = v12.shaderInt8;
  v12_on.shaderFloat16 = v12.shaderFloat16;
  rs_chain_ray_query(&rq_on, &on);
  rs_chain_maintenance1(&m1_on, &on);
  if (RS_NEEDS_RAY_QUERY) extensions[extension_count++] = VK_KHR_RAY_QUERY_EXTENSION_NAME;
  if (RS_NEEDS_MAINTENANCE1)
    extensions[extension_count++] = VK_KHR_RAY_TRACING_MAINTENANCE_1_EXTENSION_NAME;
  vkGetPhysicalDeviceQueueFamilyProperties(rs_physical, &count, families);
  for (rs_queue_family = 0; rs_queue_family < count; ++rs_queue_family)
    if (families[rs_queue_family].queueFlags & VK_QUEUE_COMPUTE_BIT) break;
  if (rs_queue_family == count) rs_unsupported("a queue family with compute");
  queue.queueFamilyIndex = rs_queue_family;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = extension_count;
  info.ppEnabledExtensionNames = extensions;
  rs_check(vkCreateDevice(rs_physical, &info, NULL, &rs_device), "vkCreateDevice");
  vkGetDeviceQueue(rs_device, rs_queue_family, 0, &rs_queue);
}

#define RS_PROC(var, type, name)                    \
  var = (type)vkGetDeviceProcAddr(rs_device, name); \
  if (!var) rs_unsupported(name)

/* The commands that copy structures (scene.build.copy) and ask their sizes. */
static void rs_load_copy_functions(void) {
  RS_PROC(rs_cmd_write_properties, PFN_vkCmdWriteAccelerationStructuresPropertiesKHR,
          "vkCmdWriteAccelerationStructuresPropertiesKHR");
  RS_PROC(rs_cmd_copy, PFN_vkCmdCopyAccelerationStructureKHR, "vkCmdCopyAccelerationStructureKHR");
  RS_PROC(rs_cmd_copy_to_memory, PFN_vkCmdCopyAccelerationStructureToMemoryKHR,
          "vkCmdCopyAccelerationStructureToMemoryKHR");
  RS_PROC(rs_cmd_copy_from_memory, PFN_vkCmdCopyMemoryToAccelerationStructureKHR,
          "vkCmdCopyMemoryToAccelerationStructureKHR");
  RS_PROC(rs_compatibility, PFN_vkGetDeviceAccelerationStructureCompatibilityKHR,
          "vkGetDeviceAccelerationStructureCompatibilityKHR");
}

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
  rs_load_copy_functions();
  pool.queueFamilyIndex = rs_queue_family;
  rs_check(vkCreateCommandPool(rs_device, &pool, NULL, &rs_pool), "vkCreateCommandPool");
}
