#include "vulkan/pipeline_cache.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <vector>

#include "base/hex_text.h"
#include "base/whole_file.h"
#include "vulkan/context.h"

namespace rayspec {
namespace {

constexpr std::uintmax_t kMaxCacheBytes = std::uintmax_t(256) << 20;

std::mutex& dirMutex() {
  static std::mutex m;
  return m;
}

std::string& cacheDir() {
  static std::string dir;
  return dir;
}

// Named by what makes two caches interchangeable (pipelineCacheUUID, with the
// vendor, the device model and the driver version): another GPU of the same
// model and driver, a new machine given a pack, finds the file.
std::string cacheFile(const VulkanContext& ctx) {
  std::lock_guard<std::mutex> lock(dirMutex());
  if (cacheDir().empty()) return {};
  char ids[32];
  std::snprintf(ids, sizeof ids, "%04x-%04x-", ctx.props.vendorID, ctx.props.deviceID);
  return cacheDir() + "/" + ids + hexBytes(ctx.props.pipelineCacheUUID, VK_UUID_SIZE) + "-" +
         std::to_string(ctx.props.driverVersion) + ".bin";
}

// The header every pipeline cache starts with (VkPipelineCacheHeaderVersionOne):
// is it this device's?
bool headerMatches(const std::vector<char>& data, const VkPhysicalDeviceProperties& props) {
  VkPipelineCacheHeaderVersionOne header{};
  if (data.size() < sizeof header) return false;
  std::memcpy(&header, data.data(), sizeof header);
  return header.headerSize >= sizeof header &&
         header.headerVersion == VK_PIPELINE_CACHE_HEADER_VERSION_ONE &&
         header.vendorID == props.vendorID && header.deviceID == props.deviceID &&
         std::memcmp(header.pipelineCacheUUID, props.pipelineCacheUUID, VK_UUID_SIZE) == 0;
}

std::vector<char> readCacheFile(const std::string& path, const VkPhysicalDeviceProperties& props) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxCacheBytes) return {};
  std::vector<char> data(static_cast<size_t>(size));
  std::ifstream in(path, std::ios::binary);
  if (!in.read(data.data(), static_cast<std::streamsize>(data.size()))) return {};
  return headerMatches(data, props) ? data : std::vector<char>{};
}

}  // namespace

void setPipelineCacheDir(const std::string& dir) {
  std::lock_guard<std::mutex> lock(dirMutex());
  cacheDir() = dir;
}

VkPipelineCache openPipelineCache(const VulkanContext& ctx) {
  const std::string path = cacheFile(ctx);
  if (path.empty()) return VK_NULL_HANDLE;
  const std::vector<char> data = readCacheFile(path, ctx.props);
  VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  info.initialDataSize = data.size();
  info.pInitialData = data.empty() ? nullptr : data.data();
  VkPipelineCache cache = VK_NULL_HANDLE;
  if (vkCreatePipelineCache(ctx.device, &info, nullptr, &cache) != VK_SUCCESS)
    return VK_NULL_HANDLE;
  return cache;
}

namespace {

// What the driver has in `cache`, at most kMaxCacheBytes.
std::vector<char> cacheData(const VulkanContext& ctx, VkPipelineCache cache) {
  size_t size = 0;
  std::vector<char> data;
  if (vkGetPipelineCacheData(ctx.device, cache, &size, nullptr) != VK_SUCCESS ||
      size > kMaxCacheBytes)
    return data;
  data.resize(size);
  if (vkGetPipelineCacheData(ctx.device, cache, &size, data.data()) != VK_SUCCESS) return {};
  data.resize(std::min(size, data.size()));
  return data;
}

// Joins into `cache` what the file holds now (another worker may have saved
// since this one loaded it).
void mergeSaved(const VulkanContext& ctx, VkPipelineCache cache, const std::string& path) {
  const std::vector<char> saved = readCacheFile(path, ctx.props);
  if (saved.empty()) return;
  VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  info.initialDataSize = saved.size();
  info.pInitialData = saved.data();
  VkPipelineCache other = VK_NULL_HANDLE;
  if (vkCreatePipelineCache(ctx.device, &info, nullptr, &other) != VK_SUCCESS) return;
  vkMergePipelineCaches(ctx.device, cache, 1, &other);
  vkDestroyPipelineCache(ctx.device, other, nullptr);
}

}  // namespace

void closePipelineCache(const VulkanContext& ctx, VkPipelineCache cache) {
  if (cache == VK_NULL_HANDLE) return;
  const std::string path = cacheFile(ctx);
  if (!path.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
    // One worker at a time reads, merges and writes the file.
    const int lock = open((path + ".lock").c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    if (lock >= 0) flock(lock, LOCK_EX);
    mergeSaved(ctx, cache, path);
    const std::vector<char> data = cacheData(ctx, cache);
    if (!data.empty()) (void)writeWholeFile(path, data.data(), data.size());  // a cache
    if (lock >= 0) close(lock);                                               // releases the lock
  }
  vkDestroyPipelineCache(ctx.device, cache, nullptr);
}

}  // namespace rayspec
