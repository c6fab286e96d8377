// What rayspec generates is rayspec's to get right: random stage programs
// over the vocabulary (each stage reads every built-in it may, and uses
// every operator with every argument list of one or two types that parses,
// in a random order) compile with glslang and pass SPIRV-Tools' validator. A built-in read in
// one order and not another (glslang 12's 3x4 matrices) shows up here, not as
// a device's crash.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <random>
#include <set>

#include "glsl/generate_glsl.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "program/builtins.h"
#include "program/ops.h"
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
  payloads: [{words: 3}]
  callable_data: [{words: 2}]
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

// One expression of each value type, readable in every stage.
const std::pair<ValueType, const char*> kTypedArgs[] = {
    {ValueType::Uint, "{add: [launch_id_x, 3]}"},
    {ValueType::Float, "{float: launch_id_y}"},
    {ValueType::Vec2, "{vec2: [{float: launch_id_x}, 0.5]}"},
    {ValueType::Vec3, "{vec3: [1.0, {float: launch_id_x}, 2.0]}"},
    {ValueType::Vec4, "{vec4: [1.0, 2.0, {float: launch_size_x}, 4.0]}"},
    {ValueType::Bool, "{lt: [launch_id_x, 2]}"},
};

// Every operator of the vocabulary a stage may use, with each argument list
// of one or two types (more arguments: one type repeated) that parses; each
// as an expression text. Ops that need a case feature the skeleton lacks
// (shader record data, an array local) parse in none and are named.
std::vector<std::string> operatorForms(Stage stage, std::vector<std::string>* skipped) {
  std::vector<std::string> out;
  for (const OpInfo& op : ops()) {
    if (!(op.stages & stageBit(stage))) continue;
    std::vector<std::vector<const char*>> lists;
    if (op.min_args == 0) lists.push_back({});
    for (const auto& a : kTypedArgs)
      for (int n = std::max(op.min_args, 1); n <= std::min(op.max_args, 4); ++n) {
        if (n == 2) {
          for (const auto& b : kTypedArgs) lists.push_back({a.second, b.second});
          continue;
        }
        lists.push_back(std::vector<const char*>(static_cast<size_t>(n), a.second));
      }
    size_t found = 0;
    for (const auto& args : lists) {
      std::string text = "{" + std::string(op.name) + ": [";
      for (size_t i = 0; i < args.size(); ++i) text += (i ? ", " : "") + std::string(args[i]);
      text += "]}";
      if (args.empty()) text = op.name;
      const std::string probe = "{let: {v0: " + text + "}}";
      if (parseCaseText(caseText({{stage, probe}}), "gen/op.yaml", "gen/op").value) {
        out.push_back(text);
        ++found;
      }
    }
    if (!found) skipped->push_back(op.name);
  }
  return out;
}

// With RAYSPEC_GENERATED_SPIRV set to a folder, every module compiled is also
// written there (N.spv), for another validator to check
// (tools/second-driver.sh generated: Debian sid's spirv-val).
void keepModule(const std::vector<uint32_t>& words) {
  static size_t n = 0;
  const char* dir = std::getenv("RAYSPEC_GENERATED_SPIRV");
  if (!dir || !*dir || words.empty()) return;
  const std::string path =
      std::string(dir) + "/" + std::to_string(getpid()) + "-" + std::to_string(n++) + ".spv";
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(words.data()),
            static_cast<std::streamsize>(words.size() * sizeof(uint32_t)));
  EXPECT_TRUE(out.good()) << "cannot write " << path;
}

// Each stage's statements in a random order (`statement` makes the i-th of
// list), `rounds` times; every distinct module compiled and validated. The
// number of modules; a failure names the round, stage and message.
template <typename T>
size_t compileShuffled(std::map<Stage, std::vector<T>>& lists, int rounds, uint32_t seed,
                       const std::function<std::string(const T&, size_t)>& statement) {
  std::mt19937 rng(seed);
  std::set<std::string> seen;
  size_t modules = 0;
  for (int round = 0; round < rounds; ++round) {
    std::map<Stage, std::string> programs;
    for (auto& [stage, list] : lists) {
      std::shuffle(list.begin(), list.end(), rng);
      std::string text;
      for (size_t i = 0; i < list.size(); ++i) text += (i ? ", " : "") + statement(list[i], i);
      programs[stage] = text.empty() ? "{count: c}" : text;
    }
    const std::string yaml = caseText(programs);
    const ParseResult p = parseCaseText(yaml, "gen/random.yaml", "gen/random");
    if (!p.value) {
      ADD_FAILURE() << p.errors.front().format() << "\n" << yaml;
      return modules;
    }
    const GeneratedPipeline g = generateGlsl(*p.value, derivePlan(*p.value));
    for (const GeneratedShader* sh : everyStage(g)) {
      if (!seen.insert(sh->glsl).second) continue;
      ++modules;
      const SpirvResult r = compileGlsl(sh->glsl, sh->stage, sh->compute);
      EXPECT_EQ(r.error, "") << "round " << round << ", " << sh->name;
      keepModule(r.words);
    }
  }
  return modules;
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
  const size_t modules = compileShuffled<const BuiltinInfo*>(
      reads, 24, 20261127,
      [](const BuiltinInfo* const& b, size_t i) { return readStatement(*b, i); });
  EXPECT_GT(modules, 100u);
}

TEST(GeneratedStages, EveryOperatorFormInRandomOrderIsValidSpirv) {
  std::map<Stage, std::vector<std::string>> forms;
  std::vector<std::string> skipped;
  size_t total = 0;
  for (const StageSlot& s : kSlots) {
    forms[s.stage] = operatorForms(s.stage, &skipped);
    total += forms[s.stage].size();
  }
  EXPECT_GT(total, 300u) << "skipped: " << ::testing::PrintToString(skipped);
  const size_t modules =
      compileShuffled<std::string>(forms, 6, 1127, [](const std::string& form, size_t i) {
        return "{let: {o" + std::to_string(i) + ": " + form + "}}";
      });
  EXPECT_GT(modules, 30u);
}

}  // namespace
}  // namespace rayspec
