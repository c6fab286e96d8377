// DeviceInfo through its JSON (run/device_info_json.h) and back, as a driver
// probe's child sends it to its parent. The fields are those of
// vulkan/device_info_fields.h, walked here with the same list: a field added
// there is covered with no change here (one of a new type needs its own
// setDistinctValue below, or this file does not build).
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run/device_info_json.h"

namespace rayspec {
namespace {

// A value unlike the default and, but for bools, unlike every other field's:
// n counts the values given so far.
void setDistinctValue(uint32_t& v, int& n) {
  v = 1000 + ++n;
}
void setDistinctValue(uint64_t& v, int& n) {
  v = (uint64_t{1} << 40) + ++n;  // beyond 32 bits: the JSON keeps all 64
}
void setDistinctValue(bool& v, int& n) {
  ++n;
  v = true;
}
void setDistinctValue(std::string& v, int& n) {
  v = "text " + std::to_string(++n);
}
void setDistinctValue(DeviceLaunchSize& v, int& n) {
  for (uint64_t& x : v) x = (uint64_t(1) << 40) + ++n;  // beyond 32 bits
}
void setDistinctValue(std::vector<std::string>& v, int& n) {
  const int first = ++n;
  v = {"format " + std::to_string(first), "format " + std::to_string(++n)};
}

DeviceInfo everyFieldDistinct() {
  DeviceInfo d;
  int n = 0;
#define RAYSPEC_DEVICE_INFO_SET(type, member, ...) setDistinctValue(d.member, n);
  RAYSPEC_DEVICE_INFO_FIELDS(RAYSPEC_DEVICE_INFO_SET)
#undef RAYSPEC_DEVICE_INFO_SET
  return d;
}

// The JSON keys of the fields where a and b differ.
std::vector<std::string> differingFields(const DeviceInfo& a, const DeviceInfo& b) {
  std::vector<std::string> keys;
#define RAYSPEC_DEVICE_INFO_DIFFERS(type, member, key, ...) \
  if (!(a.member == b.member)) keys.push_back(key);
  RAYSPEC_DEVICE_INFO_FIELDS(RAYSPEC_DEVICE_INFO_DIFFERS)
#undef RAYSPEC_DEVICE_INFO_DIFFERS
  return keys;
}

std::vector<std::string> allKeys() {
  std::vector<std::string> keys;
#define RAYSPEC_DEVICE_INFO_KEY(type, member, key, ...) keys.push_back(key);
  RAYSPEC_DEVICE_INFO_FIELDS(RAYSPEC_DEVICE_INFO_KEY)
#undef RAYSPEC_DEVICE_INFO_KEY
  return keys;
}

// Written, sent as text and read back.
DeviceInfo throughJson(const DeviceInfo& d) {
  return deviceInfoFromJson(nlohmann::json::parse(deviceInfoJson(d).dump()));
}

TEST(DeviceInfoJson, EveryFieldRoundTrips) {
  const DeviceInfo d = everyFieldDistinct();
  EXPECT_EQ(differingFields(d, DeviceInfo{}), allKeys()) << "every field set to a non-default";
  EXPECT_EQ(differingFields(d, throughJson(d)), std::vector<std::string>{});
}

// One field set at a time, the others default: a key read into another
// field (the bools all look alike above) comes back wrong.
TEST(DeviceInfoJson, EachFieldAloneRoundTrips) {
  std::vector<std::function<void(DeviceInfo&)>> setters;
#define RAYSPEC_DEVICE_INFO_SETTER(type, member, ...) \
  setters.push_back([](DeviceInfo& d) {               \
    int n = 0;                                        \
    setDistinctValue(d.member, n);                    \
  });
  RAYSPEC_DEVICE_INFO_FIELDS(RAYSPEC_DEVICE_INFO_SETTER)
#undef RAYSPEC_DEVICE_INFO_SETTER
  const std::vector<std::string> keys = allKeys();
  ASSERT_EQ(setters.size(), keys.size());
  for (size_t i = 0; i < setters.size(); ++i) {
    DeviceInfo d;
    setters[i](d);
    EXPECT_EQ(differingFields(d, DeviceInfo{}), std::vector<std::string>{keys[i]});
    EXPECT_EQ(differingFields(d, throughJson(d)), std::vector<std::string>{}) << keys[i];
  }
}

TEST(DeviceInfoJson, OneKeyPerField) {
  const nlohmann::json j = deviceInfoJson(everyFieldDistinct());
  std::vector<std::string> written;
  for (const auto& item : j.items()) written.push_back(item.key());
  std::vector<std::string> keys = allKeys();
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(written, keys);  // nlohmann keeps an object's keys sorted
  EXPECT_TRUE(j.contains("cpu") && j.contains("scalar_block_layout")) << j.dump();
  EXPECT_EQ(j["max_launch_size"].size(), 3u) << j.dump();
}

TEST(DeviceInfoJson, AMissingKeyIsAnError) {
  for (const std::string& key : allKeys()) {
    nlohmann::json j = deviceInfoJson(everyFieldDistinct());
    j.erase(key);
    EXPECT_THROW(deviceInfoFromJson(j), nlohmann::json::exception) << key;
  }
}

}  // namespace
}  // namespace rayspec
