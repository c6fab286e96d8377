// `rayspec reduce CASE`: its options (those of `rayspec run` that choose the
// device and how a case runs, and its own).
#include <memory>
#include <string>

#include "cli/commands.h"
#include "cli/device_options.h"
#include "cli/option_checks.h"
#include "cli/subcommands.h"
#include "reduce/reduce_case.h"
#include "run/fault_seam.h"

namespace rayspec {

Subcommand addReduceCommand(CLI::App& app) {
  auto* reduce = app.add_subcommand(
      "reduce",
      "Shrink a failing case to the smallest case that still fails the same way (same status, "
      "rule and kind of finding), each variant run and judged as `rayspec run` does; writes "
      "OUT/reduced.yaml, report.md and steps.txt. Exit 0 reduced, 1 the case does not fail, 2 "
      "bad input");
  auto opt = std::make_shared<ReduceOptions>();
  ReduceOptions& o = *opt;
  reduce->add_option("CASE", o.case_path, "A case file, or a case's name (a sweep's variant)")
      ->required();
  reduce->add_option("--out", o.out, "Folder for reduced.yaml, report.md, steps.txt")
      ->check(outputFolder())
      ->capture_default_str();
  reduce->add_option("--keep", o.keep,
                     "What to keep failing: a rule label (R-...; any finding of it, Fail or "
                     "QualityWarning), `crash` (a Crash or Timeout), or text of the finding's "
                     "message; default: the case's worst finding, same rule and kind");
  reduce->add_option("--max-attempts", o.max_attempts, "Variants to try at most")
      ->check(wholeCount())
      ->capture_default_str();
  addDeviceChoice(reduce, o.run);
  reduce->add_option("--cases", o.run.cases_dir, "Folder of case files")->capture_default_str();
  reduce->add_option("--model", o.run.model_tier, "Model precision tier")->capture_default_str();
  reduce->add_option("--rules", o.run.rules_file, "Rule catalog")->capture_default_str();
  reduce
      ->add_option("--timeout", o.run.timeout,
                   "Seconds per case side (and per run of --device-command)")
      ->check(positiveSeconds())
      ->capture_default_str();
  reduce->add_option("--device-command", o.device_command,
                     "Run each variant's device side by this shell command, not on a device "
                     "here: it gets RAYSPEC_VARIANT_CASES (a folder holding the variant as "
                     "<case name>.yaml), RAYSPEC_VARIANT_NAME and RAYSPEC_VARIANT_OUT (where it "
                     "leaves what `rayspec run --out` writes) in its environment, its output "
                     "goes to OUT/runs/variant-<n>/command.log, and --timeout bounds each run "
                     "(its process group is killed); one that runs out of time, or fails leaving "
                     "no results, ends the reduction (exit 2). `tools/second-driver.sh device` is "
                     "one, for the second driver");
  addValidationOptions(reduce, o.run);
  reduce->add_option("--plant-fault", o.run.plant_fault, kPlantFaultHelp);
  return {reduce, [opt] {
            return runReduce(*opt);
          }};
}

}  // namespace rayspec
