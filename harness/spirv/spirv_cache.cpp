#include "spirv/spirv_cache.h"

#include <cstring>
#include <filesystem>
#include <mutex>
#include <string_view>
#include <unordered_map>

#include "base/whole_file.h"
#include "results/sha256.h"
#include "spirv/cache_secret.h"
#include "spirv/compile_glsl.h"

namespace rayspec {
namespace fs = std::filesystem;
namespace {

// Bump when the compile options change, so old cache files are not reused.
constexpr char kCacheVersion[] = "rayspec-spirv-3:vk1.2:spv1.4:builtin-inputs";
constexpr uint32_t kSpirvMagic = 0x07230203;

struct Cache {
  std::mutex mutex;
  std::unordered_map<std::string, std::vector<uint32_t>> memory;
  std::string dir;
  std::string secret;  // keys the sums on disk (spirv/cache_secret.h); set with dir
};

Cache& cache() {
  static Cache c;
  return c;
}

std::string_view bytesOf(const std::vector<uint32_t>& words) {
  return {reinterpret_cast<const char*>(words.data()), words.size() * sizeof(uint32_t)};
}

// The sum an entry's .sum file holds: the module bound to its key, under
// the secret, which no one who can only write the cache folder holds.
Result<std::string> entrySum(const std::string& secret, const std::string& key,
                             const std::vector<uint32_t>& words) {
  return hmacSha256Hex(secret, {key, "\n", bytesOf(words)});
}

bool isRegularFile(const fs::path& p) {
  std::error_code ec;
  return fs::symlink_status(p, ec).type() == fs::file_type::regular;
}

// The module at `dir`/<key>.spv when the entry checks out (see the header).
bool readEntry(const fs::path& dir, const std::string& secret, const std::string& key,
               std::vector<uint32_t>& words) {
  const fs::path spv = dir / spirvCacheFileName(key), sum = dir / spirvCacheSumName(key);
  if (!isRegularFile(spv) || !isRegularFile(sum)) return false;
  const Result<std::string> module = readWholeFile(spv.string(), kMaxCachedModuleBytes);
  const Result<std::string> stored = readWholeFile(sum.string(), 256);
  if (!module || !stored || module->size() < 20 || module->size() % 4 != 0) return false;
  std::vector<uint32_t> data(module->size() / 4);
  std::memcpy(data.data(), module->data(), module->size());
  if (data[0] != kSpirvMagic) return false;
  const Result<std::string> expected = entrySum(secret, key, data);
  if (!expected || stored->substr(0, stored->find_first_of(" \n")) != *expected) return false;
  words = std::move(data);
  return true;
}

// Whatever is at `p` when it is not a regular file (a link, a FIFO) goes, so
// that the write below replaces it rather than follows or blocks on it.
void clearOddEntry(const fs::path& p) {
  std::error_code ec;
  const fs::file_type t = fs::symlink_status(p, ec).type();
  if (t != fs::file_type::not_found && t != fs::file_type::regular) fs::remove(p, ec);
}

void writeEntry(const fs::path& dir, const std::string& secret, const std::string& key,
                const std::vector<uint32_t>& words) {
  const fs::path spv = dir / spirvCacheFileName(key), sum = dir / spirvCacheSumName(key);
  clearOddEntry(spv);
  clearOddEntry(sum);
  // A cache: a failed write only makes the next run slower.
  const Result<std::string> entry_sum = entrySum(secret, key, words);
  if (entry_sum && writeWholeFile(spv.string(), words.data(), words.size() * 4))
    (void)writeWholeFile(sum.string(), *entry_sum + "\n");
}

}  // namespace

std::string spirvCacheKey(const std::string& glsl, Stage stage, bool compute) {
  const char s = compute ? 'C' : static_cast<char>(stage);
  const Result<std::string> key = sha256Hex({kCacheVersion, std::string_view(&s, 1), glsl});
  return key ? *key : std::string();
}

std::string spirvCacheFileName(const std::string& key) {
  return key + ".spv";
}

std::string spirvCacheSumName(const std::string& key) {
  return key + ".sum";
}

bool spirvCacheLookup(const std::string& key, std::vector<uint32_t>& words) {
  Cache& c = cache();
  std::string dir, secret;
  {
    std::lock_guard<std::mutex> lock(c.mutex);
    auto it = c.memory.find(key);
    if (it != c.memory.end()) {
      words = it->second;
      return true;
    }
    dir = c.dir;
    secret = c.secret;
  }
  if (dir.empty() || !readEntry(dir, secret, key, words)) return false;
  std::lock_guard<std::mutex> lock(c.mutex);
  c.memory.emplace(key, words);
  return true;
}

void spirvCacheStore(const std::string& key, const std::vector<uint32_t>& words) {
  Cache& c = cache();
  std::string dir, secret;
  {
    std::lock_guard<std::mutex> lock(c.mutex);
    c.memory[key] = words;
    dir = c.dir;
    secret = c.secret;
  }
  if (!dir.empty()) writeEntry(dir, secret, key, words);
}

void clearSpirvMemoryCache() {
  std::lock_guard<std::mutex> lock(cache().mutex);
  cache().memory.clear();
}

Result<void> setSpirvCacheDir(const std::string& dir) {
  Result<std::string> secret = std::string();
  if (!dir.empty()) secret = loadCacheSecret(cacheSecretFile());
  if (secret) {
    std::error_code ec;
    if (!dir.empty()) std::filesystem::create_directories(dir, ec);
  }
  std::lock_guard<std::mutex> lock(cache().mutex);
  cache().dir = secret ? dir : std::string();
  cache().secret = secret ? *secret : std::string();
  if (!secret) return errorMessage("the SPIR-V cache on disk is off: " + secret.error().format());
  return {};
}

}  // namespace rayspec
