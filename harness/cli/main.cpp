// rayspec: runs Vulkan ray tracing conformance cases on a device and on the
// Embree reference model, and compares what happened.
#include <CLI/CLI.hpp>

#include <vector>

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
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; a bad option or value is exit 2, as
    // every "nothing ran" of `rayspec run` (README, exit status).
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  for (const Subcommand& s : subcommands)
    if (s.command->parsed()) return s.run();
  return 2;
}
