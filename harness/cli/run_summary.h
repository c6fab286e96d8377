// The console side of a run: a progress line per case while it goes, and a
// readable summary at the end (counts per status, the failing cases first).
// Also writes OUT/summary.txt and OUT/results.csv (case,Status,duration).
#pragma once

#include <string>
#include <vector>

#include "compare/verdict.h"

namespace rayspec {

struct CaseOutcome {
  std::string name;
  Status status = Status::Pass;
  std::string headline;
  double seconds = 0.0, device_seconds = 0.0, model_seconds = 0.0;
  Verdict verdict;
};

class RunSummary {
 public:
  explicit RunSummary(size_t total) : total_(total) {}
  void add(const CaseOutcome& outcome);          // prints the progress line
  void addTeardownError(const std::string& m);   // validation errors at device destruction
  void print() const;
  std::string write(const std::string& dir) const;
  bool failed() const;
  bool allNotSupported() const;

 private:
  size_t total_;
  std::vector<CaseOutcome> outcomes_;
  std::vector<std::string> teardown_errors_;
};

}  // namespace rayspec
