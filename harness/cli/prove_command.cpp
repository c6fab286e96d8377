// `rayspec prove CASE_FILE...`: its options (mutate/prove_cases.h runs it).
#include <memory>

#include "cli/option_checks.h"
#include "cli/subcommands.h"
#include "mutate/prove_cases.h"

namespace rayspec {

Subcommand addProveCommand(CLI::App& app) {
  auto* prove = app.add_subcommand(
      "prove",
      "Prove each rule a case claims: plant every fault of the rule (rayspec faults --rule R) and "
      "name the one that makes the case Fail; a claim no fault fails is hollow, listed with the "
      "faults tried (exit 1). Runs on the model, no device; writes nothing");
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
  return {prove, [opt] {
            return runProve(*opt);
          }};
}

}  // namespace rayspec
