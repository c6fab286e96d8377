// The fault seam (run/fault_seam.h): which faults a run refuses, where a fault
// is planted, and what each kind arms on the device side.
#include <gtest/gtest.h>

#include "fault/planted_fault.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "result_support.h"
#include "run/fault_seam.h"
#include "vulkan/device_errors.h"
#include "vulkan/vk_fault_hook.h"

namespace rayspec {
namespace {

TEST(FaultSeam, RefusesFaultsThatCannotBePlanted) {
  RunOptions opt;
  EXPECT_EQ(errorText(plantedFaultError(opt)), "") << "no fault";
  opt.plant_fault = "no-such-fault";
  const std::string unknown = errorText(plantedFaultError(opt));
  EXPECT_EQ(unknown.rfind("unknown fault 'no-such-fault' (one of drop-miss, ", 0), 0u) << unknown;
  EXPECT_NE(unknown.find("`rayspec faults` says what each breaks"), std::string::npos) << unknown;
  opt.plant_fault = "crash";
  EXPECT_EQ(errorText(plantedFaultError(opt)), "");
  opt.no_isolation = true;
  EXPECT_NE(errorText(plantedFaultError(opt)).find("child process"), std::string::npos);
  RunOptions saved;
  saved.device_results = "/some/saved/run";
  saved.plant_fault = "device-lost";
  EXPECT_NE(errorText(plantedFaultError(saved)).find("live device"), std::string::npos);
  saved.plant_fault = "shift-t";
  EXPECT_EQ(errorText(plantedFaultError(saved)), "") << "planted in the loaded results";
}

TEST(FaultSeam, ListsEveryKindOfFault) {
  const std::string names = plantableFaultNames();
  for (const char* name : {"shift-t", "crash", "device-lost"})
    EXPECT_NE(names.find(name), std::string::npos) << name << " in " << names;
}

// The fault table (fault/planted_fault.h) describes the faults the Vulkan
// side makes, and only those, as FaultKind::Vulkan.
TEST(FaultSeam, TheFaultTableHoldsEveryVulkanFault) {
  std::vector<std::string> vulkan = deviceErrorFaultNames();
  for (const std::string& name : layoutFaultNames()) vulkan.push_back(name);
  for (const std::string& name : vulkan) {
    const FaultInfo* f = findFault(name);
    ASSERT_NE(f, nullptr) << name << " is not in the fault table";
    EXPECT_EQ(f->kind, FaultKind::Vulkan) << name;
  }
  size_t in_table = 0;
  for (const FaultInfo& f : faultTable())
    if (f.kind == FaultKind::Vulkan) {
      ++in_table;
      EXPECT_TRUE(deviceErrorFault(f.name) || layoutFault(f.name))
          << f.name << ": no such Vulkan fault";
    }
  EXPECT_EQ(in_table, vulkan.size());
}

TEST(FaultSeam, PlantsOnlyInTheCasesThatMatch) {
  RunOptions opt;
  opt.plant_fault = "shift-t";
  opt.plant_fault_in = "anyhit/*";
  EXPECT_EQ(plantedFaultIn(opt, "anyhit/ignore-all"), "shift-t");
  EXPECT_EQ(plantedFaultIn(opt, "miss/clear"), "");
  EXPECT_TRUE(faultReadsModel("shift-t"));
  EXPECT_FALSE(faultReadsModel("device-lost")) << "a Vulkan call fails; no rays chosen";
  EXPECT_FALSE(faultReadsModel(""));
}

TEST(FaultSeam, NoFaultLeavesTheSideAsItWas) {
  Side s;
  armDeviceSide(s, "", nullptr, "/tmp");
  EXPECT_FALSE(s.before);
  EXPECT_FALSE(s.after);
}

// A Vulkan error fault makes its call fail from `before` until `after`.
TEST(FaultSeam, VulkanErrorFaultFailsItsCallUntilTheSideEnds) {
  Side s;
  armDeviceSide(s, "device-lost", nullptr, "/tmp");
  ASSERT_TRUE(s.before);
  ASSERT_TRUE(s.after);
  EXPECT_FALSE(injectedVkError("vkWaitForFences").has_value());
  s.before();
  const std::optional<VkResult> injected = injectedVkError("vkWaitForFences");
  EXPECT_FALSE(injectedVkError("vkQueueSubmit").has_value()) << "only the fault's own call";
  Results r;
  const std::string note = s.after(Case{}, Plan{}, r);
  ASSERT_TRUE(injected.has_value());
  EXPECT_EQ(*injected, VK_ERROR_DEVICE_LOST);
  EXPECT_NE(note.find("planted fault device-lost"), std::string::npos) << note;
  EXPECT_FALSE(injectedVkError("vkWaitForFences").has_value()) << "still failing after the side";
}

// A layout fault holds from `before` until `after`, and says when the case
// has no layout it could change.
TEST(FaultSeam, LayoutFaultHoldsUntilTheSideEnds) {
  EXPECT_NE(plantableFaultNames().find("pointers-reversed"), std::string::npos);
  EXPECT_FALSE(faultReadsModel("stride-ignored"));
  RunOptions saved;
  saved.device_results = "/some/saved/run";
  saved.plant_fault = "offsets-ignored";
  EXPECT_NE(errorText(plantedFaultError(saved)).find("live device"), std::string::npos);
  Side s;
  armDeviceSide(s, "stride-ignored", nullptr, "/tmp");
  ASSERT_TRUE(s.before);
  ASSERT_TRUE(s.after);
  s.before();
  EXPECT_EQ(injectedLayoutFault(), LayoutFault::StrideIgnored);
  Results r;
  Case strided;
  strided.scene.build.vertex_stride = 16;
  EXPECT_EQ(s.after(strided, Plan{}, r).find("not applicable"), std::string::npos);
  EXPECT_EQ(injectedLayoutFault(), LayoutFault::None);
  EXPECT_NE(s.after(Case{}, Plan{}, r).find("not applicable"), std::string::npos);
}

// vertex-format-misread applies where a triangle geometry has a format it
// confuses, and says so where none has.
TEST(FaultSeam, FormatMisreadAppliesToFormatsItConfuses) {
  EXPECT_NE(plantableFaultNames().find("vertex-format-misread"), std::string::npos);
  Side s;
  armDeviceSide(s, "vertex-format-misread", nullptr, "/tmp");
  ASSERT_TRUE(s.before);
  s.before();
  EXPECT_EQ(injectedLayoutFault(), LayoutFault::FormatMisread);
  Results r;
  Case unorm;
  unorm.scene.blases.emplace_back();
  unorm.scene.blases[0].geometries.emplace_back();
  unorm.scene.blases[0].geometries[0].vertex_format = VertexFormat::Unorm8x2;
  EXPECT_EQ(s.after(unorm, Plan{}, r).find("not applicable"), std::string::npos);
  EXPECT_EQ(injectedLayoutFault(), LayoutFault::None);
  unorm.scene.blases[0].geometries[0].vertex_format = VertexFormat::Float3;
  EXPECT_NE(s.after(unorm, Plan{}, r).find("no triangles in a format it misreads"),
            std::string::npos);
}

}  // namespace
}  // namespace rayspec
