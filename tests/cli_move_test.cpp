// `rayspec run --move MOTION` (tests/CMakeLists.txt: cli/move): each case
// moved by an exact rigid motion runs on the device and the model alike and
// is judged as usual, so a broken device still fails; a case the motion
// cannot move exactly is NotSupported (never a pass, and not held against a
// baseline); a saved unmoved device run is not judged as the moved case.
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

// One triangle, rays with dyadic origins (any dyadic translation is exact),
// the world-space origin and hit position recorded.
const char* kCase = R"(rules: [R-BUILTIN]
scene:
  blas:
    tri: [{triangles: {vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}, flags: [opaque]}]
  instances: [{blas: tri}]
rays:
  list:
    - {origin: [0.25, 0.25, 1], direction: [0, 0, -1]}
    - {origin: [4, 4, 1], direction: [0, 0, -1]}
pipeline:
  miss: [[count: miss, record: [world_ray_origin]]]
  hit_groups:
    - closest_hit: [count: closesthit, record: [hit, hit_t, world_ray_origin, hit_position]]
outputs:
  counters: [miss, closesthit]
  per_ray: [hit, hit_t, world_ray_origin, hit_position]
)";

// A case whose miss traces its own direction: not movable.
const char* kOwnRay = R"(rules: [R-RECURSION]
scene:
  blas:
    tri: [{triangles: {vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}}]
  instances: [{blas: tri}]
rays:
  list: [{origin: [0.25, 0.25, 1], direction: [0, 0, 1]}]
pipeline:
  max_recursion: 2
  miss: [[count: miss], [count: miss2]]
  hit_groups: [{closest_hit: [count: closesthit, trace: {origin: hit_position, direction: [0.0, 0.0, -1.0], miss: 1}]}]
outputs: {counters: [miss, miss2, closesthit]}
)";

std::string write(const std::string& path, const std::string& text) {
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path) << text;
  return path;
}

struct Folder {
  std::string dir, cases;
};
Folder setUp(const std::string& name) {
  Folder f{fresh(name), ""};
  f.cases = f.dir + "/cases";
  write(f.cases + "/move/world-origin.yaml", kCase);
  write(f.cases + "/move/own-ray.yaml", kOwnRay);
  return f;
}

TEST(Move, BothSidesRunTheMovedCaseAndAFaultStillFails) {
  const Folder f = setUp("move");
  const std::string run =
      kBin + " run --no-validation --cases " + f.cases + " --records-csv --move=-y,x,z,2,-4,8";
  ASSERT_EQ(sh(run + " --out " + f.dir + "/moved", f.dir + "/moved.txt"), 0)
      << slurp(f.dir + "/moved.txt");
  EXPECT_NE(slurp(f.dir + "/moved.txt").find("Moved: every case by the rigid motion -y,x,z,2,-4,8"),
            std::string::npos);
  auto status = readDeqpCsv(f.dir + "/moved/results.csv");
  EXPECT_EQ(status["move/world-origin"], "Pass");
  EXPECT_EQ(status["move/own-ray"], "Skip");  // NotSupported
  EXPECT_NE(slurp(f.dir + "/moved.txt").find("gives its own origin or direction"),
            std::string::npos);
  // (0.25, 0.25, 1) moved: (-0.25 + 2, 0.25 - 4, 1 + 8); the hit point on z = 0 goes to z = 8.
  for (const char* side : {"device", "model"}) {
    const std::string csv = slurp(f.dir + "/moved/move/world-origin/" + side + "/records.csv");
    EXPECT_NE(csv.find("1.75 -3.75 9"), std::string::npos) << side << "\n" << csv;
    EXPECT_NE(csv.find("1.75 -3.75 8"), std::string::npos) << side << "\n" << csv;
  }
  // A device whose t is off fails the moved case as it fails the unmoved one.
  ASSERT_EQ(sh(run + " --plant-fault shift-t --out " + f.dir + "/fault", f.dir + "/fault.txt"), 1)
      << slurp(f.dir + "/fault.txt");
  EXPECT_EQ(readDeqpCsv(f.dir + "/fault/results.csv")["move/world-origin"], "Fail");
}

