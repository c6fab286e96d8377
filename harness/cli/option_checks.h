// Checks of command-line values made while CLI11 parses them, so a bad value
// is exit 2 naming the option before anything runs.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "base/output_folder.h"

namespace rayspec {

// An --out option's value: base/output_folder.h outputFolderProblem, which
// changes nothing; the command claims the folder after its own checks.
CLI::Validator outputFolder();

// Empty when the output folder and every input folder lie apart; else the
// problem: the output is an input, holds one, or lies inside one (compared
// after links, "A/." and the like are resolved), where writing the output
// would delete or overwrite what is read.
std::string outputOverlapsInputs(const std::string& out, const std::vector<std::string>& inputs);

// Every number an option takes is written plainly: digits (a decimal point
// in seconds, a unit after a size), no sign, no space, no "0x", so that what
// is checked is what is used.

// Seconds: a finite number above 0 ("2", "0.5").
CLI::Validator positiveSeconds();

// A count (jobs, threads, attempts): decimal digits only, at most 9 of them.
CLI::Validator wholeCount();

// A memory limit, as a transform to bytes: decimal digits and an optional
// unit (K, M, G, T; KB, KiB ...), checked as written, then converted by
// CLI::AsSizeValue; in bytes 0 (none) or at least kMinMemoryLimit, below
// which a case side cannot even create its devices, and below 2^64.
constexpr unsigned long long kMinMemoryLimit = 256ull << 20;
CLI::Validator memoryLimit();

// An unsigned 64-bit integer written in decimal (no sign, no wrap-around).
CLI::Validator decimalSeed();

// A --through value: one of metamorphic/feature_path.h's names.
CLI::Validator featurePath();

// A fuzz --without value: a device feature the generator leaves out
// (fuzz/generator_features.h).
CLI::Validator leavableFeature();

}  // namespace rayspec
