// The console side of a run: a progress line per case while it goes, and a
// readable summary at the end (counts per status, the failing cases first).
#pragma once

#include <string>
#include <vector>

#include "report/case_outcome.h"

namespace rayspec {

class RunSummary {
 public:
  // What is printed as cases are added: every case; only what fails the run
  // (ctest's runs, whose first lines a CI log keeps); nothing (a merge, or the
  // run's closing summary).
  enum class Progress { Every, Brief, Quiet };
  explicit RunSummary(size_t total, Progress progress = Progress::Every)
      : total_(total), progress_(progress) {}
  // On a terminal: a live "[i/N] running NAME..." line until add().
  void starting(const std::string& name);
  void add(const CaseOutcome& outcome);         // prints the progress line
  void addTeardownError(const std::string& m);  // validation errors at device destruction
  // Counts, then the cases not passing or not as the baseline expects; brief:
  // only those that fail the run. With a baseline file (the one the run was
  // judged by), the gate's line (report/baseline_gate.h gateLine) last.
  void print(bool brief = false, const std::string& baseline = "") const;
  const std::vector<CaseOutcome>& outcomes() const { return outcomes_; }
  const std::vector<std::string>& teardownErrors() const { return teardown_errors_; }
  bool failed() const;
  bool allNotSupported() const;

 private:
  size_t total_;
  Progress progress_;
  bool live_ = false;  // a live line is on screen
  std::vector<CaseOutcome> outcomes_;
  std::vector<std::string> teardown_errors_;
};

}  // namespace rayspec
