#include "run/icd_probe.h"

#include <cstdlib>

#include <nlohmann/json.hpp>

#include "run/device_info_json.h"

namespace rayspec {

namespace {

// Why a manifest's driver offers no device (it was asked and offered none).
std::string noDeviceReason(const IcdManifest& m) {
  const std::string failure = icdLoadFailure(m);
  return failure.empty() ? "the driver loaded but offers no physical device" : failure;
}

}  // namespace

DeviceListing listDevicesOrWhyNot() {
  Result<std::vector<DeviceInfo>> listed = listDevices();
  DeviceListing out;
  out.loader_error = listed ? std::string() : listed.error().format();
  if (listed) out.devices = std::move(*listed);
  if (!out.devices.empty()) return out;
  std::string text;
  const IcdSearch search = findIcdManifests();
  for (const std::string& e : search.errors) text += (text.empty() ? "" : "; ") + e;
  for (const IcdManifest& m : search.manifests)
    text += (text.empty() ? "" : "; ") + ("ICD " + m.path + ": ") + noDeviceReason(m);
  if (search.manifests.empty() && search.errors.empty())
    text = "no ICD manifest found in " + icdSourceName(search.source);
  out.no_device = text;
  return out;
}

IcdProbe probeIcd(const IcdManifest& manifest, const ChildLimits& limits) {
  IcdProbe probe;
  probe.manifest = manifest;
  const ChildEnd end = runChild(
      [&](std::string& message) {
        setenv("VK_DRIVER_FILES", manifest.path.c_str(), 1);
        setenv("VK_ICD_FILENAMES", manifest.path.c_str(), 1);
        unsetenv("VK_ADD_DRIVER_FILES");
        const Result<std::vector<DeviceInfo>> listed = listDevices();
        const std::vector<DeviceInfo> devices = listed ? *listed : std::vector<DeviceInfo>{};
        std::string why;
        if (devices.empty())
          why = noDeviceReason(manifest) + (listed ? "" : " (" + listed.error().format() + ")");
        nlohmann::json listed_json = nlohmann::json::array();
        for (const DeviceInfo& d : devices) listed_json.push_back(deviceInfoJson(d));
        message = nlohmann::json{{"devices", listed_json}, {"why", why}}.dump();
        return 0;
      },
      limits);
  if (!end.ok()) {
    probe.failure = describeChildEnd(end, "the probe of this driver", limits);
    return probe;
  }
  const nlohmann::json j = nlohmann::json::parse(end.message, nullptr, false);
  try {
    std::vector<DeviceInfo> devices;
    for (const nlohmann::json& d : j.at("devices").get<std::vector<nlohmann::json>>())
      devices.push_back(deviceInfoFromJson(d));
    probe.devices = std::move(devices);
    probe.failure = j.at("why").get<std::string>();
  } catch (const std::exception& e) {
    probe.failure = std::string("the probe of this driver answered nothing readable: ") + e.what();
  }
  return probe;
}

std::string icdOfDevice(const std::string& device_uuid, const ChildLimits& limits) {
  const IcdSearch search = findIcdManifests();
  if (search.manifests.size() == 1 && search.errors.empty()) return search.manifests[0].path;
  if (device_uuid.empty()) return {};
  for (const IcdManifest& m : search.manifests)
    for (const DeviceInfo& d : probeIcd(m, limits).devices)
      if (d.device_uuid == device_uuid) return m.path;
  return {};
}

}  // namespace rayspec
