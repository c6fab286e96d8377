// The SPIR-V cache's sums under the user's secret (issue 56): an entry forged
// by whoever can write the cache folder (another stage's module under this
// text's key, with a sum anyone can compute) is a miss, compiled again, and
// never the module a case runs; the key file is made private and read as
// untrusted input.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "result_support.h"
#include "results/sha256.h"
#include "spirv/cache_secret.h"
#include "spirv/compile_glsl.h"
#include "spirv/spirv_cache.h"
#include "test_dir.h"

namespace rayspec {
namespace {
namespace fs = std::filesystem;

// An environment variable set (or unset: nullptr) for one test, then restored.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, const char* value) : name_(name) {
    if (const char* was = std::getenv(name)) was_ = was;
    if (value)
      ::setenv(name, value, 1);
    else
      ::unsetenv(name);
  }
  ~ScopedVariable() {
    if (was_)
      ::setenv(name_, was_->c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> was_;
};

std::string fileBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void putBytes(const fs::path& p, const std::string& bytes) {
  fs::remove(p);
  std::ofstream(p, std::ios::binary) << bytes;
}

unsigned modeOf(const fs::path& p) {
  struct stat st {};
  EXPECT_EQ(::lstat(p.c_str(), &st), 0) << p;
  return st.st_mode & 0777;
}

const char* kAnyHitText = R"(#version 460
#extension GL_EXT_ray_tracing : require
layout(location = 0) rayPayloadInEXT vec4 payload;
void main() { payload.x += 1.0; }
// forged entry test
)";
const char* kClosestHitText = R"(#version 460
#extension GL_EXT_ray_tracing : require
layout(location = 0) rayPayloadInEXT vec4 payload;
void main() { payload = vec4(gl_HitTEXT, 2.0, 3.0, 4.0); }
// forged entry test
)";

// Issue 56: another stage's module under this text's key, its sum computed
// as anyone can (plain SHA-256 of the key and the module: what the cache
// checked before), or as HMAC under a secret other than the user's; and the
// right module with an old-format sum. Each is a miss: the text is compiled
// again, its own module used and the entry rewritten under the user's secret.
TEST(SpirvCacheSecret, AForgedEntryIsAMissNeverTheModuleUsed) {
  const fs::path dir = testing_support::testDir();
  fs::remove_all(dir / "cache");
  ScopedVariable config("RAYSPEC_CONFIG_DIR", (dir / "config").c_str());
  ASSERT_TRUE(setSpirvCacheDir((dir / "cache").string()).ok());
  const SpirvResult own = compileGlsl(kAnyHitText, Stage::AnyHit);
  const SpirvResult other = compileGlsl(kClosestHitText, Stage::ClosestHit);
  ASSERT_TRUE(own.error.empty() && other.error.empty()) << own.error << other.error;
  ASSERT_NE(own.words, other.words);
  const std::string key = spirvCacheKey(kAnyHitText, Stage::AnyHit);
  const fs::path spv = dir / "cache" / spirvCacheFileName(key),
                 sum = dir / "cache" / spirvCacheSumName(key);
  const std::string own_bytes = fileBytes(spv);
  const std::string other_bytes = fileBytes(
      dir / "cache" / spirvCacheFileName(spirvCacheKey(kClosestHitText, Stage::ClosestHit)));
  auto forged = [&](const std::string& what, const std::string& module, const std::string& text) {
    putBytes(spv, module);
    putBytes(sum, text + "\n");
    clearSpirvMemoryCache();
    const SpirvResult r = compileGlsl(kAnyHitText, Stage::AnyHit);
    EXPECT_FALSE(r.from_cache) << what;
    EXPECT_EQ(r.words, own.words) << what;
    EXPECT_EQ(fileBytes(spv), own_bytes) << what;
    EXPECT_NE(fileBytes(sum), text + "\n") << what << ": the entry is written anew";
    clearSpirvMemoryCache();
    EXPECT_TRUE(compileGlsl(kAnyHitText, Stage::AnyHit).from_cache) << what << ": then it hits";
  };
  forged("another stage's module, plain SHA-256", other_bytes,
         *sha256Hex({key, "\n", other_bytes}));
  forged("another stage's module, HMAC under another secret", other_bytes,
         *hmacSha256Hex(std::string(kCacheSecretBytes, 'x'), {key, "\n", other_bytes}));
  forged("its own module, the sum as the cache wrote it before the secret", own_bytes,
         *sha256Hex({key, "\n", own_bytes}));
  // The secret lives outside the cache folder.
  for (const auto& e : fs::directory_iterator(dir / "cache"))
    EXPECT_NE(e.path().filename(), "spirv-cache.key");
  EXPECT_TRUE(fs::exists(dir / "config" / "spirv-cache.key"));
  (void)setSpirvCacheDir("");
}