// R-PREC both ways: far from the origin the object-space origin is judged to
// the size of the terms that cancelled in it (model/model_builtins.h), so a
// device's rounding passes and a wrong built-in still fails. The suite's
// builtins/closest-hit-and-miss (turned, scaled instances; closest-hit
// records the object ray origin) moved 2048 away: lavapipe's origins differ
// from the model's by some 1.2e-4 there, an ulp of 2048.
TEST(Move, AFarObjectOriginIsJudgedToItsTermsNotItsResult) {
  const std::string dir = fresh("move-far");
  const std::string run = kBin + " run --no-validation --case " + cli::kCases +
                          "builtins/closest-hit-and-miss.yaml --move=z,x,y,1024,-2048,0";
  ASSERT_EQ(sh(run + " --out " + dir + "/moved", dir + "/moved.txt"), 0)
      << slurp(dir + "/moved.txt");
  EXPECT_EQ(readDeqpCsv(dir + "/moved/results.csv")["builtins/closest-hit-and-miss"], "Pass");
  ASSERT_EQ(sh(run + " --plant-fault builtin-wrong --out " + dir + "/fault", dir + "/fault.txt"), 1)
      << slurp(dir + "/fault.txt");
  EXPECT_EQ(readDeqpCsv(dir + "/fault/results.csv")["builtins/closest-hit-and-miss"], "Fail");
}

// A baseline's known failure of a case the motion cannot move is not an
// unexpected pass (the case did not run); a bad motion is exit 2.
TEST(Move, ANotMovedCaseIsNeitherAPassNorAnUnexpectedPass) {
  const Folder f = setUp("move-baseline");
  const std::string baseline = write(f.dir + "/driver.csv", "move/own-ray,Fail\n");
  ASSERT_EQ(sh(kBin + " run --no-validation --cases " + f.cases + " --move=x,-y,-z --baseline " +
                   baseline + " --out " + f.dir + "/run",
               f.dir + "/run.txt"),
            0)
      << slurp(f.dir + "/run.txt");
  EXPECT_EQ(readDeqpCsv(f.dir + "/run/results.csv")["move/own-ray"], "Skip");
  EXPECT_EQ(
      sh(kBin + " run --no-validation --cases " + f.cases + " --move=x,y --out " + f.dir + "/bad",
         f.dir + "/bad.txt"),
      2);
  EXPECT_NE(slurp(f.dir + "/bad.txt").find("--move"), std::string::npos)
      << slurp(f.dir + "/bad.txt");
}

// Device bundles saved by an unmoved run are another case's: the run folder
// records that it ran its cases as written, and judging them moved is
// refused at the start (exit 2; a bundle without its run folder's record is
// still a CaseError by its case hash, run/device_results.cpp).
TEST(Move, SavedBundlesOfTheUnmovedCaseAreNotJudgedAsTheMovedOne) {
  const Folder f = setUp("move-saved");
  ASSERT_EQ(sh(kBin + " run --no-validation --no-model --cases " + f.cases +
                   " --filter 'move/world*' --out " + f.dir + "/saved",
               f.dir + "/saved.txt"),
            77)  // one case, NotSupported: nothing compared
      << slurp(f.dir + "/saved.txt");
  EXPECT_EQ(sh(kBin + " run --no-validation --cases " + f.cases +
                   " --filter 'move/world*' --device-results " + f.dir +
                   "/saved --move=-y,x,z --out " + f.dir + "/judged",
               f.dir + "/judged.txt"),
            2);
  EXPECT_NE(slurp(f.dir + "/judged.txt")
                .find("ran its cases as written, this run would judge them by move -y,x,z"),
            std::string::npos)
      << slurp(f.dir + "/judged.txt");
}

}  // namespace
