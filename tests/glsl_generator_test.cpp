// What rayspec generates is rayspec's to get right: random stage programs
// over the vocabulary's built-ins (each stage reads every built-in it may, in
// a random order, and through every operator a value of its type allows)
// compile with glslang and pass SPIRV-Tools' validator. A built-in read in
// one order and not another (glslang 12's 3x4 matrices) shows up here, not as
// a device's crash.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "case/parse_case.h"
#include "glsl/generate_glsl.h"
#include "plan/plan.h"
#include "program/builtins.h"
#include "spirv/compile_glsl.h"

namespace rayspec {
namespace {

// A triangle (hit group 0: any-hit, closest-hit) and a box (hit group 1:
// intersection, any-hit, closest-hit); raygen traces and calls callable 0.
// The programs stand where the keys are.
const char* kSkeleton = R"(rules: [R-BUILTIN]
description: generated
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
        flags: []
    ball:
      - aabbs: [[-1, -1, -1, 1, 1, 1]]
        flags: []
  instances:
    - {blas: tri}
    - {blas: ball, transform: {translate: [10, 0, 0]}, sbt_offset: 1}
rays:
  list:
    - {origin: [0, 0, 3], direction: [0, 0, -1]}
pipeline:
  raygen: [RAYGEN, {trace: {}}, {call: {index: 0}}]
  miss:
    - [MISS]
  hit_groups:
    - any_hit: [ANY_HIT]
      closest_hit: [CLOSEST_HIT]
    - intersection: [INTERSECTION, {report: {t: 1.5, kind: 1}}]
      any_hit: [ANY_HIT]
      closest_hit: [CLOSEST_HIT]
  callables:
    - [CALLABLE]
outputs:
  counters: [c]
)";

struct StageSlot {
  Stage stage;
  const char* key;
};
const StageSlot kSlots[] = {{Stage::Raygen, "RAYGEN"},
                            {Stage::Miss, "MISS"},
                            {Stage::AnyHit, "ANY_HIT"},
                            {Stage::ClosestHit, "CLOSEST_HIT"},
                            {Stage::Intersection, "INTERSECTION"},
                            {Stage::Callable, "CALLABLE"}};

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// The case with each stage's program (flow YAML statements) in place.
std::string caseText(const std::map<Stage, std::string>& programs) {
  std::string text = kSkeleton;
  for (const StageSlot& s : kSlots) {
    const auto it = programs.find(s.stage);
    text = replaceAll(text, s.key, it == programs.end() ? "{count: c}" : it->second);
  }
  return text;
}

// A statement that reads built-in b into a local and folds it into a value
// other statements see (so no compiler may drop the read).
std::string readStatement(const BuiltinInfo& b, size_t i) {
  const std::string v = "v" + std::to_string(i);
  const std::string name = replaceAll(b.name, "<i>", "0");  // payload.word<i>: word 0
  std::string folded;
  switch (b.type) {
    case ValueType::Uint:
      folded = "{add: [var." + v + ", 1]}";
      break;
    case ValueType::Float:
      folded = "{add: [var." + v + ", 1.0]}";
      break;
    case ValueType::Vec2:
      folded = "{x: var." + v + "}";
      break;
    default:  // vec3, vec4
      folded = "{y: var." + v + "}";
      break;
  }
  return "{let: {" + v + ": " + name + "}}, {let: {w" + std::to_string(i) + ": " + folded + "}}";
}

// The built-ins a stage may read that parse in the skeleton alone (those that
// need a case feature the skeleton lacks, such as payload words, are named).
std::vector<const BuiltinInfo*> readable(Stage stage, std::vector<std::string>* skipped) {
  std::vector<const BuiltinInfo*> out;
  for (const BuiltinInfo& b : builtins()) {
    if (!(b.stages & stageBit(stage))) continue;
    const ParseResult p =
        parseCaseText(caseText({{stage, readStatement(b, 0)}}), "gen/probe.yaml", "gen/probe");
    if (p.value)
      out.push_back(&b);
    else
      skipped->push_back(std::string(b.name));
  }
  return out;
}

std::vector<const GeneratedShader*> stagesOf(const GeneratedPipeline& g) {
  std::vector<const GeneratedShader*> out{&g.raygen};
  for (const GeneratedShader& s : g.miss) out.push_back(&s);
  for (const GeneratedGroup& h : g.hit_groups)
    for (const auto* s : {&h.closest_hit, &h.any_hit, &h.intersection})
      if (*s) out.push_back(&**s);
  for (const GeneratedShader& s : g.callables) out.push_back(&s);
  return out;
}

TEST(GeneratedStages, EveryBuiltinInRandomOrderIsValidSpirv) {
  std::map<Stage, std::vector<const BuiltinInfo*>> reads;
  std::vector<std::string> skipped;
  size_t total = 0;
  for (const StageSlot& s : kSlots) {
    reads[s.stage] = readable(s.stage, &skipped);
    total += reads[s.stage].size();
  }
  // Vocabulary built-ins outside the skeleton: payload, call data and
  // attribute words, vertex positions and the like.
  EXPECT_GT(total, 120u) << "skipped: " << ::testing::PrintToString(skipped);
  std::mt19937 rng(20261127);
  std::set<std::string> seen;
  size_t modules = 0, invalid = 0;
  for (int round = 0; round < 24; ++round) {
    std::map<Stage, std::string> programs;
    for (auto& [stage, list] : reads) {
      std::shuffle(list.begin(), list.end(), rng);
      std::string text;
      for (size_t i = 0; i < list.size(); ++i) text += (i ? ", " : "") + readStatement(*list[i], i);
      programs[stage] = text.empty() ? "{count: c}" : text;
    }
    const std::string yaml = caseText(programs);
    const ParseResult p = parseCaseText(yaml, "gen/random.yaml", "gen/random");
    ASSERT_TRUE(p.value) << p.errors.front().format() << "\n" << yaml;
    const GeneratedPipeline g = generateGlsl(*p.value, derivePlan(*p.value));
    for (const GeneratedShader* sh : stagesOf(g)) {
      if (!seen.insert(sh->glsl).second) continue;
      ++modules;
      const SpirvResult r = compileGlsl(sh->glsl, sh->stage);
      if (r.error.empty()) continue;
      ++invalid;
      ADD_FAILURE() << "round " << round << ", " << sh->name << ":\n" << r.error;
    }
  }
  EXPECT_EQ(invalid, 0u);
  EXPECT_GT(modules, 100u);
}

}  // namespace
}  // namespace rayspec
