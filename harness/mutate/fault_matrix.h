// The fault matrix of generated cases (`rayspec fuzz --fault-matrix`): every
// rule-breaking planted fault (fault/planted_fault.h: neither a process
// fault nor a legal variation) planted in each case's saved device results
// that pass, as `rayspec run --plant-fault` plants it, and judged against
// the model, until one case finds it: a Fail, or a QualityWarning (a
// "should" rule's break; the fuzzer keeps either as a finding). Per fault:
// the rules it breaks (fault/rule_faults.h), the cases it was planted in and
// changed something in, and the first case that found it.
#pragma once

#include <string>
#include <vector>

#include "mutate/mutate_run.h"

namespace rayspec {

struct FaultRow {
  std::string fault, rules;       // rules: those whose breaking faults list it, ", "
  size_t tried = 0, applied = 0;  // cases planted in before found / changed something in
  std::string found_by;           // the first case that found it ("" none)
  std::string status, headline;   // that case's verdict
  std::string what;               // the last planting's note (why nothing changed, or what did)
};

class FaultMatrix {
 public:
  FaultMatrix();  // every rule-breaking fault, none found
  // Plants every fault not found yet in `saved`'s device results and judges each.
  void add(const std::string& case_name, const SavedCase& saved);
  size_t found() const;
  size_t cases() const { return cases_; }
  double seconds = 0;  // wall time the plantings took (the caller's clock)
  const std::vector<FaultRow>& rows() const { return rows_; }
  // fault-matrix.txt: the score, one line per fault, the faults never found.
  std::string text() const;

 private:
  std::vector<FaultRow> rows_;
  size_t cases_ = 0;
};

}  // namespace rayspec
