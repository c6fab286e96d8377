#include "run/device_probe.h"

#include <nlohmann/json.hpp>

#include "run/vulkan_adapter.h"

namespace rayspec {
namespace {

std::vector<std::string> deviceList() {
  std::string error;
  std::vector<std::string> out;
  for (const DeviceInfo& d : listDevices(&error))
    out.push_back("[" + std::to_string(d.index) + "] " + d.name +
                  (d.ray_tracing_pipeline && d.acceleration_structure ? " (ray tracing)" : " (no ray tracing)"));
  if (!error.empty()) out.push_back("(cannot list devices: " + error + ")");
  return out;
}

}  // namespace

DeviceProbe probeDeviceInProcess(const VulkanOptions& options) {
  DeviceProbe p;
  {
    VulkanAdapter adapter(options);
    p.found = adapter.found();
    p.description = adapter.description();
    p.error = adapter.error();
    adapter.close();
  }
  if (!p.found) p.devices = deviceList();
  return p;
}

DeviceProbe probeDevice(const VulkanOptions& options, const ChildLimits& limits) {
  const ChildEnd end = runChild(
      [&](std::string& message) {
        const DeviceProbe p = probeDeviceInProcess(options);
        message = nlohmann::json{{"found", p.found}, {"description", p.description}, {"error", p.error},
                                 {"devices", p.devices}}
                      .dump();
        return 0;
      },
      limits);
  DeviceProbe p;
  if (!end.ok()) {
    p.error = describeChildEnd(end, "the device probe", limits);
    return p;
  }
  const nlohmann::json j = nlohmann::json::parse(end.message, nullptr, false);
  if (j.is_discarded()) {
    p.error = "the device probe answered nothing readable";
    return p;
  }
  p.found = j.value("found", false);
  p.description = j.value("description", "");
  p.error = j.value("error", "");
  p.devices = j.value("devices", std::vector<std::string>{});
  return p;
}

std::string probeFailure(const DeviceProbe& p) {
  std::string text = p.error;
  text += p.devices.empty() ? "; the Vulkan loader sees no device" : "; devices:";
  for (const std::string& d : p.devices) text += "\n  " + d;
  return text;
}

}  // namespace rayspec
