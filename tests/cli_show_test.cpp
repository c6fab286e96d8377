// `rayspec show` and `rayspec list` run as programs: a missing case file, rule
// labels outside the catalog, the undefined behaviour of a robustness probe,
// sweep variants, and the coverage of every rule by the suite's cases.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {
namespace fs = std::filesystem;

struct ShowRun {
  int status = -1;
  std::string out, err;
};

// Runs `rayspec ARGS` from the source folder; stdout and stderr apart.
ShowRun rayspec(const std::string& args) {
  // One folder per process: ctest runs this binary's suites (cli/show,
  // cli/list-rules) at once, and shared output files would race.
  const std::string dir = std::string(RAYSPEC_TEST_OUT) + "/show/run-" + std::to_string(::getpid());
  fs::create_directories(dir);
  const std::string out = dir + "/stdout", err = dir + "/stderr";
  const std::string command =
      "cd " RAYSPEC_SOURCE_DIR " && " RAYSPEC_BIN " " + args + " > " + out + " 2> " + err;
  const int s = std::system(command.c_str());
  ShowRun r;
  r.status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  std::ifstream o(out), e(err);
  std::stringstream so, se;
  so << o.rdbuf();
  se << e.rdbuf();
  r.out = so.str();
  r.err = se.str();
  return r;
}

ShowRun show(const std::string& args) {
  return rayspec("show " + args);
}

TEST(Show, AMissingCaseFileIsAClearErrorAndANonZeroExit) {
  for (const std::string& arg : {std::string("cases/nope.yaml"), std::string("nope/x")}) {
    const ShowRun r = show(arg);
    EXPECT_NE(r.status, 0) << arg;
    EXPECT_NE(r.err.find("no such case file: '" + arg + "'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(".yaml.yaml"), std::string::npos) << "no mangled path: " << r.err;
    EXPECT_EQ(r.out, "") << arg;
  }
  const ShowRun ok = show("builtins/closest-hit-and-miss --no-glsl");
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(ok.out.find("Case builtins/closest-hit-and-miss"), std::string::npos);
}

// A case file outside the cases folder is named by its stem, with no family
// (issue 43: it was shown as a family of its own).
TEST(Show, AFileOutsideTheCasesFolderHasNoFamily) {
  const std::string dir =
      std::string(RAYSPEC_TEST_OUT) + "/show/outside-" + std::to_string(::getpid());
  fs::create_directories(dir);
  fs::copy_file(RAYSPEC_SOURCE_DIR "/cases/anyhit/ignore-odd-primitives.yaml", dir + "/mine.yaml",
                fs::copy_options::overwrite_existing);
  const ShowRun r = show(dir + "/mine.yaml --no-glsl");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Case mine  ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("family: (none: a file outside the cases folder)"), std::string::npos)
      << r.out;
  const ShowRun inside = show("anyhit/ignore-odd-primitives --no-glsl");
  EXPECT_NE(inside.out.find("family: anyhit\n"), std::string::npos) << inside.out;
}

TEST(Show, AnUnknownRuleLabelIsAnErrorAtItsLineAndColumn) {
  const std::string path = std::string(RAYSPEC_TEST_OUT) + "/show/unknown-rule.yaml";
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path) << "rules: [R-MASK, R-NOT-A-RULE]\nrays: {list: [{origin: [0, 0, 1], "
                         "direction: [0, 0, -1]}]}\npipeline: {miss: [[]]}\n";
  const ShowRun r = show(path + " --no-glsl");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find(path + ":1:17: rules[1]: unknown rule label 'R-NOT-A-RULE'"),
            std::string::npos)
      << r.err;
}

