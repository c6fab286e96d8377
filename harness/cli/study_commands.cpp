// The subcommands that make studies of runs: stability, accuracy, mutate.
#include <memory>

#include "accuracy/run_accuracy.h"
#include "cli/option_checks.h"
#include "cli/subcommands.h"
#include "mutate/mutate_run.h"
#include "stability/run_stability.h"

namespace rayspec {

Subcommand addStabilityCommand(CLI::App& app) {
  auto* stability = app.add_subcommand(
      "stability",
      "Leak and double-hit rates of the stability families per coordinate magnitude: the device "
      "and each model tier (OUT/stability.txt, stability.json, stability.png)");
  auto opt = std::make_shared<StabilityOptions>();
  StabilityOptions& stability_opt = *opt;
  stability_opt.run.filter = "stability/*";
  stability->add_option("--device", stability_opt.run.device, "Vulkan device name (substring)");
  stability->add_flag("--no-device", stability_opt.run.no_device, "The model tiers only");
  stability->add_option("--device-results", stability_opt.saved_devices,
                        "Run folders of other devices (e.g. a run-only binary's run on a GPU "
                        "machine): their device bundles are counted too, one source each");
  stability->add_option("--filter", stability_opt.run.filter, "Cases (glob)")
      ->capture_default_str();
  stability->add_option("--cases", stability_opt.run.cases_dir, "Folder of case files")
      ->capture_default_str();
  stability->add_option("--out", stability_opt.out, "Folder for the report and the runs")
      ->check(outputFolder())
      ->capture_default_str();
  stability->add_option("--baseline", stability_opt.run.baseline, "Known failures of this driver");
  stability->add_option("--timeout", stability_opt.run.timeout, "Seconds per case side")
      ->check(positiveSeconds())
      ->capture_default_str();
  stability->add_flag("--strict-validation", stability_opt.run.strict_validation,
                      "Fail when the validation layer is not installed");

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
  AccuracyOptions& accuracy_opt = *opt;
  accuracy
      ->add_option("--ordinary", accuracy_opt.ordinary, "Ordinary cases (glob; repeat it for more)")
      ->capture_default_str();
  accuracy->add_option("--hard", accuracy_opt.hard, "Hard cases (glob; repeat it for more)")
      ->capture_default_str();
  accuracy->add_option("--device", accuracy_opt.run.device, "Vulkan device name (substring)");
  accuracy->add_flag("--no-device", accuracy_opt.run.no_device, "The model tiers only");
  accuracy->add_option("--device-results", accuracy_opt.saved_devices,
                       "Run folders of other devices (e.g. a run-only binary's run on a GPU "
                       "machine): their device bundles are compared too, one source each");
  accuracy->add_option("--cases", accuracy_opt.run.cases_dir, "Folder of case files")
      ->capture_default_str();
  accuracy->add_option("--out", accuracy_opt.out, "Folder for the report and the runs")
      ->check(outputFolder())
      ->capture_default_str();
  accuracy->add_option("--timeout", accuracy_opt.run.timeout, "Seconds per case side")
      ->check(positiveSeconds())
      ->capture_default_str();
  accuracy->add_flag("--no-validation", accuracy_opt.run.no_validation,
                     "Do not load the Khronos validation layer");
  accuracy->add_flag("--strict-validation", accuracy_opt.run.strict_validation,
                     "Fail when the validation layer is not installed");

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
      ->capture_default_str();

  return {mutate, [opt] {
            return runMutate(*opt);
          }};
}

}  // namespace rayspec
