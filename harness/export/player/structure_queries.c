/* ---- Structure queries (scene.build.queries) held to the specification -- */

/* Each answer that breaks a guarantee: printed, counted into the verdict. */
static int rs_structure_failures;

static void rs_query_finding(const rs_level* l, uint32_t i, const char* rule, const char* what) {
  printf("FAIL: %s: %s %u: %s\n", rule, l->name, (unsigned)l->index[i], what);
  ++rs_structure_failures;
}

/* A finding with the value observed and what it is held to. */
static void rs_query_numbers(const rs_level* l, uint32_t i, const char* rule, const char* what,
                             unsigned long long observed, unsigned long long against) {
  rs_query_finding(l, i, rule, what);
  printf("  observed %llu, against %llu\n", observed, against);
}

/* R-AS-QUERY-AVAILABILITY: each query available after the wait, its value
   the same read with the availability word; R-AS-QUERY-COMPACTED and
   R-AS-QUERY-SIZE: nonzero, at most the size the structure was created with. */
static void rs_check_query(const rs_level* l, VkQueryType type, uint64_t* values) {
  VkQueryPool pool = rs_write_properties(l, type);
  uint64_t pairs[2 * RS_MAX_LEVEL];
  const int sized = type == VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR ||
                    type == VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SIZE_KHR;
  const char* rule = type == VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR
                         ? "R-AS-QUERY-COMPACTED"
                         : "R-AS-QUERY-SIZE";
  uint32_t i;
  rs_pool_results(pool, l->count, 1, 0, values);
  rs_pool_results(pool, l->count, 2, VK_QUERY_RESULT_WITH_AVAILABILITY_BIT, pairs);
  for (i = 0; i < l->count; ++i) {
    if (pairs[2 * i + 1] == 0)
      rs_query_numbers(l, i, "R-AS-QUERY-AVAILABILITY",
                       "the availability word after VK_QUERY_RESULT_WAIT_BIT is 0 (query type)",
                       type, 0);
    if (pairs[2 * i] != values[i])
      rs_query_numbers(l, i, "R-AS-QUERY-AVAILABILITY",
                       "the value read with the availability word differs from the one without",
                       pairs[2 * i], values[i]);
    if (sized && (values[i] == 0 || values[i] > l->size[i]))
      rs_query_numbers(l, i, rule, "queried size outside (0, the size it was created with]",
                       values[i], l->size[i]);
  }
}

/* The device's VkPhysicalDeviceIDProperties::driverUUID. */
static void rs_driver_uuid(uint8_t* uuid) {
  VkPhysicalDeviceIDProperties id = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ID_PROPERTIES};
  VkPhysicalDeviceProperties2 p = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &id};
  vkGetPhysicalDeviceProperties2(rs_physical, &p);
  memcpy(uuid, id.driverUUID, VK_UUID_SIZE);
}

static void rs_print_uuid(const char* what, const uint8_t* uuid) {
  uint32_t k;
  printf("  %s ", what);
  for (k = 0; k < VK_UUID_SIZE; ++k) printf("%02x", uuid[k]);
  printf("\n");
}

/* R-AS-SERIAL-HEADER: the header's driverUUID the device's, its UUIDs
   compatible, its serialized size the queried one. */
