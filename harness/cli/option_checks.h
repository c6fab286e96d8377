// Checks of command-line values made while CLI11 parses them, so a bad value
// is exit 2 naming the option before anything runs.
#pragma once

#include <CLI/CLI.hpp>

namespace rayspec {

// An output folder: not empty, not the filesystem root, not a file; created
// when missing and writable (a probe file is made and removed).
CLI::Validator outputFolder();

// Seconds: a finite number above 0.
CLI::Validator positiveSeconds();

// A memory limit in bytes (after CLI::AsSizeValue): 0 (none) or at least
// kMinMemoryLimit, below which a case side cannot even create its devices.
constexpr unsigned long long kMinMemoryLimit = 256ull << 20;
CLI::Validator memoryLimit();

// An unsigned 64-bit integer written in decimal (no sign, no wrap-around).
CLI::Validator decimalSeed();

}  // namespace rayspec
