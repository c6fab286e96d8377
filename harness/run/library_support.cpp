#include "run/library_support.h"

#include <utility>

#include "library/case_discovery.h"
#include "run/case_as_run.h"
#include "vulkan/case_support.h"

namespace rayspec {
namespace {

template <typename T>
void addFeatureRow(std::vector<FeatureRow>&, const char*, T DeviceInfo::*) {}
void addFeatureRow(std::vector<FeatureRow>& rows, const char* label, bool DeviceInfo::*member) {
  if (label) rows.emplace_back(label, member);
}

bool runs(const LibraryCase& l, const DeviceInfo& d, uint32_t validation_layer) {
  const Result<void> r = checkCaseSupport(d, validation_layer, l.c, l.plan);
  return r || r.error().kind != ErrorKind::NotSupported;
}

// The cases that run on `with` and not on `without`.
int skippedBy(const std::vector<LibraryCase>& cases, const DeviceInfo& with, uint32_t with_layer,
              const DeviceInfo& without, uint32_t without_layer) {
  int n = 0;
  for (const LibraryCase& l : cases)
    if (runs(l, with, with_layer) && !runs(l, without, without_layer)) ++n;
  return n;
}

}  // namespace

std::vector<FeatureRow> featureRows() {
  std::vector<FeatureRow> rows;
#define RAYSPEC_FEATURE_ROW(type, member, key, label, meaning) \
  addFeatureRow(rows, label, &DeviceInfo::member);
  RAYSPEC_DEVICE_INFO_FIELDS(RAYSPEC_FEATURE_ROW)
#undef RAYSPEC_FEATURE_ROW
  return rows;
}

std::vector<LibraryCase> libraryCases(const std::string& cases_dir) {
  std::vector<LibraryCase> cases;
  for (const CaseFile& f : findCases(cases_dir, "*")) {
    const ParseResult parsed = loadCase(f, cases_dir);
    if (!parsed.value) continue;
    const CaseAsRun as_run = caseAsRun(*parsed.value, RunOptions{});
    if (!as_run.runs) continue;
    cases.push_back({*as_run.runs, derivePlan(*as_run.runs)});
  }
  return cases;
}

LibrarySupport librarySupport(const std::vector<LibraryCase>& cases, const DeviceInfo& d,
                              uint32_t validation_layer) {
  LibrarySupport s;
  s.cases = static_cast<int>(cases.size());
  for (const LibraryCase& l : cases)
    if (!runs(l, d, validation_layer)) ++s.not_supported;
  DeviceInfo full = d;  // every feature d lacks, granted
  const std::vector<FeatureRow> rows = featureRows();
  for (const auto& [label, member] : rows) full.*member = true;
  for (const auto& [label, member] : rows) {
    if (d.*member) continue;
    DeviceInfo without = full;
    without.*member = false;
    s.missing.push_back({label, skippedBy(cases, full, 0, without, 0)});
  }
  if (validation_layer != 0) {
    const int n = skippedBy(cases, full, 0, full, validation_layer);
    if (n > 0) s.missing.push_back({vulkanVersionText(validation_layer), n, true});
  }
  return s;
}

}  // namespace rayspec
