// A case the probed device cannot run (vulkan/case_support.h) is its
// NotSupported before either side runs (run/case_steps.h): no model time,
// the device's bundle written where its side writes it, and the outcome the
// one both sides give when they run; and the probe tells the device as the
// device side sees it (run/device_probe.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>

#include "bundle/results_io.h"
#include "case/flag_names.h"
#include "device_info_support.h"
#include "run/case_steps.h"
#include "run/device_info_json.h"
#include "run/device_probe.h"
#include "run/vulkan_adapter.h"
#include "suite_cases.h"
#include "temp_dir.h"
#include "vulkan/case_support.h"

namespace rayspec {
namespace {

// A side that counts its runs. With a device's DeviceInfo it answers as that
// device's side would: NotSupported where checkCaseRuns says so.
class CountingSide : public Backend {
 public:
  CountingSide(std::string name, std::optional<DeviceInfo> device)
      : name_(std::move(name)), device_(std::move(device)) {}
  std::string name() const override { return name_; }
  std::string description() const override { return "a side that counts its runs"; }
  Result<Results> run(const Case& c, const Plan& plan) override {
    ++runs;
    Results r;
    r.backend = name_;
    r.width = c.rays.width;
    r.height = c.rays.height;
    if (!device_) return r;
    r.device = device_->name;
    if (const Result<void> runs_there = checkCaseRuns(*device_, 0, c, plan); !runs_there)
      r.setStatus(SideStatus::NotSupported, runs_there.error().format());
    return r;
  }
  std::vector<std::string> close() override { return {}; }
  int runs = 0;

 private:
  std::string name_;
  std::optional<DeviceInfo> device_;
};

// A case whose instances carry opacity micromap flags, and a device without
// VK_EXT_opacity_micromap.
Case micromapCase() {
  Case c = suiteCaseFile("results/miss-xor-closest-hit");
  for (Instance& i : c.scene.instances) i.flags |= kInstanceOpacityMicromapFlags;
  return c;
}

DeviceInfo withoutMicromaps() {
  DeviceInfo d = capableDevice();
  d.name = "a device without micromaps";
  d.opacity_micromap = false;
  return d;
}

RunOptions inProcess(const std::string& out) {
  RunOptions opt;
  opt.out = freshTempDir("rayspec-run-refused/" + out);
  opt.no_isolation = true;
  return opt;
}

TEST(RefusedCase, CostsNoModelTimeAndIsTheOutcomeOfBothSides) {
  const Case c = micromapCase();
  const DeviceInfo d = withoutMicromaps();
  const RunOptions opt = inProcess("refused");
  CountingSide device("vulkan", d), model("model", std::nullopt);
  bool interrupted = false;
  const Result<CaseOutcome> refused =
      CaseRunner(opt, &device, &model, ProbedDevice{d, 0}).run(c, &interrupted);
  ASSERT_TRUE(refused.ok()) << errorText(refused);
  EXPECT_EQ(device.runs, 0);
  EXPECT_EQ(model.runs, 0);
  EXPECT_EQ(refused->status, Status::NotSupported);
  EXPECT_EQ(refused->headline,
            "NotSupported: vulkan: NotSupported: scene.instances[].flags: opacity micromap "
            "flags need VK_EXT_opacity_micromap");
  EXPECT_EQ(refused->device_name, d.name);
  // The device's bundle, as its side writes it; no model bundle.
  const std::string dir = opt.out + "/" + c.name;
  const Result<Results> bundle = readResults(dir + "/device");
  ASSERT_TRUE(bundle.ok()) << errorText(bundle);
  EXPECT_EQ(bundle->status, SideStatus::NotSupported);
  EXPECT_EQ(bundle->case_hash, c.source_hash);
  EXPECT_FALSE(std::filesystem::exists(dir + "/model"));
  // Both sides run without the probe: the same outcome, at the model's cost.
  const Result<CaseOutcome> ran =
      CaseRunner(inProcess("both-ran"), &device, &model).run(c, &interrupted);
  ASSERT_TRUE(ran.ok()) << errorText(ran);
  EXPECT_EQ(device.runs, 1);
  EXPECT_EQ(model.runs, 1);
  EXPECT_EQ(ran->status, refused->status);
  EXPECT_EQ(ran->headline, refused->headline);
  ASSERT_EQ(ran->verdict.findings.size(), refused->verdict.findings.size());
  for (size_t k = 0; k < ran->verdict.findings.size(); ++k)
    EXPECT_EQ(ran->verdict.findings[k].message, refused->verdict.findings[k].message);
}

TEST(RefusedCase, ACaseTheDeviceRunsRunsBothSides) {
  const Case c = micromapCase();
  CountingSide device("vulkan", capableDevice()), model("model", std::nullopt);
  bool interrupted = false;
  const Result<CaseOutcome> ran =
      CaseRunner(inProcess("runs"), &device, &model, ProbedDevice{capableDevice(), 0})
          .run(c, &interrupted);
  ASSERT_TRUE(ran.ok()) << errorText(ran);
  EXPECT_EQ(device.runs, 1);
  EXPECT_EQ(model.runs, 1);
}

// A planted fault may change what the device side answers: that side runs.
TEST(RefusedCase, APlantedFaultLetsTheSidesRun) {
  const Case c = micromapCase();
  const DeviceInfo d = withoutMicromaps();
  RunOptions opt = inProcess("fault");
  opt.plant_fault = "shift-t";
  CountingSide device("vulkan", d), model("model", std::nullopt);
  bool interrupted = false;
  const Result<CaseOutcome> ran =
      CaseRunner(opt, &device, &model, ProbedDevice{d, 0}).run(c, &interrupted);
  ASSERT_TRUE(ran.ok()) << errorText(ran);
  EXPECT_EQ(device.runs, 1);
  EXPECT_EQ(model.runs, 1);
}

// The probe makes its device without the validation layer; the device side
// makes it with the layer on: what each sees of the device is the same, and
// the probe tells the layer that side runs under.
TEST(DeviceProbe, TellsTheDeviceAsTheDeviceSideSeesIt) {
  VulkanOptions with_layer;
  with_layer.validation = true;
  const DeviceProbe p = probeDevice(with_layer, ChildLimits{60, kDefaultMemoryLimit});
  if (!p.found) GTEST_SKIP() << "no ray tracing device: " << p.error;
  ASSERT_TRUE(p.probed.has_value());
  VulkanAdapter side(with_layer);
  ASSERT_TRUE(side.found()) << side.error();
  EXPECT_EQ(deviceInfoJson(p.probed->info), deviceInfoJson(side.deviceInfo()));
  EXPECT_EQ(p.probed->validation_layer, side.validationLayerVersion());
  EXPECT_EQ(p.probed->validation_layer, validationLayerFor(true));
  side.close();
}

}  // namespace
}  // namespace rayspec
