// `rayspec faults [--rule R-X]`: every planted fault with the rules it
// breaks (fault/rule_faults.h) and what it breaks (fault/planted_fault.h's
// table, one line per fault); with a rule, its text and section from the
// catalog and its faults. `rayspec faults --doc`: docs/wrong-devices.md with
// its list of the planted faults made from the same table (its one
// definition), printed whole; tests/mutate_fault_listing_test.cpp fails when
// the committed page differs.
#pragma once

#include <string>
#include <vector>

#include "base/result.h"
#include "run/run_options.h"  // RAYSPEC_SOURCE_DIR

namespace rayspec {

struct FaultsOptions {
  std::string rule;  // "" every fault
  std::string rules_file = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";
  bool doc = false;  // print doc_file with its list of faults made from the table
  std::string doc_file = RAYSPEC_SOURCE_DIR "/docs/wrong-devices.md";
};

// The markers around the generated list of docs/wrong-devices.md.
extern const char* const kFaultsDocBegin;
extern const char* const kFaultsDocEnd;

// The generated list: every fault under the heading of its kind, with the
// rules it breaks or that allow it and what it breaks (Markdown).
std::string faultsDocPart();

// `doc` with its generated list replaced by faultsDocPart(); an error names
// a marker the doc lacks.
Result<std::string> faultsDocument(const std::string& doc);

// "a, b, c".
std::string commaList(const std::vector<std::string>& list);

// 0; 2 when the rule is not in the catalog, the catalog or the doc does not
// read or the doc lacks a marker.
int runFaults(const FaultsOptions& opt);

}  // namespace rayspec
