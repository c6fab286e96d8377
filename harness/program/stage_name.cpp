// Names of stages and value types, and component counts of value types.
#include "program/program.h"

namespace rayspec {

const char* stageName(Stage s) {
  switch (s) {
    case Stage::Raygen:
      return "raygen";
    case Stage::Miss:
      return "miss";
    case Stage::ClosestHit:
      return "closest_hit";
    case Stage::AnyHit:
      return "any_hit";
    case Stage::Intersection:
      return "intersection";
    case Stage::Callable:
      return "callable";
  }
  return "?";
}

const char* valueTypeName(ValueType t) {
  switch (t) {
    case ValueType::Bool:
      return "Bool";
    case ValueType::Uint:
      return "Uint";
    case ValueType::Float:
      return "Float";
    case ValueType::Vec2:
      return "Vec2";
    case ValueType::Vec3:
      return "Vec3";
    case ValueType::Vec4:
      return "Vec4";
  }
  return "?";
}

int componentCount(ValueType t) {
  switch (t) {
    case ValueType::Vec2:
      return 2;
    case ValueType::Vec3:
      return 3;
    case ValueType::Vec4:
      return 4;
    default:
      return 1;
  }
}

}  // namespace rayspec