TEST(Show, ARobustnessProbeListsItsUndefinedBehaviour) {
  const ShowRun r = show("robustness/undefined-rays --no-glsl");
  EXPECT_EQ(r.status, 0) << r.err;
  const size_t at = r.out.find("Undefined behaviour (R-UB probe");
  ASSERT_NE(at, std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rays.list[4].tmin: tmin is NaN", at), std::string::npos) << r.out;
}

// scene.split moves a mesh's triangles into geometries or instances of
// their own after rays.aim aimed at the mesh (parse_case.cpp): show lists
// each ray's target in the mesh as aimed (it listed none, aiming again at
// the split scene).
TEST(Show, AimedRaysOfASplitMesh) {
  for (const char* name : {"watertight/closed-fan-geometries/mag-1-n-4",
                           "watertight/closed-fan-instances/moved-mag-1e3-n-4"}) {
    const ShowRun r = show(std::string(name) + " --no-glsl --no-model");
    ASSERT_EQ(r.status, 0) << name << ": " << r.err;
    const size_t aimed = r.out.find("Aimed rays (rays.aim: what each ray is aimed at):\n");
    ASSERT_NE(aimed, std::string::npos) << name << ": " << r.out;
    EXPECT_NE(
        r.out.find("  ray 0: vertex of instance 0 geometry 0 triangles 0, 1, 2, 3 at (", aimed),
        std::string::npos)
        << name << ": " << r.out;
    EXPECT_NE(r.out.find("  ray 1: edge of instance 0 geometry 0 triangles ", aimed),
              std::string::npos)
        << name << ": " << r.out;
  }
}

// Issue 61: show lists what each aimed ray is aimed at, and what the model
// expects of each ray (which stage ran, the recorded fields, the legal
// answers of an ambiguous ray).
TEST(Show, AimedRaysTargetsAndWhatTheModelExpects) {
  const std::string path = std::string(RAYSPEC_TEST_OUT) + "/show/aimed.yaml";
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path) << R"(rules: [R-WATERTIGHT]
scene:
  blas:
    grid: [{triangles: {grid: {cells: [2, 2], size: [2, 2], center: [0, 0, 0]}}, flags: [opaque]}]
  instances: [{blas: grid, transform: {translate: [10, 0, 0]}}]
rays:
  aim: {at: [vertices, faces], offset: [0, 0, 1]}
  tmax: 10
pipeline:
  miss: [[record: {hit: 0}]]
  hit_groups: [{closest_hit: [record: [hit, primitive_id]]}]
outputs: {per_ray: [hit, primitive_id]}
)";
  const ShowRun r = show(path + " --no-glsl");
  ASSERT_EQ(r.status, 0) << r.err;
  const size_t aimed = r.out.find("Aimed rays (rays.aim: what each ray is aimed at):\n");
  ASSERT_NE(aimed, std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  ray 0: vertex of instance 0 geometry 0 triangles ", aimed),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(" at (0, 0, 0) (world (10, 0, 0))\n", aimed), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  ray 1: centroid of instance 0 geometry 0 triangle 0 at (", aimed),
            std::string::npos)
      << r.out;
  const size_t model = r.out.find("Model (exact tier) expects:\n");
  ASSERT_NE(model, std::string::npos) << r.out;
  const size_t ray0 = r.out.find("  ray 0: closest-hit ran; hit 1, primitive_id ", model);
  ASSERT_NE(ray0, std::string::npos) << r.out;
  const std::string line0 = r.out.substr(ray0, r.out.find('\n', ray0) - ray0);
  EXPECT_NE(line0.find("; ambiguous (vertex): legal answers instance 0 geometry 0 primitives "),
            std::string::npos)
      << "the vertex's triangles are its legal answers: " << line0;
  EXPECT_NE(r.out.find("  ray 1: closest-hit ran; hit 1, primitive_id 0\n", model),
            std::string::npos)
      << r.out;
}

// Issue 61: a case traced by ray queries from a compute shader is launched
// by a dispatch, not by trace_rays.
TEST(Show, AComputeCaseIsLaunchedByADispatch) {
  const ShowRun r = show("ray-query/compute-closest-hit-and-miss --no-glsl --no-model");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("launched by vkCmdDispatch of 7 x 1 x 1 workgroups of 64 "
                       "(pipeline.traces: ray_query_compute"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("launched by trace_rays"), std::string::npos) << r.out;
  const ShowRun pipeline = show("builtins/closest-hit-and-miss --no-glsl --no-model");
  EXPECT_NE(pipeline.out.find(", launched by trace_rays\n"), std::string::npos) << pipeline.out;
  EXPECT_EQ(pipeline.out.find("Model (exact tier)"), std::string::npos) << "--no-model";
}

