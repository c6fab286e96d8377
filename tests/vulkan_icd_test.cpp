// Driver manifests (vulkan/icd_manifest.h), --icd's environment
// (vulkan/icd_environment.h), device usability, and the driver library a
// device's commands come from (lavapipe here).
#include <gtest/gtest.h>
#include <vulkan/vulkan.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include "result_support.h"
#include "temp_dir.h"
#include "vulkan/device_usability.h"
#include "vulkan/icd_environment.h"
#include "vulkan/icd_manifest.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {
namespace {
namespace fs = std::filesystem;

// Sets (or unsets) environment variables for one test and restores them.
class ScopedEnv {
 public:
  explicit ScopedEnv(std::initializer_list<std::pair<const char*, const char*>> vars) {
    for (const auto& [name, value] : vars) {
      const char* old = std::getenv(name);
      saved_.push_back({name, old ? std::optional<std::string>(old) : std::nullopt});
      if (value)
        setenv(name, value, 1);
      else
        unsetenv(name);
    }
  }
  ~ScopedEnv() {
    for (const auto& [name, old] : saved_) {
      if (old)
        setenv(name.c_str(), old->c_str(), 1);
      else
        unsetenv(name.c_str());
    }
  }

 private:
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

std::string tempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rayspec-icd-test-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

std::string manifestText(const std::string& library) {
  return R"({"file_format_version": "1.0.0", "ICD": {"library_path": ")" + library +
         R"(", "api_version": "1.3.0"}})";
}

// lavapipe's manifest as the loader's standard search finds it.
std::string lavapipeManifest() {
  ScopedEnv env{{"VK_DRIVER_FILES", nullptr},
                {"VK_ICD_FILENAMES", nullptr},
                {"VK_ADD_DRIVER_FILES", nullptr}};
  for (const IcdManifest& m : findIcdManifests().manifests)
    if (m.library_path.find("libvulkan_lvp") != std::string::npos) return m.path;
  return {};
}

TEST(IcdManifest, ReadsLibraryAndVersion) {
  const std::string dir = tempDir("read");
  const Result<IcdManifest> m = readIcdManifest(write(dir + "/a.json", manifestText("libfoo.so")));
  ASSERT_TRUE(m) << m.error().format();
  EXPECT_EQ(m->library_path, "libfoo.so");
  EXPECT_EQ(m->api_version, "1.3.0");
  EXPECT_EQ(m->path, dir + "/a.json");
}

TEST(IcdManifest, BadFilesAreErrorsNamingTheFile) {
  const std::string dir = tempDir("bad");
  const std::pair<std::string, std::string> bad[] = {
      {dir + "/missing.json", "no such file"},
      {write(dir + "/text.json", "not json at all"), "not JSON"},
      {write(dir + "/layer.json", R"({"layer": {"name": "x"}})"), "no \"ICD\" object"},
      {write(dir + "/nolib.json", R"({"ICD": {"api_version": "1.3.0"}})"), "no ICD.library_path"},
      {dir, "a folder"},
      {sparseFile(dir + "/huge.json", kMaxIcdManifestBytes + 1), "more than the"},
  };
  for (const auto& [path, why] : bad) {
    const Result<IcdManifest> m = readIcdManifest(path);
    ASSERT_FALSE(m) << path;
    const std::string error = m.error().format();
    EXPECT_NE(error.find(path), std::string::npos) << error;
    EXPECT_NE(error.find(why), std::string::npos) << error;
  }
}

TEST(IcdManifest, LibraryPathResolvesAsTheLoaderDoes) {
  IcdManifest m{"/x/icd.d/a.json", "libvulkan_lvp.so", ""};
  EXPECT_EQ(icdLibraryToLoad(m), "libvulkan_lvp.so");  // bare: the dynamic linker searches
  EXPECT_TRUE(icdLibraryMatches(m, "/lib/x86_64-linux-gnu/libvulkan_lvp.so"));
  EXPECT_FALSE(icdLibraryMatches(m, "/lib/x86_64-linux-gnu/libvulkan_radeon.so"));
  m.library_path = "../lib/libd.so";  // relative to the manifest's folder
  EXPECT_EQ(icdLibraryToLoad(m), "/x/lib/libd.so");
  m.library_path = "/opt/libd.so";
  EXPECT_EQ(icdLibraryToLoad(m), "/opt/libd.so");
}

