// `rayspec list`: the cases of a folder (sweeps expanded) with the rules they
// claim; `--rules`: rule -> cases, failing when a rule has no case.
#include <cstdio>

#include "cli/commands.h"
#include "library/case_discovery.h"
#include "report/rule_catalog.h"
#include "report/rule_listing.h"

namespace rayspec {

int runList(const ListOptions& opt) {
  const Result<std::vector<Rule>> loaded = loadRuleCatalog(opt.rules_file);
  if (!loaded) {
    std::fprintf(stderr, "rayspec list: %s\n", loaded.error().format().c_str());
    return 2;
  }
  const std::vector<Rule>& catalog = *loaded;
  const std::vector<CaseFile> files = findCases(opt.cases_dir, opt.filter);
  if (files.empty()) {
    std::fprintf(stderr, "rayspec list: no case matches '%s' in %s\n", opt.filter.c_str(),
                 opt.cases_dir.c_str());
    return 2;
  }
  const std::vector<std::string> labels = ruleLabels(catalog);
  std::vector<ListedCase> cases;
  int bad = 0;
  for (const CaseFile& f : files) {
    const ParseResult parsed = loadCase(f, opt.cases_dir, &labels);
    for (const Error& e : parsed.errors) std::fprintf(stderr, "%s\n", e.format().c_str());
    if (!parsed.value) {
      ++bad;
      continue;
    }
    const std::string sweep = f.generated ? f.name.substr(0, f.name.rfind('/')) : "";
    cases.push_back({f.name, sweep, parsed.value->rules});
  }
  int status = bad ? 1 : 0;
  if (opt.rules) {
    const RuleListing listing = listRules(catalog, cases);
    std::printf("%s", listing.text.c_str());
    if (!listing.uncovered.empty() || !listing.unknown.empty()) status = 1;
  } else {
    for (const ListedCase& c : cases) {
      std::printf("%-52s", c.name.c_str());
      for (const std::string& r : c.rules) std::printf(" %s", r.c_str());
      std::printf("\n");
    }
    std::printf("%zu cases\n", cases.size());
  }
  if (bad)
    std::fprintf(stderr, "rayspec list: %d case%s do not parse (above)\n", bad,
                 bad == 1 ? "" : "s");
  return status;
}

}  // namespace rayspec
