// `rayspec reduce CASE`: a case that fails on a device (or under a planted
// fault) shrunk to the smallest case that still fails the same way, with a
// report to paste upstream (docs/reduce.md).
#pragma once

#include <cstddef>
#include <string>

#include "run/run_options.h"

namespace rayspec {

struct ReduceOptions {
  std::string case_path;  // a case file, or a case name under run.cases_dir (a sweep's variant)
  std::string out = "rayspec-reduce";
  std::string keep;  // "": the case's worst finding; a rule label; "crash"; a message's text
  size_t max_attempts = 3000;
  RunOptions run;  // the device, --icd, --plant-fault, the model tier, limits
  // --device-command: each variant's device side run by this shell command,
  // not by a device here (reduce/variant_judge.h: a driver this process
  // cannot load, such as tools/second-driver.sh's).
  std::string device_command;
};

// Exit statuses: 0 reduced (reduced.yaml, report.md, steps.txt written), 1
// the case does not fail (that way) to begin with, 2 bad input (a device
// command that is no use among it: reduce/variant_judge.h).
inline constexpr int kReduceDone = 0;
inline constexpr int kReduceNotFailing = 1;
inline constexpr int kReduceBadInput = 2;

int runReduce(const ReduceOptions& opt);

}  // namespace rayspec
