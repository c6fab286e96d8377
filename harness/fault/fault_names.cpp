#include <algorithm>

#include "fault/planted_fault.h"

namespace rayspec {

const std::vector<std::string>& faultNames() {
  static const std::vector<std::string> names = {"drop-miss", "swap-primitive-id", "chit-after-ignore", "shift-t",
                                                 "duplicate-any-hit", "leak-edge", "closed-triangle-interval",
                                                 "open-aabb-interval", "crash", "hang"};
  return names;
}

bool isFaultName(const std::string& name) {
  const auto& n = faultNames();
  return std::find(n.begin(), n.end(), name) != n.end();
}

bool isProcessFault(const std::string& name) { return name == "crash" || name == "hang"; }

}  // namespace rayspec
