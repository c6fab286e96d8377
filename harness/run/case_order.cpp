#include "run/case_order.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "base/whole_file.h"

namespace rayspec {
namespace {

// A cache file larger than this is not read (it is ours, but every file read is input).
constexpr std::uintmax_t kMaxCacheBytes = 16u << 20;

std::string cachePath(const std::string& cache_dir) {
  return cache_dir + "/case-seconds.json";
}

}  // namespace

std::map<std::string, double> loadCaseSeconds(const std::string& cache_dir) {
  std::map<std::string, double> out;
  if (cache_dir.empty()) return out;
  const Result<std::string> text = readWholeFile(cachePath(cache_dir), kMaxCacheBytes);
  if (!text) return out;  // none yet, or not one to use: the run orders by name
  const nlohmann::json j = nlohmann::json::parse(*text, nullptr, false);
  if (!j.is_object()) return out;
  for (const auto& [name, seconds] : j.items())
    if (seconds.is_number()) out[name] = seconds.get<double>();
  return out;
}

void saveCaseSeconds(const std::string& cache_dir, const std::map<std::string, double>& seconds) {
  if (cache_dir.empty() || seconds.empty()) return;
  std::map<std::string, double> all = loadCaseSeconds(cache_dir);
  for (const auto& [name, s] : seconds) all[name] = s;
  std::error_code ec;
  std::filesystem::create_directories(cache_dir, ec);
  const std::string text = nlohmann::json(all).dump(0) + "\n";
  (void)writeWholeFile(cachePath(cache_dir), text);  // a cache, which runs beside this one read
}

std::vector<size_t> longestFirst(const std::vector<std::string>& names,
                                 const std::map<std::string, double>& seconds) {
  std::vector<double> cost(names.size());
  for (size_t i = 0; i < names.size(); ++i) {
    const auto it = seconds.find(names[i]);
    cost[i] = it == seconds.end() ? std::numeric_limits<double>::infinity() : it->second;
  }
  std::vector<size_t> order(names.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return cost[a] > cost[b]; });
  return order;
}

}  // namespace rayspec
