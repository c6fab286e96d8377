// Device selection by driver manifest as a program: `rayspec devices` lists
// each manifest's devices, usable or not and why; `run --icd FILE` loads only
// that driver, names it in the Device line and summary.json, and a manifest
// that is missing or whose driver cannot load is a setup error (exit 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"
#include "vulkan/device_info_fields.h"

namespace {
namespace fs = std::filesystem;
using cli::caseArg;
using cli::fresh;
using cli::kBin;
using cli::sh;
using cli::slurp;

const std::string kOneCase = "results/miss-xor-closest-hit";

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

// A manifest whose driver library does not exist.
std::string brokenManifest(const std::string& dir) {
  const std::string path = dir + "/broken_icd.json";
  std::ofstream(path)
      << R"({"file_format_version": "1.0.0", "ICD": {"library_path": "./libnosuch_vulkan.so", "api_version": "1.3.0"}})";
  return path;
}

// What `rayspec devices` printed of one manifest: from its "ICD" line to the
// next; "" when it printed none.
std::string manifestBlock(const std::string& log, const std::string& manifest) {
  const size_t at = log.find("ICD " + manifest + " ");
  if (at == std::string::npos) return {};
  return log.substr(at, log.find("\nICD ", at + 1) - at);
}

TEST(Icd, DevicesListsLavapipeUsableWithItsManifest) {
  const std::string lvp = lavapipeManifest();
  ASSERT_FALSE(lvp.empty()) << "lavapipe is not installed";
  const std::string out = fresh("icd-devices");
  EXPECT_EQ(sh(kBin + " devices", out + "/log"), 0);
  const std::string log = slurp(out + "/log");
  const std::string block = manifestBlock(log, lvp);
  ASSERT_FALSE(block.empty()) << log;
  EXPECT_NE(block.find("llvmpipe"), std::string::npos) << block;
  EXPECT_NE(block.find(": USABLE"), std::string::npos) << block;
  EXPECT_NE(block.find("select: --icd " + lvp + " --device 'llvmpipe"), std::string::npos) << block;
  EXPECT_NE(block.find("maxRayRecursionDepth"), std::string::npos) << block;
  EXPECT_NE(log.find("usable device"), std::string::npos) << log;
}

// Issue 61: each device's identity (conformance version, driver ID, UUIDs),
// the validation layer, and the library cases a usable one cannot run with
// the missing feature that keeps them; an old layer's skips (Debian 12's
// 1.3.239 predates position fetch) are gone with --no-validation.
TEST(Icd, DevicesNamesIdentityLayerAndTheCasesEachMissingFeatureSkips) {
  const std::string lvp = lavapipeManifest();
  ASSERT_FALSE(lvp.empty()) << "lavapipe is not installed";
  const std::string out = fresh("icd-devices-identity");
  EXPECT_EQ(sh(kBin + " devices --icd " + lvp, out + "/log"), 0);
  const std::string log = slurp(out + "/log");
  const std::string block = manifestBlock(log, lvp);
  for (const char* line : {"\n        conformance version 1.", ", driver ID MesaLlvmpipe (13)\n",
                           "\n        device UUID ", ", driver UUID ",
                           "\n        pipeline cache UUID ", " cases NotSupported here\n"})
    EXPECT_NE(block.find(line), std::string::npos) << line << "\n" << block;
  EXPECT_TRUE(std::regex_search(block, std::regex("\n        library: [0-9]+ of [0-9]+ cases "
                                                  "NotSupported here\n")))
      << block;
  EXPECT_TRUE(std::regex_search(log, std::regex("\nValidation layer: (not installed|"
                                                "VK_LAYER_KHRONOS_validation [0-9.]+ \\(on)")))
      << log;
  const bool old_layer = log.find("VK_LAYER_KHRONOS_validation 1.3.239 (on") != std::string::npos;
  EXPECT_EQ(block.find(" cases under the validation layer 1.3.239 (older than an extension they "
                       "use; --no-validation runs them)") != std::string::npos,
            old_layer)
      << block;
  EXPECT_EQ(sh(kBin + " devices --no-validation --icd " + lvp, out + "/off"), 0);
  const std::string off = slurp(out + "/off");
  EXPECT_EQ(off.find("under the validation layer"), std::string::npos) << off;
  if (old_layer) {
    EXPECT_NE(off.find("1.3.239 (off: --no-validation)"), std::string::npos) << off;
  }
}

// Every labelled row of vulkan/device_info_fields.h is a line of a usable
// device's limits, scalarBlockLayout among them (lavapipe has it).
TEST(Icd, DevicesPrintsEveryLimitOfTheFieldList) {
  const std::string lvp = lavapipeManifest();
  ASSERT_FALSE(lvp.empty()) << "lavapipe is not installed";
  const std::string out = fresh("icd-devices-limits");
  EXPECT_EQ(sh(kBin + " devices --icd " + lvp, out + "/log"), 0);
  const std::string block = manifestBlock(slurp(out + "/log"), lvp);
  ASSERT_NE(block.find(": USABLE"), std::string::npos) << block;
  std::vector<std::string> labels;
#define RAYSPEC_DEVICE_INFO_LABEL(type, member, key, label, ...) \
  if (const char* l = label) labels.push_back(l);
  RAYSPEC_DEVICE_INFO_FIELDS(RAYSPEC_DEVICE_INFO_LABEL)
#undef RAYSPEC_DEVICE_INFO_LABEL
  for (const std::string& label : labels)
    EXPECT_NE(block.find("\n        " + label + " "), std::string::npos) << label << "\n" << block;
  EXPECT_TRUE(std::regex_search(block, std::regex("\n        scalarBlockLayout +yes\n"))) << block;
}

// The required limits against lavapipe's baseline of known violations: each
// listed violation is expected; without the baseline they fail the command,
// and a baseline that lists a limit the driver meets is out of date.
TEST(Icd, CheckLimitsJudgesEachRequiredLimitAgainstTheBaseline) {
  const std::string lvp = lavapipeManifest();
  ASSERT_FALSE(lvp.empty()) << "lavapipe is not installed";
  const std::string out = fresh("icd-check-limits");
  const std::string baseline =
      std::string(RAYSPEC_SOURCE_DIR) + "/references/baselines/lavapipe-limits.csv";
  EXPECT_EQ(
      sh(kBin + " devices --check-limits --icd " + lvp + " --baseline " + baseline, out + "/with"),
      0)
      << slurp(out + "/with");
  const std::string with = slurp(out + "/with");
  EXPECT_NE(with.find("Fail         limits/maxPrimitiveCount: "), std::string::npos) << with;
  EXPECT_NE(with.find("Pass         limits/shaderGroupHandleSize: 32, exactly 32"),
            std::string::npos)
      << with;
  EXPECT_NE(with.find("0 unexpected), 0 unexpected passes."), std::string::npos) << with;

  EXPECT_EQ(with.find("Known violations"), std::string::npos) << with;

  // Without it the two are unexpected, and the message names the kept
  // baseline that lists them and how to pass it (issue 61).
  EXPECT_EQ(sh(kBin + " devices --check-limits --icd " + lvp, out + "/without"), 1);
  const std::string without = slurp(out + "/without");
  EXPECT_NE(without.find("(UNEXPECTED)"), std::string::npos);
  EXPECT_NE(without.find("Known violations: " + baseline + " lists them all as this driver's"),
            std::string::npos)
      << without;
  EXPECT_NE(without.find("\n  rayspec devices --check-limits --baseline " + baseline + "\n"),
            std::string::npos)
      << without;

  std::ofstream(out + "/stale.csv") << "limits/shaderGroupHandleSize,Fail\n";
  EXPECT_EQ(sh(kBin + " devices --check-limits --icd " + lvp + " --baseline " + out + "/stale.csv",
               out + "/stale"),
            1);
  const std::string stale = slurp(out + "/stale");
  EXPECT_NE(stale.find("the baseline expects Fail: update it"), std::string::npos);
  EXPECT_NE(stale.find("Known violations: " + baseline + " lists them all"), std::string::npos)
      << stale;
}

// Issue 56: a limits baseline entry that could never apply (a case, a limit
// the table does not have, a status other than Fail) and a malformed line
// are refused: exit 2, naming the file and line, before any driver is probed.
TEST(Icd, ALimitsBaselineEntryThatNeverAppliesIsExit2AtItsLine) {
  const std::string lvp = lavapipeManifest();
  ASSERT_FALSE(lvp.empty()) << "lavapipe is not installed";
  const std::string out = fresh("icd-limits-baseline");
  const std::string known = "# known\nlimits/maxPrimitiveCount,Fail\n";
  struct Bad {
    std::string file, text, error;
  };
  const std::vector<Bad> bad = {
      {"case.csv", known + "anyhit/ignore-odd-primitives,Fail\n",
       ":3: anyhit/ignore-odd-primitives names no required limit"},
      {"misspelt.csv", known + "limits/maxPrimitveCount,Fail\n",
       ":3: limits/maxPrimitveCount names no required limit"},
      {"lower-case.csv", "limits/maxprimitivecount,Fail\n",
       ":1: limits/maxprimitivecount names no required limit"},
      {"crash.csv", "limits/maxRayDispatchInvocationCount,Crash # why\n" + known,
       ":1: limits/maxRayDispatchInvocationCount,Crash: a limits baseline lists known "
       "violations only, each as Fail"},
      {"pass.csv", known + "limits/shaderGroupHandleSize,Pass\n",
       ":3: limits/shaderGroupHandleSize,Pass: a limits baseline"},
      {"malformed.csv", known + "limits/maxGeometryCount\n", ":3: expected 'case,Status'"},
  };
  for (const Bad& b : bad) {
    const std::string path = out + "/" + b.file;
    std::ofstream(path) << b.text;
    const std::string log = out + "/" + b.file + ".txt";
    EXPECT_EQ(sh(kBin + " devices --check-limits --icd " + lvp + " --baseline " + path, log), 2)
        << b.file << "\n"
        << slurp(log);
    EXPECT_NE(slurp(log).find(path + b.error), std::string::npos) << b.file << "\n" << slurp(log);
    EXPECT_EQ(slurp(log).find("ICD "), std::string::npos) << b.file << ": probed nonetheless";
  }
}

TEST(Icd, RunOnLavapipeByItsManifest) {
  const std::string lvp = lavapipeManifest();
  ASSERT_FALSE(lvp.empty());
  const std::string out = fresh("icd-run");
  // The user's own variable points at a driver that cannot load: --icd wins and says so.
  const int rc = sh("VK_DRIVER_FILES=" + brokenManifest(out) + " " + kBin + " run --icd " + lvp +
                        " --device llvmpipe --strict-validation" + caseArg(kOneCase) + " --out " +
                        out + "/run",
                    out + "/log");
  const std::string log = slurp(out + "/log");
  EXPECT_EQ(rc, 0) << log;
  EXPECT_NE(log.find("--icd overrides VK_DRIVER_FILES="), std::string::npos) << log;
  EXPECT_NE(log.find("Device: llvmpipe"), std::string::npos) << log;
  EXPECT_NE(log.find(", ICD " + lvp + ","), std::string::npos) << log;
  const nlohmann::json summary = nlohmann::json::parse(slurp(out + "/run/summary.json"));
  EXPECT_EQ(summary["icd"], lvp);
  EXPECT_EQ(summary["counts"]["Pass"], 1) << summary.dump();
  EXPECT_NE(slurp(out + "/run/report.html").find("(ICD " + lvp + ")"), std::string::npos);
}

// Without --icd the Device line still names the manifest (found, not given).
TEST(Icd, RunNamesTheManifestItFound) {
  const std::string lvp = lavapipeManifest();
  const std::string out = fresh("icd-found");
  for (const char* isolation : {"", " --no-isolation"}) {
    EXPECT_EQ(sh(kBin + " run --no-validation --no-model" + isolation + caseArg(kOneCase) +
                     " --out " + out + "/run",
                 out + "/log"),
              77);  // the device alone, one case: nothing compared (ctest's skip)
    const std::string log = slurp(out + "/log");
    EXPECT_NE(log.find(", ICD " + lvp + ","), std::string::npos) << isolation << "\n" << log;
  }
}

TEST(Icd, MissingManifestIsASetupError) {
  const std::string out = fresh("icd-missing");
  for (const std::string& command :
       {" run" + caseArg(kOneCase) + " --out " + out + "/run", std::string(" devices")}) {
    EXPECT_EQ(sh(kBin + command + " --icd /nonexistent.json", out + "/log"), 2) << command;
    const std::string log = slurp(out + "/log");
    EXPECT_NE(log.find("ICD manifest /nonexistent.json: no such file"), std::string::npos) << log;
  }
  EXPECT_FALSE(fs::exists(out + "/run/summary.json")) << "nothing ran";
}

TEST(Icd, DriverThatCannotLoad) {
  const std::string out = fresh("icd-broken");
  const std::string broken = brokenManifest(out);
  for (const char* isolation : {"", " --no-isolation"}) {
    EXPECT_EQ(
        sh(kBin + " run --icd " + broken + isolation + caseArg(kOneCase) + " --out " + out + "/run",
           out + "/log"),
        2);
    const std::string log = slurp(out + "/log");
    EXPECT_NE(log.find("no device to run on"), std::string::npos) << log;
    EXPECT_NE(log.find("ICD " + broken + ": the driver library " + out +
                       "/libnosuch_vulkan.so could not be loaded"),
              std::string::npos)
        << log;
  }
  EXPECT_EQ(sh(kBin + " devices --icd " + broken, out + "/log"), 1);
  const std::string log = slurp(out + "/log");
  EXPECT_NE(log.find("ICD " + broken + " (library ./libnosuch_vulkan.so"), std::string::npos)
      << log;
  EXPECT_NE(log.find("NOT USABLE: the driver library " + out +
                     "/libnosuch_vulkan.so could not be loaded"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("No usable device"), std::string::npos) << log;
}

// Two manifests, ':'-separated: the usable one is listed, the broken one says why.
TEST(Icd, SeveralManifests) {
  const std::string lvp = lavapipeManifest();
  const std::string out = fresh("icd-several");
  const std::string broken = brokenManifest(out);
  EXPECT_EQ(sh(kBin + " devices --icd " + lvp + ":" + broken, out + "/log"), 0);
  const std::string log = slurp(out + "/log");
  EXPECT_NE(log.find(": USABLE"), std::string::npos) << log;
  EXPECT_NE(log.find("NOT USABLE: the driver library"), std::string::npos) << log;
  EXPECT_NE(log.find("1 usable device through 2 driver manifests"), std::string::npos) << log;
}

TEST(Icd, NoSuchDeviceNamesTheDevicesThere) {
  const std::string out = fresh("icd-nosuch");
  EXPECT_EQ(sh(kBin + " run --no-validation --icd " + lavapipeManifest() + " --device nosuch" +
                   caseArg(kOneCase) + " --out " + out + "/run",
               out + "/log"),
            2);
  const std::string log = slurp(out + "/log");
  EXPECT_NE(log.find("'nosuch'"), std::string::npos) << log;
  EXPECT_NE(log.find("[0] llvmpipe"), std::string::npos) << log;
}

}  // namespace
