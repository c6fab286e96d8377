#include "cli/limits_check.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <utility>
#include <vector>

#include "report/baseline_gate.h"
#include "vulkan/required_limits.h"

namespace rayspec {

LimitsVerdict printLimitChecks(const DeviceInfo& d, const Baseline& baseline) {
  LimitsVerdict v;
  std::printf("        required limits (Vulkan specification, Limits chapter, Required Limits):\n");
  for (const LimitCheck& c : checkRequiredLimits(d)) {
    const bool listed = expectedStatus(baseline, c.caseName()) == Status::Fail;
    const char* verdict = !c.applies ? "NotSupported" : c.ok ? "Pass" : "Fail";
    std::string note;
    if (c.applies && !c.ok) {
      ++v.violations;
      ++(listed ? v.expected : v.unexpected);
      if (!listed) v.unexpected_limits.push_back(c.caseName());
      note = listed ? " (expected by the baseline)" : " (UNEXPECTED)";
    } else if (listed) {
      ++v.unexpected_passes;
      note = " (the baseline expects Fail: update it)";
    }
    std::printf("          %-12s %s: %llu, %s %s%s\n", verdict, c.caseName().c_str(),
                static_cast<unsigned long long>(c.value), c.requirement.c_str(),
                c.applies ? ("(" + c.structure + ")").c_str() : "(the device lacks it)",
                note.c_str());
  }
  return v;
}

Result<Baseline> loadLimitsBaseline(const std::string& path) {
  RAYSPEC_TRY(Baseline b, loadBaseline(path));
  std::set<std::string> limits;
  for (const LimitCheck& c : checkRequiredLimits(DeviceInfo{})) limits.insert(c.caseName());
  std::vector<std::pair<int, std::string>> entries;  // in the file's order
  for (const auto& [name, line] : b.line_of) entries.emplace_back(line, name);
  std::sort(entries.begin(), entries.end());
  for (const auto& [line, name] : entries) {
    const std::string where = path + ":" + std::to_string(line) + ": " + name;
    if (!limits.count(name))
      return errorMessage(where +
                          " names no required limit (a limits baseline lists limits/<name>, as "
                          "`rayspec devices --check-limits` prints them)");
    if (const Status s = b.expected.at(name); s != Status::Fail)
      return errorMessage(where + "," + statusName(s) +
                          ": a limits baseline lists known violations only, each as Fail");
  }
  return b;
}

std::vector<std::string> baselinesListing(const std::string& folder,
                                          const std::vector<std::string>& violations) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const std::filesystem::directory_entry& e :
       std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = e.path().filename().string();
    const std::string suffix = "-limits.csv";
    if (name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  std::vector<std::string> listing;
  for (const std::string& path : files) {
    const Result<Baseline> b = loadLimitsBaseline(path);
    if (b && !violations.empty() &&
        std::all_of(violations.begin(), violations.end(), [&](const std::string& limit) {
          return expectedStatus(*b, limit) == Status::Fail;
        }))
      listing.push_back(path);
  }
  return listing;
}

}  // namespace rayspec
