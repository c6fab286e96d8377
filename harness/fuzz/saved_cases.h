// `rayspec fuzz --device-results DIR --saved-cases CASES`: a device run saved
// elsewhere is judged against the case texts it ran (--generate-only's
// OUT/cases, as packed), never against what the generator here makes from
// the same seeds (a generator changed since makes other cases). The text of
// seed S is CASES/fuzz/seed-S.yaml; where DIR holds its device bundle, the
// bundle's case_hash must be that text's (run/device_results.h checks the
// same of any saved run). Its features are those its text shows
// (fuzz/content_features.h), whatever the generator here makes of the seed:
// the known classes (fuzz/known_classes.h) match what the case holds.
#pragma once

#include <cstdint>
#include <string>

#include "base/result.h"
#include "fuzz/generate_case.h"

namespace rayspec {

// The saved case of `seed`. The error (ErrorKind::Input) names the file:
// CASES/fuzz/seed-S.yaml when it is missing or does not read, or
// DIR/fuzz/seed-S/device/results.json and its field case_hash when the
// bundle there ran another text.
Result<GeneratedCase> savedCase(const std::string& cases, const std::string& device_results,
                                uint64_t seed);

}  // namespace rayspec
