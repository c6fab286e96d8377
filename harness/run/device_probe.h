// Before the first case: is there a device to run on? Asked in a short child
// process (the parent must not initialise Vulkan before it forks the cases'
// children), or in this process with --no-isolation. A run whose --device
// matches nothing stops there, naming the devices there are.
#pragma once

#include <string>
#include <vector>

#include "run/child_process.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

struct DeviceProbe {
  bool found = false;
  std::string description;  // the device the cases will run on: "llvmpipe (...) (Mesa ...)"
  std::string icd;          // the driver manifest it came from ("" when unknown)
  std::string device_uuid;  // DeviceInfo::device_uuid of that device
  bool cpu = false;         // DeviceInfo::cpu: a CPU device (lavapipe)
  std::string error;        // why none was found
  std::vector<std::string> devices;  // every device the loader sees, for people
  std::string no_device;             // no device at all: why, per driver manifest
};

class VulkanAdapter;

DeviceProbe probeDevice(const VulkanOptions& options,
                        const ChildLimits& limits);  // in a child process
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
