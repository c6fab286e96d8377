// Before the first case: is there a device to run on? Asked in a short child
// process (the parent must not initialise Vulkan before it forks the cases'
// children), or in this process with --no-isolation. A run whose --device
// matches nothing stops there, naming the devices there are.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "run/child_process.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

// What the device side will find of the device a probe found: what it
// offers and the validation layer the side runs it under (0: none). The
// NotSupported reasons of vulkan/case_support.h follow from these and the
// case alone, so the run decides them before either side of a case runs.
struct ProbedDevice {
  DeviceInfo info;
  uint32_t validation_layer = 0;
};

struct DeviceProbe {
  bool found = false;
  std::string description;  // the device the cases will run on: "llvmpipe (...) (Mesa ...)"
  std::string icd;          // the driver manifest it came from ("" when unknown)
  std::string device_uuid;  // DeviceInfo::device_uuid of that device
  bool cpu = false;         // DeviceInfo::cpu: a CPU device (lavapipe)
  std::string error;        // why none was found
  std::vector<std::string> devices;    // every device the loader sees, for people
  std::string no_device;               // no device at all: why, per driver manifest
  std::optional<ProbedDevice> probed;  // found: the device as the device side will see it
};

class VulkanAdapter;

// In a child process, which makes the device without the validation layer
// (only what is there matters) and tells which layer a device side made with
// `options` runs under (validationLayerFor).
DeviceProbe probeDevice(const VulkanOptions& options, const ChildLimits& limits);
DeviceProbe probeDeviceInProcess(const VulkanOptions& options);
// What an adapter already created found (the device, its ICD manifest when
// its driver library tells, see icdOfLibrary), and when it found none, the
// devices there are. probeDevice, in the parent, asks icdOfDevice when the
// library did not tell; in this process (--no-isolation) the ICD may stay
// unknown.
DeviceProbe describeAdapter(const VulkanAdapter& adapter);

// The manifest (of those the loader reads now) whose driver library is loaded
// at `library`; "" when none is.
std::string icdOfLibrary(const std::string& library);

// "no Vulkan device ... whose name contains 'x'; devices: [0] llvmpipe (ray tracing)".
std::string probeFailure(const DeviceProbe& p);

}  // namespace rayspec
