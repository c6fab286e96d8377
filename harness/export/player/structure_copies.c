/* ---- Copies of acceleration structures (scene.build.copy, R-AS-COPY) ---- */

static void rs_copy_failed(const rs_level* l, uint32_t i, const char* what,
                           unsigned long long bytes) {
  printf("FAIL: R-AS-COPY: %s %u: %s (%llu bytes)\n", l->name, (unsigned)l->index[i], what, bytes);
  exit(1);
}

/* A property of each structure of the level written into a new query pool
   (vkCmdWriteAccelerationStructuresPropertiesKHR) after the builds. */
static VkQueryPool rs_write_properties(const rs_level* l, VkQueryType type) {
  VkQueryPoolCreateInfo info = {VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  VkQueryPool pool;
  VkCommandBuffer cmd;
  info.queryType = type;
  info.queryCount = l->count;
  rs_check(vkCreateQueryPool(rs_device, &info, NULL, &pool), "vkCreateQueryPool");
  cmd = rs_begin();
  vkCmdResetQueryPool(cmd, pool, 0, l->count);
  rs_cmd_write_properties(cmd, l->count, l->handle, type, pool, 0);
  rs_submit(cmd);
  return pool;
}

/* The pool's `count` results, 64-bit, waited for: `words` words each (2:
   the value and, with VK_QUERY_RESULT_WITH_AVAILABILITY_BIT in flags, its
   availability). */
static void rs_pool_results(VkQueryPool pool, uint32_t count, uint32_t words,
                            VkQueryResultFlags flags, uint64_t* out) {
  rs_check(vkGetQueryPoolResults(rs_device, pool, 0, count, (size_t)count * words * 8, out,
                                 (VkDeviceSize)words * 8,
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT | flags),
           "vkGetQueryPoolResults");
}

/* A size of each structure of the level as the device reports it
   (compacted or serialized). */
static void rs_query_sizes(const rs_level* l, VkQueryType type, VkDeviceSize* out) {
  uint64_t values[RS_MAX_LEVEL];
  uint32_t i;
  rs_pool_results(rs_write_properties(l, type), l->count, 1, 0, values);
  for (i = 0; i < l->count; ++i) out[i] = values[i];
}

/* Clones at each structure's size, or compacted copies at the compacted
   size the device reports (R-AS-COPY), by one submission. */
static void rs_copy_level(rs_level* l, int compact) {
  VkCopyAccelerationStructureInfoKHR copy = {
      VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR};
  VkAccelerationStructureKHR to[RS_MAX_LEVEL];
  VkDeviceSize sizes[RS_MAX_LEVEL];
  VkCommandBuffer cmd;
  uint32_t i;
  if (compact)
    rs_query_sizes(l, VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, sizes);
  else
    memcpy(sizes, l->size, sizeof sizes);
  for (i = 0; i < l->count; ++i) {
    if (sizes[i] == 0 || sizes[i] > l->size[i])
      rs_copy_failed(l, i, "compacted size outside (0, the structure's size]",
                     (unsigned long long)sizes[i]);
    to[i] = rs_create_structure(l->type, sizes[i]);
  }
  cmd = rs_begin();
  copy.mode = compact ? VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR
                      : VK_COPY_ACCELERATION_STRUCTURE_MODE_CLONE_KHR;
  for (i = 0; i < l->count; ++i) {
    copy.src = l->handle[i];
    copy.dst = to[i];
    rs_cmd_copy(cmd, &copy);
  }
  rs_submit(cmd);
  for (i = 0; i < l->count; ++i) {
    l->handle[i] = to[i];
    l->size[i] = sizes[i];
    l->room[i] = compact ? 0 : sizes[i];
  }
}

/* Serialized data: the two UUIDs, then 64-bit sizes (serialized, deserialized). */
#define RS_SERIAL_HEADER (2 * VK_UUID_SIZE + 16)

/* The serialized data checked as rayspec checks it before deserializing:
   the device calls it compatible, its size is the one the query gave. */
static VkDeviceSize rs_check_serialized(const rs_level* l, uint32_t i, const uint8_t* data,
                                        VkDeviceSize queried) {
  VkAccelerationStructureVersionInfoKHR version = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_VERSION_INFO_KHR};
  VkAccelerationStructureCompatibilityKHR compatible =
      VK_ACCELERATION_STRUCTURE_COMPATIBILITY_INCOMPATIBLE_KHR;
  uint64_t serialized, deserialized;
  version.pVersionData = data;
  rs_compatibility(rs_device, &version, &compatible);
  if (compatible != VK_ACCELERATION_STRUCTURE_COMPATIBILITY_COMPATIBLE_KHR)
    rs_copy_failed(l, i, "the device calls its own serialized data incompatible",
                   (unsigned long long)queried);
  memcpy(&serialized, data + 2 * VK_UUID_SIZE, 8);
  memcpy(&deserialized, data + 2 * VK_UUID_SIZE + 8, 8);
  if (serialized != queried)
    rs_copy_failed(l, i, "serialized data names another size than the query gave",
                   (unsigned long long)serialized);
  return deserialized;
}

