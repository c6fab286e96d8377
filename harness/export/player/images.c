/* ---- Storage images (outputs.images) ------------------------------------ */

/* One image: the storage image, its view, and the host buffer it is copied into. */
typedef struct {
  VkImage image;
  VkImageView view;
  rs_buffer readback;
} rs_image_target;

static uint32_t rs_image_extent[2]; /* every image's width and height */
/* The count as a variable: a loop up to a count of 0 draws no warning. */
static const uint32_t rs_image_count = RS_IMAGE_COUNT;

/* The images' extent, as rayspec's: the launch's, or where that is wider than
   maxImageDimension2D, the rays in order folded into rows as wide as allowed. */
static void rs_choose_image_extent(void) {
  VkPhysicalDeviceProperties p;
  uint64_t rays = (uint64_t)RS_IMAGE_WIDTH * RS_IMAGE_HEIGHT, most, rows;
  vkGetPhysicalDeviceProperties(rs_physical, &p);
  most = p.limits.maxImageDimension2D;
  rs_image_extent[0] = RS_IMAGE_WIDTH;
  rs_image_extent[1] = RS_IMAGE_HEIGHT;
  if (RS_IMAGE_WIDTH <= most && RS_IMAGE_HEIGHT <= most) return;
  rows = (rays + most - 1) / most;
  if (rows > most) rs_unsupported("an image of the launch's rays within maxImageDimension2D");
  rs_image_extent[0] = (uint32_t)most;
  rs_image_extent[1] = (uint32_t)rows;
}

static rs_image_target rs_make_image(const rs_image* im) {
  VkImageCreateInfo info = {VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  VkImageViewCreateInfo view = {VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  VkMemoryAllocateInfo alloc = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  VkMemoryRequirements req;
  VkDeviceMemory memory;
  rs_image_target t;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = im->is_float ? VK_FORMAT_R32G32B32A32_SFLOAT : VK_FORMAT_R32_UINT;
  info.extent.width = rs_image_extent[0];
  info.extent.height = rs_image_extent[1];
  info.extent.depth = 1;
  info.mipLevels = info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
               VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  rs_check(vkCreateImage(rs_device, &info, NULL, &t.image), "vkCreateImage");
  vkGetImageMemoryRequirements(rs_device, t.image, &req);
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = rs_memory_type(req.memoryTypeBits, 0);
  rs_check(vkAllocateMemory(rs_device, &alloc, NULL, &memory), "vkAllocateMemory");
  rs_check(vkBindImageMemory(rs_device, t.image, memory, 0), "vkBindImageMemory");
  view.image = t.image;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = info.format;
  view.subresourceRange.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
  view.subresourceRange.levelCount = view.subresourceRange.layerCount = 1;
  rs_check(vkCreateImageView(rs_device, &view, NULL, &t.view), "vkCreateImageView");
  t.readback = rs_make_buffer(
      (VkDeviceSize)rs_image_extent[0] * rs_image_extent[1] * (im->is_float ? 16 : 4),
      VK_BUFFER_USAGE_TRANSFER_DST_BIT, NULL);
  return t;
}

static const VkImageSubresourceRange rs_whole_image = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};

/* Before the launch: each image in the general layout, cleared to zero. */
static void rs_clear_images(VkCommandBuffer cmd, const rs_image_target* images) {
  const VkClearColorValue zero = {{0, 0, 0, 0}};
  uint32_t i;
  for (i = 0; i < rs_image_count; ++i) {
    VkImageMemoryBarrier b = {VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    b.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = images[i].image;
    b.subresourceRange = rs_whole_image;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                         0, NULL, 0, NULL, 1, &b);
    vkCmdClearColorImage(cmd, images[i].image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &rs_whole_image);
  }
  rs_barrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
             VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
}

/* After the launch: each image copied into its host buffer (tightly packed rows). */
static void rs_copy_images(VkCommandBuffer cmd, const rs_image_target* images) {
  uint32_t i;
  rs_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  for (i = 0; i < rs_image_count; ++i) {
    VkBufferImageCopy copy;
    memset(&copy, 0, sizeof copy);
    copy.imageSubresource.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    copy.imageSubresource.layerCount = 1;
    copy.imageExtent.width = rs_image_extent[0];
    copy.imageExtent.height = rs_image_extent[1];
    copy.imageExtent.depth = 1;
    vkCmdCopyImageToBuffer(cmd, images[i].image, VK_IMAGE_LAYOUT_GENERAL, images[i].readback.buffer,
                           1, &copy);
  }
}