// Issue 61: show runs `rayspec check`'s portability check and says its verdict.
TEST(Show, SaysWhetherTheCaseIsPortable) {
  const ShowRun bad =
      show(RAYSPEC_SOURCE_DIR "/tests/data/not-portable/candidates-exact.yaml --no-glsl");
  ASSERT_EQ(bad.status, 0) << bad.err;
  const size_t at = bad.out.find("NOT PORTABLE:\n  ");
  ASSERT_NE(at, std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("counters[0].candidates: not portable: a device the specification "
                         "allows",
                         at),
            std::string::npos)
      << bad.out;
  const ShowRun good =
      show(RAYSPEC_SOURCE_DIR "/tests/data/portable/candidates-at-least.yaml --no-glsl");
  ASSERT_EQ(good.status, 0) << good.err;
  EXPECT_NE(good.out.find("Portable: every device the specification allows passes it ("),
            std::string::npos)
      << good.out;
  EXPECT_EQ(good.out.find("NOT PORTABLE"), std::string::npos) << good.out;
}

// The coverage contract: every rule of the catalog but R-UB is claimed by a
// case of the suite (sweep variants included).
// `show --vocabulary` lists each built-in's and each operator's stages from
// their tables' stages column (cases/README.md says it does): a row read in
// some stages names those, in the Stage enum's order, one of every stage says
// so, and each row of both tables ends in its stages.
TEST(Show, VocabularyListsTheStagesOfEachBuiltinAndOperator) {
  const ShowRun r = rayspec("show --vocabulary");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto line_of = [&](const std::string& start) {
    const size_t at = r.out.find("\n  " + start + " ");
    return at == std::string::npos ? std::string()
                                   : r.out.substr(at, r.out.find('\n', at + 1) - at);
  };
  EXPECT_NE(line_of("hit_kind").find(" [closest_hit, any_hit]"), std::string::npos);
  EXPECT_NE(line_of("primitive_id").find(" [closest_hit, any_hit, intersection]"),
            std::string::npos);
  EXPECT_NE(line_of("aabb_min").find(" [intersection]"), std::string::npos);
  EXPECT_NE(line_of("call.position").find(" [callable]"), std::string::npos);
  EXPECT_NE(line_of("callee.color").find(" [raygen, miss, closest_hit, callable]"),
            std::string::npos);
  EXPECT_NE(line_of("candidate.t").find(" [all stages]"), std::string::npos);
  EXPECT_NE(line_of("add").find(" [all stages]"), std::string::npos);
  EXPECT_NE(line_of("sphere_hit").find(" [intersection]"), std::string::npos);
  std::istringstream lines(r.out);
  int rows = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("  ", 0) != 0) continue;
    ++rows;
    EXPECT_EQ(line.back(), ']') << line;
  }
  EXPECT_GT(rows, 150) << r.out;
}

TEST(List, EveryRuleHasACase) {
  const ShowRun r = rayspec("list --rules");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("UNCOVERED"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("R-UB  "), std::string::npos);
  EXPECT_NE(r.out.find("(probes: undefined behaviour is never judged"), std::string::npos);
}

// A case folder, made anew under the tests' output, holding only
// cases/sbt/hit-group-index.yaml.
fs::path folderWithOneCase(const std::string& name) {
  const fs::path dir = fs::path(RAYSPEC_TEST_OUT) / name;
  fs::remove_all(dir);
  fs::create_directories(dir / "sbt");
  fs::copy_file(fs::path(RAYSPEC_SOURCE_DIR) / "cases/sbt/hit-group-index.yaml",
                dir / "sbt/hit-group-index.yaml");
  return dir;
}

