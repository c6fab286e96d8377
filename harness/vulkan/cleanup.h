// Destroys what one case created, in reverse order of creation, on every path
// (success, Vulkan error, NotSupported): each create is followed by add().
#pragma once

#include <functional>
#include <utility>
#include <vector>

namespace rayspec {

class Cleanup {
 public:
  Cleanup() = default;
  Cleanup(const Cleanup&) = delete;
  Cleanup& operator=(const Cleanup&) = delete;
  ~Cleanup() { run(); }

  void add(std::function<void()> fn) { fns_.push_back(std::move(fn)); }
  void run() {
    while (!fns_.empty()) {
      std::function<void()> fn = std::move(fns_.back());
      fns_.pop_back();
      fn();
    }
  }

 private:
  std::vector<std::function<void()>> fns_;
};

}  // namespace rayspec
