// JSON files a test reads, edits and writes back (a saved run's summary.json,
// a bundle's results.json), as a hostile user would edit them.
#pragma once

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace testing_support {

inline nlohmann::json readJsonFile(const std::string& path) {
  return nlohmann::json::parse(std::ifstream(path));
}

inline void writeJsonFile(const std::string& path, const nlohmann::json& j) {
  std::ofstream(path) << j.dump(1);
}

}  // namespace testing_support
