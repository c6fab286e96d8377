// `rayspec run`: its options, grouped by what they decide.
#include <memory>
#include <string>

#include "cli/check_command.h"
#include "cli/commands.h"
#include "cli/device_options.h"
#include "cli/option_checks.h"
#include "cli/subcommands.h"
#include "metamorphic/feature_path.h"
#include "metamorphic/motion_spec.h"
#include "run/fault_seam.h"
#include "run/run_loop.h"
#include "vulkan/device_errors.h"

namespace rayspec {
namespace {

std::vector<std::string> modelTierNames() {
  std::vector<std::string> names;
  for (const EnumName<ModelTier>& row : enumNames<ModelTier>()) names.push_back(row.name);
  return names;
}

// Which cases run, on which device, into which folder, judged against what.
void addSelectionOptions(CLI::App* run, RunOptions& run_opt) {
  addDeviceChoice(run, run_opt);
  // One glob is RunOptions::filter; several are RunOptions::filters.
  run->add_option_function<std::vector<std::string>>(
      "--filter",
      [&run_opt](const std::vector<std::string>& globs) {
        if (globs.size() == 1)
          run_opt.filter = globs.front();
        else
          run_opt.filters = globs;
      },
      "Run only cases whose name matches this glob (e.g. 'anyhit/*'); given again, cases that "
      "match any of them");
  run->add_option("--out", run_opt.out, "Folder for results bundles and reports")
      ->check(outputFolder())
      ->capture_default_str();
  run->add_option("--cases", run_opt.cases_dir, "Folder of case files")->capture_default_str();
  run->add_option("--case", run_opt.case_files, "Run these case files (instead of --cases)");
  run->add_option("--model", run_opt.model_tier, "Model precision tier: fast, robust or exact")
      ->check(CLI::IsMember(modelTierNames()))
      ->capture_default_str();
  run->add_option(
      "--baseline", run_opt.baseline,
      "Expected results of this driver (case,Status lines; unlisted: Pass). The run fails on "
      "anything unexpected (an unexpected failure is re-run once to tell a flake; an unexpected "
      "pass fails until the baseline is updated) and writes failures.csv");
  run->add_option(
      "--flakes", run_opt.flakes,
      "Regular expressions of cases known to flake (default: <baseline>-flakes.txt beside it)");
  run->add_option(
      "--skips", run_opt.skips,
      "Regular expressions of cases not to run (default: <baseline>-skips.txt beside it)");
  run->add_option("--shard", run_opt.shard,
                  "Run shard I of N (I/N, from 1): every N-th case from the I-th; without it, "
                  "GTEST_TOTAL_SHARDS and GTEST_SHARD_INDEX are honoured");
  run->add_flag(
      "--resume", run_opt.resume,
      "Keep the cases the --out folder already holds (a run that was killed) and run the rest");
  run->add_option("--rules", run_opt.rules_file, "Rule catalog (references/spec-rules.yaml)")
      ->capture_default_str();
}

// Which sides run, with which checks, and what every bundle holds.
void addSideOptions(CLI::App* run, RunOptions& run_opt) {
  run->add_flag("--no-model", run_opt.no_model, "Run the device only");
  run->add_flag("--no-device", run_opt.no_device, "Run the model only");
  addValidationOptions(run, run_opt);
  run->add_option("--threads", run_opt.threads, "Model threads (0: all cores)")
      ->check(wholeCount())
      ->capture_default_str();
  run->add_flag("--brief", run_opt.brief, kBriefHelp);
  run->add_flag("--records-csv", run_opt.records_csv,
                "records.csv (the per-ray records as text) in every bundle; without it only where "
                "the case did not pass");
  run->add_option("--cache-dir", run_opt.cache_dir,
                  "Folder for the SPIR-V of generated stages, reused by every case process and "
                  "later runs ('': none)")
      ->capture_default_str();
}

// How the sides are isolated: workers, their limits, devices per case.
void addIsolationOptions(CLI::App* run, RunOptions& run_opt) {
  run->add_option(
         "--timeout", run_opt.timeout,
         "Seconds a case's model side, and then its device side, may run before it is a Timeout")
      ->check(positiveSeconds())
      ->capture_default_str();
  run->add_option("--memory-limit", run_opt.memory_limit,
                  "Memory each worker process may hold (e.g. 8G, 512M; 0: no limit): its private "
                  "data (RLIMIT_DATA) and its resident set, shared mappings included (watched "
                  "every 50 ms); beyond it the case that was running is a Crash")
      ->transform(memoryLimit())
      ->default_str(std::to_string(kDefaultMemoryLimit >> 30) + "G");
  run->add_option(
         "-j,--jobs", run_opt.jobs,
         "Cases at once (0: one per core, at most 16; 4 on a GPU); each side of a case runs in a "
         "long-lived worker process, a new one after a crash, timeout or memory-limit hit")
      ->check(wholeCount())
      ->capture_default_str();
  run->add_option("--device-per-case", run_opt.device_per_case,
                  "A VkDevice of its own for each case in a worker (auto: on lavapipe, whose "
                  "pipelines would otherwise miss the shader cache)")
      ->check(CLI::IsMember({"auto", "yes", "no"}))
      ->capture_default_str();
  CLI::Option* per_case =
      run->add_flag("--process-per-case", run_opt.process_per_case,
                    "Each side of each case in a process of its own instead of long-lived workers "
                    "(slower; a new VkInstance and VkDevice per case)");
  CLI::Option* per_case_for = run->add_option(
      "--process-per-case-for", run_opt.process_per_case_for,
      "Only the cases whose name matches one of these globs each in a process of its "
      "own, the others in workers (a driver that leaves state behind that these "
      "cases trip over)");
  // Processes of their own and no processes at all cannot both hold.
  run->add_flag("--no-isolation", run_opt.no_isolation,
                "Run the model and the device in this process (one VkDevice for every case; no "
                "timeout, no memory limit, a crash ends the run)")
      ->excludes(per_case)
      ->excludes(per_case_for);
}

// Runs that change what is run: saved device results, permuted and moved
// scenes, and (tests only) planted faults.
// Options whose text becomes a value once parsing is done.
struct VariantTexts {
  std::string move_spec, through_name;
};

void addVariantOptions(CLI::App* run, RunOptions& run_opt, VariantTexts& texts) {
  std::string& move_spec = texts.move_spec;
  std::string& through_name = texts.through_name;
  run->add_option("--device-results", run_opt.device_results,
                  "Run no device: judge the device bundles a run saved in this folder "
                  "(DIR/<case>/device, e.g. from a run-only build) against the model run here");
  run->add_option("--permute", run_opt.permute,
                  "Permute each case's primitives and instances from this seed (R-ORDER-UNSPEC: "
                  "verdicts must not move; the same seed gives the same permutation)")
      ->check(decimalSeed());
  run->add_option("--move", move_spec,
                  "Move each case by an exact rigid motion: three signed axes and an optional "
                  "translation, e.g. -y,x,z or z,x,y,1024,-2048,0 (verdicts must not move; a case "
                  "it cannot move exactly is NotSupported)")
      ->check(
          [](const std::string& spec) {
            const Result<RigidMotion> motion = parseMotionSpec(spec);
            return motion ? std::string() : motion.error().message;
          },
          "MOTION");
  run->add_option("--through", through_name,
                  "Send every case through a feature path that must not change what shaders "
                  "observe (" +
                      featurePathNames() +
                      "; a case that takes its own way there is NotSupported, as is one the device "
                      "cannot take)")
      ->check(featurePath());
  run->add_option("--plant-fault", run_opt.plant_fault, kPlantFaultHelp);
  run->add_option("--plant-fault-in", run_opt.plant_fault_in,
                  "Test only: plant the fault only in cases matching this glob")
      ->capture_default_str();
}

}  // namespace

Subcommand addRunCommand(CLI::App& app) {
  auto* run = app.add_subcommand("run", "Run cases on a device and on the model");
  auto opt = std::make_shared<RunOptions>();
  auto texts = std::make_shared<VariantTexts>();
  addSelectionOptions(run, *opt);
  addSideOptions(run, *opt);
  addIsolationOptions(run, *opt);
  addVariantOptions(run, *opt, *texts);
  addCheckCaseOptions(run, *opt);
  return {run, [opt, texts] {
            if (!texts->move_spec.empty())  // checked while parsing
              if (Result<RigidMotion> motion = parseMotionSpec(texts->move_spec))
                opt->move = *motion;
            if (!texts->through_name.empty())
              opt->through = featurePathFromName(texts->through_name);
            return runCases(*opt, portabilityCheckFor(*opt));
          }};
}

}  // namespace rayspec
