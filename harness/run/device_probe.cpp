#include "run/device_probe.h"

#include <nlohmann/json.hpp>

#include "run/device_info_json.h"
#include "run/icd_probe.h"
#include "run/vulkan_adapter.h"
#include "vulkan/device_usability.h"

namespace rayspec {
namespace {

void listWhatThereIs(DeviceProbe& p) {
  const DeviceListing listing = listDevicesOrWhyNot();  // its loader error is the adapter's
  p.no_device = listing.no_device;
  for (const DeviceInfo& d : listing.devices) {
    const DeviceUsability u = deviceUsability(d);
    p.devices.push_back(
        "[" + std::to_string(d.index) + "] " + d.name +
        (u == DeviceUsability::Usable ? " (ray tracing)" : " (" + usabilityReason(u, d) + ")"));
  }
}

// What the probe's child tells its parent.
nlohmann::json probeJson(const DeviceProbe& p) {
  nlohmann::json j{{"found", p.found},     {"description", p.description},
                   {"icd", p.icd},         {"device_uuid", p.device_uuid},
                   {"cpu", p.cpu},         {"error", p.error},
                   {"devices", p.devices}, {"no_device", p.no_device}};
  if (p.probed) {
    j["device_info"] = deviceInfoJson(p.probed->info);
    j["validation_layer"] = p.probed->validation_layer;
  }
  return j;
}

// The probe as its child told it. A device whose details do not read back
// is left unprobed: the device side then decides every case itself.
DeviceProbe probeFromJson(const nlohmann::json& j) {
  DeviceProbe p;
  p.found = j.value("found", false);
  p.description = j.value("description", "");
  p.icd = j.value("icd", "");
  p.cpu = j.value("cpu", false);
  p.device_uuid = j.value("device_uuid", "");
  p.error = j.value("error", "");
  p.devices = j.value("devices", std::vector<std::string>{});
  p.no_device = j.value("no_device", "");
  if (!p.found || !j.contains("device_info")) return p;
  try {
    p.probed = ProbedDevice{deviceInfoFromJson(j.at("device_info")),
                            j.at("validation_layer").get<uint32_t>()};
  } catch (const nlohmann::json::exception&) {
    p.probed.reset();
  }
  return p;
}

}  // namespace

std::string icdOfLibrary(const std::string& library) {
  const IcdSearch search = findIcdManifests();
  const IcdManifest* m = manifestOfLibrary(search.manifests, library);
  return m ? m->path : std::string();
}

DeviceProbe describeAdapter(const VulkanAdapter& adapter) {
  DeviceProbe p;
  p.found = adapter.found();
  p.description = adapter.description();
  p.error = adapter.error();
  if (p.found) {
    p.icd = icdOfLibrary(adapter.driverLibrary());
    p.device_uuid = adapter.deviceUuid();
    p.cpu = adapter.cpuDevice();
    p.probed = ProbedDevice{adapter.deviceInfo(), adapter.validationLayerVersion()};
  } else {
    listWhatThereIs(p);
  }
  return p;
}

DeviceProbe probeDeviceInProcess(const VulkanOptions& options) {
  VulkanAdapter adapter(options);
  DeviceProbe p = describeAdapter(adapter);
  adapter.close();
  return p;
}

DeviceProbe probeDevice(const VulkanOptions& options, const ChildLimits& limits) {
  const ChildEnd end = runChild(
      [&](std::string& message) {
        VulkanOptions quick = options;
        quick.validation = false;  // what there is, not what the layer says of it
        DeviceProbe p = probeDeviceInProcess(quick);
        if (p.probed) p.probed->validation_layer = validationLayerFor(options.validation);
        message = probeJson(p).dump();
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
  p = probeFromJson(j);
  if (p.found && p.icd.empty())
    p.icd = icdOfDevice(p.device_uuid, ChildLimits{kProbeSeconds, limits.memory_limit});
  return p;
}

std::string probeFailure(const DeviceProbe& p) {
  std::string text = p.error;
  if (p.devices.empty())
    text += "; the Vulkan loader sees no device" + (p.no_device.empty() ? "" : ": " + p.no_device);
  else
    text += "; devices:";
  for (const std::string& d : p.devices) text += "\n  " + d;
  return text;
}

}  // namespace rayspec
