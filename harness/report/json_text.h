// JSON as text, for the files a run writes (summary.json, the journal,
// cost.json).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "base/result.h"

namespace rayspec {

// j.dump(indent), or an ErrorKind::Input error holding what nlohmann-json
// threw: text in it that is not UTF-8 (a case's name or message) cannot be
// written as JSON. Input, because the details of a case are at fault, not the
// disk; the run makes that case a CaseError (run/case_steps.h).
Result<std::string> jsonText(const nlohmann::json& j, int indent = -1);

}  // namespace rayspec
