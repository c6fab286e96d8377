// The subcommands that make studies of runs: stability, accuracy, mutate.
#include <memory>
#include <string>
#include <vector>

#include "accuracy/run_accuracy.h"
#include "cli/device_options.h"
#include "cli/option_checks.h"
#include "cli/subcommands.h"
#include "mutate/mutate_run.h"
#include "stability/run_stability.h"

namespace rayspec {

namespace {

// The options a study shares with `rayspec run`'s device side, and its own
// report folder. `counted`: what happens to other devices' saved bundles.
void addStudyOptions(CLI::App* study, RunOptions& run, std::vector<std::string>& saved_devices,
                     std::string& out, const std::string& counted) {
  addDeviceChoice(study, run);
  study->add_flag("--no-device", run.no_device, "The model tiers only");
  study->add_option("--device-results", saved_devices,
                    "Run folders of other devices (e.g. a run-only binary's run on a GPU "
                    "machine): their device bundles are " +
                        counted + " too, one source each");
  study->add_option("--cases", run.cases_dir, "Folder of case files")->capture_default_str();
  study->add_option("--out", out, "Folder for the report and the runs")
      ->check(outputFolder())
      ->capture_default_str();
  study->add_option("--timeout", run.timeout, "Seconds per case side")
      ->check(positiveSeconds())
      ->capture_default_str();
  addValidationOptions(study, run);
}

}  // namespace

Subcommand addStabilityCommand(CLI::App& app) {
  auto* stability = app.add_subcommand(
      "stability",
      "Leak and double-hit rates of the stability families per coordinate magnitude: the device "
      "and each model tier (OUT/stability.txt, stability.json, stability.png)");
  auto opt = std::make_shared<StabilityOptions>();
  opt->run.filter = "stability/*";
  addStudyOptions(stability, opt->run, opt->saved_devices, opt->out, "counted");
  stability->add_option("--filter", opt->run.filter, "Cases (glob)")->capture_default_str();
  stability->add_option("--baseline", opt->run.baseline, "Known failures of this driver");
  return {stability, [opt] {
            return runStability(*opt);
          }};
}

Subcommand addAccuracyCommand(CLI::App& app) {
  auto* accuracy = app.add_subcommand(
      "accuracy",
      "Trace time per million rays and per-ray disagreements with the model's exact tier (leaks, "
      "double hits, other primitives, t error in ULP), each model tier and device, on ordinary and "
      "hard cases (OUT/accuracy.txt, accuracy.json, accuracy.png)");
  auto opt = std::make_shared<AccuracyOptions>();
  accuracy->add_option("--ordinary", opt->ordinary, "Ordinary cases (glob; repeat it for more)")
      ->capture_default_str();
  accuracy->add_option("--hard", opt->hard, "Hard cases (glob; repeat it for more)")
      ->capture_default_str();
  addStudyOptions(accuracy, opt->run, opt->saved_devices, opt->out, "compared");
  return {accuracy, [opt] {
            return runAccuracy(*opt);
          }};
}

Subcommand addMutateCommand(CLI::App& app) {
  auto* mutate = app.add_subcommand(
      "mutate",
      "Judge generic wrong devices made from a saved device run (null device, fields perturbed, "
      "counters moved, rays swapped, ...): the kill matrix and every survivor with the reason it "
      "may legally survive (OUT/mutate.txt, mutate.json); fails on a survivor with no reason");
  auto opt = std::make_shared<MutateOptions>();
  MutateOptions& mutate_opt = *opt;
  mutate_opt.cases_dir = RAYSPEC_SOURCE_DIR "/cases";
  mutate->add_option("RUN_DIR", mutate_opt.run_dir, "Run folder with <case>/device bundles")
      ->required();
  mutate->add_option("--out", mutate_opt.out, "Folder for mutate.txt and mutate.json")
      ->check(outputFolder())
      ->capture_default_str();
  mutate->add_option("--cases", mutate_opt.cases_dir, "Folder of case files")
      ->capture_default_str();
  mutate->add_option("--filter", mutate_opt.filter, "Cases (glob)")->capture_default_str();
  mutate->add_option("--threads", mutate_opt.threads, "Model threads (0: all cores)")
      ->check(wholeCount())
      ->capture_default_str();

  return {mutate, [opt] {
            return runMutate(*opt);
          }};
}

}  // namespace rayspec
