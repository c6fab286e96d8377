// rayspec: runs Vulkan ray tracing conformance cases on a device and on the
// Embree reference model, and compares what happened.
#include <CLI/CLI.hpp>

#include "accuracy/run_accuracy.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "metamorphic/motion_spec.h"
#include "mutate/mutate_run.h"
#include "run/run_loop.h"
#include "stability/run_stability.h"
#include "fault/planted_fault.h"
#include "vulkan/device_errors.h"

int main(int argc, char** argv) {
  CLI::App app{"rayspec: Vulkan ray tracing pipeline conformance, device against a CPU reference model"};
  app.require_subcommand(1);

  auto* devices = app.add_subcommand("devices", "List Vulkan devices and their ray tracing limits");
  rayspec::DevicesOptions devices_opt;
  devices->add_flag("--no-validation", devices_opt.no_validation, "Do not load the Khronos validation layer");
  devices->add_option("--icd", devices_opt.icd_files, rayspec::kIcdOptionHelp)->delimiter(':');

  auto* run = app.add_subcommand("run", "Run cases on a device and on the model");
  rayspec::RunOptions run_opt;
  run->add_option("--device", run_opt.device, "Vulkan device name (substring); default: first with ray tracing");
  run->add_option("--icd", run_opt.icd_files, rayspec::kIcdOptionHelp)->delimiter(':');
  run->add_option("--filter", run_opt.filter, "Run only cases whose name matches this glob (e.g. 'anyhit/*')");
  run->add_option("--out", run_opt.out, "Folder for results bundles and reports")
      ->check(rayspec::outputFolder())
      ->capture_default_str();
  run->add_option("--cases", run_opt.cases_dir, "Folder of case files")->capture_default_str();
  run->add_option("--case", run_opt.case_files, "Run these case files (instead of --cases)");
  run->add_option("--model", run_opt.model_tier, "Model precision tier: fast, robust or exact")
      ->check(CLI::IsMember({"fast", "robust", "exact"}))->capture_default_str();
  run->add_option("--baseline", run_opt.baseline,
                  "Expected results of this driver (case,Status lines; unlisted: Pass). The run fails on anything "
                  "unexpected (an unexpected failure is re-run once to tell a flake; an unexpected pass fails "
                  "until the baseline is updated) and writes failures.csv");
  run->add_option("--flakes", run_opt.flakes,
                  "Regular expressions of cases known to flake (default: <baseline>-flakes.txt beside it)");
  run->add_option("--skips", run_opt.skips,
                  "Regular expressions of cases not to run (default: <baseline>-skips.txt beside it)");
  run->add_option("--shard", run_opt.shard,
                  "Run shard I of N (I/N, from 1): every N-th case from the I-th; without it, GTEST_TOTAL_SHARDS "
                  "and GTEST_SHARD_INDEX are honoured");
  run->add_flag("--resume", run_opt.resume,
                "Keep the cases the --out folder already holds (a run that was killed) and run the rest");
  run->add_option("--rules", run_opt.rules_file, "Rule catalog (references/spec-rules.yaml)")->capture_default_str();
  run->add_flag("--no-model", run_opt.no_model, "Run the device only");
  run->add_flag("--no-device", run_opt.no_device, "Run the model only");
  run->add_flag("--no-validation", run_opt.no_validation, "Do not load the Khronos validation layer");
  run->add_flag("--strict-validation", run_opt.strict_validation,
                "Fail when the validation layer is not installed (ctest sets this)");
  run->add_option("--threads", run_opt.threads, "Model threads (0: all cores)")->capture_default_str();
  run->add_flag("--records-csv", run_opt.records_csv,
                "records.csv (the per-ray records as text) in every bundle; without it only where the case did "
                "not pass");
  run->add_option("--cache-dir", run_opt.cache_dir,
                  "Folder for the SPIR-V of generated stages, reused by every case process and later runs ('': "
                  "none)")
      ->capture_default_str();
  run->add_option("--timeout", run_opt.timeout,
                  "Seconds a case's model side, and then its device side, may run before it is a Timeout")
      ->check(rayspec::positiveSeconds())
      ->capture_default_str();
  run->add_option("--memory-limit", run_opt.memory_limit,
                  "Memory each worker process may hold (RLIMIT_DATA; e.g. 8G, 512M; 0: no limit); beyond "
                  "it the case that was running is a Crash")
      ->transform(CLI::AsSizeValue(false))
      ->check(rayspec::memoryLimit())
      ->default_str(std::to_string(rayspec::kDefaultMemoryLimit >> 30) + "G");
  run->add_option("-j,--jobs", run_opt.jobs,
                  "Cases at once (0: one per core, at most 16; 4 on a GPU); each side of a case runs in a long-lived worker "
                  "process, a new one after a crash, timeout or memory-limit hit")
      ->capture_default_str();
  run->add_option("--device-per-case", run_opt.device_per_case,
                  "A VkDevice of its own for each case in a worker (auto: on lavapipe, whose pipelines would "
                  "otherwise miss the shader cache)")
      ->check(CLI::IsMember({"auto", "yes", "no"}))
      ->capture_default_str();
  run->add_flag("--process-per-case", run_opt.process_per_case,
                "Each side of each case in a process of its own instead of long-lived workers (slower; a new "
                "VkInstance and VkDevice per case)");
  run->add_flag("--no-isolation", run_opt.no_isolation,
                "Run the model and the device in this process (one VkDevice for every case; no timeout, no "
                "memory limit, a crash ends the run)");
  std::string fault_list;
  for (const std::string& name : rayspec::faultNames()) fault_list += (fault_list.empty() ? "" : ", ") + name;
  for (const std::string& name : rayspec::deviceErrorFaultNames()) fault_list += ", " + name;
  run->add_option("--device-results", run_opt.device_results,
                  "Run no device: judge the device bundles a run saved in this folder (DIR/<case>/device, e.g. "
                  "from a run-only build) against the model run here");
  run->add_option("--permute", run_opt.permute,
                  "Permute each case's primitives and instances from this seed (R-ORDER-UNSPEC: verdicts must not "
                  "move; the same seed gives the same permutation)")
      ->check(rayspec::decimalSeed());
  std::string move_spec;
  run->add_option("--move", move_spec,
                  "Move each case by an exact rigid motion: three signed axes and an optional translation, e.g. "
                  "-y,x,z or z,x,y,1024,-2048,0 (verdicts must not move; a case it cannot move exactly is "
                  "NotSupported)")
      ->check(
          [](const std::string& spec) {
            std::string why;
            return rayspec::parseMotionSpec(spec, &why) ? std::string() : why;
          },
          "MOTION");
  run->add_option("--plant-fault", run_opt.plant_fault,
                  "Test only: corrupt the device's results in a known way (" + fault_list + ")");
  run->add_option("--plant-fault-in", run_opt.plant_fault_in, "Test only: plant the fault only in cases matching this glob")
      ->capture_default_str();

  auto* compare = app.add_subcommand("compare", "Compare two saved results: bundles (device against model) or "
                                                "run folders (A's device against B's device, cases by name)");
  rayspec::CompareOptions compare_opt;
  compare->add_option("A", compare_opt.a, "Results bundle or run folder (the one judged)")->required();
  compare->add_option("B", compare_opt.b, "Results bundle or run folder (the reference)")->required();
  compare->add_option("--out", compare_opt.out, "Folder for the reports")
      ->check(rayspec::outputFolder())
      ->capture_default_str();
  compare->add_option("--cases", compare_opt.cases_dir, "Folder of case files (when a bundle's case file moved)")
      ->capture_default_str();

  auto* merge = app.add_subcommand("merge", "Join run folders (shards, or runs of one device on several machines) "
                                            "into one, with its reports");
  rayspec::MergeOptions merge_opt;
  merge->add_option("dirs", merge_opt.dirs, "Run folders")->required()->check(CLI::ExistingDirectory);
  merge->add_option("--out", merge_opt.out, "Folder for the merged run")
      ->check(rayspec::outputFolder())
      ->capture_default_str();
  merge->add_option("--baseline", merge_opt.baseline, "Judge the merged results against this baseline anew");
  merge->add_option("--flakes", merge_opt.flakes, "Flakes file (default: beside the baseline)");
  merge->add_option("--skips", merge_opt.skips, "Skips file (default: beside the baseline)");
  merge->add_option("--rules", merge_opt.rules_file, "Rule catalog")->capture_default_str();

  auto* show = app.add_subcommand("show", "Print a parsed case, its plan and its generated GLSL");
  rayspec::ShowOptions show_opt;
  show->add_option("case", show_opt.case_file, "Case file (or case name under cases/)");
  show->add_flag("--no-glsl", show_opt.no_glsl, "Leave out the generated GLSL");
  show->add_flag("--vocabulary", show_opt.vocabulary, "List the built-ins and operators of the stage vocabulary");
  show->add_option("--cases", show_opt.cases_dir, "Folder of case files")->capture_default_str();

  auto* list = app.add_subcommand("list", "List the cases (sweeps expanded) and the rules they claim");
  rayspec::ListOptions list_opt;
  list->add_flag("--rules", list_opt.rules,
                 "Rule -> cases for every rule of the catalog; exits 1 when a rule (R-UB apart) has no case");
  list->add_option("--filter", list_opt.filter, "Only cases whose name matches this glob")->capture_default_str();
  list->add_option("--cases", list_opt.cases_dir, "Folder of case files")->capture_default_str();
  list->add_option("--rules-file", list_opt.rules_file, "Rule catalog")->capture_default_str();

  auto* stability = app.add_subcommand(
      "stability", "Leak and double-hit rates of the stability families per coordinate magnitude: the device and "
                   "each model tier (OUT/stability.txt, stability.json, stability.png)");
  rayspec::StabilityOptions stability_opt;
  stability_opt.run.filter = "stability/*";
  stability->add_option("--device", stability_opt.run.device, "Vulkan device name (substring)");
  stability->add_flag("--no-device", stability_opt.run.no_device, "The model tiers only");
  stability->add_option("--device-results", stability_opt.saved_devices,
                        "Run folders of other devices (e.g. a run-only binary's run on a GPU machine): their device "
                        "bundles are counted too, one source each");
  stability->add_option("--filter", stability_opt.run.filter, "Cases (glob)")->capture_default_str();
  stability->add_option("--cases", stability_opt.run.cases_dir, "Folder of case files")->capture_default_str();
  stability->add_option("--out", stability_opt.out, "Folder for the report and the runs")
      ->check(rayspec::outputFolder())
      ->capture_default_str();
  stability->add_option("--baseline", stability_opt.run.baseline, "Known failures of this driver");
  stability->add_option("--timeout", stability_opt.run.timeout, "Seconds per case side")
      ->check(rayspec::positiveSeconds())
      ->capture_default_str();
  stability->add_flag("--strict-validation", stability_opt.run.strict_validation,
                      "Fail when the validation layer is not installed");

  auto* accuracy = app.add_subcommand(
      "accuracy", "Trace time per million rays and per-ray disagreements with the model's exact tier (leaks, double "
                  "hits, other primitives, t error in ULP), each model tier and device, on ordinary and hard cases "
                  "(OUT/accuracy.txt, accuracy.json, accuracy.png)");
  rayspec::AccuracyOptions accuracy_opt;
  accuracy->add_option("--ordinary", accuracy_opt.ordinary, "Ordinary cases (glob; repeat it for more)")
      ->capture_default_str();
  accuracy->add_option("--hard", accuracy_opt.hard, "Hard cases (glob; repeat it for more)")->capture_default_str();
  accuracy->add_option("--device", accuracy_opt.run.device, "Vulkan device name (substring)");
  accuracy->add_flag("--no-device", accuracy_opt.run.no_device, "The model tiers only");
  accuracy->add_option("--device-results", accuracy_opt.saved_devices,
                       "Run folders of other devices (e.g. a run-only binary's run on a GPU machine): their device "
                       "bundles are compared too, one source each");
  accuracy->add_option("--cases", accuracy_opt.run.cases_dir, "Folder of case files")->capture_default_str();
  accuracy->add_option("--out", accuracy_opt.out, "Folder for the report and the runs")
      ->check(rayspec::outputFolder())
      ->capture_default_str();
  accuracy->add_option("--timeout", accuracy_opt.run.timeout, "Seconds per case side")
      ->check(rayspec::positiveSeconds())
      ->capture_default_str();
  accuracy->add_flag("--no-validation", accuracy_opt.run.no_validation, "Do not load the Khronos validation layer");
  accuracy->add_flag("--strict-validation", accuracy_opt.run.strict_validation,
                     "Fail when the validation layer is not installed");

  auto* mutate = app.add_subcommand(
      "mutate", "Judge generic wrong devices made from a saved device run (null device, fields perturbed, counters "
                "moved, rays swapped, ...): the kill matrix and every survivor with the reason it may legally "
                "survive (OUT/mutate.txt, mutate.json); fails on a survivor with no reason");
  rayspec::MutateOptions mutate_opt;
  mutate_opt.cases_dir = RAYSPEC_SOURCE_DIR "/cases";
  mutate->add_option("RUN_DIR", mutate_opt.run_dir, "Run folder with <case>/device bundles")->required();
  mutate->add_option("--out", mutate_opt.out, "Folder for mutate.txt and mutate.json")
      ->check(rayspec::outputFolder())
      ->capture_default_str();
  mutate->add_option("--cases", mutate_opt.cases_dir, "Folder of case files")->capture_default_str();
  mutate->add_option("--filter", mutate_opt.filter, "Cases (glob)")->capture_default_str();
  mutate->add_option("--threads", mutate_opt.threads, "Model threads (0: all cores)")->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; a bad option or value is exit 2, as
    // every "nothing ran" of `rayspec run` (README, exit status).
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  if (*accuracy) return rayspec::runAccuracy(accuracy_opt);
  if (*stability) return rayspec::runStability(stability_opt);
  if (*list) return rayspec::runList(list_opt);
  if (*devices) return rayspec::runDevices(devices_opt);
  if (*run && !move_spec.empty()) {
    std::string why;
    run_opt.move = rayspec::parseMotionSpec(move_spec, &why);
  }
  if (*run) return rayspec::runCases(run_opt);
  if (*show) return rayspec::runShow(show_opt);
  if (*compare) return rayspec::runCompare(compare_opt);
  if (*merge) return rayspec::runMerge(merge_opt);
  if (*mutate) return rayspec::runMutate(mutate_opt);
  return 2;
}