static void rs_check_header(const rs_level* l, uint32_t i, const uint8_t* data, uint64_t queried) {
  VkAccelerationStructureVersionInfoKHR version = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_VERSION_INFO_KHR};
  VkAccelerationStructureCompatibilityKHR compatible =
      VK_ACCELERATION_STRUCTURE_COMPATIBILITY_INCOMPATIBLE_KHR;
  uint8_t uuid[VK_UUID_SIZE];
  uint64_t serialized;
  rs_driver_uuid(uuid);
  if (memcmp(uuid, data, VK_UUID_SIZE) != 0) {
    rs_query_finding(l, i, "R-AS-SERIAL-HEADER",
                     "serialized header's driverUUID is not the device's driverUUID");
    rs_print_uuid("header driverUUID", data);
    rs_print_uuid("device driverUUID", uuid);
  }
  version.pVersionData = data;
  rs_compatibility(rs_device, &version, &compatible);
  if (compatible != VK_ACCELERATION_STRUCTURE_COMPATIBILITY_COMPATIBLE_KHR)
    rs_query_finding(l, i, "R-AS-SERIAL-HEADER",
                     "the device calls its own serialized header's UUIDs incompatible");
  memcpy(&serialized, data + 2 * VK_UUID_SIZE, 8);
  if (serialized != queried)
    rs_query_numbers(l, i, "R-AS-SERIAL-HEADER",
                     "the header's serialized size is not the serialization size query's",
                     serialized, queried);
}

/* R-AS-SERIAL-POINTERS of top level i: its handle count the pointers
   query's (when asked), each handle the address of a BLAS it references. */
static void rs_check_pointers(const rs_level* l, uint32_t i, const uint8_t* data, uint64_t bytes,
                              const uint64_t* queried) {
  uint64_t count, k, handle;
  uint32_t b;
  memcpy(&count, data + RS_SERIAL_HEADER, 8);
  if (queried && count != *queried)
    rs_query_numbers(l, i, "R-AS-SERIAL-POINTERS",
                     "the header's handle count is not the bottom-level pointers query's", count,
                     *queried);
  if (bytes < RS_SERIAL_HEADER + 8 || count > (bytes - RS_SERIAL_HEADER - 8) / 8) {
    rs_query_numbers(l, i, "R-AS-SERIAL-POINTERS",
                     "the header's handle count is more than the serialized bytes hold", count,
                     bytes);
    return;
  }
  for (k = 0; k < count; ++k) {
    int known = 0;
    memcpy(&handle, data + RS_SERIAL_HEADER + 8 + 8 * k, 8);
    for (b = 0; b < RS_BLAS_COUNT; ++b)
      if (rs_referenced[l->index[i] * RS_BLAS_COUNT + b] && rs_blas_address[b] == handle) known = 1;
    if (!known)
      rs_query_numbers(l, i, "R-AS-SERIAL-POINTERS",
                       "a handle of the header (its index, its value) is no address of a BLAS "
                       "its instances reference",
                       k, handle);
  }
}

/* scene.build.queries of the level's structures, in the case's order (the
   bottom-level pointers of top levels only); then, where a serialization
   size or the pointers were asked, each structure serialized and its header
   checked (rayspec's vulkan/structure_queries.cpp). */
static void rs_query_level(const rs_level* l) {
  uint64_t values[RS_MAX_LEVEL], sizes[RS_MAX_LEVEL], pointers[RS_MAX_LEVEL];
  int top = l->type == VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, serialize = 0, counted = 0;
  static rs_serialized s;
  uint32_t q, i;
  if (!l->count) return;
  for (q = 0; q < rs_query_count; ++q) {
    const VkQueryType type = rs_queries[q];
    const int is_pointers =
        type == VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SERIALIZATION_BOTTOM_LEVEL_POINTERS_KHR;
    if (is_pointers && !top) continue; /* VUID-...-12425: top levels only */
    rs_check_query(l, type, values);
    if (type == VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SERIALIZATION_SIZE_KHR) {
      serialize = 1;
      memcpy(sizes, values, sizeof sizes);
    }
    if (is_pointers) {
      counted = 1;
      memcpy(pointers, values, sizeof pointers);
    }
  }
  if (!serialize && !counted) return;
  rs_serialize(l, &s);
  for (i = 0; i < l->count; ++i) {
    rs_check_header(l, i, rs_serialized_data(&s, i), serialize ? sizes[i] : s.sizes[i]);
    if (top)
      rs_check_pointers(l, i, rs_serialized_data(&s, i), s.sizes[i], counted ? &pointers[i] : NULL);
  }
}
