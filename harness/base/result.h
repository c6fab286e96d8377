// Result<T>: what a fallible function returns, its value or an Error
// (base/error.h); Result<void> for one that returns nothing. Read it as
//   Result<Baseline> b = loadBaseline(...);
//   if (!b) return setupFailed(b.error());
//   use(*b);
// Where a failed step only passes its error up, the macros below say so in
// one line, so that a function reads as its named steps:
//   RAYSPEC_TRY(VkCommandBuffer cmd, beginCommands(ctx, cleanup));
//   RAYSPEC_TRY_VOID(submitAndWait(ctx, cmd));
#pragma once

#include <optional>
#include <utility>
#include <variant>

#include "base/error.h"

namespace rayspec {

template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::in_place_index<0>, std::move(value)) {}
  Result(Error error) : v_(std::in_place_index<1>, std::move(error)) {}

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& operator*() { return std::get<0>(v_); }
  const T& operator*() const { return std::get<0>(v_); }
  T* operator->() { return &std::get<0>(v_); }
  const T* operator->() const { return &std::get<0>(v_); }
  const Error& error() const { return std::get<1>(v_); }

 private:
  std::variant<T, Error> v_;
};

template <>
class [[nodiscard]] Result<void> {
 public:
  Result() = default;  // success
  Result(Error error) : error_(std::move(error)) {}

  bool ok() const { return !error_; }
  explicit operator bool() const { return ok(); }
  const Error& error() const { return *error_; }

 private:
  std::optional<Error> error_;
};

}  // namespace rayspec

#define RAYSPEC_TRY_JOIN2(a, b) a##b
#define RAYSPEC_TRY_JOIN(a, b) RAYSPEC_TRY_JOIN2(a, b)

// RAYSPEC_TRY(DECLARATION, EXPR): EXPR is a Result<T>; on an error the
// enclosing function returns it (its own return type a Result of any T),
// else DECLARATION (e.g. `Buffer b`, or an existing variable) takes the
// value. Expands to two statements: not the lone body of an if or a loop.
#define RAYSPEC_TRY(declaration, expr)                         \
  auto RAYSPEC_TRY_JOIN(rayspec_tried_, __LINE__) = (expr);    \
  if (!RAYSPEC_TRY_JOIN(rayspec_tried_, __LINE__))             \
    return RAYSPEC_TRY_JOIN(rayspec_tried_, __LINE__).error(); \
  declaration = std::move(*RAYSPEC_TRY_JOIN(rayspec_tried_, __LINE__))

// RAYSPEC_TRY_VOID(EXPR): EXPR is a Result of any T, its value unused; on an
// error the enclosing function returns it.
#define RAYSPEC_TRY_VOID(expr)                                                          \
  do {                                                                                  \
    if (auto rayspec_tried = (expr); !rayspec_tried.ok()) return rayspec_tried.error(); \
  } while (false)
