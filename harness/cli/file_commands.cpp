// The subcommands on saved files and folders, cases and devices: devices,
// compare, merge, show, list, compile.
#include <memory>

#include "cli/commands.h"
#include "cli/option_checks.h"
#include "cli/subcommands.h"

namespace rayspec {

Subcommand addDevicesCommand(CLI::App& app) {
  auto* devices = app.add_subcommand("devices", "List Vulkan devices and their ray tracing limits");
  auto opt = std::make_shared<DevicesOptions>();
  DevicesOptions& devices_opt = *opt;
  devices->add_flag("--no-validation", devices_opt.no_validation,
                    "Do not load the Khronos validation layer");
  devices->add_option("--icd", devices_opt.icd_files, kIcdOptionHelp)->delimiter(':');
  devices->add_flag("--check-limits", devices_opt.check_limits,
                    "Check each usable device's ray tracing limits against the minimums and "
                    "maximums the Vulkan specification requires (exit 1 on a violation the "
                    "baseline does not list)");
  devices
      ->add_option("--baseline", devices_opt.limits_baseline,
                   "With --check-limits: the violations this driver is known for "
                   "(`limits/<limit>,Fail` lines, e.g. references/baselines/lavapipe-limits.csv)")
      ->check(CLI::ExistingFile);

  return {devices, [opt] {
            return runDevices(*opt);
          }};
}

Subcommand addCompareCommand(CLI::App& app) {
  auto* compare = app.add_subcommand("compare",
                                     "Compare two saved results: bundles (device against model) or "
                                     "run folders (A's device against B's device, cases by name)");
  auto opt = std::make_shared<CompareOptions>();
  CompareOptions& compare_opt = *opt;
  compare->add_option("A", compare_opt.a, "Results bundle or run folder (the one judged)")
      ->required();
  compare->add_option("B", compare_opt.b, "Results bundle or run folder (the reference)")
      ->required();
  compare->add_option("--out", compare_opt.out, "Folder for the reports")
      ->check(outputFolder())
      ->capture_default_str();
  compare
      ->add_option("--cases", compare_opt.cases_dir,
                   "Folder of case files (each bundle's case, by name; its case_hash must match)")
      ->capture_default_str();
  compare->add_flag("--brief", compare_opt.brief, kBriefHelp);

  return {compare, [opt] {
            return runCompare(*opt);
          }};
}

Subcommand addMergeCommand(CLI::App& app) {
  auto* merge = app.add_subcommand("merge",
                                   "Join run folders (shards, or runs of one device on several "
                                   "machines) into one, with its reports");
  auto opt = std::make_shared<MergeOptions>();
  MergeOptions& merge_opt = *opt;
  merge->add_option("dirs", merge_opt.dirs, "Run folders")
      ->required()
      ->check(CLI::ExistingDirectory);
  merge->add_option("--out", merge_opt.out, "Folder for the merged run")
      ->check(outputFolder())
      ->capture_default_str();
  merge->add_option("--baseline", merge_opt.baseline,
                    "Judge the merged results against this baseline anew");
  merge->add_option("--flakes", merge_opt.flakes, "Flakes file (default: beside the baseline)");
  merge->add_option("--skips", merge_opt.skips, "Skips file (default: beside the baseline)");
  merge->add_option("--rules", merge_opt.rules_file, "Rule catalog")->capture_default_str();
  merge
      ->add_option("--cases", merge_opt.cases_dir,
                   "Folder of case files: every case is judged anew from its bundles by its case "
                   "here (its case_hash must match)")
      ->capture_default_str();
  merge->add_flag("--brief", merge_opt.brief, kBriefHelp);

  return {merge, [opt] {
            return runMerge(*opt);
          }};
}

Subcommand addShowCommand(CLI::App& app) {
  auto* show = app.add_subcommand(
      "show",
      "Print a parsed case (aimed rays' targets too), its plan, what the model expects of each "
      "ray, whether the case is portable (as `rayspec check`) and its generated GLSL");
  auto opt = std::make_shared<ShowOptions>();
  ShowOptions& show_opt = *opt;
  show->add_option("case", show_opt.case_file, "Case file (or case name under cases/)");
  show->add_flag("--no-glsl", show_opt.no_glsl, "Leave out the generated GLSL");
  show->add_flag("--no-model", show_opt.no_model,
                 "Leave out what the model expects of each ray and the portability check (as "
                 "`rayspec check`: every device the specification allows judged on the case), "
                 "both of which run the model");
  show->add_flag("--vocabulary", show_opt.vocabulary,
                 "List the built-ins and operators of the stage vocabulary");
  show->add_option("--cases", show_opt.cases_dir, "Folder of case files")->capture_default_str();

  return {show, [opt] {
            return runShow(*opt);
          }};
}

Subcommand addListCommand(CLI::App& app) {
  auto* list =
      app.add_subcommand("list", "List the cases (sweeps expanded) and the rules they claim");
  auto opt = std::make_shared<ListOptions>();
  ListOptions& list_opt = *opt;
  list->add_flag(
      "--rules", list_opt.rules,
      "Rule -> cases for every rule of the catalog; exits 1 when a rule (R-UB apart) has no case");
  list->add_flag("--cts-map", list_opt.cts_map,
                 "Print --cts-doc with its CTS tables made from --cts-map-file (the counts from "
                 "the files it names); exits 1 when a group, count, case glob or path is wrong");
  list->add_option("--cts-map-file", list_opt.cts_map_file, "The map of CTS groups")
      ->capture_default_str();
  list->add_option("--cts-doc", list_opt.cts_doc, "The page holding the CTS tables")
      ->capture_default_str();
  list->add_option("--filter", list_opt.filter, "Only cases whose name matches this glob")
      ->capture_default_str();
  list->add_option("--cases", list_opt.cases_dir, "Folder of case files")->capture_default_str();
  list->add_option("--rules-file", list_opt.rules_file, "Rule catalog")->capture_default_str();

  return {list, [opt] {
            return opt->cts_map ? runCtsMap(*opt) : runList(*opt);
          }};
}

Subcommand addCompileCommand(CLI::App& app) {
  auto* compile = app.add_subcommand(
      "compile",
      "Compile the SPIR-V of every generated stage into the cache folder (no device, nothing run); "
      "exit 1 when a stage does not compile");
  auto opt = std::make_shared<CompileOptions>();
  CompileOptions& compile_opt = *opt;
  compile->add_option("--filter", compile_opt.filter, "Only cases whose name matches this glob")
      ->capture_default_str();
  compile->add_option("--cases", compile_opt.cases_dir, "Folder of case files")
      ->capture_default_str();
  compile->add_option("--cache-dir", compile_opt.cache_dir, "Folder of the SPIR-V cache")
      ->capture_default_str();

  return {compile, [opt] {
            return runCompile(*opt);
          }};
}

}  // namespace rayspec
