/* ---- Buffers and command submission ------------------------------------- */

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
