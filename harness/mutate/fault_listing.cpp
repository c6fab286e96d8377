// `rayspec faults`: the fault table and the rules, printed.
#include "mutate/fault_listing.h"

#include <cstdio>
#include <sstream>
#include <vector>

#include "base/generated_part.h"
#include "base/whole_file.h"
#include "compare/verdict.h"
#include "fault/planted_fault.h"
#include "fault/rule_faults.h"
#include "report/rule_catalog.h"

namespace rayspec {
namespace {

// What a fault stands for: the rules it breaks or that allow it; `none`
// where it breaks no rule.
std::string rulesLine(
    const FaultInfo& f,
    const char* none = "no rule: a fault of the run itself (how a run reports it)") {
  const RulesOfFault r = rulesOfFault(f.name);
  std::string line;
  if (!r.breaks.empty()) line = "breaks " + commaList(r.breaks);
  if (!r.allows.empty()) line += (line.empty() ? "" : "; ") + ("allowed by " + commaList(r.allows));
  if (line.empty()) line = none;
  return line;
}

void printFault(const FaultInfo& f) {
  const bool live = f.kind == FaultKind::Process || f.kind == FaultKind::Vulkan;
  std::printf("%s  %s%s\n    %s\n", f.name.c_str(), rulesLine(f).c_str(),
              live ? " (a live device only)" : "", f.breaks.c_str());
}

void printFaultList(const std::string& heading, const std::vector<std::string>& names) {
  if (names.empty()) return;
  std::printf("\n%s\n", heading.c_str());
  for (const std::string& name : names)
    if (const FaultInfo* f = findFault(name))
      std::printf("  %s\n      %s\n", name.c_str(), f->breaks.c_str());
}

// One kind's faults: a heading and a line per fault.
void writeKindPart(std::ostringstream& out, FaultKind kind) {
  out << "\n**" << faultKindText(kind) << ":**\n\n";
  for (const FaultInfo& f : faultTable())
    if (f.kind == kind)
      out << "- `" << f.name << "` (" << rulesLine(f, "no rule: a fault of the run itself")
          << "): " << f.breaks << "\n";
}

int printFaultsDocument(const FaultsOptions& opt) {
  const Result<std::string> doc = readWholeFile(opt.doc_file, 1u << 20);
  if (!doc) {
    std::fprintf(stderr, "rayspec faults --doc: %s\n", doc.error().format().c_str());
    return 2;
  }
  const Result<std::string> made = faultsDocument(*doc);
  if (!made) {
    std::fprintf(stderr, "rayspec faults --doc: %s: %s\n", opt.doc_file.c_str(),
                 made.error().format().c_str());
    return 2;
  }
  std::fwrite(made->data(), 1, made->size(), stdout);
  return 0;
}

int printRule(const Rule& rule) {
  std::printf("%s: %s\n", rule.label.c_str(), rule.title.c_str());
  if (!rule.text.empty()) std::printf("  %s\n", rule.text.c_str());
  if (!rule.spec.empty()) std::printf("  Specification: %s\n", rule.spec.c_str());
  const RuleFaults* rf = findRuleFaults(rule.label);
  if (!rf) {
    std::printf("\nNo planted fault stands for this rule yet.\n");
    return 0;
  }
  if (!rf->pending.empty()) std::printf("\nNo fault: %s\n", rf->pending.c_str());
  printFaultList("Faults that break it (a case claiming it must " +
                     std::string(statusName(rf->expect)) +
                     " under one; rayspec prove plants each):",
                 rf->breaks);
  printFaultList("Faults that break it on a live device only (rayspec run --plant-fault NAME):",
                 rf->live);
  printFaultList("Variations it allows (a case claiming it must still pass each):", rf->legal);
  return 0;
}

}  // namespace

std::string commaList(const std::vector<std::string>& list) {
  std::string out;
  for (const std::string& s : list) out += (out.empty() ? "" : ", ") + s;
  return out;
}

const char* const kFaultsDocBegin =
    "<!-- planted faults: begin (generated from harness/fault/fault_table.cpp: rayspec faults "
    "--doc) -->";
const char* const kFaultsDocEnd = "<!-- planted faults: end -->";

std::string faultsDocPart() {
  std::ostringstream out;
  out << faultTable().size() << " planted faults, by where each is made; a fault whose text "
      << "begins \"legal:\" is a variation a rule allows (a legal device of `rayspec mutate`).\n";
  for (FaultKind kind :
       {FaultKind::RecordEdit, FaultKind::CaseMutation, FaultKind::Process, FaultKind::Vulkan})
    writeKindPart(out, kind);
  return out.str();
}

Result<std::string> faultsDocument(const std::string& doc) {
  return withGeneratedPart(doc, kFaultsDocBegin, kFaultsDocEnd, faultsDocPart());
}

int runFaults(const FaultsOptions& opt) {
  if (opt.doc) return printFaultsDocument(opt);
  if (opt.rule.empty()) {
    std::printf("Planted faults (rayspec run --plant-fault NAME, rayspec prove): %zu\n\n",
                faultTable().size());
    for (const FaultInfo& f : faultTable()) printFault(f);
    return 0;
  }
  const Result<std::vector<Rule>> catalog = loadRuleCatalog(opt.rules_file);
  if (!catalog) {
    std::fprintf(stderr, "rayspec faults: %s\n", catalog.error().format().c_str());
    return 2;
  }
  for (const Rule& r : *catalog)
    if (r.label == opt.rule) return printRule(r);
  std::fprintf(stderr,
               "rayspec faults: --rule: unknown rule '%s' (not in %s; `rayspec list --rules` "
               "lists the rules)\n",
               opt.rule.c_str(), opt.rules_file.c_str());
  return 2;
}

}  // namespace rayspec
