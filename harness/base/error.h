// The one error convention: a fallible function returns Result<T>
// (base/result.h), which holds its value or an Error: a message and, when the
// error is about a place in an input file (a case, sweep, baseline or saved
// file), where. Exceptions stay at the boundaries that force them (yaml-cpp,
// nlohmann-json, CLI11) and are turned into an Error there.
#pragma once

#include <string>

#include "base/source_loc.h"

namespace rayspec {

struct Error {
  SourceLoc loc;  // loc.file empty: not about a place in an input file
  std::string message;

  // "FILE:LINE:COL: FIELD: MESSAGE" (the field when known), or MESSAGE when
  // there is no file; input quoted in it made visible (base/visible_text.h).
  std::string format() const;
};

// An error about no place in an input file.
inline Error errorMessage(std::string message) {
  return Error{{}, std::move(message)};
}

}  // namespace rayspec
