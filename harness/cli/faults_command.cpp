// `rayspec faults [--rule R-X] [--doc]`: its options (mutate/fault_listing.h runs it).
#include <memory>

#include "cli/subcommands.h"
#include "mutate/fault_listing.h"

namespace rayspec {

Subcommand addFaultsCommand(CLI::App& app) {
  auto* faults = app.add_subcommand(
      "faults",
      "List the planted faults (run --plant-fault, prove): each with the rules it breaks and what "
      "it breaks; with --rule, the rule's text, its specification section and its faults");
  auto opt = std::make_shared<FaultsOptions>();
  faults->add_option("--rule", opt->rule, "Only this rule (R-NAME): its text and its faults");
  faults->add_option("--rules", opt->rules_file, "Rule catalog")->capture_default_str();
  faults->add_flag("--doc", opt->doc,
                   "Print --doc-file with its list of the planted faults made from the fault "
                   "table (redirect it over the page)");
  faults->add_option("--doc-file", opt->doc_file, "The page that lists the planted faults")
      ->capture_default_str();
  return {faults, [opt] {
            return runFaults(*opt);
          }};
}

}  // namespace rayspec
