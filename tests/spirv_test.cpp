// GLSL -> SPIR-V through glslang, validated by SPIRV-Tools, cached by content.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "spirv/compile_glsl.h"
#include "spirv/spirv_cache.h"

namespace rayspec {
namespace {

const char* kAnyHit = R"(#version 460
#extension GL_EXT_ray_tracing : require
struct P { vec4 color; uint value; uint depth; };
layout(location = 0) rayPayloadInEXT P payload;
hitAttributeEXT vec2 attr;
void main() {
  if ((gl_PrimitiveID & 1) != 0) ignoreIntersectionEXT;
  payload.value += 1u;
  payload.color = vec4(attr, gl_HitTEXT, 1.0);
}
)";

constexpr uint32_t kSpirvMagic = 0x07230203;

TEST(CompileGlsl, AnyHitCompilesAndValidates) {
  SpirvResult r = compileGlsl(kAnyHit, Stage::AnyHit);
  ASSERT_TRUE(r.error.empty()) << r.error;
  ASSERT_GT(r.words.size(), 5u);
  EXPECT_EQ(r.words[0], kSpirvMagic);
  EXPECT_EQ(r.words[1], 0x00010400u);  // SPIR-V 1.4
}

// A closest-hit shader whose payload is the vec4 `color`.
std::string closestHitWriting(const std::string& color) {
  return "#version 460\n#extension GL_EXT_ray_tracing : require\nlayout(location = 0) "
         "rayPayloadInEXT vec4 payload;\nvoid main() { payload = " +
         color + "; }\n";
}

// glslang 12 gives gl_HitTEXT and gl_RayTmaxEXT a variable each; SPIRV-Tools
// 2024 and later reject the module (VUID-StandaloneSpirv-OpEntryPoint-09658).
TEST(CompileGlsl, TwoInputsOfOneBuiltinAreAnError) {
  SpirvResult r = compileGlsl(closestHitWriting("vec4(gl_HitTEXT, gl_RayTmaxEXT, 0.0, 1.0)"),
                              Stage::ClosestHit);
  EXPECT_TRUE(r.words.empty());
  EXPECT_NE(r.error.find("OpEntryPoint-09658"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("'main'"), std::string::npos) << r.error;
  // One of them alone is a valid module.
  SpirvResult ok = compileGlsl(closestHitWriting("vec4(gl_RayTmaxEXT, gl_RayTminEXT, 0.0, 1.0)"),
                               Stage::ClosestHit);
  EXPECT_TRUE(ok.error.empty()) << ok.error;
}

TEST(CompileGlsl, WrongStageIsAnError) {
  // ignoreIntersectionEXT is only legal in any-hit.
  SpirvResult r = compileGlsl(kAnyHit, Stage::ClosestHit);
  EXPECT_TRUE(r.words.empty());
  EXPECT_FALSE(r.error.empty());
}

TEST(CompileGlsl, BrokenShaderQuotesTheLine) {
  const std::string broken = R"(#version 460
#extension GL_EXT_ray_tracing : require
layout(location = 0) rayPayloadInEXT vec4 payload;
void main() {
  payload = vec4(1.0);
  payload.w = undeclared_thing * 2.0;
}
)";
  SpirvResult r = compileGlsl(broken, Stage::Miss);
  EXPECT_TRUE(r.words.empty());
  EXPECT_NE(r.error.find("0:6:"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("6 |   payload.w = undeclared_thing * 2.0;"), std::string::npos)
      << r.error;
  EXPECT_FALSE(r.from_cache);
  // Errors are not cached.
  EXPECT_FALSE(compileGlsl(broken, Stage::Miss).from_cache);
}

TEST(CompileGlsl, SecondCompileHitsTheMemoryCache) {
  const std::string glsl = std::string(kAnyHit) + "// memory cache test\n";
  SpirvResult first = compileGlsl(glsl, Stage::AnyHit);
  ASSERT_TRUE(first.error.empty()) << first.error;
  EXPECT_FALSE(first.from_cache);
  SpirvResult second = compileGlsl(glsl, Stage::AnyHit);
  EXPECT_TRUE(second.from_cache);
  EXPECT_EQ(first.words, second.words);
}

TEST(CompileGlsl, CacheKeyDependsOnStageAndText) {
  EXPECT_NE(spirvCacheKey("x", Stage::AnyHit), spirvCacheKey("x", Stage::ClosestHit));
  EXPECT_NE(spirvCacheKey("x", Stage::AnyHit), spirvCacheKey("y", Stage::AnyHit));
  EXPECT_EQ(spirvCacheKey("x", Stage::Miss), spirvCacheKey("x", Stage::Miss));
}

TEST(CompileGlsl, DiskCacheSurvivesTheMemoryCache) {
  const auto dir =
      std::filesystem::temp_directory_path() /
      ("rayspec-spirv-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(setSpirvCacheDir(dir.string()).ok());
  const std::string glsl = std::string(kAnyHit) + "// disk cache test\n";
  SpirvResult first = compileGlsl(glsl, Stage::AnyHit);
  ASSERT_TRUE(first.error.empty()) << first.error;
  const auto file = dir / spirvCacheFileName(spirvCacheKey(glsl, Stage::AnyHit));
  EXPECT_TRUE(std::filesystem::exists(file));
  EXPECT_EQ(std::filesystem::file_size(file), first.words.size() * 4);
  clearSpirvMemoryCache();
  SpirvResult second = compileGlsl(glsl, Stage::AnyHit);
  EXPECT_TRUE(second.from_cache);
  EXPECT_EQ(first.words, second.words);
  // A corrupt file is not trusted: the shader is compiled again.
  clearSpirvMemoryCache();
  std::filesystem::resize_file(file, 6);
  SpirvResult third = compileGlsl(glsl, Stage::AnyHit);
  EXPECT_FALSE(third.from_cache);
  EXPECT_EQ(first.words, third.words);
  (void)setSpirvCacheDir("");
  std::filesystem::remove_all(dir);
}

TEST(CompileGlsl, CacheKeysAreSha256) {
  const std::string key = spirvCacheKey("x", Stage::Miss);
  EXPECT_EQ(key.size(), 64u);
  EXPECT_EQ(key.find_first_not_of("0123456789abcdef"), std::string::npos);
}

// Poisoned entries (issue 44): another text's module under this key, junk
// after the magic number, a FIFO, a link: each is a miss, compiled anew and
// rewritten, never a module used for this text.
TEST(CompileGlsl, APoisonedCacheEntryIsAMissAndIsRewritten) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() /
      ("rayspec-spirv-poison-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::remove_all(dir);
  ASSERT_TRUE(setSpirvCacheDir(dir.string()).ok());
  const std::string glsl = std::string(kAnyHit) + "// poisoned cache test\n";
  const std::string other = std::string(kAnyHit) + "// another text\n";
  const SpirvResult good = compileGlsl(glsl, Stage::AnyHit);
  const SpirvResult foreign = compileGlsl(other, Stage::AnyHit);
  ASSERT_TRUE(good.error.empty() && foreign.error.empty());
  const std::string key = spirvCacheKey(glsl, Stage::AnyHit);
  const std::string other_key = spirvCacheKey(other, Stage::AnyHit);
  const fs::path spv = dir / spirvCacheFileName(key), sum = dir / spirvCacheSumName(key);
  auto recompiles = [&](const std::string& what) {
    clearSpirvMemoryCache();
    const SpirvResult r = compileGlsl(glsl, Stage::AnyHit);
    EXPECT_FALSE(r.from_cache) << what;
    EXPECT_EQ(r.words, good.words) << what;
    EXPECT_EQ(fs::symlink_status(spv).type(), fs::file_type::regular) << what;
  };
  // Another text's module and sum copied under this key.
  fs::copy_file(dir / spirvCacheFileName(other_key), spv, fs::copy_options::overwrite_existing);
  fs::copy_file(dir / spirvCacheSumName(other_key), sum, fs::copy_options::overwrite_existing);
  recompiles("another text's entry");
  // Junk after the magic number, the sum left as it was.
  {
    std::fstream f(spv, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(8);
    f.write("junkjunk", 8);
  }
  recompiles("junk after the magic");
  // A FIFO in place of the module (opening it would block).
  fs::remove(spv);
  ASSERT_EQ(::mkfifo(spv.c_str(), 0600), 0);
  recompiles("a FIFO");
  // A link to a file elsewhere.
  fs::remove(spv);
  fs::create_symlink(dir / spirvCacheFileName(other_key), spv);
  recompiles("a link");
  (void)setSpirvCacheDir("");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rayspec
