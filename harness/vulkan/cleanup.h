// Destroys what one case created, in reverse order of creation, on every path
// (success, Vulkan error, NotSupported): each create is followed by add().
#pragma once

#include <vulkan/vulkan.h>

#include <functional>
#include <utility>
#include <vector>

namespace rayspec {

// A VkDeviceMemory that a case's buffers are placed in one after another
// (vulkan/memory.cpp); freed by the function added when it was allocated, so
// after every buffer placed in it is destroyed.
struct MemoryBlock {
  VkDeviceMemory memory = VK_NULL_HANDLE;
  uint32_t type = 0;
  VkDeviceSize size = 0, used = 0;
  void* mapped = nullptr;  // when the type is HOST_VISIBLE
};

class Cleanup {
 public:
  Cleanup() = default;
  Cleanup(const Cleanup&) = delete;
  Cleanup& operator=(const Cleanup&) = delete;
  ~Cleanup() { run(); }

  void add(std::function<void()> fn) { fns_.push_back(std::move(fn)); }
  // The case's memory blocks, newest last.
  std::vector<MemoryBlock>& blocks() { return blocks_; }
  void run() {
    while (!fns_.empty()) {
      std::function<void()> fn = std::move(fns_.back());
      fns_.pop_back();
      fn();
    }
    blocks_.clear();
  }

 private:
  std::vector<std::function<void()>> fns_;
  std::vector<MemoryBlock> blocks_;
};

}  // namespace rayspec
