// The subcommands of the rayspec command line. Each add*Command adds its
// subcommand and options to the parser and returns what runs it once the
// command line is parsed.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace rayspec {

struct Subcommand {
  CLI::App* command = nullptr;  // the subcommand in the parser
  std::function<int()> run;     // runs it; returns the exit status
};

// cli/run_command.cpp
Subcommand addRunCommand(CLI::App& app);
// cli/file_commands.cpp: saved files and folders, cases, devices
Subcommand addDevicesCommand(CLI::App& app);
Subcommand addCompareCommand(CLI::App& app);
Subcommand addMergeCommand(CLI::App& app);
Subcommand addShowCommand(CLI::App& app);
Subcommand addListCommand(CLI::App& app);
Subcommand addCompileCommand(CLI::App& app);
// cli/study_commands.cpp: studies made of runs
Subcommand addStabilityCommand(CLI::App& app);
Subcommand addAccuracyCommand(CLI::App& app);
Subcommand addMutateCommand(CLI::App& app);
// cli/reduce_command.cpp
Subcommand addReduceCommand(CLI::App& app);
// cli/fuzz_command.cpp
Subcommand addFuzzCommand(CLI::App& app);
// cli/faults_command.cpp: the planted faults and the rules they break
Subcommand addFaultsCommand(CLI::App& app);
// cli/prove_command.cpp: a case's rule claims proven by planted faults
Subcommand addProveCommand(CLI::App& app);
// cli/export_command.cpp: a case as a standalone C reproducer
Subcommand addExportCommand(CLI::App& app);

}  // namespace rayspec
