#include "run/failing_rays.h"

#include <set>

#include "bundle/results_io.h"
#include "results/record_layout.h"

namespace rayspec {

std::vector<RayRow> failingRays(const Verdict& v, const Plan& plan, const Results& device,
                                const Results& model) {
  constexpr size_t kMaxRays = 16;
  std::set<uint32_t> rays;
  for (const Finding& f : v.findings)
    if (f.status == Status::Fail || f.status == Status::QualityWarning)
      for (uint32_t r : f.rays)
        if (rays.size() < kMaxRays) rays.insert(r);
  std::vector<std::string> fields = plan.record_fields;
  for (const RecordField& f : recordFields())
    if (f.automatic) fields.push_back(f.name);
  std::vector<RayRow> rows;
  const uint32_t words = recordWords();
  for (uint32_t r : rays) {
    if ((r + 1) * static_cast<size_t>(words) > device.records.size() ||
        (r + 1) * static_cast<size_t>(words) > model.records.size())
      continue;
    const uint32_t* d = &device.records[r * words];
    const uint32_t* m = &model.records[r * words];
    for (const std::string& f : fields) {
      RayRow row{r,
                 device.width ? r % device.width : r,
                 device.width ? r / device.width : 0,
                 f,
                 formatField(f, d),
                 formatField(f, m)};
      rows.push_back(row);
    }
  }
  return rows;
}

}  // namespace rayspec