TEST(SpirvCacheSecret, TheKeyFileIsMadePrivateOnFirstUseAndKept) {
  const fs::path dir = testing_support::testDir();
  fs::remove_all(dir / "config");
  const fs::path file = dir / "config" / "rayspec" / "spirv-cache.key";
  std::string error;
  const std::string secret = orError(loadCacheSecret(file.string()), &error);
  ASSERT_EQ(error, "");
  EXPECT_EQ(secret.size(), kCacheSecretBytes);
  EXPECT_EQ(fileBytes(file), secret);
  EXPECT_EQ(modeOf(file), 0600u);
  EXPECT_EQ(modeOf(file.parent_path()), 0700u);
  EXPECT_EQ(orError(loadCacheSecret(file.string()), &error), secret) << error;
  // Where it is: RAYSPEC_CONFIG_DIR, else XDG_CONFIG_HOME/rayspec, else ~/.config/rayspec.
  ScopedVariable own("RAYSPEC_CONFIG_DIR", nullptr);
  ScopedVariable xdg("XDG_CONFIG_HOME", "/x");
  EXPECT_EQ(cacheSecretFile(), "/x/rayspec/spirv-cache.key");
  ScopedVariable no_xdg("XDG_CONFIG_HOME", nullptr);
  ScopedVariable home("HOME", "/h");
  EXPECT_EQ(cacheSecretFile(), "/h/.config/rayspec/spirv-cache.key");
  ScopedVariable set("RAYSPEC_CONFIG_DIR", "/c");
  EXPECT_EQ(cacheSecretFile(), "/c/spirv-cache.key");
}

// A key file as someone else may have left it: a link to a file of 32 bytes
// (followed, it would hand over a secret its writer knows), a file open to
// others, one of the wrong size, a FIFO (opening it could block). Each is
// replaced by a new private secret; the link's target is left as it was.
TEST(SpirvCacheSecret, AnUnusableKeyFileIsReplacedNeverFollowed) {
  const fs::path dir = testing_support::testDir();
  fs::remove_all(dir / "config");
  fs::create_directories(dir / "config");
  const fs::path file = dir / "config" / "spirv-cache.key", known = dir / "known.key";
  const std::string known_secret(kCacheSecretBytes, 'k');
  putBytes(known, known_secret);
  fs::permissions(known, fs::perms::owner_read | fs::perms::owner_write);
  auto replaced = [&](const std::string& what) {
    std::string error;
    const std::string secret = orError(loadCacheSecret(file.string()), &error);
    EXPECT_EQ(error, "") << what;
    EXPECT_EQ(secret.size(), kCacheSecretBytes) << what;
    EXPECT_NE(secret, known_secret) << what;
    EXPECT_EQ(fs::symlink_status(file).type(), fs::file_type::regular) << what;
    EXPECT_EQ(modeOf(file), 0600u) << what;
    EXPECT_EQ(fileBytes(file), secret) << what;
    fs::remove(file);
  };
  fs::create_symlink(known, file);
  replaced("a link");
  EXPECT_EQ(fileBytes(known), known_secret);
  putBytes(file, known_secret);
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::others_read);
  replaced("open to others");
  putBytes(file, known_secret + "more");
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);
  replaced("too long");
  putBytes(file, known_secret.substr(1));
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);
  replaced("too short");
  ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0);
  replaced("a FIFO");
  // What cannot be replaced is an error naming the file.
  fs::create_directories(file / "inside");
  std::string error;
  orError(loadCacheSecret(file.string()), &error);
  EXPECT_NE(error.find(file.string()), std::string::npos) << error;
}

// Nowhere to keep the secret: the disk cache is off (and says why), the
// SPIR-V kept in memory only.
TEST(SpirvCacheSecret, WithoutAPlaceForTheKeyTheDiskCacheIsOff) {
  const fs::path dir = testing_support::testDir();
  fs::remove_all(dir / "cache");
  ScopedVariable own("RAYSPEC_CONFIG_DIR", nullptr);
  ScopedVariable xdg("XDG_CONFIG_HOME", nullptr);
  ScopedVariable home("HOME", nullptr);
  std::string error;
  EXPECT_FALSE(orError(setSpirvCacheDir((dir / "cache").string()), &error));
  EXPECT_NE(error.find("SPIR-V cache on disk is off"), std::string::npos) << error;
  EXPECT_NE(error.find("RAYSPEC_CONFIG_DIR"), std::string::npos) << error;
  const std::string text = std::string(kAnyHitText) + "// no key\n";
  EXPECT_TRUE(compileGlsl(text, Stage::AnyHit).error.empty());
  EXPECT_FALSE(fs::exists(dir / "cache" / spirvCacheFileName(spirvCacheKey(text, Stage::AnyHit))));
  EXPECT_TRUE(compileGlsl(text, Stage::AnyHit).from_cache) << "in memory still";
  (void)setSpirvCacheDir("");
}

}  // namespace
}  // namespace rayspec
