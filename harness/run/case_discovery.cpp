#include "run/case_discovery.h"

#include <fnmatch.h>

#include <algorithm>
#include <filesystem>

namespace rayspec {
namespace fs = std::filesystem;

std::vector<CaseFile> findCases(const std::string& dir, const std::string& glob) {
  std::vector<CaseFile> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file() || it->path().extension() != ".yaml") continue;
    CaseFile f = caseFileFor(it->path().string(), dir);
    if (fnmatch(glob.c_str(), f.name.c_str(), 0) == 0) out.push_back(f);
  }
  std::sort(out.begin(), out.end(), [](const CaseFile& a, const CaseFile& b) { return a.name < b.name; });
  return out;
}

CaseFile caseFileFor(const std::string& path, const std::string& cases_dir) {
  std::error_code ec;
  const fs::path abs = fs::weakly_canonical(path, ec);
  const fs::path root = fs::weakly_canonical(cases_dir, ec);
  fs::path rel = abs.lexically_relative(root);
  if (rel.empty() || *rel.begin() == "..") rel = fs::path(path).filename();
  rel.replace_extension();
  return {path, rel.generic_string()};
}

}  // namespace rayspec
