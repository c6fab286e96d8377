// For tests of fallible functions (base/result.h): the value, or a default
// one with the error's text in *error, so a test can assert on both.
#pragma once

#include <string>
#include <utility>

#include "base/result.h"

namespace rayspec {

template <typename T>
T orError(Result<T> r, std::string* error) {
  if (r) return std::move(*r);
  *error = r.error().format();
  return T{};
}

// Result<void>: true when it succeeded, else false with the error's text in *error.
inline bool orError(Result<void> r, std::string* error) {
  if (r) return true;
  *error = r.error().format();
  return false;
}

}  // namespace rayspec
