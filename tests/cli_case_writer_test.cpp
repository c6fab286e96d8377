// The case writer's loop of cases/HOWTO.md ("The steps"), run start to finish
// on a new case written outside the tree (issue 61), with the commands the
// HOWTO gives and no ctest: the rule's faults, show, check (every device the
// specification allows), run, prove, then the permuted and the moved run.
// Each step's exit status and a line of its output are asserted. The runs
// use the device (lavapipe here) and the model, a second or so each.
#include <filesystem>
#include <fstream>

#include "cli_helpers.h"

namespace {
namespace fs = std::filesystem;
using cli::fresh;
using cli::kBin;
using cli::readDeqpCsv;
using cli::sh;
using cli::slurp;

// A new case as the HOWTO's steps 2 and 3 write one: the smallest scene
// (one triangle, a ray through its inside and one beside it), each shader
// with a counter and a record of its own.
const char* kCase = R"(rules: [R-MISS-XOR-CHIT, R-BUILTIN]
description: Ray 0 hits the triangle (closest-hit, primitive 0); ray 1 misses it.
scene:
  blas:
    tri: [{triangles: {vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}, flags: [opaque]}]
  instances: [{blas: tri}]
rays:
  list:
    - {origin: [0.25, 0.25, 1], direction: [0, 0, -1]}
    - {origin: [4, 4, 1], direction: [0, 0, -1]}
pipeline:
  miss: [[count: miss, record: {hit: 0, value: 7}]]
  hit_groups:
    - closest_hit: [count: closesthit, record: [hit, primitive_id, hit_t]]
outputs:
  counters: [miss, closesthit]
  per_ray: [hit, primitive_id, hit_t, value]
)";

struct Ran {
  int status = -1;
  std::string out;
};

// `rayspec ARGS`, stdout and stderr together in DIR/STEP.txt.
Ran rayspec(const std::string& args, const std::string& dir, const std::string& step) {
  const std::string log = dir + "/" + step + ".txt";
  Ran r;
  r.status = sh(kBin + " " + args, log);
  r.out = slurp(log);
  return r;
}

bool has(const Ran& r, const std::string& line) {
  return r.out.find(line) != std::string::npos;
}

// One run of the case file (step 6, step 8's permuted and moved runs): a
// file outside cases/ is checked portable first (step 5), then passes.
void expectPasses(const std::string& file, const std::string& dir, const std::string& step,
                  const std::string& options) {
  const std::string out = dir + "/" + step;
  const Ran r = rayspec("run --case " + file + " --out " + out + options, dir, step);
  EXPECT_EQ(r.status, 0) << step << "\n" << r.out;
  EXPECT_TRUE(has(r, "hit-or-miss: checked against the devices the specification allows: portable"))
      << step << "\n"
      << r.out;
  EXPECT_EQ(readDeqpCsv(out + "/results.csv")["hit-or-miss"], "Pass") << step << "\n" << r.out;
}

TEST(CaseWriter, TheHowtoStepsOnANewCaseOutsideTheTree) {
  const std::string dir = fresh("case-writer");
  const std::string file = dir + "/my-cases/hit-or-miss.yaml";
  fs::create_directories(fs::path(file).parent_path());
  std::ofstream(file) << kCase;

  // 1. The rule and its faults.
  const Ran faults = rayspec("faults --rule R-MISS-XOR-CHIT", dir, "faults");
  EXPECT_EQ(faults.status, 0) << faults.out;
  EXPECT_TRUE(has(faults, "R-MISS-XOR-CHIT")) << faults.out;
  // 4. What both sides will build.
  const Ran show = rayspec("show " + file, dir, "show");
  EXPECT_EQ(show.status, 0) << show.out;
  EXPECT_TRUE(has(show, "traceRayEXT")) << show.out;
  // 5. Portable: every device the specification allows passes it.
  const Ran check = rayspec("check " + file, dir, "check");
  EXPECT_EQ(check.status, 0) << check.out;
  EXPECT_TRUE(has(check, "portable      hit-or-miss (")) << check.out;
  EXPECT_TRUE(has(check, "1 of 1 cases portable")) << check.out;
  // 6. Run on the device and the model, the records of both as text.
  expectPasses(file, dir, "run", " --records-csv");
  for (const char* side : {"device", "model"})
    EXPECT_TRUE(fs::exists(dir + "/run/hit-or-miss/" + side + "/records.csv")) << side;
  // 7. Every claim proved by a fault.
  const Ran prove = rayspec("prove " + file, dir, "prove");
  EXPECT_EQ(prove.status, 0) << prove.out;
  EXPECT_TRUE(has(prove, "R-MISS-XOR-CHIT: proved by ")) << prove.out;
  EXPECT_TRUE(has(prove, "R-BUILTIN: proved by ")) << prove.out;
  EXPECT_TRUE(has(prove, "1 cases, 2 claims: 2 proved")) << prove.out;
  // 8. Neither the order nor the placement moves the verdict.
  // One triangle, one instance: nothing to permute, so not run (a repeat of
  // step 6's run), and said so.
  const Ran permuted =
      rayspec("run --case " + file + " --out " + dir + "/permute --permute 1", dir, "permute");
  EXPECT_EQ(readDeqpCsv(dir + "/permute/results.csv")["hit-or-miss"], "Skip") << permuted.out;
  EXPECT_TRUE(has(permuted, "--permute 1 moves nothing in this case")) << permuted.out;
  expectPasses(file, dir, "move", " --move=-y,x,z");
  expectPasses(file, dir, "move-far", " --move=z,-x,-y,2,-4,8");
}

}  // namespace
