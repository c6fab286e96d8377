// Each variant of a reduction judged as `rayspec run` judges one case: parsed
// by the case parser (a variant that does not parse is rejected without a
// run), both sides run isolated in child processes (run/case_steps.h
// CaseRunner), judged by the usual comparison; kept when it fails the way
// the original did (reduce/failure_signature.h) and, once keepPortable() is
// called, every legal device still passes it (reduce/portability_check.h).
// Every attempt is logged.
// With a device command, the device side of each variant is run by it
// instead: the variant is written to RUN_OUT/variant-<n>/cases/<case name>.yaml,
// the command runs with RAYSPEC_VARIANT_CASES (that folder), RAYSPEC_VARIANT_NAME
// (the case's name) and RAYSPEC_VARIANT_OUT (RUN_OUT/variant-<n>/device: where it
// must leave what `rayspec run --out` writes), and the bundle it left is
// judged as `rayspec run --device-results` judges one (none: NotSupported,
// so never kept). The command runs as reduce/device_command.h runs it, under
// --timeout; when it runs out of time, or ends badly (a non-zero exit, a
// signal) leaving no results, it is no use: commandFailure() says why, and
// no more variants are tried.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "reduce/failure_signature.h"
#include "reduce/portability_check.h"
#include "run/case_steps.h"

namespace rayspec {

struct Attempt {
  std::string what;     // the change tried
  std::string verdict;  // "kept", or why not: "does not parse: ...", "Pass", ...
  bool kept = false;
  bool ran = false;  // the sides ran (it parsed)
  double seconds = 0;
};

class VariantJudge {
 public:
  // name: the case's name (every variant runs under it, so a fault planted
  // in cases matching a glob stays planted).
  VariantJudge(const RunOptions& run, std::string name, std::vector<std::string> labels,
               FailureSignature signature, size_t max_attempts, std::string device_command = "");
  // The case as text, run and judged: its outcome (a CaseError when it does
  // not parse). *interrupted: a signal stopped it.
  CaseOutcome judge(const std::string& text, bool* interrupted) const;

  // The variant parsed by the case parser; where it does not parse and
  // error is given, *error is the CaseError outcome that says why.
  ParseResult parse(const std::string& text, CaseOutcome* error = nullptr) const;
  const FailureSignature& signature() const { return signature_; }

 private:
  // The parsed variant (its text for a device command) run and judged.
  CaseOutcome judgeParsed(const std::string& text, const Case& c, bool* interrupted) const;
  // The device side by the device command, then the case judged from what it left.
  CaseOutcome judgeByCommand(const std::string& text, const Case& c, bool* interrupted) const;

 public:
  // With a planted fault: why the parsed variant fails without it too ("": it
  // does not, or no fault is planted).
  std::string failureWithoutTheFault(const Case& c, bool* interrupted) const;
  // From now on a variant is kept only where the legal devices that pass
  // `original` pass it too (reduce/portability_check.h).
  void keepPortable(const Case& original) { portability_.emplace(original, run_.threads); }
  // Whether the variant fails the same way (and, with a planted fault, passes
  // without it, and is portable); a text seen before is not run again.
  bool fails(const std::string& text, const std::string& what);
  const std::vector<Attempt>& attempts() const { return attempts_; }
  // No more attempts: the limit was reached, a signal stopped one, or the
  // device command is no use.
  bool stopped() const { return stopped_; }
  // Why the device command is no use, naming it and its log ("" it is).
  const std::string& commandFailure() const { return command_failure_; }
  // The outcome of a kept text (nullptr: none).
  const CaseOutcome* keptOutcome(const std::string& text) const;
  // With a device command: the device and driver manifest its run of the
  // last kept variant (or, none kept, of the last variant) says it ran on
  // (empty: none said).
  struct CommandDevice {
    std::string device, icd;
  };
  CommandDevice commandDevice() const {
    return kept_device_.device.empty() ? last_device_ : kept_device_;
  }

 private:
  const RunOptions& run_;
  std::string name_;
  std::vector<std::string> labels_;
  FailureSignature signature_;
  size_t max_attempts_;
  CaseRunner runner_;
  // With a planted fault: the same run without it, which a kept variant
  // must pass (the failure must stay the fault's, not the reduced case's own).
  RunOptions clean_run_;
  CaseRunner clean_runner_;
  std::string device_command_;
  mutable size_t commands_run_ = 0;
  mutable CommandDevice last_device_;
  mutable std::string command_failure_;
  CommandDevice kept_device_;
  std::optional<PortabilityCheck> portability_;
  std::map<std::string, bool> seen_;
  std::map<std::string, CaseOutcome> kept_;
  std::vector<Attempt> attempts_;
  bool stopped_ = false;
};

}  // namespace rayspec
