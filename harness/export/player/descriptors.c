/* ---- The descriptor set: the top level and the buffers bound ------------ */

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

