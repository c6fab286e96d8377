// Names of stages and value types, and component counts of value types.
#include "program/program.h"

namespace rayspec {

const char* valueTypeSpelling(ValueType t) {
#define RAYSPEC_VALUE_TYPE_SPELLING(id, name, spelling, components) spelling,
  static constexpr const char* kSpellings[] = {RAYSPEC_VALUE_TYPES(RAYSPEC_VALUE_TYPE_SPELLING)};
#undef RAYSPEC_VALUE_TYPE_SPELLING
  return kSpellings[static_cast<size_t>(t)];
}

int componentCount(ValueType t) {
#define RAYSPEC_VALUE_TYPE_COMPONENTS(id, name, spelling, components) components,
  static constexpr int kComponents[] = {RAYSPEC_VALUE_TYPES(RAYSPEC_VALUE_TYPE_COMPONENTS)};
#undef RAYSPEC_VALUE_TYPE_COMPONENTS
  return kComponents[static_cast<size_t>(t)];
}

}  // namespace rayspec