TEST(IcdManifest, DriverFilesVariableListsFilesAndFolders) {
  const std::string dir = tempDir("search");
  fs::create_directories(dir + "/folder");
  const std::string a = write(dir + "/a.json", manifestText("liba.so"));
  write(dir + "/folder/c.json", manifestText("libc.so"));
  write(dir + "/folder/b.json", manifestText("libb.so"));
  write(dir + "/folder/notes.txt", "not a manifest");
  write(dir + "/folder/z.json", "broken");
  {
    ScopedEnv env{{"VK_DRIVER_FILES", (a + ":" + dir + "/folder:" + a).c_str()},
                  {"VK_ADD_DRIVER_FILES", nullptr}};
    const IcdSearch s = findIcdManifests();
    EXPECT_EQ(s.source, IcdSource::DriverFilesVariable);
    ASSERT_EQ(s.manifests.size(), 3u);  // a once, then the folder's sorted
    EXPECT_EQ(s.manifests[0].library_path, "liba.so");
    EXPECT_EQ(s.manifests[1].library_path, "libb.so");
    EXPECT_EQ(s.manifests[2].library_path, "libc.so");
    ASSERT_EQ(s.errors.size(), 1u);
    EXPECT_NE(s.errors[0].find("z.json"), std::string::npos);
  }
  {
    ScopedEnv env{{"VK_DRIVER_FILES", nullptr},
                  {"VK_ICD_FILENAMES", a.c_str()},
                  {"VK_ADD_DRIVER_FILES", nullptr}};
    const IcdSearch s = findIcdManifests();
    EXPECT_EQ(s.source, IcdSource::IcdFilenamesVariable);
    ASSERT_EQ(s.manifests.size(), 1u);
  }
}

TEST(IcdManifest, StandardFoldersFollowXdgDirs) {
  const std::string dir = tempDir("xdg");
  fs::create_directories(dir + "/data/vulkan/icd.d");
  write(dir + "/data/vulkan/icd.d/mine.json", manifestText("libmine.so"));
  ScopedEnv env{{"VK_DRIVER_FILES", nullptr},
                {"VK_ICD_FILENAMES", nullptr},
                {"VK_ADD_DRIVER_FILES", nullptr},
                {"XDG_DATA_DIRS", (dir + "/data").c_str()}};
  const IcdSearch s = findIcdManifests();
  EXPECT_EQ(s.source, IcdSource::StandardFolders);
  bool found = false;
  for (const IcdManifest& m : s.manifests) found = found || m.library_path == "libmine.so";
  EXPECT_TRUE(found);
  EXPECT_EQ(s.places.back(), dir + "/data/vulkan/icd.d");
}

TEST(IcdManifest, LoadFailureSaysWhy) {
  const std::string dir = tempDir("load");
  const IcdManifest missing{dir + "/m.json", "./libnosuch_vulkan.so", ""};
  const std::string why = icdLoadFailure(missing);
  EXPECT_NE(why.find("could not be loaded"), std::string::npos) << why;
  EXPECT_NE(why.find(dir + "/libnosuch_vulkan.so"), std::string::npos) << why;
  const IcdManifest not_vulkan{dir + "/c.json", "libc.so.6", ""};  // loads, but is no driver
  EXPECT_NE(icdLoadFailure(not_vulkan).find("vk_icdGetInstanceProcAddr"), std::string::npos);
  const std::string lvp = lavapipeManifest();
  ASSERT_FALSE(lvp.empty()) << "lavapipe's manifest is not installed";
  EXPECT_EQ(icdLoadFailure(*readIcdManifest(lvp)), "");
}

