#include "vulkan/pipeline_cache.h"

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <vector>

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

std::string cacheFile(const VulkanContext& ctx) {
  std::lock_guard<std::mutex> lock(dirMutex());
  if (cacheDir().empty() || ctx.info.device_uuid.empty()) return {};
  return cacheDir() + "/" + ctx.info.device_uuid + "-" + std::to_string(ctx.props.driverVersion) + ".bin";
}

// The header every pipeline cache starts with (VkPipelineCacheHeaderVersionOne):
// is it this device's?
bool headerMatches(const std::vector<char>& data, const VkPhysicalDeviceProperties& props) {
  VkPipelineCacheHeaderVersionOne header{};
  if (data.size() < sizeof header) return false;
  std::memcpy(&header, data.data(), sizeof header);
  return header.headerSize >= sizeof header && header.headerVersion == VK_PIPELINE_CACHE_HEADER_VERSION_ONE &&
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
  if (vkCreatePipelineCache(ctx.device, &info, nullptr, &cache) != VK_SUCCESS) return VK_NULL_HANDLE;
  return cache;
}

void closePipelineCache(const VulkanContext& ctx, VkPipelineCache cache) {
  if (cache == VK_NULL_HANDLE) return;
  size_t size = 0;
  std::vector<char> data;
  if (vkGetPipelineCacheData(ctx.device, cache, &size, nullptr) == VK_SUCCESS && size <= kMaxCacheBytes) {
    data.resize(size);
    if (vkGetPipelineCacheData(ctx.device, cache, &size, data.data()) != VK_SUCCESS) data.clear();
    data.resize(std::min(size, data.size()));
  }
  vkDestroyPipelineCache(ctx.device, cache, nullptr);
  const std::string path = cacheFile(ctx);
  if (path.empty() || data.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  const std::string part = path + ".part." + std::to_string(::getpid());
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    if (!out) return;
  }
  std::filesystem::rename(part, path, ec);
  if (ec) std::filesystem::remove(part, ec);
}

}  // namespace rayspec
