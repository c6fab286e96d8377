// What a reduction writes: DIR/reduced.yaml (a case file), DIR/repro.c (the
// reduced case as a standalone C file, export/export_c.h, where it can be
// exported), DIR/repro.amber (the same as an Amber script,
// export/export_amber.h), DIR/report.md (the bug report: how to build and
// run repro.c and repro.amber or why there is none, the case, the command that shows it, the
// failing rays device against model, the rule's text, the driver and device), DIR/steps.txt (every
// attempt and its verdict).
#pragma once

#include <array>

#include <string>
#include <vector>

#include "export/export_amber.h"
#include "export/export_c.h"
#include "reduce/case_size.h"
#include "reduce/failure_signature.h"
#include "reduce/variant_judge.h"
#include "report/case_outcome.h"

namespace rayspec {

struct ReductionRecord {
  std::string case_name, case_path;
  std::string reduced_text;  // reduced.yaml
  std::string reproducer;    // repro.c ("": none, for the reason below)
  std::string reproducer_refused;
  std::string amber;  // repro.amber ("": none, for the reason below)
  std::string amber_refused;
  FailureSignature signature;
  CaseOutcome outcome;  // the reduced case's
  CaseSize before, after;
  double seconds = 0;
  std::string device, icd, fault, rule_title;
  std::string command;  // the one-line reproduction
  std::vector<Attempt> attempts;
};

// The `description:` of the reduced case.
std::string reducedDescription(const ReductionRecord& r);

// Why a case is not reduced: "NAME does not fail[ by KEEP] to begin with: "
// and its verdict, named once ("it passes" for a Pass), made visible.
std::string notFailingText(const std::string& name, const std::string& keep,
                           const CaseOutcome& outcome);

// What a reduction writes in its --out: the files of writeReduction, the
// runs of its variants (runs/) and, for a device command, the case files it
// reads (cases/).
inline constexpr const char* kReducedCaseFile = "reduced.yaml";
inline constexpr const char* kReductionReportFile = "report.md";
inline constexpr const char* kReductionStepsFile = "steps.txt";
inline constexpr const char* kReductionRunsFolder = "runs";
inline constexpr const char* kReductionCasesFolder = "cases";
inline constexpr std::array<const char*, 7> kReductionWrites = {
    kReducedCaseFile,    kReproducerFile,      kAmberScriptFile,     kReductionReportFile,
    kReductionStepsFile, kReductionRunsFolder, kReductionCasesFolder};

// reduced.yaml, report.md, steps.txt, repro.c and repro.amber (where there
// is one; an earlier run's removed where not) into dir; the error ("" none).
std::string writeReduction(const ReductionRecord& r, const std::string& dir);

// The summary printed at the end.
std::string reductionSummary(const ReductionRecord& r, const std::string& dir);

}  // namespace rayspec
