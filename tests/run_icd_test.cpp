// Each driver manifest probed alone in a child (run/icd_probe.h), and the
// manifest a device came from found by probing (icdOfDevice).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "run/icd_probe.h"
#include "vulkan/device_usability.h"

namespace rayspec {
namespace {
namespace fs = std::filesystem;

const IcdManifest* lavapipe(const IcdSearch& s) {
  for (const IcdManifest& m : s.manifests)
    if (m.library_path.find("libvulkan_lvp") != std::string::npos) return &m;
  return nullptr;
}

TEST(IcdProbe, LavapipeAloneIsUsable) {
  const IcdSearch s = findIcdManifests();
  const IcdManifest* lvp = lavapipe(s);
  ASSERT_TRUE(lvp) << "lavapipe's manifest is not installed";
  const IcdProbe p = probeIcd(*lvp, ChildLimits{kProbeSeconds, 0});
  ASSERT_EQ(p.devices.size(), 1u)
      << p.failure;  // only lavapipe's device, whatever else is installed
  EXPECT_NE(p.devices[0].name.find("llvmpipe"), std::string::npos);
  EXPECT_EQ(deviceUsability(p.devices[0]), DeviceUsability::Usable);
  EXPECT_EQ(p.devices[0].shader_group_handle_size, 32u);  // carried through the child's answer
  EXPECT_EQ(p.failure, "");
}

TEST(IcdProbe, MissingLibraryIsNotUsableWithTheReason) {
  const fs::path dir = fs::temp_directory_path() / "rayspec-run-icd-test";
  fs::create_directories(dir);
  std::ofstream(dir / "broken.json")
      << R"({"file_format_version": "1.0.0", "ICD": {"library_path": "./libnosuch_vulkan.so"}})";
  const IcdProbe p =
      probeIcd(IcdManifest{(dir / "broken.json").string(), "./libnosuch_vulkan.so", ""},
               ChildLimits{kProbeSeconds, 0});
  EXPECT_TRUE(p.devices.empty());
  EXPECT_NE(p.failure.find("could not be loaded"), std::string::npos) << p.failure;
  EXPECT_NE(p.failure.find("libnosuch_vulkan.so"), std::string::npos) << p.failure;
  EXPECT_EQ(std::getenv("VK_DRIVER_FILES") ? std::string(std::getenv("VK_DRIVER_FILES")) : "", "")
      << "the probe's environment stays in its child";
}

// The fallback for drivers dladdr cannot place: the manifest whose probe lists
// the device's UUID, among every installed manifest.
TEST(IcdProbe, DeviceFoundByItsUuid) {
  const IcdSearch s = findIcdManifests();
  const IcdManifest* lvp = lavapipe(s);
  ASSERT_TRUE(lvp);
  const IcdProbe p = probeIcd(*lvp, ChildLimits{kProbeSeconds, 0});
  ASSERT_EQ(p.devices.size(), 1u);
  EXPECT_EQ(icdOfDevice(p.devices[0].device_uuid, ChildLimits{kProbeSeconds, 0}), lvp->path);
  if (s.manifests.size() > 1) {
    EXPECT_EQ(icdOfDevice("no-such-uuid", ChildLimits{kProbeSeconds, 0}), "");
  }
}

}  // namespace
}  // namespace rayspec
