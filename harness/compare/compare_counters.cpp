#include <cstdlib>
#include <set>

#include "compare/compare_parts.h"
#include "compare/counter_modes.h"

namespace rayspec {

void compareCounters(const Case& c, const Results& device, const Results& model, size_t ambiguous_rays,
                     size_t undefined_rays, Verdict& v) {
  auto modes = counterModes(c);
  // R-UB: what a ray with undefined behaviour counts is anyone's guess.
  std::set<std::string> moved;
  if (undefined_rays) moved = countersUndefinedRaysMayMove(c);
  for (auto& [name, mode] : modes) {
    const bool undefined = moved.count(name) > 0;
    if (undefined) mode = CounterMode::Informational;
    const auto d_it = device.counters.find(name);
    const auto m_it = model.counters.find(name);
    const uint64_t d = d_it == device.counters.end() ? 0 : d_it->second;
    const uint64_t m = m_it == model.counters.end() ? 0 : m_it->second;
    Finding f;
    f.rule = "counter";
    const std::string values = "counter '" + name + "' (" + counterModeName(mode) + "): device " +
                               std::to_string(d) + ", model " + std::to_string(m);
    bool ok = true;
    switch (mode) {
      case CounterMode::Exact: {
        // Each numerically ambiguous ray may legally take the other path once.
        const uint64_t diff = d > m ? d - m : m - d;
        ok = diff <= ambiguous_rays;
        if (ok && diff) f.message = values + " (within " + std::to_string(ambiguous_rays) + " ambiguous rays)";
        break;
      }
      // Each ambiguous ray may legally take another path once here too.
      case CounterMode::AtLeast:
        ok = d + ambiguous_rays >= m;
        f.message = values;
        break;
      case CounterMode::AtMost:
        ok = d <= m + ambiguous_rays;
        f.message = values;
        break;
      case CounterMode::Informational: f.message = values; break;
    }
    if (undefined)
      f.message = values + " (informational: " + std::to_string(undefined_rays) +
                  " rays with undefined behaviour, R-UB, may have moved it)";
    if (!ok) {
      f.status = Status::Fail;
      f.message = values;
      v.add(f);
    } else if (!f.message.empty()) {
      f.status = Status::Pass;
      v.add(f);
    }
  }
}

}  // namespace rayspec
