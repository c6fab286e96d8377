// Names of stages and value types, component counts of value types, and the
// sized scalars' rows (program/program.h).
#include "program/program.h"

namespace rayspec {

const char* valueTypeSpelling(ValueType t) {
#define RAYSPEC_VALUE_TYPE_SPELLING(id, name, spelling, ...) spelling,
  static constexpr const char* kSpellings[] = {RAYSPEC_VALUE_TYPES(RAYSPEC_VALUE_TYPE_SPELLING)};
#undef RAYSPEC_VALUE_TYPE_SPELLING
  return kSpellings[static_cast<size_t>(t)];
}

const char* valueTypeGlsl(ValueType t) {
#define RAYSPEC_VALUE_TYPE_GLSL(id, name, spelling, components, glsl) glsl,
  static constexpr const char* kGlsl[] = {RAYSPEC_VALUE_TYPES(RAYSPEC_VALUE_TYPE_GLSL)};
#undef RAYSPEC_VALUE_TYPE_GLSL
  return kGlsl[static_cast<size_t>(t)];
}

int componentCount(ValueType t) {
#define RAYSPEC_VALUE_TYPE_COMPONENTS(id, name, spelling, components, ...) components,
  static constexpr int kComponents[] = {RAYSPEC_VALUE_TYPES(RAYSPEC_VALUE_TYPE_COMPONENTS)};
#undef RAYSPEC_VALUE_TYPE_COMPONENTS
  return kComponents[static_cast<size_t>(t)];
}

const SizedType* sizedType(ValueType t) {
#define RAYSPEC_SIZED_TYPE_ROW(X, id, name, spelling, glsl, bits, kind, extension, feature, vec) \
  SizedType{ValueType::id, bits, SizedKind::kind, extension, feature},
  static constexpr SizedType kRows[] = {RAYSPEC_SIZED_TYPES(RAYSPEC_SIZED_TYPE_ROW, )};
  static constexpr SizedType kUintRow[] = {RAYSPEC_UINT_VECTORS(RAYSPEC_SIZED_TYPE_ROW, )};
#undef RAYSPEC_SIZED_TYPE_ROW
  if (t >= ValueType::UintVec2 && t <= ValueType::UintVec4) return &kUintRow[0];
  const ValueType scalar = sizedComponent(t);
  for (const SizedType& row : kRows)
    if (row.type == scalar) return &row;
  return nullptr;
}

bool isSizedVector(ValueType t) {
  return t >= ValueType::Int8Vec2 && t <= ValueType::UintVec4;
}

ValueType sizedComponent(ValueType t) {
  if (!isSizedVector(t)) return t;
  if (t >= ValueType::UintVec2) return ValueType::Uint;
  const int k = static_cast<int>(t) - static_cast<int>(ValueType::Int8Vec2);
  return static_cast<ValueType>(static_cast<int>(ValueType::Int8) + k / 3);
}

ValueType sizedVectorOf(ValueType s, int n) {
  if (s == ValueType::Uint)
    return static_cast<ValueType>(static_cast<int>(ValueType::UintVec2) + n - 2);
  const int k = static_cast<int>(s) - static_cast<int>(ValueType::Int8);
  return static_cast<ValueType>(static_cast<int>(ValueType::Int8Vec2) + 3 * k + n - 2);
}

bool isSizedInteger(ValueType t) {
  const SizedType* s = sizedType(t);
  return s && s->kind != SizedKind::Floating;
}

bool isSizedFloat(ValueType t) {
  const SizedType* s = sizedType(t);
  return s && s->kind == SizedKind::Floating;
}

std::string arrayTypeSpellings() {
  std::string out;
  for (ValueType t : enumValues<ValueType>()) {
    if (t == ValueType::Bool) continue;
    out += (out.empty() ? "" : ", ") + std::string(valueTypeSpelling(t));
  }
  return out;
}

}  // namespace rayspec
