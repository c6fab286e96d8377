// The VkPipelineCache kept between runs (vulkan/pipeline_cache.h): a device
// that keeps its device across cases saves its pipelines' cache when it is
// destroyed; a file that is not this device's cache is not given to the
// driver, and the next device writes a good one.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "parse/parse_case.h"
#include "plan/plan.h"
#include "result_support.h"
#include "vulkan/pipeline_cache.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {
namespace {
namespace fs = std::filesystem;

Case exampleCase() {
  const std::string cases = RAYSPEC_SOURCE_DIR "/cases";
  ParseResult p = parseCaseFile(cases + "/results/miss-xor-closest-hit.yaml", cases);
  EXPECT_TRUE(p.value);
  return p.value ? *p.value : Case{};
}

// Runs the case on a backend that keeps one device; the cache files after.
std::vector<fs::path> runOnce(const Case& c, const std::string& dir) {
  VulkanOptions v;
  v.validation = false;
  v.device_per_case = false;
  std::string error;
  std::unique_ptr<VulkanEngine> b = orError(VulkanEngine::create(v), &error);
  EXPECT_TRUE(b) << error;
  if (!b) return {};
  const Results r = b->run(c, derivePlan(c));
  EXPECT_TRUE(r.ok()) << r.statusText();
  EXPECT_TRUE(b->close().empty());
  std::vector<fs::path> files;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".bin") files.push_back(e.path());  // beside it: <file>.lock
  return files;
}

// The file starts with a pipeline cache header (version one).
bool hasHeader(const fs::path& file) {
  VkPipelineCacheHeaderVersionOne header{};
  std::ifstream in(file, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) return false;
  return header.headerSize == sizeof header &&
         header.headerVersion == VK_PIPELINE_CACHE_HEADER_VERSION_ONE;
}

TEST(PipelineCache, SavedAtTheEndAndABadFileIsNotUsed) {
  const std::string dir = ::testing::TempDir() + "/rayspec-pipeline-cache";
  fs::remove_all(dir);
  setPipelineCacheDir(dir);
  const Case c = exampleCase();
  std::vector<fs::path> files = runOnce(c, dir);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].extension(), ".bin");
  EXPECT_TRUE(
      hasHeader(files[0]));  // lavapipe keeps its pipelines in Mesa's cache: often the header alone
  // Another device's header (or garbage) in its place: not used, and replaced.
  std::ofstream(files[0], std::ios::binary | std::ios::trunc) << std::string(64, '\x7f');
  files = runOnce(c, dir);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_TRUE(hasHeader(files[0]));
  setPipelineCacheDir("");
}

}  // namespace
}  // namespace rayspec
