// Leaks (no any-hit) and double hits (more than one) per ray.
#include "stability/leak_counts.h"

#include "results/record_layout.h"

namespace rayspec {

LeakCounts countLeaks(const Results& r) {
  LeakCounts c;
  const uint32_t words = recordWords();
  const uint32_t ahit = findRecordField("any_hit_runs")->offset;
  for (size_t i = 0; i + words <= r.records.size(); i += words) {
    const uint32_t runs = r.records[i + ahit];
    ++c.rays;
    c.leaks += runs == 0;
    c.doubles += runs > 1;
  }
  return c;
}

}  // namespace rayspec