TEST(IcdEnvironment, SetsBothVariablesAndSaysWhatItOverrides) {
  const std::string dir = tempDir("env");
  const std::string a = write(dir + "/a.json", manifestText("liba.so"));
  const std::string b = write(dir + "/b.json", manifestText("libb.so"));
  ScopedEnv env{{"VK_DRIVER_FILES", "/users/own.json"},
                {"VK_ICD_FILENAMES", nullptr},
                {"VK_ADD_DRIVER_FILES", "/x.json"}};
  const IcdSelection s = useIcdFiles({a, b});
  EXPECT_EQ(s.error, "");
  EXPECT_EQ(std::string(std::getenv("VK_DRIVER_FILES")), a + ":" + b);
  EXPECT_EQ(std::string(std::getenv("VK_ICD_FILENAMES")), a + ":" + b);
  EXPECT_EQ(std::getenv("VK_ADD_DRIVER_FILES"), nullptr);
  ASSERT_EQ(s.notes.size(), 2u);
  EXPECT_NE(s.notes[0].find("VK_DRIVER_FILES=/users/own.json"), std::string::npos);
}

TEST(IcdEnvironment, MissingFileIsAnErrorAndChangesNothing) {
  ScopedEnv env{{"VK_DRIVER_FILES", "/users/own.json"}};
  const IcdSelection s = useIcdFiles({"/nonexistent.json"});
  EXPECT_NE(s.error.find("/nonexistent.json"), std::string::npos) << s.error;
  EXPECT_EQ(std::string(std::getenv("VK_DRIVER_FILES")), "/users/own.json");
  EXPECT_EQ(useIcdFiles({}).error, "");  // no --icd: nothing to do
}

TEST(DeviceUsability, EachMissingPieceIsItsReason) {
  DeviceInfo d;
  d.api_version_number = VK_MAKE_API_VERSION(0, 1, 3, 0);
  d.ray_tracing_extension = d.ray_tracing_pipeline = true;
  d.acceleration_structure_extension = d.acceleration_structure = true;
  EXPECT_EQ(deviceUsability(d), DeviceUsability::Usable);
  DeviceInfo old = d;
  old.api_version_number = VK_MAKE_API_VERSION(0, 1, 1, 0);
  old.api_version = "1.1.0";
  EXPECT_EQ(deviceUsability(old), DeviceUsability::ApiBelow12);
  EXPECT_NE(usabilityReason(DeviceUsability::ApiBelow12, old).find("1.1.0"), std::string::npos);
  DeviceInfo no_rt = d;
  no_rt.ray_tracing_extension = false;
  EXPECT_EQ(deviceUsability(no_rt), DeviceUsability::NoRayTracingPipelineExtension);
  EXPECT_EQ(usabilityReason(deviceUsability(no_rt), no_rt), "no VK_KHR_ray_tracing_pipeline");
  DeviceInfo no_rt_feature = d;
  no_rt_feature.ray_tracing_pipeline = false;
  EXPECT_EQ(deviceUsability(no_rt_feature), DeviceUsability::NoRayTracingPipelineFeature);
  DeviceInfo no_as = d;
  no_as.acceleration_structure_extension = false;
  EXPECT_EQ(deviceUsability(no_as), DeviceUsability::NoAccelerationStructureExtension);
  DeviceInfo no_as_feature = d;
  no_as_feature.acceleration_structure = false;
  EXPECT_EQ(deviceUsability(no_as_feature), DeviceUsability::NoAccelerationStructureFeature);
}

// The driver library of lavapipe's device is lavapipe's manifest's, with and
// without the validation layer (which sits on top of the device's commands).
TEST(DriverLibrary, LavapipeDeviceComesFromItsManifest) {
  const std::string lvp = lavapipeManifest();
  ASSERT_FALSE(lvp.empty());
  std::string error;
  const IcdManifest m = *readIcdManifest(lvp);
  for (bool validation : {false, true}) {
    std::unique_ptr<VulkanEngine> b =
        orError(VulkanEngine::create({"llvmpipe", validation}), &error);
    ASSERT_TRUE(b) << error;
    const std::string library = b->driverLibrary();
    EXPECT_TRUE(icdLibraryMatches(m, library)) << library << (validation ? " (validation on)" : "");
    EXPECT_FALSE(b->device().device_uuid.empty());
  }
}

}  // namespace
}  // namespace rayspec
