// The parts of the generated programs: nested traces, calls, ray queries,
// control flow and locals live across calls, any-hit decisions. Each is a
// statement list without its brackets.
#include "fuzz/program_generator.h"

namespace rayspec {
namespace {}  // namespace

// A trace from closest-hit or miss, only below max_recursion (the depth
// built-in decides, so no ray goes deeper: R-UB), from the ray's origin or
// a point around the scene, with a payload it starts; built-ins read before
// it (into a local) and after it, the nested payload folded into this one.
std::string ProgramGenerator::nestedTrace(Stage stage) {
  feature(stage == Stage::Miss ? "nested-trace-from-miss" : "nested-trace");
  ++nested_sites_;
  std::string origin = "world_ray_origin";
  std::string direction = "[" + CaseGenerator::num(g_.eighths(-0.5, 0.5)) + ", " +
                          CaseGenerator::num(g_.eighths(-0.5, 0.5)) +
                          (g_.chance(0.7) ? ", -1.0]" : ", 1.0]");
  if (g_.chance(0.5)) {
    const double ox = g_.eighths(-4, 4), oy = g_.eighths(-4, 4), oz = g_.chance(0.5) ? 6.0 : -6.0;
    const double tx = g_.eighths(-1.5, 1.5), ty = g_.eighths(-1.5, 1.5);
    origin = "[" + CaseGenerator::num(ox) + ", " + CaseGenerator::num(oy) + ", " +
             CaseGenerator::num(oz) + "]";
    direction = "[" + CaseGenerator::num(tx - ox) + ", " + CaseGenerator::num(ty - oy) + ", " +
                CaseGenerator::num(-oz) + "]";
  }
  const std::string before = local();
  std::string s = "{let: {" + before + ": " + g_.uintExpr(stage, 1) + "}}";
  std::string then = "{trace: {origin: " + origin + ", direction: " + direction +
                     ", payload: {value: " + g_.uintExpr(stage, 1) + "}}}";
  then += ", " + std::string(kAfterNestedTrace) + before + "]}}}";
  then += ", {record: {" + freeField() + ": {bit_xor: [var." + before + ", " +
          g_.uintExpr(stage, 1) + "]}}}";
  if (g_.chance(0.3)) then += ", {record: {" + colorField() + ": child.color}}";
  return s + ", {if: {lt: [depth, " + std::to_string(max_recursion_) + "]}, then: [" + then + "]}";
}

// executeCallableEXT of a callable from `first_callee` on (a callable calls
// only those after it: no recursion, at most two frames deep), with
// callable data, the result recorded.
std::string ProgramGenerator::call(Stage stage, size_t first_callee) {
  const size_t count = g_.callable_count_;
  if (first_callee >= count) return "";
  if (stage == Stage::ClosestHit) feature("call-in-hit");
  if (stage == Stage::Miss) feature("call-in-miss");
  if (stage == Stage::Callable) feature("call-in-callable");
  std::string index = std::to_string(first_callee + g_.pick(count - first_callee));
  if (first_callee == 0 && count > 1 && g_.chance(0.3))
    index = "{mod: [" + g_.uintExpr(stage, 1) + ", " + std::to_string(count) + "]}";
  std::string s = "{call: {index: " + index + ", value: " + g_.uintExpr(stage, 1);
  // The data's words beyond the plain 48 bytes, in and out (R-CALLABLE:
  // fault call-data-words-lost).
  const bool words = g_.chance(0.4);
  if (words) s += ", word0: " + g_.uintExpr(stage, 1);
  if (g_.chance(0.4))
    s += ", position: {vec3: [" + floatExpr(stage, 1) + ", " + floatExpr(stage, 1) + ", " +
         floatExpr(stage, 1) + "]}";
  s += "}}, {record: {" + freeField() + ": callee.value}}";
  if (words) {
    feature("call-words");
    s += ", {record: {" + freeField() + ": callee.word1}}";
  }
  if (g_.chance(0.3)) s += ", {record: {" + colorField() + ": callee.color}}";
  return s;
}

// A ray query: each triangle candidate confirmed (all, some, or the first
// and then the traversal ended), boxes committed where the ray crosses them
// (queryCrossing), the committed intersection read after.
std::string ProgramGenerator::rayQuery(Stage stage) {
  feature("ray-query");
  std::string q = "{ray_query: {";
  if (stage != Stage::Raygen)
    q += "origin: world_ray_origin, direction: [" + CaseGenerator::num(g_.eighths(-0.5, 0.5)) +
         ", " + CaseGenerator::num(g_.eighths(-0.5, 0.5)) + ", -1.0], ";
  // The query's tmax, which its aabb block holds a generate's t to (in
  // raygen the launch ray's origin, direction and tmin stay).
  const double tmax = g_.chance(0.6) ? 100.0 : g_.eighths(5, 9);
  q += "tmax: " + CaseGenerator::num(tmax) + ", ";
  switch (g_.pick(4)) {
    case 0:
      q += "triangle: [confirm]";
      break;
    case 1:
      q += "triangle: [{if: {odd: {add: [candidate.primitive_id, " + std::to_string(g_.pick(2)) +
           "]}}, then: [confirm]}]";
      break;
    case 2:
      feature("ray-query-terminate");
      q += "triangle: [{if: {eq: [candidate.instance_id, " + std::to_string(g_.pick(3)) +
           "]}, then: [confirm, terminate_query]}]";
      break;
    default:
      q += "triangle: [{if: {lt: [candidate.geometry_index, 2]}, then: [confirm]}]";
  }
  if (g_.chance(0.6)) {
    feature("ray-query-generate");
    q += ", aabb: [" + queryCrossing(tmax) + "]";
  }
  return q + ", after: [" + queryAfter() + "]}}";
}

// An AABB candidate committed only where the ray crosses the sphere inscribed
// in its box (sphere_hit, the query's candidate's: program/ops.h), at the
// sphere's near root, ahead of tmin and not beyond what is committed (the
// query's tmax before a commit): inside [tmin, committed t], never
// undefined (R-RQ-COMMIT), and the same whichever order the candidates come
// in. A box the test only bounds (R-AABB-CONS: a device may offer one the
// ray passes beside or behind) commits nothing. Now and then only the boxes
// of some primitives.
std::string ProgramGenerator::queryCrossing(double tmax) {
  const std::string top = local();
  std::string cross =
      "sphere_hit, {ge: [sphere_near, query.ray_tmin]}, {le: [sphere_near, var." + top + "]}";
  if (g_.chance(0.5)) cross += ", {even: {add: [candidate.primitive_id, candidate.instance_id]}}";
  return "{let: {" + top + ": " + CaseGenerator::num(tmax) +
         "}}, {if: {ne: [committed.type, 0]}, then: [{set: {" + top +
         ": committed.t}}]}, {if: {and: [" + cross + "]}, then: [{generate: sphere_near}]}";
}

std::string ProgramGenerator::queryAfter() {
  std::string a = "{record: {" + freeField() + ": committed.type}}";
  std::string then = "{record: {" + freeField() +
                     ": {add: [{mul: [committed.instance_id, 64]}, {add: [{mul: "
                     "[committed.geometry_index, 16]}, committed.primitive_id]}]}}}";
  if (g_.chance(0.5))
    then += ", {record: {" + colorField() +
            ": {vec4: [committed.t, query.ray_tmin, {float: committed.instance_custom_index}, "
            "1.0]}}}";
  return a + ", {if: {ne: [committed.type, 0]}, then: [" + then + "]}";
}

// A local folded by an if/else, a bounded loop, a switch or a function, then
// recorded.
std::string ProgramGenerator::controlFlow(Stage stage) {
  const std::string v = local(), var = "var." + v;
  const auto set = [&](const std::string& value) {
    return "{set: {" + v + ": " + value + "}}";
  };
  std::string start = g_.uintExpr(stage, 1);
  // The bits of a Float the case gives (floatBitsToUint: fault
  // float-bits-converted); only a literal is the same bits on every device.
  if (g_.chance(0.2)) {
    feature("float-bits");
    start =
        "{bit_xor: [" + start + ", {float_bits: " + CaseGenerator::num(g_.eighths(-4, 4)) + "}]}";
  }
  std::string s = "{let: {" + v + ": " + start + "}}, ";
  switch (g_.pick(4)) {
    case 0:
      feature("if-else");
      s += "{if: " + g_.condition(stage) + ", then: [" +
           set("{add: [" + var + ", " + g_.uintExpr(stage, 1) + "]}") + "], else: [" +
           set("{bit_xor: [" + var + ", " + g_.uintExpr(stage, 1) + "]}") + "]}";
      break;
    case 1: {
      feature("repeat");
      const std::string k = local();
      s += "{repeat: " + std::to_string(1 + g_.pick(4)) + ", var: " + k + ", do: [" +
           set("{add: [{mul: [" + var + ", 3]}, var." + k + "]}") + ", {if: {eq: [var." + k + ", " +
           std::to_string(1 + g_.pick(3)) + "]}, then: [break]}]}";
      break;
    }
    case 2:
      feature("switch");
      s += "{switch: {mod: [" + g_.uintExpr(stage, 1) + ", 4]}, cases: {0: [" +
           set("{add: [" + var + ", 5]}") + "], 2: [" + set("{mul: [" + var + ", 7]}") +
           "]}, default: [" + set("{shr: [" + var + ", 1]}") + "]}";
      break;
    default:
      feature("function");
      uses_fold_ = true;
      s += "{invoke: fold, with: {a: " + var + ", b: " + g_.uintExpr(stage, 1) + "}}";
  }
  return s + ", {record: {" + freeField() + ": " + var + "}}";
}

// A value read before `across` (traces, calls) and recorded after it, now
// and then with typed state beside it: every local a stage holds is the same
// after them (R-LIVE-STATE).
std::string ProgramGenerator::liveLocal(Stage stage, const std::string& across) {
  if (across.empty()) return "";
  feature("local-across-call");
  const std::string v = local();
  std::string s = "{let: {" + v + ": " + g_.uintExpr(stage, 2) + "}}, ";
  const TypedState typed = typedState(stage);
  if (!typed.before.empty()) s += typed.before + ", ";
  s += across + ", {record: {" + freeField() + ": {add: [var." + v + ", 1]}}}";
  if (!typed.fold.empty()) s += ", {record: {" + freeField() + ": " + typed.fold + "}}";
  return s;
}

// Whether an any-hit ignores or terminates: on a condition, a switch, or in
// a function.
std::string ProgramGenerator::anyHitDecision(bool aabbs) {
  const bool terminate = g_.chance(0.35);
  std::string end = terminate ? "terminate" : "ignore";
  // Now and then a statement after it, which must never run (R-IGNORE,
  // R-TERMINATE: faults code-after-ignore-runs, code-after-terminate-runs).
  if (g_.chance(0.3)) {
    feature("code-after-end");
    end += ", {payload: {value: " + g_.uintExpr(Stage::AnyHit, 1) + "}}";
  }
  const uint64_t shape = g_.pick(5);
  feature(terminate && shape != 1 ? "any-hit-terminate" : "any-hit-ignore");
  switch (shape) {
    case 0:
      feature("switch");
      return "{switch: {mod: [primitive_id, 3]}, cases: {" + std::to_string(g_.pick(3)) + ": [" +
             end + "]}}";
    case 1:
      feature("any-hit-function");
      uses_decide_ = true;
      return "{invoke: decide, with: {p: primitive_id, q: " + g_.uintExpr(Stage::AnyHit, 1) + "}}";
    case 2:
      feature("if-else");
      return "{if: " + hitCondition(aabbs) + ", then: [" + end +
             "], else: [{if: " + hitCondition(aabbs) + ", then: [" +
             (terminate ? "ignore" : "terminate") + "]}]}";
    default:
      return "{if: " + hitCondition(aabbs) + ", then: [" + end + "]}";
  }
}

}  // namespace rayspec
