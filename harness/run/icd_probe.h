// `rayspec devices`: each driver manifest probed alone, in a child process
// whose loader sees only that manifest (VK_DRIVER_FILES), so that a driver
// that crashes or hangs while loading ends only that child.
#pragma once

#include <string>
#include <vector>

#include "run/child_process.h"
#include "vulkan/icd_manifest.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

struct IcdProbe {
  IcdManifest manifest;
  std::vector<DeviceInfo> devices;  // every device the driver offers, usable or not
  std::string failure;  // no device: why (driver not loadable, none found, the probe died)
};

IcdProbe probeIcd(const IcdManifest& manifest, const ChildLimits& limits);

// What the loader shows in this process (a child's body).
struct DeviceListing {
  std::vector<DeviceInfo> devices;
  // When there are none, why, told for each manifest it would read ("ICD
  // FILE: the driver library ... could not be loaded: ..."; "" with devices).
  std::string no_device;
  std::string loader_error;  // the loader's own error ("vkCreateInstance: ..."; "" none)
};
DeviceListing listDevicesOrWhyNot();

// The manifest (of those the loader reads now) that offers the device with
// this deviceUUID-driverUUID: the only one there is, or the one whose probe
// lists it (a child per manifest); "" when none does. For drivers whose
// device commands live in another library than the manifest's (NVIDIA's are
// in libnvidia-eglcore, the manifest names libGLX_nvidia), where dladdr alone
// cannot tell.
std::string icdOfDevice(const std::string& device_uuid, const ChildLimits& limits);

// Limits of a child that only asks the loader.
inline constexpr double kProbeSeconds = 60;

}  // namespace rayspec