/* A level's structures serialized into host-visible memory, each at the
   size the query reports and at a 256-byte aligned address. */
typedef struct {
  rs_buffer memory;
  VkDeviceAddress at[RS_MAX_LEVEL]; /* each one's address */
  VkDeviceSize sizes[RS_MAX_LEVEL]; /* each one's serialization size */
} rs_serialized;

static const uint8_t* rs_serialized_data(const rs_serialized* s, uint32_t i) {
  return (const uint8_t*)s->memory.mapped + (s->at[i] - s->memory.address);
}

/* The serialization sizes asked (each at least the header, else a FAIL:
   rayspec stops there before anything is written past a region), then every
   structure serialized, readable by the host once this returns. */
static void rs_serialize(const rs_level* l, rs_serialized* s) {
  VkCopyAccelerationStructureToMemoryInfoKHR out = {
      VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_TO_MEMORY_INFO_KHR};
  VkDeviceSize offsets[RS_MAX_LEVEL], total = 0;
  VkDeviceAddress base;
  VkCommandBuffer cmd;
  uint32_t i;
  rs_query_sizes(l, VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SERIALIZATION_SIZE_KHR, s->sizes);
  for (i = 0; i < l->count; ++i) {
    if (s->sizes[i] < RS_SERIAL_HEADER)
      rs_copy_failed(l, i,
                     "the serialization size query gave less than the header every serialized "
                     "structure holds",
                     (unsigned long long)s->sizes[i]);
    offsets[i] = total;
    total += (s->sizes[i] + 255) & ~(VkDeviceSize)255;
  }
  s->memory =
      rs_make_buffer(total + 256, rs_input_usage | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, NULL);
  base = (s->memory.address + 255) & ~(VkDeviceAddress)255;
  cmd = rs_begin();
  out.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_SERIALIZE_KHR;
  for (i = 0; i < l->count; ++i) {
    s->at[i] = base + offsets[i];
    out.src = l->handle[i];
    out.dst.deviceAddress = s->at[i];
    rs_cmd_copy_to_memory(cmd, &out);
  }
  rs_submit(cmd);
}

/* Each structure serialized, checked, and deserialized into a new structure
   of the size its data names. */
static void rs_serialize_level(rs_level* l) {
  VkCopyMemoryToAccelerationStructureInfoKHR back = {
      VK_STRUCTURE_TYPE_COPY_MEMORY_TO_ACCELERATION_STRUCTURE_INFO_KHR};
  static rs_serialized s;
  VkCommandBuffer cmd;
  uint32_t i;
  rs_serialize(l, &s);
  cmd = rs_begin();
  back.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_DESERIALIZE_KHR;
  for (i = 0; i < l->count; ++i) {
    l->size[i] = l->room[i] = rs_check_serialized(l, i, rs_serialized_data(&s, i), s.sizes[i]);
    l->handle[i] = rs_create_structure(l->type, l->size[i]);
    back.src.deviceAddress = s.at[i];
    back.dst = l->handle[i];
    rs_cmd_copy_from_memory(cmd, &back);
  }
  rs_submit(cmd);
}

/* The level's structures replaced by their copies (scene.build.copy). */
static void rs_copy_structures(rs_level* l) {
  if (!l->count) return;
  if (RS_COPY == RS_COPY_SERIALIZE)
    rs_serialize_level(l);
  else if (RS_COPY != RS_COPY_NONE)
    rs_copy_level(l, RS_COPY == RS_COPY_COMPACT);
}
