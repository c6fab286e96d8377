// Hostile inputs, round two (issue 44): links inside output folders and
// shards, an output that is an input, YAML anchors that refer to themselves
// or expand without bound, poisoned SPIR-V cache entries, option pairs that
// cannot both hold. Each ends in a clear error or a judged run, and nothing
// outside the run's folders is touched.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <utility>
#include <vector>

#include "cli_helpers.h"

namespace {
namespace fs = std::filesystem;
using cli::caseArg;
using cli::fresh;
using cli::sh;
using cli::slurp;
using cli::victim;

const std::string kCase = "results/miss-xor-closest-hit";

size_t filesUnder(const std::string& dir) {
  size_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) n += e.is_regular_file();
  return n;
}

// A case file whose raygen is an alias of its own anchor (it would nest
// without end).
const char* kSelfAlias = R"(rules: [R-MISS-XOR-CHIT]
scene:
  blas:
    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]
  instances: [{blas: t}]
rays:
  list: [{origin: [0.2, 0.2, 1], direction: [0, 0, -1]}]
pipeline:
  raygen: &p [{if: true, then: *p}]
outputs:
  per_ray: [value]
)";

// A case file of 40 aliases, each doubling the one before: 2^40 nodes.
std::string aliasBomb() {
  std::string text =
      "rules: [R-MISS-XOR-CHIT]\nscene:\n  blas:\n"
      "    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
      "  instances: [{blas: t}]\nrays:\n  list: [{origin: [0.2, 0.2, 1], direction: [0, 0, "
      "-1]}]\nx:\n  a0: &a0 {add: [1, 2]}\n";
  for (int i = 1; i <= 40; ++i)
    text += "  a" + std::to_string(i) + ": &a" + std::to_string(i) + " {add: [*a" +
            std::to_string(i - 1) + ", *a" + std::to_string(i - 1) + "]}\n";
  return text + "pipeline:\n  raygen: [{record: {value: *a40}}]\noutputs:\n  per_ray: [value]\n";
}

// Issue 44's "done means": an --out holding a link to a folder outside it, a
// SPIR-V cache whose entries are all poisoned, and a self-referring case and
// an alias bomb among good cases. With links where the run writes, the run
// refuses (exit 2) naming one, and removes none (issue 56: only what rayspec
// wrote is touched); once the user has moved them, the run finishes: the
// good cases are judged, the bad ones are CaseErrors naming what is wrong,
// and the folder the links pointed to keeps its file.
TEST(Hostile, ARunAmongLinksPoisonAndBombsJudgesTheGoodCases) {
  const std::string root = fresh("hostile-run");
  const std::string kept = victim(root, "outside");
  const std::string out = root + "/out";
  fs::create_directories(out + "/results");
  fs::create_symlink(kept, out + "/results/miss-xor-closest-hit");
  fs::create_symlink(kept + "/keep.txt", out + "/summary.txt");
  const std::string cases = root + "/cases";
  fs::create_directories(cases);
  std::ofstream(cases + "/self.yaml") << kSelfAlias;
  std::ofstream(cases + "/bomb.yaml") << aliasBomb();
  // First fill a cache, then poison every entry: junk after the magic number.
  const std::string cache = root + "/cache";
  ASSERT_EQ(sh(cli::kBin + " run --no-validation" + caseArg(kCase) + " --cache-dir " + cache +
                   " --out " + root + "/warm",
               root + "/warm.txt"),
            0)
      << slurp(root + "/warm.txt");
  size_t poisoned = 0;
  for (const auto& e : fs::directory_iterator(cache + "/spirv"))
    if (e.path().extension() == ".spv") {
      std::fstream f(e.path(), std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(8);
      f.write("junkjunk", 8);
      ++poisoned;
    }
  ASSERT_GT(poisoned, 0u);
  const std::string run = cli::kBin + " run --no-validation" + caseArg(kCase) + " --case " + cases +
                          "/self.yaml --case " + cases + "/bomb.yaml --cache-dir " + cache +
                          " --out " + out;
  const int rc = sh(run, root + "/run.txt");
  const std::string log = slurp(root + "/run.txt");
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find("summary.txt is a symbolic link"), std::string::npos) << log;
  EXPECT_TRUE(fs::is_symlink(out + "/summary.txt"));
  EXPECT_TRUE(fs::is_symlink(out + "/results/miss-xor-closest-hit"));
  EXPECT_EQ(slurp(kept + "/keep.txt"), "keep");
  fs::remove(out + "/summary.txt");
  const int moved = sh(run, root + "/run.txt");
  EXPECT_EQ(moved, 2) << slurp(root + "/run.txt");
  EXPECT_NE(slurp(root + "/run.txt").find("miss-xor-closest-hit is a symbolic link"),
            std::string::npos)
      << slurp(root + "/run.txt");
  fs::remove(out + "/results/miss-xor-closest-hit");
  const int judged = sh(run, root + "/run.txt");
  const std::string judged_log = slurp(root + "/run.txt");
  EXPECT_EQ(judged, 1) << judged_log;  // the two CaseErrors fail the run; the good case is judged
  EXPECT_NE(judged_log.find(kCase), std::string::npos) << judged_log;
  const std::string summary = slurp(out + "/summary.txt");
  EXPECT_NE(summary.find(kCase + ": Pass"), std::string::npos) << summary;
  EXPECT_NE(summary.find("nests deeper than 100 levels"), std::string::npos) << summary;
  EXPECT_NE(summary.find("expands to more than"), std::string::npos) << summary;
  EXPECT_EQ(slurp(kept + "/keep.txt"), "keep");
  EXPECT_EQ(filesUnder(kept), 1u);
}