// A folder whose cases leave rules unclaimed: exit 1, each uncovered rule named.
TEST(List, ARuleWithoutACaseFailsTheListing) {
  const fs::path dir = folderWithOneCase("list-cases");
  const ShowRun r = rayspec("list --rules --cases " + dir.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("R-MASK  instance mask"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("UNCOVERED: no case claims this rule"), std::string::npos) << r.out;
  // The catalog's rules, its lines "R-NAME: title", R-UB apart (probes only).
  std::ifstream catalog(RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml");
  size_t rules = 0;
  for (std::string line; std::getline(catalog, line);)
    rules += line.rfind("R-", 0) == 0 && line.rfind("R-UB:", 0) != 0;
  EXPECT_NE(r.out.find("2 of " + std::to_string(rules) + " rules have a case"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("Uncovered: R-CAND-TRI-OPEN"), std::string::npos) << r.out;
  const ShowRun plain = rayspec("list --cases " + dir.string());
  EXPECT_EQ(plain.status, 0) << plain.err;
  EXPECT_NE(plain.out.find("sbt/hit-group-index"), std::string::npos);
  EXPECT_NE(plain.out.find("R-SBT-HIT R-BUILTIN"), std::string::npos);
}

// A sweep's variants are listed and shown by name.
TEST(List, SweepVariantsAreCasesOfTheirOwn) {
  const fs::path dir = fs::path(RAYSPEC_TEST_OUT) / "list-sweep";
  fs::remove_all(dir);
  fs::create_directories(dir / "sbt");
  std::ifstream in(fs::path(RAYSPEC_SOURCE_DIR) / "cases/sbt/hit-group-index.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::ofstream(dir / "sbt/rows.sweep.yaml") << "sweep:\n  name: row-${r}\n  product: {r: [0, 1]}\n"
                                             << text.str();
  const ShowRun r = rayspec("list --rules --cases " + dir.string());
  EXPECT_NE(r.out.find("sbt/rows (sweep: 2 variants)"), std::string::npos) << r.out;
  const ShowRun plain = rayspec("list --cases " + dir.string());
  EXPECT_NE(plain.out.find("sbt/rows/row-1"), std::string::npos) << plain.out;
  const ShowRun one = show("--no-glsl --cases " + dir.string() + " sbt/rows/row-1");
  EXPECT_EQ(one.status, 0) << one.err;
  EXPECT_NE(one.out.find("Case sbt/rows/row-1"), std::string::npos) << one.out;
}

// `rayspec compile` fills a SPIR-V cache with no device: every stage of the
// family compiled once, then all found there; a KEY.spv beside each KEY.sum.
TEST(Compile, FillsTheCacheThenFindsEverything) {
  const fs::path cache = fs::path(RAYSPEC_TEST_OUT) / "compile-cache";
  fs::remove_all(cache);
  const ShowRun first = rayspec("compile --filter 'sbt/*' --cache-dir " + cache.string());
  ASSERT_EQ(first.status, 0) << first.out << first.err;
  EXPECT_NE(first.out.find("0 from the cache, 0 failed"), std::string::npos) << first.out;
  int spv = 0, sums = 0;
  for (const auto& e : fs::directory_iterator(cache / "spirv")) {
    spv += e.path().extension() == ".spv";
    sums += e.path().extension() == ".sum";
  }
  EXPECT_GT(spv, 10);
  EXPECT_EQ(spv, sums);
  const ShowRun again = rayspec("compile --filter 'sbt/*' --cache-dir " + cache.string());
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find(": 0 compiled"), std::string::npos) << again.out;
}

// A case that does not parse: its error, and exit 1 once the others are done.
TEST(Compile, ACaseThatDoesNotParseFailsTheCommand) {
  const fs::path dir = folderWithOneCase("compile-cases");
  std::ofstream(dir / "sbt/broken.yaml") << "scene: [\n";
  const ShowRun r = rayspec("compile --cases " + dir.string() + " --cache-dir ''");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("broken.yaml"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("1 cases, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 cases do not parse"), std::string::npos) << r.out;
}

}  // namespace
