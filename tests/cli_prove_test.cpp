// `rayspec prove` and `rayspec faults` run as programs: a library case's
// claims proved, a copy outside cases/ with a claim nothing in it exercises
// reported hollow (exit 1) from a read-only folder that stays as it was, and
// the fault listing with its rules and the rule's text from the checkout.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {
namespace fs = std::filesystem;

struct Ran {
  int status = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `rayspec ARGS` in folder `cwd`; its output is kept under the build's
// test folder, never in cwd.
Ran rayspec(const std::string& args, const std::string& cwd = RAYSPEC_SOURCE_DIR) {
  const fs::path dir = fs::path(RAYSPEC_TEST_OUT) / ("prove-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string command = "cd '" + cwd + "' && " RAYSPEC_BIN " " + args + " > " +
                              (dir / "out").string() + " 2> " + (dir / "err").string();
  const int s = std::system(command.c_str());
  return {WIFEXITED(s) ? WEXITSTATUS(s) : -1, slurp(dir / "out"), slurp(dir / "err")};
}

const std::string kCase = RAYSPEC_SOURCE_DIR "/cases/inactive/nan-min-x-aabb-second.yaml";

TEST(Prove, ALibraryCaseHasEveryClaimProvedByAFault) {
  const Ran r = rayspec("prove " + kCase);
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("Device: the model's exact tier"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("inactive/nan-min-x-aabb-second ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nan-min-x-aabb-second.yaml), proved on the model in "), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("R-INACTIVE: proved by inactive-revived: Fail"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("R-BUILTIN: proved by "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 cases, 2 claims: 2 proved, 0 not checked (R-UB), 0 not proved"),
            std::string::npos)
      << r.out;
}

// A proof line shows the finding that names the claim, not the verdict's
// worst: tmax-view-initial's worst finding is R-PAYLOAD's barycentrics, its
// R-TMAX-VIEW finding the ray_tmax field; where only a field of another rule
// is evidence against the claim (confirm-nearest's R-RQ-VALUES), it says so.
TEST(Prove, EachProofLineShowsTheFindingNamingTheClaim) {
  const Ran r =
      rayspec("prove cases/intersection/tmax-view.yaml cases/ray-query/confirm-nearest.yaml");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(
      r.out.find("  R-TMAX-VIEW: proved by tmax-view-initial: Fail: R-TMAX-VIEW: per-ray field "
                 "'ray_tmax' differs"),
      std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  R-RQ-VALUES: proved by query-custom-index-is-instance-id: Fail: "
                       "R-PAYLOAD: per-ray field 'value3' differs from the model on clear rays "
                       "(4 rays; first: 0 1 2 3) (evidence against R-RQ-VALUES)\n"),
            std::string::npos)
      << r.out;
  std::istringstream lines(r.out);
  size_t proofs = 0;
  for (std::string line; std::getline(lines, line);) {
    const size_t by = line.find(": proved by ");
    if (line.rfind("  R-", 0) != 0 || by == std::string::npos) continue;
    ++proofs;
    const std::string claim = line.substr(2, by - 2);
    const std::string shown = line.substr(line.find(": ", by + 12) + 2);  // "Fail: R-X: ..."
    const size_t rule = shown.find(": ") + 2;                             // after the status
    const std::string labels = "/" + shown.substr(rule, shown.find(": ", rule) - rule) + "/";
    EXPECT_TRUE(labels.find("/" + claim + "/") != std::string::npos ||
                line.find("(evidence against " + claim + ")") != std::string::npos)
        << line;
  }
  EXPECT_GE(proofs, 4u) << r.out;
}

// The case copied outside the tree, into a folder nobody may write, with a
// claim of R-MASK (one instance, no mask: no fault of R-MASK changes
// anything) and of R-AS-BUILD (one build): both claims are hollow.
TEST(Prove, AHollowClaimOutsideTheTreeIsNamedWithTheFaultsTried) {
  const fs::path dir = fs::path(RAYSPEC_TEST_OUT) / "prove-read-only";
  if (fs::exists(dir)) fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string text = slurp(kCase);
  text.replace(text.find("rules: [R-INACTIVE, R-BUILTIN]"), 30,
               "rules: [R-INACTIVE, R-BUILTIN, R-MASK, R-AS-BUILD]");
  std::ofstream(dir / "my-case.yaml") << text;
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
  const Ran r = rayspec("prove my-case.yaml", dir.string());
  fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("my-case (my-case.yaml)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("R-INACTIVE: proved by inactive-revived"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("NOT PROVED ON THE MODEL: R-MASK: hollow"), std::string::npos) << r.out;
  // R-AS-BUILD's fault on the model builds nothing here; those of a live
  // device are named with the command that plants them.
  EXPECT_NE(r.out.find("NOT PROVED ON THE MODEL: R-AS-BUILD: hollow"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("faults a live device alone shows: stride-ignored, offsets-ignored, "
                       "pointers-reversed, sparse-page-lost (rayspec run --case my-case.yaml "
                       "--plant-fault NAME"),
            std::string::npos)
      << r.out;
  for (const char* tried : {"break instance-mask-ignored: ", "break inactive-hides-last-active: ",
                            "break shared-scratch-keeps-previous: "})
    EXPECT_NE(r.out.find(tried), std::string::npos) << tried << " in\n" << r.out;
  EXPECT_NE(
      r.out.find("4 claims: 2 proved, 0 not checked (R-UB), 2 not proved; 1 cases not proven"),
      std::string::npos)
      << r.out;
  size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.exists();
  EXPECT_EQ(files, 1u) << "prove wrote nothing beside the case";
}

// lavapipe's manifest where Mesa installs it (lvp_icd.json or lvp_icd.x86_64.json).
std::string lavapipeManifest() {
  for (const char* dir :
       {"/usr/share/vulkan/icd.d", "/usr/local/share/vulkan/icd.d", "/etc/vulkan/icd.d"}) {
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
      if (e.path().filename().string().rfind("lvp_icd", 0) == 0) return e.path().string();
  }
  return {};
}

// R-AS-BUILD claimed by a case of strided vertices: the model has no fault
// for it here (one build), a live device misreading the stride fails it. With
// --icd the claim is proved on lavapipe by the planted stride-ignored.
TEST(Prove, AClaimOnlyALiveDeviceBreaksIsProvedThere) {
  const std::string icd = lavapipeManifest();
  if (icd.empty()) GTEST_SKIP() << "no lavapipe manifest";
  const fs::path file = fs::path(RAYSPEC_TEST_OUT) / "prove-live" / "layout-claim.yaml";
  fs::create_directories(file.parent_path());
  std::string text = slurp(RAYSPEC_SOURCE_DIR "/cases/accel/layouts-triangles.yaml");
  text.replace(text.find("rules: [R-BUILTIN, R-INST-XFORM]"), 32, "rules: [R-BUILTIN, R-AS-BUILD]");
  std::ofstream(file) << text;
  const Ran model = rayspec("prove " + file.string());
  EXPECT_EQ(model.status, 1) << model.out << model.err;
  EXPECT_NE(model.out.find("NOT PROVED ON THE MODEL: R-AS-BUILD: hollow"), std::string::npos)
      << model.out;
  const Ran live = rayspec("prove " + file.string() + " --icd " + icd);
  EXPECT_EQ(live.status, 0) << live.out << live.err;
  EXPECT_NE(live.out.find("Live device: "), std::string::npos) << live.out;
  EXPECT_NE(live.out.find("    on the device: stride-ignored: Fail: R-BUILTIN: "),
            std::string::npos)
      << live.out;
  EXPECT_NE(live.out.find("  R-AS-BUILD: proved on the device by stride-ignored"),
            std::string::npos)
      << live.out;
}

TEST(Prove, AMissingOrBadCaseIsExit2NamingIt) {
  const Ran missing = rayspec("prove cases/nope.yaml");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("no such case file: 'cases/nope.yaml'"), std::string::npos)
      << missing.err;
  const fs::path bad = fs::path(RAYSPEC_TEST_OUT) / "prove-bad-rule.yaml";
  std::string text = slurp(kCase);
  text.replace(text.find("R-BUILTIN]"), 10, "R-NOPE]");
  std::ofstream(bad) << text;
  const Ran r = rayspec("prove " + bad.string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.err.find(bad.string() + ":1:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("R-NOPE"), std::string::npos) << r.err;
}

TEST(Faults, EveryFaultWithItsRulesAndWhatItBreaks) {
  const Ran r = rayspec("faults");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("drop-miss  breaks R-MISS-XOR-CHIT\n    a clear ray that missed"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("reverse-order  allowed by R-ORDER-UNSPEC, R-TOFH"), std::string::npos);
  EXPECT_NE(r.out.find("stride-ignored  breaks R-AS-BUILD (a live device only)"),
            std::string::npos);
  EXPECT_NE(r.out.find("crash  no rule"), std::string::npos);
}

TEST(Faults, ARuleWithItsTextSectionAndFaults) {
  const Ran r = rayspec("faults --rule R-MASK");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("R-MASK: instance mask", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("An instance is skipped when"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Specification: Vulkan, Ray Traversal"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  instance-mask-ignored\n      instance masks are ignored"),
            std::string::npos)
      << r.out;
  const Ran unknown = rayspec("faults --rule R-NOPE");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("unknown rule 'R-NOPE'"), std::string::npos) << unknown.err;
}

// --plant-fault's help sends the reader to `rayspec faults` instead of
// listing every name; a bad name still lists them.
TEST(Faults, PlantFaultHelpPointsAtTheListing) {
  for (const char* command : {"run", "reduce", "fuzz"}) {
    const Ran help = rayspec(std::string(command) + " --help");
    EXPECT_NE(help.out.find("`rayspec faults` lists every fault"), std::string::npos) << command;
    EXPECT_EQ(help.out.find("inactive-hides-last-active"), std::string::npos) << command;
  }
  const Ran bad = rayspec("run --no-device --case " + kCase + " --plant-fault nope --out " +
                          std::string(RAYSPEC_TEST_OUT) + "/prove-bad-fault");
  EXPECT_EQ(bad.status, 2) << bad.out;
  EXPECT_NE((bad.out + bad.err).find("unknown fault 'nope' (one of drop-miss, "), std::string::npos)
      << bad.out << bad.err;
}

}  // namespace