// A shard whose case folder is a link to a folder elsewhere: merge refuses
// it, and the merged output holds none of that folder's files.
TEST(Hostile, MergeRefusesALinkInAShard) {
  const std::string root = fresh("hostile-merge");
  const std::string shard = root + "/shard";
  ASSERT_EQ(sh(cli::kBin + " run --no-validation" + caseArg(kCase) + " --out " + shard,
               root + "/shard.txt"),
            0)
      << slurp(root + "/shard.txt");
  const std::string kept = victim(root, "secret");
  fs::remove_all(shard + "/" + kCase);
  fs::create_symlink(kept, shard + "/" + kCase);
  const std::string out = root + "/merged";
  const int rc = sh(cli::kBin + " merge " + shard + " --out " + out, root + "/merge.txt");
  const std::string log = slurp(root + "/merge.txt");
  EXPECT_NE(rc, 0) << log;
  EXPECT_NE(log.find("is a symbolic link"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(out + "/" + kCase + "/keep.txt"));
  EXPECT_EQ(slurp(kept + "/keep.txt"), "keep");
}

// compare with its --out one of the folders it compares (as given, through
// "A/." or a link): exit 2, and A keeps every file.
TEST(Hostile, CompareRefusesAnOutputThatIsAnInput) {
  const std::string root = fresh("hostile-compare");
  const std::string a = root + "/a";
  ASSERT_EQ(
      sh(cli::kBin + " run --no-validation" + caseArg(kCase) + " --out " + a, root + "/a.txt"), 0)
      << slurp(root + "/a.txt");
  fs::create_symlink(a, root + "/link-to-a");
  const size_t before = filesUnder(a);
  for (const std::string& out : {a, a + "/.", root + "/link-to-a", root}) {
    const int rc = sh(cli::kBin + " compare " + a + " " + a + " --out " + out, root + "/c.txt");
    const std::string log = slurp(root + "/c.txt");
    EXPECT_EQ(rc, 2) << out << "\n" << log;
    EXPECT_NE(log.find("its reports would replace what is compared"), std::string::npos) << log;
    EXPECT_EQ(filesUnder(a), before) << out;
  }
}

// A run records its variant (--through, --permute, --move): resuming it,
// judging its saved device results or merging it as another variant is
// refused (issue 44: all three exited 0).
TEST(Hostile, RunsOfAnotherVariantNeverMix) {
  const std::string root = fresh("hostile-variant");
  const std::string through = root + "/through";
  const std::string plain = root + "/plain";
  ASSERT_EQ(
      sh(cli::kBin + " run --no-validation --through update" + caseArg(kCase) + " --out " + through,
         root + "/through.txt"),
      0)
      << slurp(root + "/through.txt");
  ASSERT_EQ(sh(cli::kBin + " run --no-validation" + caseArg(kCase) + " --out " + plain,
               root + "/plain.txt"),
            0)
      << slurp(root + "/plain.txt");
  EXPECT_NE(slurp(through + "/summary.json").find("\"variant\": \"through update\""),
            std::string::npos);
  struct Mixed {
    std::string command, message;
  } mixed[] = {
      {" run --no-validation --resume" + caseArg(kCase) + " --out " + through,
       "ran its cases by through update, this run would run them as written"},
      {" run --no-validation --through update --device-results " + plain + caseArg(kCase) +
           " --out " + root + "/judged",
       "ran its cases as written, this run would judge them by through update"},
      {" merge " + through + " " + plain + " --out " + root + "/merged",
       "only runs of one variant merge"},
  };
  for (const Mixed& m : mixed) {
    const int rc = sh(cli::kBin + m.command, root + "/mixed.txt");
    const std::string log = slurp(root + "/mixed.txt");
    EXPECT_EQ(rc, 2) << m.command << "\n" << log;
    EXPECT_NE(log.find(m.message), std::string::npos) << log;
  }
}

// The execution model of a SPIR-V module's first OpEntryPoint (0: none).
uint32_t executionModel(const std::string& module) {
  std::vector<uint32_t> words(module.size() / 4);
  std::memcpy(words.data(), module.data(), words.size() * 4);
  constexpr uint32_t kOpEntryPoint = 15;
  for (size_t i = 5; i + 1 < words.size();) {
    if ((words[i] & 0xFFFF) == kOpEntryPoint) return words[i + 1];
    i += (words[i] >> 16) ? (words[i] >> 16) : 1;
  }
  return 0;
}

// Issue 56: a cache folder others can write (a shared RAYSPEC_CACHE_DIR, a
// CI cache from another job) with another case's module under each of this
// case's keys, its .sum recomputed as the cache checked it before (SHA-256
// of the key and the module, which anyone can compute). The run compiles
// the case's own stages again and passes: the forged entries are rewritten,
// never a verdict on the device.
TEST(Hostile, AForgedSpirvCacheIsNeverAVerdict) {
  const std::string root = fresh("hostile-forged-cache");
  const std::string env = "RAYSPEC_CONFIG_DIR=" + root + "/config ";
  const std::string other_case = "culling/cull-opaque";
  for (const auto& [name, c] : {std::pair{"mine", kCase}, std::pair{"other", other_case}})
    ASSERT_EQ(sh(env + cli::kBin + " run --no-validation" + caseArg(c) + " --cache-dir " + root +
                     "/" + name + "-cache --out " + root + "/" + name,
                 root + "/" + name + ".txt"),
              0)
        << slurp(root + "/" + name + ".txt");
  std::map<uint32_t, std::string> other_modules;  // execution model -> module
  for (const auto& e : fs::directory_iterator(root + "/other-cache/spirv"))
    if (e.path().extension() == ".spv") {
      const std::string module = slurp(e.path().string());
      other_modules[executionModel(module)] = module;
    }
  std::map<std::string, std::string> forged;  // .sum file -> the sum written there
  for (const auto& e : fs::directory_iterator(root + "/mine-cache/spirv")) {
    if (e.path().extension() != ".spv") continue;
    const std::string mine = slurp(e.path().string());
    const auto other = other_modules.find(executionModel(mine));
    if (other == other_modules.end() || other->second == mine) continue;
    std::ofstream(e.path(), std::ios::binary | std::ios::trunc) << other->second;
    const std::string key = e.path().stem().string(), sum_file = root + "/sum.txt";
    ASSERT_EQ(sh("{ printf '%s\\n' " + key + "; cat " + e.path().string() +
                     "; } | sha256sum | cut -c1-64",
                 sum_file),
              0);
    const std::string sum = slurp(sum_file);
    ASSERT_EQ(sum.size(), 65u) << sum;
    const std::string sum_path = root + "/mine-cache/spirv/" + key + ".sum";
    std::ofstream(sum_path, std::ios::trunc) << sum;
    forged[sum_path] = sum;
  }
  ASSERT_FALSE(forged.empty()) << "no stage of " << other_case << " to forge " << kCase
                               << "'s with";
  const int rc = sh(env + cli::kBin + " run --no-validation" + caseArg(kCase) + " --cache-dir " +
                        root + "/mine-cache --out " + root + "/again",
                    root + "/again.txt");
  EXPECT_EQ(rc, 0) << slurp(root + "/again.txt");
  EXPECT_NE(slurp(root + "/again/summary.txt").find(kCase + ": Pass"), std::string::npos)
      << slurp(root + "/again/summary.txt");
  for (const auto& [path, sum] : forged) EXPECT_NE(slurp(path), sum) << path << " was used";
}

// Processes of their own and no processes at all: refused before anything runs.
TEST(Hostile, ProcessPerCaseForAndNoIsolationAreRefusedTogether) {
  const std::string root = fresh("hostile-options");
  for (const std::string& pair : {std::string(" --process-per-case-for 'results/*' --no-isolation"),
                                  std::string(" --no-isolation --process-per-case")}) {
    const int rc =
        sh(cli::kBin + " run --no-validation" + caseArg(kCase) + pair + " --out " + root + "/out",
           root + "/o.txt");
    const std::string log = slurp(root + "/o.txt");
    EXPECT_EQ(rc, 2) << pair << "\n" << log;
    EXPECT_NE(log.find("excludes"), std::string::npos) << log;
  }
}

}  // namespace
