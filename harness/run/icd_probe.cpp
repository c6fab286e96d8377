#include "run/icd_probe.h"

#include <cstdlib>

#include <nlohmann/json.hpp>

namespace rayspec {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(
    DeviceInfo, index, name, driver_name, driver_info, api_version, api_version_number, device_uuid,
    ray_tracing_extension, acceleration_structure_extension, ray_tracing_pipeline,
    acceleration_structure, shader_group_handle_size, shader_group_handle_alignment,
    shader_group_base_alignment, max_ray_recursion_depth, max_ray_hit_attribute_size,
    max_shader_group_stride, max_ray_dispatch_invocation_count, max_image_dimension_2d,
    max_storage_buffer_range, max_launch_size, acceleration_structure_host_commands,
    pipeline_library, opacity_micromap, ray_tracing_maintenance1, trace_rays_indirect,
    trace_rays_indirect2, position_fetch, library_group_handles, vertex_formats)

namespace {

// Why a manifest's driver offers no device (it was asked and offered none).
std::string noDeviceReason(const IcdManifest& m) {
  const std::string failure = icdLoadFailure(m);
  return failure.empty() ? "the driver loaded but offers no physical device" : failure;
}

}  // namespace

std::vector<DeviceInfo> listDevicesOrWhyNot(std::string* why, std::string* loader_error) {
  Result<std::vector<DeviceInfo>> listed = listDevices();
  if (loader_error) *loader_error = listed ? std::string() : listed.error().format();
  std::vector<DeviceInfo> devices = listed ? std::move(*listed) : std::vector<DeviceInfo>{};
  if (!devices.empty()) return devices;
  std::string text;
  const IcdSearch search = findIcdManifests();
  for (const std::string& e : search.errors) text += (text.empty() ? "" : "; ") + e;
  for (const IcdManifest& m : search.manifests)
    text += (text.empty() ? "" : "; ") + ("ICD " + m.path + ": ") + noDeviceReason(m);
  if (search.manifests.empty() && search.errors.empty())
    text = "no ICD manifest found in " + icdSourceName(search.source);
  if (why) *why = text;
  return devices;
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
        message = nlohmann::json{{"devices", devices}, {"why", why}}.dump();
        return 0;
      },
      limits);
  if (!end.ok()) {
    probe.failure = describeChildEnd(end, "the probe of this driver", limits);
    return probe;
  }
  const nlohmann::json j = nlohmann::json::parse(end.message, nullptr, false);
  try {
    probe.devices = j.at("devices").get<std::vector<DeviceInfo>>();
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
