// `rayspec prove CASE_FILE...`: its options (mutate/prove_cases.h runs it).
#include <memory>

#include "cli/commands.h"
#include "cli/device_options.h"
#include "cli/option_checks.h"
#include "cli/subcommands.h"
#include "mutate/prove_cases.h"

namespace rayspec {

Subcommand addProveCommand(CLI::App& app) {
  auto* prove = app.add_subcommand(
      "prove",
      "Prove each rule a case claims: plant every fault of the rule (rayspec faults --rule R) and "
      "name the one that makes the case Fail; a claim no fault fails is hollow, listed with the "
      "faults tried (exit 1). Runs on the model (a live device only with --device or --icd, for "
      "the faults only it shows); writes nothing in the checkout or beside the case");
  auto opt = std::make_shared<ProveOptions>();
  prove->add_option("CASE_FILE", opt->files, "Case files or sweep files, anywhere")->required();
  prove
      ->add_option("--cases", opt->cases_dir,
                   "Folder of case files: a file under it is named by its path there, any other "
                   "by its stem")
      ->capture_default_str();
  prove->add_option("--rules", opt->rules_file, "Rule catalog")->capture_default_str();
  prove->add_option("--threads", opt->threads, "Model threads (0: all cores)")
      ->check(wholeCount())
      ->capture_default_str();
  prove->add_flag("-v,--verbose", opt->verbose,
                  "Every fault tried for every claim, and its outcome");
  addDeviceChoice(prove, opt->run);
  addValidationOptions(prove, opt->run);
  prove->add_option("--timeout", opt->run.timeout, "On the device: seconds per case side")
      ->check(positiveSeconds())
      ->capture_default_str();
  return {prove, [opt] {
            opt->live = !opt->run.device.empty() || !opt->run.icd_files.empty();
            return runProve(*opt);
          }};
}

}  // namespace rayspec
