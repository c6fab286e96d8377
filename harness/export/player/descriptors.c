/* ---- The descriptor set: the top level and the buffers bound ------------ */

typedef struct {
  rs_buffer rays, records, records_ref, counters;
  rs_buffer words[RS_BINDING_COUNT];      /* each RS_BIND_WORDS binding's, by its index */
  rs_image_target images[RS_IMAGE_SLOTS]; /* in rs_images' order */
} rs_io;

/* The buffers the descriptor set binds: the rays, the records (by address),
   the counters and each binding of fixed words; and the storage images. */
static rs_io rs_make_io(void) {
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  rs_io io;
  uint32_t i;
  memset(&io, 0, sizeof io);
  io.rays = rs_make_buffer(sizeof rs_rays, storage, rs_rays);
  io.records = rs_make_buffer((VkDeviceSize)RS_RAY_COUNT * RS_RECORD_WORDS * 4, storage, NULL);
  io.records_ref = rs_make_buffer(8, storage, &io.records.address);
  io.counters = rs_make_buffer(4 * (RS_COUNTER_COUNT ? RS_COUNTER_COUNT : 1), storage, NULL);
  for (i = 0; i < RS_BINDING_COUNT; ++i)
    if (rs_bindings[i].kind == RS_BIND_WORDS)
      io.words[i] = rs_make_buffer(rs_bindings[i].bytes, storage, rs_bindings[i].words);
  if (rs_image_count) rs_choose_image_extent();
  for (i = 0; i < rs_image_count; ++i) io.images[i] = rs_make_image(&rs_images[i]);
  return io;
}

/* The buffer binding i reads (the top level's binding: none). */
static const rs_buffer* rs_bound_buffer(uint32_t i, const rs_io* io) {
  switch (rs_bindings[i].kind) {
    case RS_BIND_RAYS:
      return &io->rays;
    case RS_BIND_RECORDS:
      return &io->records_ref;
    case RS_BIND_COUNTERS:
      return &io->counters;
    case RS_BIND_WORDS:
      return &io->words[i];
    case RS_BIND_TLAS:
    case RS_BIND_IMAGE:
      break;
  }
  return NULL;
}

static VkDescriptorType rs_descriptor_type(enum rs_binding_kind kind) {
  if (kind == RS_BIND_TLAS) return VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  return kind == RS_BIND_IMAGE ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                               : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

/* The set: the top levels (an array where there are several) and the buffers. */
static VkDescriptorSet rs_bind(VkDescriptorSetLayout* set_layout,
                               const VkAccelerationStructureKHR* tlas, const rs_io* io) {
  VkDescriptorSetLayoutBinding b[RS_BINDING_COUNT];
  VkWriteDescriptorSet w[RS_BINDING_COUNT];
  VkDescriptorBufferInfo buffers[RS_BINDING_COUNT];
  VkDescriptorImageInfo images[RS_BINDING_COUNT];
  VkWriteDescriptorSetAccelerationStructureKHR as = {
      VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
  VkDescriptorPoolSize sizes[3] = {{VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, RS_TLAS_COUNT},
                                   {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, RS_BINDING_COUNT},
                                   {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, RS_BINDING_COUNT}};
  VkDescriptorSetLayoutCreateInfo layout = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  VkDescriptorPoolCreateInfo pool = {VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  VkDescriptorSetAllocateInfo alloc = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  VkDescriptorPool pool_handle;
  VkDescriptorSet set;
  uint32_t i;
  as.accelerationStructureCount = RS_TLAS_COUNT;
  as.pAccelerationStructures = tlas;
  for (i = 0; i < RS_BINDING_COUNT; ++i) {
    const rs_buffer* src = rs_bound_buffer(i, io);
    int is_tlas = rs_bindings[i].kind == RS_BIND_TLAS;
    int is_image = rs_bindings[i].kind == RS_BIND_IMAGE;
    memset(&b[i], 0, sizeof b[i]);
    memset(&w[i], 0, sizeof w[i]);
    b[i].binding = w[i].dstBinding = rs_bindings[i].binding;
    b[i].descriptorType = w[i].descriptorType = rs_descriptor_type(rs_bindings[i].kind);
    b[i].descriptorCount = w[i].descriptorCount = is_tlas ? RS_TLAS_COUNT : 1;
    b[i].stageFlags = VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR |
                      VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_ANY_HIT_BIT_KHR |
                      VK_SHADER_STAGE_INTERSECTION_BIT_KHR | VK_SHADER_STAGE_CALLABLE_BIT_KHR |
                      VK_SHADER_STAGE_COMPUTE_BIT;
    w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    buffers[i].buffer = src ? src->buffer : VK_NULL_HANDLE;
    buffers[i].offset = 0;
    buffers[i].range = VK_WHOLE_SIZE;
    memset(&images[i], 0, sizeof images[i]);
    if (is_image) {
      images[i].imageView = io->images[rs_bindings[i].binding - RS_FIRST_IMAGE_BINDING].view;
      images[i].imageLayout = VK_IMAGE_LAYOUT_GENERAL;
    }
    if (is_tlas)
      w[i].pNext = &as;
    else if (is_image)
      w[i].pImageInfo = &images[i];
    else
      w[i].pBufferInfo = &buffers[i];
  }
  layout.bindingCount = RS_BINDING_COUNT;
  layout.pBindings = b;
  rs_check(vkCreateDescriptorSetLayout(rs_device, &layout, NULL, set_layout),
           "vkCreateDescriptorSetLayout");
  pool.maxSets = 1;
  pool.poolSizeCount = 3;
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
