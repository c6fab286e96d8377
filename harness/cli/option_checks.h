// Checks of command-line values made while CLI11 parses them, so a bad value
// is exit 2 naming the option before anything runs.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace rayspec {

// An output folder: not empty, not the filesystem root, not a file; created
// when missing and writable (a probe file is made and removed). Every entry
// in it that is neither a regular file nor a folder (a link to write or
// delete through, a FIFO) is removed itself, with a line on stderr. Empty
// when the folder is usable; else the problem.
std::string outputFolderProblem(const std::string& dir);
// The same as a validator of an --out option.
CLI::Validator outputFolder();

// Empty when the output folder and every input folder lie apart; else the
// problem: the output is an input, holds one, or lies inside one (compared
// after links, "A/." and the like are resolved), where writing the output
// would delete or overwrite what is read.
std::string outputOverlapsInputs(const std::string& out, const std::vector<std::string>& inputs);

// Seconds: a finite number above 0.
CLI::Validator positiveSeconds();

// A memory limit in bytes (after CLI::AsSizeValue): 0 (none) or at least
// kMinMemoryLimit, below which a case side cannot even create its devices.
constexpr unsigned long long kMinMemoryLimit = 256ull << 20;
CLI::Validator memoryLimit();

// An unsigned 64-bit integer written in decimal (no sign, no wrap-around).
CLI::Validator decimalSeed();

}  // namespace rayspec
