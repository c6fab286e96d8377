// The one way an enum gets its names: a list macro with one row per
// enumerator, X(Enumerator, "name"), from which the enum itself, its names,
// the name's inverse and the list printed in help and errors are all made.
// Because the enum is made from the list, no enumerator can lack a name.
//
//   #define RAYSPEC_COST_SIDES(X) X(Parent, "parent") X(Model, "model") X(Device, "device")
//   enum class CostSide { RAYSPEC_COST_SIDES(RAYSPEC_ENUMERATOR) };
//   RAYSPEC_ENUM_NAMES(CostSide, RAYSPEC_COST_SIDES)
//
//   nameOf(CostSide::Model)           "model"
//   valueNamed<CostSide>("model")     CostSide::Model (nullopt for no such name)
//   namesJoined(enumNames<CostSide>())  "parent, model, device"
//
// A row may carry more columns after the name (another spelling of the same
// enumerator); RAYSPEC_ENUMERATOR and the name table ignore them.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace rayspec {

template <typename E>
struct EnumName {
  E value;
  const char* name;
};

// Specialised for each enum by RAYSPEC_ENUM_NAMES, in namespace rayspec.
template <typename E>
struct EnumNameTable;

#define RAYSPEC_ENUMERATOR(id, ...) id,
#define RAYSPEC_ENUM_NAME_ROW(id, name, ...) EnumName<Enum>{Enum::id, name},
#define RAYSPEC_ENUM_NAMES(E, LIST)                                                    \
  template <>                                                                          \
  struct EnumNameTable<E> {                                                            \
    using Enum = E;                                                                    \
    static constexpr EnumName<E> rows[] = {LIST(RAYSPEC_ENUM_NAME_ROW)};               \
  };                                                                                   \
  static_assert(enumRowsInOrder(std::span<const EnumName<E>>(EnumNameTable<E>::rows)), \
                #E ": the enum and its names come from one list")

// Every row i names enumerator i: true for any enum made by RAYSPEC_ENUMERATOR
// from the same list, so nameOf may index the table.
template <typename E>
constexpr bool enumRowsInOrder(std::span<const EnumName<E>> rows) {
  for (size_t i = 0; i < rows.size(); ++i)
    if (static_cast<size_t>(rows[i].value) != i) return false;
  return true;
}

template <typename E>
constexpr std::span<const EnumName<E>> enumNames() {
  return EnumNameTable<E>::rows;
}

template <typename E>
constexpr size_t enumCount() {
  return enumNames<E>().size();
}

// Every enumerator, in order.
template <typename E>
constexpr std::array<E, enumCount<E>()> enumValues() {
  std::array<E, enumCount<E>()> values{};
  for (size_t i = 0; i < values.size(); ++i) values[i] = enumNames<E>()[i].value;
  return values;
}

// "?" for a value outside the enum (a cast from bad data).
template <typename E>
constexpr const char* nameOf(E value) {
  const size_t i = static_cast<size_t>(value);
  return i < enumCount<E>() ? enumNames<E>()[i].name : "?";
}

template <typename E>
std::optional<E> valueNamed(std::string_view name) {
  for (const EnumName<E>& row : enumNames<E>())
    if (name == row.name) return row.value;
  return std::nullopt;
}

// valueNamed as the older "bool parseX(name, &out)" functions read it.
template <typename E>
bool parseEnumName(std::string_view name, E* out) {
  const std::optional<E> value = valueNamed<E>(name);
  if (value) *out = *value;
  return value.has_value();
}

// The names of any table whose rows have a `name`, joined: "a, b, c".
template <typename Rows>
std::string namesJoined(const Rows& rows, std::string_view separator = ", ") {
  std::string joined;
  for (const auto& row : rows) {
    if (!joined.empty()) joined += separator;
    joined += row.name;
  }
  return joined;
}

}  // namespace rayspec
