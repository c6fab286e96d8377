// The backend's allocator (vulkan/memory.h): a case's buffers share a few
// memory blocks, each buffer on a 256-byte boundary with its own bytes, a
// large buffer in a block of its own, everything freed by the case's Cleanup
// without a validation error.
#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <utility>
#include <vector>

#include "vulkan/context.h"
#include "vulkan/memory.h"
#include "vulkan_support.h"

namespace rayspec {
namespace {

// A device of this machine with the validation layer on (when installed).
class MemoryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!rayTracingDeviceExists()) GTEST_SKIP() << "no ray tracing device on this machine";
    const Result<void> instance = createInstance(ctx_, true);
    ASSERT_TRUE(instance.ok()) << instance.error().message;
    Result<void> picked = selectDevice(ctx_, "");
    ASSERT_TRUE(picked.ok()) << picked.error().message;
    const Result<void> device = createDevice(ctx_);
    ASSERT_TRUE(device.ok()) << device.error().message;
  }
  void TearDown() override {
    if (ctx_.device) destroyDevice(ctx_);
    if (ctx_.instance) destroyInstance(ctx_);
  }
  VulkanContext ctx_;
};

constexpr VkBufferUsageFlags kUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

TEST_F(MemoryTest, ACaseBuffersShareBlocksOnAlignedBoundaries) {
  std::vector<Buffer> host;
  {
    Cleanup cleanup;
    for (VkDeviceSize size : {VkDeviceSize(1), VkDeviceSize(100), VkDeviceSize(4096)})
      host.push_back(*createBuffer(ctx_, size, kUsage, MemoryUse::Host, cleanup));
    const Buffer device = *createBuffer(ctx_, 1000, kUsage, MemoryUse::Device, cleanup);
    // Host buffers of one memory type: one block; the device buffer's type
    // may be the same one (lavapipe) or another.
    EXPECT_LE(cleanup.blocks().size(), 2u);
    std::set<VkDeviceMemory> host_blocks;
    for (const Buffer& b : host) host_blocks.insert(b.memory);
    EXPECT_EQ(host_blocks.size(), 1u);
    std::set<VkDeviceAddress> addresses;
    for (const Buffer& b : host) {
      EXPECT_EQ(b.address % 256, 0u) << b.size;
      addresses.insert(b.address);
    }
    EXPECT_EQ(device.address % 256, 0u);
    EXPECT_EQ(addresses.size(), host.size());
    // Each host buffer's bytes are its own: writing one leaves the others.
    for (size_t i = 0; i < host.size(); ++i)
      std::memset(host[i].mapped, static_cast<int>(i + 1), host[i].size);
    for (size_t i = 0; i < host.size(); ++i)
      for (VkDeviceSize k = 0; k < host[i].size; ++k)
        ASSERT_EQ(static_cast<const uint8_t*>(host[i].mapped)[k], i + 1) << i << " " << k;
  }
  EXPECT_TRUE(ctx_.capture->take().empty());
}

TEST_F(MemoryTest, ALargeBufferGetsABlockOfItsOwn) {
  Cleanup cleanup;
  const Buffer small = *createBuffer(ctx_, 64, kUsage, MemoryUse::Host, cleanup);
  const Buffer large = *createBuffer(ctx_, VkDeviceSize(5) << 20, kUsage, MemoryUse::Host, cleanup);
  EXPECT_NE(small.memory, large.memory);
  EXPECT_EQ(cleanup.blocks().size(), 2u);
  std::memset(large.mapped, 7, large.size);  // all of it is mapped and writable
  cleanup.run();
  EXPECT_TRUE(cleanup.blocks().empty());
  EXPECT_TRUE(ctx_.capture->take().empty());
}

}  // namespace
}  // namespace rayspec
