// DeviceInfo's JSON, both ways generated from vulkan/device_info_fields.h.
#include "run/device_info_json.h"

namespace rayspec {

nlohmann::json deviceInfoJson(const DeviceInfo& d) {
  nlohmann::json j = nlohmann::json::object();
#define RAYSPEC_DEVICE_INFO_TO_JSON(type, member, key, ...) j[key] = d.member;
  RAYSPEC_DEVICE_INFO_FIELDS(RAYSPEC_DEVICE_INFO_TO_JSON)
#undef RAYSPEC_DEVICE_INFO_TO_JSON
  return j;
}

DeviceInfo deviceInfoFromJson(const nlohmann::json& j) {
  DeviceInfo d;
#define RAYSPEC_DEVICE_INFO_FROM_JSON(type, member, key, ...) j.at(key).get_to(d.member);
  RAYSPEC_DEVICE_INFO_FIELDS(RAYSPEC_DEVICE_INFO_FROM_JSON)
#undef RAYSPEC_DEVICE_INFO_FROM_JSON
  return d;
}

}  // namespace rayspec
