// Reads a case file (cases/README.md) into a Case, checks it, and reports every
// problem with file, line, column and field. Never throws on bad input.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "case/case.h"
#include "case/source_loc.h"

namespace rayspec {

struct CaseError {
  SourceLoc loc;
  std::string message;
  std::string format() const;  // "FILE:LINE:COL: FIELD: MESSAGE"
};

struct ParseResult {
  std::optional<Case> value;     // set only when there is no error
  std::vector<CaseError> errors;
};

// name = path relative to cases_root without ".yaml"; family = its first folder.
ParseResult parseCaseFile(const std::string& path, const std::string& cases_root);
// Parses YAML text; file_name is used in locations, name becomes Case::name.
ParseResult parseCaseText(const std::string& yaml, const std::string& file_name,
                          const std::string& name);

}  // namespace rayspec
