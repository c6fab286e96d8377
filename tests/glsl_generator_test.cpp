// What rayspec generates is rayspec's to get right: random stage programs
// over the vocabulary (each stage reads every built-in it may, and uses
// every operator with every argument list of one or two types that parses,
// in a random order; the forms are fuzz/stage_vocabulary.h's) compile with glslang and pass
// SPIRV-Tools' validator. A built-in read in one order and not another (glslang 12's 3x4 matrices)
// shows up here, not as a device's crash.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <random>
#include <set>

#include "fuzz/stage_vocabulary.h"
#include "glsl/generate_glsl.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "program/builtins.h"
#include "program/ops.h"
#include "spirv/compile_glsl.h"

namespace rayspec {
namespace {

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
    const std::string yaml = skeletonCase(programs);
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
  for (const StageSlot& s : skeletonSlots()) {
    reads[s.stage] = readableBuiltins(s.stage, &skipped);
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
  for (const StageSlot& s : skeletonSlots()) {
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
