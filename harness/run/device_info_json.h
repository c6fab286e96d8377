// A DeviceInfo as JSON and back, one key per row of
// vulkan/device_info_fields.h: what a driver probe's child process tells its
// parent (run/icd_probe.h).
#pragma once

#include <nlohmann/json.hpp>

#include "vulkan/vulkan_engine.h"

namespace rayspec {

nlohmann::json deviceInfoJson(const DeviceInfo& d);
// Throws nlohmann::json::exception where a key is missing or holds another type.
DeviceInfo deviceInfoFromJson(const nlohmann::json& j);

}  // namespace rayspec
