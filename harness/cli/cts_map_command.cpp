// `rayspec list --cts-map`: docs/cts-map.md with the tables of each CTS
// list made from references/cts-map.yaml and the counts it names, printed
// whole (redirect it over the page); what is wrong in the map (a group or
// count the mustpass list lacks, a case glob no case matches, a path that is
// no --through path) is printed to stderr and makes the exit status 1.
#include <algorithm>
#include <cstdio>

#include "base/whole_file.h"
#include "cli/commands.h"
#include "library/case_discovery.h"
#include "metamorphic/feature_path.h"
#include "report/cts_map.h"

namespace rayspec {

namespace {

constexpr uint64_t kMaxCtsDocBytes = 1u << 20;

// Case globs that match no case and paths that are no --through path.
std::vector<std::string> unknownCoverage(const CtsList& list, const std::string& cases_dir,
                                         const std::vector<CaseFile>& all) {
  std::vector<std::string> out;
  for (const CtsGroup& g : list.groups)
    for (const CtsAxis& a : g.axes) {
      for (const std::string& glob : a.cases)
        if (std::none_of(all.begin(), all.end(),
                         [&](const CaseFile& f) { return caseMatches(f, cases_dir, glob); }))
          out.push_back(list.name + "." + g.group + ": `" + glob + "` matches no case");
      for (const std::string& path : a.through)
        if (!featurePathFromName(path))
          out.push_back(list.name + "." + g.group + ": " + path + " is no --through path (" +
                        featurePathNames() + ")");
    }
  return out;
}

// Each list's section, and its problems appended to `problems`.
Result<std::vector<std::string>> listSections(const ListOptions& opt,
                                              const std::vector<CtsList>& lists,
                                              std::vector<std::string>& problems) {
  std::vector<std::string> sections;
  const std::vector<CaseFile> all = findCases(opt.cases_dir, "*");
  for (const CtsList& list : lists) {
    RAYSPEC_TRY(const CtsCounts counts, loadCtsCounts(ctsCountsPath(opt.cts_map_file, list)));
    for (const std::string& p : ctsMapProblems(list, counts)) problems.push_back(p);
    for (const std::string& p : unknownCoverage(list, opt.cases_dir, all)) problems.push_back(p);
    sections.push_back(ctsListSection(list, counts));
  }
  return sections;
}

Result<std::string> ctsMapPage(const ListOptions& opt, std::vector<std::string>& problems) {
  RAYSPEC_TRY(const std::vector<CtsList> lists, loadCtsMap(opt.cts_map_file));
  RAYSPEC_TRY(const std::vector<std::string> sections, listSections(opt, lists, problems));
  RAYSPEC_TRY(const std::string doc, readWholeFile(opt.cts_doc, kMaxCtsDocBytes));
  return ctsMapDocument(doc, lists, sections);
}

}  // namespace

int runCtsMap(const ListOptions& opt) {
  std::vector<std::string> problems;
  const Result<std::string> page = ctsMapPage(opt, problems);
  if (!page) {
    std::fprintf(stderr, "rayspec list --cts-map: %s\n", page.error().format().c_str());
    return 2;
  }
  std::fwrite(page->data(), 1, page->size(), stdout);
  for (const std::string& p : problems)
    std::fprintf(stderr, "rayspec list --cts-map: %s\n", p.c_str());
  return problems.empty() ? 0 : 1;
}

}  // namespace rayspec
