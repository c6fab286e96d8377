// rayspec: runs Vulkan ray tracing conformance cases on a device and on the
// Embree reference model, and compares what happened.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "cli/check_command.h"
#include "cli/option_checks.h"
#include "cli/subcommands.h"

int main(int argc, char** argv) {
  CLI::App app{
      "rayspec: Vulkan ray tracing pipeline conformance, device against a CPU reference model"};
  app.require_subcommand(1);
  using namespace rayspec;
  const std::vector<Subcommand> subcommands = {
      addDevicesCommand(app),   addRunCommand(app),      addCompareCommand(app),
      addMergeCommand(app),     addShowCommand(app),     addListCommand(app),
      addStabilityCommand(app), addAccuracyCommand(app), addMutateCommand(app),
      addCompileCommand(app),   addReduceCommand(app),   addFuzzCommand(app),
      addFaultsCommand(app),    addProveCommand(app),    addCheckCommand(app),
      addExportCommand(app),
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; a bad option or value is exit 2, as
    // every "nothing ran" of `rayspec run` (README, exit status).
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  for (const Subcommand& s : subcommands) {
    if (!s.command->parsed()) continue;
    // CLI11 checks values given, not defaults: an --out left at its default
    // is held to the same checks here.
    const CLI::Option* out = s.command->get_option_no_throw("--out");
    if (out && out->count() == 0)
      if (const std::string problem = outputFolderProblem(out->as<std::string>());
          !problem.empty()) {
        std::fprintf(stderr, "rayspec %s: --out: %s\n", s.command->get_name().c_str(),
                     problem.c_str());
        return 2;
      }
    return s.run();
  }
  return 2;
}
