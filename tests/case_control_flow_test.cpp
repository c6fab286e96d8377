// Errors of the control-flow vocabulary: each names the line and the field.
#include <gtest/gtest.h>

#include "case_support.h"

namespace rayspec {
namespace {

// A one-triangle case whose raygen is `raygen` (YAML lines indented by four,
// the first on line 10) and whose pipeline has `functions` (indented by two).
std::string withRaygen(const std::string& raygen, const std::string& functions = "") {
  return "rules: [R-CONTROL-FLOW]\n"
         "scene:\n"
         "  blas:\n"
         "    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
         "  instances: [{blas: t}]\n"
         "rays:\n"
         "  list: [{origin: [0.2, 0.2, 1], direction: [0, 0, -1]}]\n"
         "pipeline:\n"
         "  raygen:\n" +
         raygen + functions +
         "outputs:\n"
         "  per_ray: [value]\n";
}

TEST(CaseControlFlow, LocalsMustBeDeclaredOnceAndTyped) {
  expectError(parse(withRaygen("    - set: {x: 1}\n")), 10, "raygen", "no local");
  expectError(parse(withRaygen("    - let: {x: 1}\n    - let: {x: 2}\n")), 11, "raygen",
              "already declared");
  expectError(parse(withRaygen("    - let: {x: 1}\n    - set: {x: 2.5}\n")), 11, "set.x",
              "expected Uint");
  expectError(parse(withRaygen("    - record: {value: var.y}\n")), 10, "value", "not declared");
  expectError(parse(withRaygen("    - let: {X: 1}\n")), 10, "let.X", "lower-case");
  // A block's locals end with it.
  expectError(parse(withRaygen("    - if: true\n      then: [{let: {x: 1}}]\n"
                               "    - record: {value: var.x}\n")),
              12, "value", "not declared");
}

TEST(CaseControlFlow, ArraysAreBoundedAndReadThroughLoad) {
  expectError(parse(withRaygen("    - array: {name: a, of: uint, size: 129}\n")), 10, "size");
  expectError(parse(withRaygen("    - array: {name: a, of: bool, size: 2}\n")), 10, "of");
  expectError(parse(withRaygen("    - array: {name: a, size: 2}\n    - record: {value: var.a}\n")),
              11, "value", "is an array");
  expectError(parse(withRaygen("    - let: {a: 1}\n"
                               "    - record: {value: {load: [var.a, 0]}}\n")),
              11, "value", "array local");
}

TEST(CaseControlFlow, BreakAndContinueNeedARepeat) {
  expectError(parse(withRaygen("    - break\n")), 10, "raygen", "outside a repeat");
  expectError(parse(withRaygen("    - continue\n")), 10, "raygen", "outside a repeat");
  expectError(parse(withRaygen("    - repeat: 2\n      do:\n        - switch: 1\n"
                               "          cases: {1: [break]}\n")),
              13, "raygen", "switch");
  expectError(parse(withRaygen("    - repeat: 1025\n")), 10, "repeat", "above 1024");
  expectError(parse(withRaygen("    - repeat: 2\n      var: i\n      do: [{set: {i: 0}}]\n")), 12,
              "set.i", "read-only");
}

TEST(CaseControlFlow, FunctionsAreKnownNotRecursiveAndGetTheirArguments) {
  const std::string f =
      "  functions:\n"
      "    f:\n"
      "      params: {a: uint}\n"
      "      do: [{invoke: g, with: {b: var.a}}]\n"
      "    g:\n"
      "      params: {b: uint}\n"
      "      do: [{invoke: f, with: {a: var.b}}]\n";
  expectError(parse(withRaygen("    - invoke: h\n", f)), 10, "invoke", "no function 'h'");
  expectError(parse(withRaygen("    - invoke: f\n", f)), 10, "invoke", "parameter 'a'");
  expectError(parse(withRaygen("    - invoke: f\n      with: {a: 1, z: 2}\n", f)), 10, "invoke",
              "names no parameter");
  // The error is where the cycle closes: g's invoke of f.
  const ParseResult cycle = parse(withRaygen("    - invoke: f\n      with: {a: 1}\n", f));
  expectError(cycle, 18, "functions.g.do[0].invoke", "call themselves");
  EXPECT_EQ(cycle.errors.size(), 1u) << allErrors(cycle);
  // A function sees its parameters, not the caller's locals.
  expectError(parse(withRaygen("    - let: {x: 1}\n    - invoke: k\n",
                               "  functions:\n    k:\n      do: [{record: {value: var.x}}]\n")),
              14, "value", "not declared");
  // Statements a stage may not hold stay refused inside a function.
  expectError(parse(withRaygen("    - invoke: k\n", "  functions:\n    k:\n      do: [ignore]\n")),
              13, "do", "not allowed in raygen");
}

TEST(CaseControlFlow, AGoodProgramParses) {
  const ParseResult r = parse(withRaygen(
      "    - let: {s: 0}\n"
      "    - array: {name: a, of: uint, size: 4}\n"
      "    - repeat: 4\n"
      "      var: i\n"
      "      do:\n"
      "        - store: {array: a, index: var.i, value: var.i}\n"
      "        - switch: var.i\n"
      "          cases: {1: [continue], 2: [{set: {s: 5}}]}\n"
      "          default: [{invoke: f, with: {x: var.i}}]\n"
      "    - record: {value: {add: [var.s, {load: [var.a, 3]}]}}\n",
      "  functions:\n    f:\n      params: {x: uint}\n      do: [{record: {value: var.x}}, "
      "return]\n"));
  EXPECT_TRUE(r.value.has_value()) << allErrors(r);
}

}  // namespace
}  // namespace rayspec
