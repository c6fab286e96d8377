// For tests of fallible functions (base/result.h): the value, or a default
// one with the error's text in *error, so a test can assert on both.
#pragma once

#include <optional>
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

// The value, or nullopt with the error's message in *error: for tests that
// assert on whether there was a value, then on the message.
template <typename T>
std::optional<T> valueOrMessage(Result<T> r, std::string* error) {
  if (r) return std::move(*r);
  *error = r.error().message;
  return std::nullopt;
}

// Result<void>: true when it succeeded, else false with the error's text in *error.
inline bool orError(Result<void> r, std::string* error) {
  if (r) return true;
  *error = r.error().format();
  return false;
}

// "" when it succeeded, else the error's text: a test asserts it is "" and
// shows the error when it is not, or looks for words in it.
template <typename T>
std::string errorText(const Result<T>& r) {
  return r ? std::string() : r.error().format();
}

}  // namespace rayspec
