// A device of this machine for the device tests of the Vulkan backend
// (tests/vulkan_*_test.cpp): created with the validation layer on (when
// installed) before each test, skipped where no ray tracing device exists,
// destroyed after it with the layout fault a test planted (vk_fault_hook.h)
// cleared.
#pragma once

#include <gtest/gtest.h>

#include "vulkan/context.h"
#include "vulkan/vk_fault_hook.h"
#include "vulkan_support.h"

namespace rayspec {

class LiveDevice : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!rayTracingDeviceExists()) GTEST_SKIP() << "no ray tracing device on this machine";
    ASSERT_TRUE(createInstance(ctx_, true).ok());
    ASSERT_TRUE(selectDevice(ctx_, "").ok());
    ASSERT_TRUE(createDevice(ctx_).ok());
  }
  void TearDown() override {
    injectLayoutFault(LayoutFault::None);
    if (ctx_.device) destroyDevice(ctx_);
    if (ctx_.instance) destroyInstance(ctx_);
  }
  VulkanContext ctx_;
};

}  // namespace rayspec
