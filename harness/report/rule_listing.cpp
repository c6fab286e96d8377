#include "report/rule_listing.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace rayspec {
namespace {

constexpr const char* kProbeRule = "R-UB";

// The names under one rule: single cases, and sweeps as "name (N variants)".
std::vector<std::string> groupedNames(const std::vector<const ListedCase*>& cases) {
  std::vector<std::string> out;
  std::map<std::string, size_t> sweeps;  // sweep -> index in out
  std::map<std::string, int> counts;
  for (const ListedCase* c : cases) {
    if (c->sweep.empty()) {
      out.push_back(c->name);
      continue;
    }
    if (!sweeps.count(c->sweep)) {
      sweeps[c->sweep] = out.size();
      out.emplace_back();
    }
    ++counts[c->sweep];
  }
  for (const auto& [sweep, index] : sweeps)
    out[index] = sweep + " (sweep: " + std::to_string(counts[sweep]) + " variant" +
                 (counts[sweep] == 1 ? "" : "s") + ")";
  return out;
}

}  // namespace

RuleListing listRules(const std::vector<Rule>& catalog, const std::vector<ListedCase>& cases) {
  RuleListing listing;
  std::map<std::string, std::vector<const ListedCase*>> by_rule;
  std::set<std::string> known;
  for (const Rule& r : catalog) known.insert(r.label);
  for (const ListedCase& c : cases)
    for (const std::string& r : c.rules) {
      by_rule[r].push_back(&c);
      if (!known.count(r) &&
          std::find(listing.unknown.begin(), listing.unknown.end(), r) == listing.unknown.end())
        listing.unknown.push_back(r);
    }
  std::ostringstream out;
  size_t covered = 0, judged = 0;
  for (const Rule& r : catalog) {
    const std::vector<const ListedCase*>& claimed = by_rule[r.label];
    const bool probe = r.label == kProbeRule;
    if (!probe) {
      ++judged;
      if (claimed.empty())
        listing.uncovered.push_back(r.label);
      else
        ++covered;
    }
    out << r.label << "  " << r.title << "\n";
    if (probe)
      out << "  (probes: undefined behaviour is never judged; the device only has to survive "
             "these)\n";
    if (claimed.empty()) out << "  UNCOVERED: no case claims this rule\n";
    for (const std::string& name : groupedNames(claimed)) out << "  " << name << "\n";
    out << "  " << claimed.size() << " case" << (claimed.size() == 1 ? "" : "s") << "\n\n";
  }
  for (const std::string& r : listing.unknown) {
    out << r << "  NOT IN THE CATALOG (references/spec-rules.yaml)\n";
    for (const std::string& name : groupedNames(by_rule[r])) out << "  " << name << "\n";
    out << "\n";
  }
  out << covered << " of " << judged << " rules have a case (" << kProbeRule
      << " apart: " << by_rule[kProbeRule].size() << " probe"
      << (by_rule[kProbeRule].size() == 1 ? "" : "s") << "); " << cases.size() << " cases in all\n";
  if (!listing.uncovered.empty()) {
    out << "Uncovered:";
    for (const std::string& r : listing.uncovered) out << " " << r;
    out << "\n";
  }
  listing.text = out.str();
  return listing;
}

}  // namespace rayspec
