#include "mutate/fault_matrix.h"

#include <cstdio>
#include <map>

#include "fault/planted_fault.h"
#include "fault/rule_faults.h"
#include "mutate/planted_mutants.h"

namespace rayspec {
namespace {

bool breaksARule(const FaultInfo& f) {
  return f.kind != FaultKind::Process && f.breaks.rfind("legal:", 0) != 0;
}

// Each fault's rules, from the catalog's breaking faults.
std::map<std::string, std::string> rulesByFault() {
  std::map<std::string, std::string> rules;
  for (const RuleFaults& r : ruleFaults())
    for (const std::string& fault : r.breaks) {
      std::string& list = rules[fault];
      list += (list.empty() ? "" : ", ") + r.rule;
    }
  return rules;
}

}  // namespace

FaultMatrix::FaultMatrix() {
  const std::map<std::string, std::string> rules = rulesByFault();
  for (const FaultInfo& f : faultTable())
    if (breaksARule(f)) {
      FaultRow row;
      row.fault = f.name;
      const auto it = rules.find(f.name);
      row.rules = it == rules.end() ? "(no rule lists it)" : it->second;
      rows_.push_back(row);
    }
}

void FaultMatrix::add(const std::string& case_name, const SavedCase& saved) {
  ++cases_;
  for (FaultRow& row : rows_) {
    if (!row.found_by.empty()) continue;
    ++row.tried;
    const MutantOutcome o = judgePlantedFault(saved.c, saved.plan, saved.model, saved.device,
                                              *findFault(row.fault), false);
    row.what = o.mutation.what;
    if (!o.mutation.applied) continue;
    ++row.applied;
    if (!o.killed && o.status != Status::QualityWarning) continue;
    row.found_by = case_name;
    row.status = statusName(o.status);
    row.headline = o.headline;
  }
}

size_t FaultMatrix::found() const {
  size_t n = 0;
  for (const FaultRow& row : rows_) n += !row.found_by.empty();
  return n;
}

std::string FaultMatrix::text() const {
  std::string t = "Fault matrix: " + std::to_string(found()) + " of " +
                  std::to_string(rows_.size()) +
                  " rule-breaking planted faults found, planted in the device results of " +
                  std::to_string(cases_) + " passing cases\n";
  char took[64];
  std::snprintf(took, sizeof took, "Planting and judging took %.1f s\n\n", seconds);
  t += took;
  t += "fault | rules | found | first case | cases planted in (changed) | verdict\n";
  for (const FaultRow& r : rows_)
    t += r.fault + " | " + r.rules + " | " + (r.found_by.empty() ? "no" : "yes") + " | " +
         (r.found_by.empty() ? "-" : r.found_by) + " | " + std::to_string(r.tried) + " (" +
         std::to_string(r.applied) + ") | " + (r.found_by.empty() ? "-" : r.status) + "\n";
  t += "\nNever found (the generator's gaps):\n";
  for (const FaultRow& r : rows_)
    if (r.found_by.empty())
      t += "- " + r.fault + " (" + r.rules + "): " +
           (r.applied ? "changed something in " + std::to_string(r.applied) + " cases, never failed"
                      : "never changed anything (" + r.what + ")") +
           "\n";
  return t;
}

}  // namespace rayspec
