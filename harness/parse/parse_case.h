// Reads a case file (cases/README.md) into a Case, checks it, and reports every
// problem with file, line, column and field. Never throws on bad input.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/source_loc.h"
#include "case/case.h"

namespace rayspec {

struct ParseResult {
  std::optional<Case> value;  // set only when there is no error
  std::vector<Error> errors;
  // Undefined behaviour (R-UB) found where the values are constants: errors
  // above unless the case claims R-UB (then also Case::static_undefined).
  std::vector<StaticUndefined> undefined;
};

// name = path relative to cases_root without ".yaml"; family = its first folder.
// catalog: the rule labels of references/spec-rules.yaml (report/rule_catalog.h
// ruleLabels()); when given, a label outside it is an error at its line:col.
ParseResult parseCaseFile(const std::string& path, const std::string& cases_root,
                          const std::vector<std::string>* catalog = nullptr);
// Parses YAML text; file_name is used in locations, name becomes Case::name.
ParseResult parseCaseText(const std::string& yaml, const std::string& file_name,
                          const std::string& name,
                          const std::vector<std::string>* catalog = nullptr);

}  // namespace rayspec
