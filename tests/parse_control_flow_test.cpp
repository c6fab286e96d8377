// Errors of the control-flow vocabulary: each names the line and the field.
#include <gtest/gtest.h>

#include "parse_support.h"

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

// A struct's members are typed by name; each error names its line and field.
TEST(CaseControlFlow, StructMembersAreTypedAndReadByName) {
  expectError(parse(withRaygen("    - struct: {name: s, members: {a: int8, b: int9}}\n")), 10,
              "members.b", "unknown member type 'int9'");
  expectError(parse(withRaygen("    - struct: {name: s, members: {a: bool}}\n")), 10, "members.a",
              "unknown member type");
  const std::string s = "    - struct: {name: s, members: {a: int8, c: vec3}}\n";
  expectError(parse(withRaygen(s + "    - record: {value: {uint: var.s.b}}\n")), 11, "value",
              "struct 's' has no member 'b' (its members: a, c)");
  expectError(parse(withRaygen(s + "    - set: {s.b: 1}\n")), 11, "set.s.b", "no member 'b'");
  expectError(parse(withRaygen(s + "    - record: {value: var.s}\n")), 11, "value",
              "'s' is a struct");
  expectError(parse(withRaygen("    - let: {x: 1}\n    - record: {value: var.x.a}\n")), 11, "value",
              "'x' is not a struct");
  expectError(parse(withRaygen("    - record: {value: var.t.a}\n")), 10, "value", "no struct 't'");
  expectError(parse(withRaygen(s + "    - set: {s.a: 1.5}\n")), 11, "set.s.a", "expected Int8");
  expectError(parse(withRaygen(s + "    - let: {s: 1}\n")), 11, "raygen", "already declared");
  expectError(parse(withRaygen("    - let: {s.a: 1}\n")), 10, "let.s.a", "lower-case");
  expectError(parse(withRaygen("    - struct: {name: s, members: {}}\n")), 10, "raygen",
              "1 to 16 members");
  const ParseResult good =
      parse(withRaygen(s + "    - set: {s.a: {int8: 3}, s.c: [1.0, 2.0, 3.0]}\n"
                           "    - record: {value: {uint: {add: [var.s.a, 1]}}}\n"));
  EXPECT_TRUE(good.value.has_value()) << allErrors(good);
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

TEST(CaseControlFlow, ConstantsAreDeclaredTypedAndSetForShadersThatExist) {
  const std::string constants =
      "  constants: {n: 2, scale: 0.5, on: true}\n"
      "  specialize:\n";
  expectError(parse(withRaygen("    - record: {value: const.m}\n")), 10, "value",
              "not in pipeline.constants");
  expectError(
      parse(withRaygen("    - record: {value: const.n}\n", constants + "    miss7: {n: 3}\n")), 13,
      "specialize.miss7", "no shader 'miss7'");
  expectError(
      parse(withRaygen("    - record: {value: const.n}\n", constants + "    raygen: {k: 3}\n")), 13,
      "specialize.raygen.k", "no constant 'k'");
  expectError(
      parse(withRaygen("    - record: {value: const.n}\n", constants + "    raygen: {n: 2.5}\n")),
      13, "specialize.raygen.n", "is a Uint");
  const ParseResult good =
      parse(withRaygen("    - record: {value: const.n}\n", constants + "    raygen: {n: 9}\n"));
  ASSERT_TRUE(good.value.has_value()) << allErrors(good);
  EXPECT_EQ(good.value->pipeline.constantIn("raygen", 0), 9.0);
  EXPECT_EQ(good.value->pipeline.constantIn("miss0", 0), 2.0);
  EXPECT_EQ(good.value->pipeline.constants[2].type, ValueType::Bool);
}

// A procedural group's attribute words: within pipeline.hit_attribute, read
// only where an intersection shader reports them.
TEST(CaseControlFlow, AttributeWordsStayWithinTheirTypeAndTheBoxes) {
  const std::string head =
      "rules: [R-PAYLOAD]\n"
      "scene:\n"
      "  blas:\n"
      "    b: [{aabbs: [[-1, -1, -1, 1, 1, 1]]}]\n"
      "    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
      "  instances: [{blas: b}, {blas: t, sbt_offset: 1}]\n"
      "rays:\n"
      "  list: [{origin: [0, 0, 5], direction: [0, 0, -1]}]\n"
      "pipeline:\n"
      "  hit_attribute: {words: 2}\n"
      "  hit_groups:\n";
  const std::string tail = "outputs:\n  per_ray: [value]\n";
  expectError(parse(head + "    - intersection: [report: {t: 1.0, kind: 1, word2: 5}]\n" +
                    "    - closest_hit: [record: {value: 1}]\n" + tail),
              12, "word2", "has 2 word(s)");
  expectError(parse(head + "    - intersection: [report: {t: 1.0, kind: 1}]\n" +
                    "    - closest_hit: [record: {value: attribute.word0}]\n" + tail),
              13, "value", "triangles");
  const ParseResult good =
      parse(head + "    - intersection: [report: {t: 1.0, kind: 1, word1: 5}]\n" +
            "      closest_hit: [record: {value: attribute.word1}]\n" +
            "    - closest_hit: [record: {value: 1}]\n" + tail);
  EXPECT_TRUE(good.value.has_value()) << allErrors(good);
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
