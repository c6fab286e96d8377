#include "compare/undefined_behaviour.h"

#include <algorithm>
#include <map>
#include <sstream>

#include "compare/compare_results.h"

namespace rayspec {
namespace {

constexpr const char* kRule = "R-UB";

// "3 rays: hit-record-out-of-range 2 (rays 4 5; ray 4: WHAT); ..."
std::string describe(const std::vector<UndefinedRays>& groups) {
  uint32_t total = 0;
  for (const UndefinedRays& g : groups) total += g.ray_count;
  std::ostringstream s;
  s << total << (total == 1 ? " ray: " : " rays: ");
  for (size_t i = 0; i < groups.size(); ++i) {
    const UndefinedRays& g = groups[i];
    s << (i ? "; " : "") << undefinedReasonName(g.reason) << ' ' << g.ray_count << " (rays";
    for (uint32_t r : g.rays) s << ' ' << r;
    if (g.ray_count > g.rays.size()) s << " ...";
    s << "; ray " << g.rays.front() << ": " << g.what << ')';
  }
  return s.str();
}

// The first rays over every reason, in launch order, and their count.
Finding undefinedFinding(Status status, const std::vector<UndefinedRays>& groups,
                         const std::string& message) {
  Finding f{status, kRule, message, {}, 0};
  std::vector<uint32_t> first;
  for (const UndefinedRays& g : groups) {
    f.ray_count += g.ray_count;
    first.insert(first.end(), g.rays.begin(), g.rays.end());
  }
  std::sort(first.begin(), first.end());
  first.resize(std::min(first.size(), kFirstRays));
  f.rays = first;
  return f;
}

}  // namespace

std::vector<UndefinedRays> groupUndefinedRays(const std::vector<UndefinedRay>& rays) {
  std::map<UndefinedReason, UndefinedRays> by_reason;
  for (const UndefinedRay& u : rays) {
    UndefinedRays& g = by_reason[u.reason];
    if (g.ray_count++ == 0) {
      g.reason = u.reason;
      g.what = u.what;
    }
    if (g.rays.size() < kFirstRays) g.rays.push_back(u.ray);
  }
  std::vector<UndefinedRays> groups;
  for (auto& [reason, g] : by_reason) groups.push_back(std::move(g));
  return groups;
}

bool judgeUndefinedBehaviour(const Case& c, const Results& device, const Results& model,
                             Verdict& v) {
  if (!model.ok() || model.undefined.empty()) return true;
  const std::vector<UndefinedRays> groups = groupUndefinedRays(model.undefined);
  const std::string what = describe(groups);
  const bool survived = device.status != SideStatus::Crash && device.status != SideStatus::Timeout;
  if (c.claims(kRule)) {
    // A robustness probe: surviving is all that is asked of the undefined rays.
    v.undefined = groups;
    if (device.ok())
      v.add(undefinedFinding(Status::Pass, groups,
                             "R-UB probe: the device survived undefined behaviour: " + what));
    else if (!survived)
      v.add(undefinedFinding(Status::Pass, groups, "R-UB probe: undefined behaviour: " + what));
    return device.ok();
  }
  // Not a probe: the case is at fault, not the device; nothing is judged.
  std::string message = "the case has undefined behaviour: " + what +
                        "; fix the case, or claim R-UB to make it a robustness probe";
  if (!survived)
    message = std::string("the device ") +
              (device.status == SideStatus::Crash ? "crashed" : "timed out") + " (" +
              device.statusText() + "); " + message;
  v = Verdict{};
  v.undefined = groups;
  v.add(undefinedFinding(Status::CaseError, groups, message));
  return false;
}

}  // namespace rayspec
