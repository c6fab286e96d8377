// The expressions of the generated programs: Uint expressions over the
// built-ins and operators the vocabulary finds (fuzz/stage_vocabulary.h),
// float expressions exact in float32 whatever the algorithm, and colours of
// float built-ins (compared within the colour tolerance).
#include <map>
#include <mutex>

#include "fuzz/program_generator.h"
#include "fuzz/stage_vocabulary.h"

namespace rayspec {
namespace {

// The Uint built-ins `stage` reads in the skeleton, but those that need a
// device feature lavapipe lacks or a scene part the generator does not make
// (the cull mask built-in, vertex positions, box data, hit objects), computed
// once.
const std::vector<std::string>& uintBuiltins(Stage stage) {
  static std::mutex mutex;
  static std::map<Stage, std::vector<std::string>> found;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = found.find(stage);
  if (it != found.end()) return it->second;
  using namespace builtin_needs;
  std::vector<std::string> names, skipped;
  for (const BuiltinInfo* b : readableBuiltins(stage, &skipped)) {
    if (b->type != ValueType::Uint || (b->needs & (CullMask | PositionFetch | BoxData | HitObject)))
      continue;
    names.push_back(builtinSpelling(builtinId(b), 0));  // payload.word<i>: word 0
  }
  return found.emplace(stage, std::move(names)).first->second;
}

// The float built-ins of a stage as given or computed by the device once
// (no arithmetic of ours on them): Vec3 ones for a colour's xyz, Float ones
// for its w. Barycentrics are left out (a box's attribute is a known
// lavapipe class of its own).
struct FloatBuiltins {
  std::vector<std::string> vec3s, floats;
};
const FloatBuiltins& floatBuiltins(Stage stage) {
  static const FloatBuiltins kNone{};
  static const FloatBuiltins kMiss{{"world_ray_origin", "world_ray_direction"},
                                   {"ray_tmin", "ray_tmax"}};
  static const FloatBuiltins kHit{
      {"world_ray_origin", "world_ray_direction", "object_ray_origin", "object_ray_direction",
       "object_to_world0", "object_to_world1", "object_to_world2", "object_to_world3",
       "world_to_object0", "world_to_object1", "world_to_object2", "world_to_object3",
       "hit_position"},
      {"hit_t", "ray_tmin", "ray_tmax"}};
  static const FloatBuiltins kCallable{{"call.position", "call.normal"}, {}};
  switch (stage) {
    case Stage::Miss:
      return kMiss;
    case Stage::ClosestHit:
      return kHit;
    case Stage::Callable:
      return kCallable;
    default:
      return kNone;
  }
}

}  // namespace

std::string CaseGenerator::uintAtom(Stage stage) {
  const std::vector<std::string>& names = uintBuiltins(stage);
  // Constants from 1: no division by a constant zero.
  if (names.empty() || chance(0.3)) return std::to_string(1 + pick(15));
  return oneOf(names);
}

std::string CaseGenerator::uintExpr(Stage stage, int depth) {
  const std::vector<UintOperator>& operators = uintOperators(stage);
  if (depth <= 0 || operators.empty() || chance(0.35)) return uintAtom(stage);
  const UintOperator& op = oneOf(operators);
  const int arity = oneOf(op.arities);
  // A divisor with its low bit set is never zero: no division by zero
  // (undefined: the model would refuse the case).
  const bool divides = op.name == "div" || op.name == "mod";
  std::string text = "{" + op.name + ": [";
  for (int i = 0; i < arity; ++i) {
    const std::string arg = uintExpr(stage, depth - 1);
    text += (i ? ", " : "") + (divides && i == 1 ? "{bit_or: [" + arg + ", 1]}" : arg);
  }
  return text + "]}";
}

std::string CaseGenerator::condition(Stage stage) {
  if (chance(0.5)) return "{odd: " + uintExpr(stage, 1) + "}";
  return "{lt: [" + uintExpr(stage, 1) + ", " + std::to_string(pick(8)) + "]}";
}

// A multiple of 1/8 below 16 in magnitude, or a Uint below 16 as a Float:
// at most 4 integer and 3 fraction bits.
std::string ProgramGenerator::floatAtom(Stage stage) {
  if (g_.chance(0.5)) return CaseGenerator::num(g_.eighths(-4, 4));
  return "{float: {bit_and: [" + g_.uintExpr(stage, 1) + ", 15]}}";
}

// Sums, differences, products, minima and maxima of atoms, at most two
// deep: at most 10 integer and 6 fraction bits, so every step is exact in
// float32 (no rounding a device could do otherwise).
std::string ProgramGenerator::floatExpr(Stage stage, int depth) {
  static const std::vector<std::string> kOps = {"add", "sub", "mul", "min", "max"};
  if (depth <= 0 || g_.chance(0.3)) return floatAtom(stage);
  if (g_.chance(0.1)) return "{round: " + floatExpr(stage, depth - 1) + "}";
  return "{" + g_.oneOf(kOps) + ": [" + floatExpr(stage, depth - 1) + ", " +
         floatExpr(stage, depth - 1) + "]}";
}

std::string ProgramGenerator::exactColor(Stage stage) {
  feature("float-color");
  std::string c = "{vec4: [";
  for (int i = 0; i < 4; ++i)
    c += (i ? ", " : "") + (i < 3 && g_.chance(0.15) ? vectorComponent(stage, i)
                                                     : floatExpr(stage, 1 + int(g_.pick(2))));
  return c + "]}";
}

// Component `i` of a cross product or a 3x3 matrix (or its transpose) times
// a vector, of vectors of atoms: every product and sum exact in float32
// (faults cross-operands-swapped, matrix-transposed).
std::string ProgramGenerator::vectorComponent(Stage stage, int i) {
  feature("vector-math");
  const auto vec3 = [&] {
    return "{vec3: [" + floatAtom(stage) + ", " + floatAtom(stage) + ", " + floatAtom(stage) + "]}";
  };
  static const char* const kAxes[] = {"x", "y", "z"};
  std::string v;
  if (g_.chance(0.5)) {
    v = "{cross: [" + vec3() + ", " + vec3() + "]}";
  } else {
    v = std::string(g_.chance(0.5) ? "{mat3_mul: [" : "{mat3_tmul: [");
    for (int k = 0; k < 4; ++k) v += (k ? ", " : "") + vec3();
    v += "]}";
  }
  return "{" + std::string(kAxes[i]) + ": " + v + "}";
}

// The components of a float built-in as given (no arithmetic): compared
// within the colour tolerance.
std::string ProgramGenerator::builtinColor(Stage stage) {
  const FloatBuiltins& b = floatBuiltins(stage);
  if (b.vec3s.empty()) return exactColor(stage);
  feature("float-builtin");
  const std::string v = g_.oneOf(b.vec3s);
  const std::string w = b.floats.empty() ? floatExpr(stage, 1) : g_.oneOf(b.floats);
  return "{vec4: [{x: " + v + "}, {y: " + v + "}, {z: " + v + "}, " + w + "]}";
}

// An any-hit's condition: on the primitive, the instance, the hit kind (a
// triangle's face, a box's report), the payload counter (the candidates
// before, order-dependent: the exact tier tries the orders), or any Uint.
std::string ProgramGenerator::hitCondition(bool aabbs) {
  switch (g_.pick(5)) {
    case 0:
      return "{odd: {add: [primitive_id, " + std::to_string(g_.pick(3)) + "]}}";
    case 1:
      return "{eq: [instance_id, " + std::to_string(g_.pick(3)) + "]}";
    case 2:
      return aabbs ? "{lt: [hit_kind, " + std::to_string(g_.pick(128)) + "]}"
                   : "{eq: [hit_kind, " + std::string(g_.chance(0.5) ? "254" : "255") + "]}";
    case 3:
      if (accumulates_) {
        feature("any-hit-on-payload");
        return "{gt: [payload.word0, " + std::to_string(g_.pick(3)) + "]}";
      }
      [[fallthrough]];
    default:
      return g_.condition(Stage::AnyHit);
  }
}

std::string ProgramGenerator::local() {
  return "l" + std::to_string(locals_++);
}

// value4 .. value10 in turn (value11 is fold's), so that the records of
// one case rarely overwrite each other.
std::string ProgramGenerator::freeField() {
  const std::string f = "value" + std::to_string(4 + fields_++ % 7);
  g_.fields_.insert(f);
  return f;
}

std::string ProgramGenerator::colorField() {
  const std::string f = g_.chance(0.5) ? "color2" : "color3";
  g_.fields_.insert(f);
  return f;
}

}  // namespace rayspec
