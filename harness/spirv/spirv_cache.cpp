#include "spirv/spirv_cache.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>
#include <unordered_map>

#include <unistd.h>

#include "base/whole_file.h"
#include "results/content_hash.h"
#include "spirv/compile_glsl.h"

namespace rayspec {
namespace {

// Bump when the compile options change, so old cache files are not reused.
constexpr char kCacheVersion[] = "rayspec-spirv-2:vk1.2:spv1.4:builtin-inputs";
constexpr uint32_t kSpirvMagic = 0x07230203;

struct Cache {
  std::mutex mutex;
  std::unordered_map<uint64_t, std::vector<uint32_t>> memory;
  std::string dir;
};

Cache& cache() {
  static Cache c;
  return c;
}

bool readFile(const std::filesystem::path& path, std::vector<uint32_t>& words) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return false;
  const std::streamsize size = in.tellg();
  if (size < 20 || size % 4 != 0) return false;
  std::vector<uint32_t> data(static_cast<size_t>(size) / 4);
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(data.data()), size)) return false;
  if (data[0] != kSpirvMagic) return false;
  words = std::move(data);
  return true;
}

void writeFile(const std::filesystem::path& path, const std::vector<uint32_t>& words) {
  (void)writeWholeFile(path.string(), words.data(), words.size() * 4);  // a cache: only slower
}

}  // namespace

uint64_t spirvCacheKey(const std::string& glsl, Stage stage) {
  uint64_t h = contentHash(kContentHashSeed, kCacheVersion, sizeof(kCacheVersion));
  const unsigned char s = static_cast<unsigned char>(stage);
  h = contentHash(h, &s, 1);
  return contentHash(h, glsl.data(), glsl.size());
}

std::string spirvCacheFileName(uint64_t key) {
  char name[32];
  std::snprintf(name, sizeof(name), "%016llx.spv", static_cast<unsigned long long>(key));
  return name;
}

bool spirvCacheLookup(uint64_t key, std::vector<uint32_t>& words) {
  Cache& c = cache();
  std::string dir;
  {
    std::lock_guard<std::mutex> lock(c.mutex);
    auto it = c.memory.find(key);
    if (it != c.memory.end()) {
      words = it->second;
      return true;
    }
    dir = c.dir;
  }
  if (dir.empty()) return false;
  if (!readFile(std::filesystem::path(dir) / spirvCacheFileName(key), words)) return false;
  std::lock_guard<std::mutex> lock(c.mutex);
  c.memory.emplace(key, words);
  return true;
}

void spirvCacheStore(uint64_t key, const std::vector<uint32_t>& words) {
  Cache& c = cache();
  std::string dir;
  {
    std::lock_guard<std::mutex> lock(c.mutex);
    c.memory[key] = words;
    dir = c.dir;
  }
  if (!dir.empty()) writeFile(std::filesystem::path(dir) / spirvCacheFileName(key), words);
}

void clearSpirvMemoryCache() {
  std::lock_guard<std::mutex> lock(cache().mutex);
  cache().memory.clear();
}

void setSpirvCacheDir(const std::string& dir) {
  if (!dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
  }
  std::lock_guard<std::mutex> lock(cache().mutex);
  cache().dir = dir;
}

}  // namespace rayspec
