// `rayspec fuzz`: its own options, and those of `rayspec run` that choose
// the device and how each case runs.
#include <memory>
#include <string>

#include "cli/check_command.h"
#include "cli/commands.h"
#include "cli/device_options.h"
#include "cli/option_checks.h"
#include "cli/subcommands.h"
#include "fuzz/fuzz_run.h"
#include "metamorphic/feature_path.h"
#include "run/fault_seam.h"
#include "run/run_loop.h"

namespace rayspec {
namespace {

void addDeviceOptions(CLI::App* fuzz, RunOptions& run) {
  addDeviceChoice(fuzz, run);
  fuzz->add_option("--model", run.model_tier, "Model precision tier")->capture_default_str();
  fuzz->add_option("--rules", run.rules_file, "Rule catalog")->capture_default_str();
  fuzz->add_option("--timeout", run.timeout, "Seconds per case side")
      ->check(positiveSeconds())
      ->capture_default_str();
  fuzz->add_option("--jobs", run.jobs, "Cases at once (0: one per core)")->capture_default_str();
  addValidationOptions(fuzz, run);
  fuzz->add_option("--plant-fault", run.plant_fault, kPlantFaultHelp);
}

}  // namespace

Subcommand addFuzzCommand(CLI::App& app) {
  auto* fuzz = app.add_subcommand(
      "fuzz",
      "Generate random cases from consecutive seeds (OUT/cases/fuzz/seed-<seed>.yaml), run and "
      "judge each as `rayspec run` does, keep every finding as OUT/findings/<signature>/ and "
      "list them in OUT/fuzz.txt. Exit 0 nothing found, 1 findings, 2 bad input");
  auto opt = std::make_shared<FuzzOptions>();
  auto through = std::make_shared<std::string>();
  auto without = std::make_shared<std::vector<std::string>>();
  FuzzOptions& o = *opt;
  fuzz->add_option("--seed", o.seed, "The first seed")->check(decimalSeed())->capture_default_str();
  auto* cases = fuzz->add_option("--cases", o.cases, "Cases to generate")->check(wholeCount());
  auto* minutes = fuzz->add_option("--minutes", o.minutes,
                                   "Generate batches until this many minutes have passed")
                      ->check(CLI::PositiveNumber)
                      ->excludes(cases);
  fuzz->add_option("--batch", o.batch, "Cases a run of the run loop (its workers live that long)")
      ->check(wholeCount())
      ->capture_default_str();
  fuzz->add_option("--out", o.out, "Folder for cases, runs, findings and fuzz.txt")
      ->check(outputFolder())
      ->capture_default_str();
  fuzz->add_option("--through", *through,
                   "Send every case through a feature path (" + featurePathNames() + ")")
      ->check(featurePath());
  fuzz->add_option("--reduce", o.reduce,
                   "Reduce each new signature's first case with `rayspec reduce`, trying at most "
                   "this many variants (0: no reduction)")
      ->check(wholeCount())
      ->capture_default_str();
  fuzz->add_option("--known", o.known,
                   "Known driver bug classes (lines `FEATURE REASON`): a finding whose case holds "
                   "one's feature is counted apart and does not fail the run")
      ->check(CLI::ExistingFile);
  fuzz->add_option("--without", *without,
                   "Leave a device feature out of the generated cases, for a device that lacks it "
                   "(as `rayspec devices` names it: " +
                       leavableFeatureNames() + "); a seed then makes another case")
      ->check(leavableFeature());
  auto* generate_only = fuzz->add_flag(
      "--generate-only", o.generate_only,
      "Write the cases of --cases seeds under OUT/cases and stop: for a device elsewhere "
      "(tools/pack-device.sh with PACK_CASES=OUT/cases), judged here by --device-results");
  generate_only->excludes(minutes);
  auto* device_results =
      fuzz->add_option("--device-results", o.run.device_results,
                       "Judge the device bundles a `rayspec run` of the same seeds' cases saved "
                       "in this folder (elsewhere, as run --device-results) instead of running a "
                       "device; with --saved-cases")
          ->check(CLI::ExistingDirectory)
          ->excludes(generate_only);
  auto* saved = fuzz->add_option("--saved-cases", o.saved_cases,
                                 "The cases folder that device run ran (--generate-only's "
                                 "OUT/cases, as packed): its texts are judged, never the cases "
                                 "this build's generator makes from the seeds")
                    ->check(CLI::ExistingDirectory)
                    ->needs(device_results);
  device_results->needs(saved);
  fuzz->add_flag("--fault-matrix", o.fault_matrix,
                 "Plant every rule-breaking fault in each passing case's device results until a "
                 "case finds it: OUT/fault-matrix.txt (fault, rules, found, first case)")
      ->excludes(generate_only);
  addDeviceOptions(fuzz, o.run);
  addCheckCaseOptions(fuzz, o.run);  // generated cases lie outside the library: checked by default
  return {fuzz, [opt, through, without] {
            if (!through->empty()) opt->run.through = featurePathFromName(*through);
            for (const std::string& name : *without)
              if (!leaveOut(opt->allowed, name)) return kExitSetup;  // checked as parsed
            if (!opt->cases && opt->minutes <= 0) opt->cases = 100;
            opt->check = portabilityCheckFor(opt->run);
            return runFuzz(*opt);
          }};
}

}  // namespace rayspec
