#include "library/case_discovery.h"

#include <fnmatch.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "base/whole_file.h"
#include "library/expand_sweep.h"
#include "results/file_name.h"

namespace rayspec {
namespace fs = std::filesystem;
namespace {

// The name of a file under cases_dir: its relative path without .yaml (and
// without .sweep for a sweep file), else its stem.
std::string nameOf(const std::string& path, const std::string& cases_dir) {
  std::error_code ec;
  const fs::path abs = fs::weakly_canonical(path, ec);
  const fs::path root = fs::weakly_canonical(cases_dir, ec);
  fs::path rel = abs.lexically_relative(root);
  if (rel.empty() || *rel.begin() == "..") rel = fs::path(path).filename();
  std::string name = rel.generic_string();
  for (const std::string suffix : {".sweep.yaml", ".yaml"})
    if (name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      return name.substr(0, name.size() - suffix.size());
  return name;
}

std::vector<CaseFile> expand(const std::string& path, const std::string& name) {
  const Result<std::string> text = readWholeFile(path, kMaxCaseFileBytes);
  if (!text) return {CaseFile{path, name, false, {}, {text.error()}}};
  SweepExpansion ex = expandSweep(*text, path, name);
  if (!ex.errors.empty()) return {CaseFile{path, name, false, {}, std::move(ex.errors)}};
  std::vector<CaseFile> out;
  for (SweepVariant& v : ex.variants)
    out.push_back(CaseFile{path, v.name, true, std::move(v.text), {}, std::move(v.params)});
  return out;
}

Error nameError(const CaseFile& f, const std::string& what) {
  return Error{SourceLoc{f.path, 0, 0, "name"},
               "case name '" + f.name.substr(0, 200) + "' " + what};
}

}  // namespace

void checkCaseNames(std::vector<CaseFile>& files) {
  std::vector<CaseFile> out;
  std::map<std::string, size_t> at;  // name -> its entry in out
  for (CaseFile& f : files) {
    // A name that is none: a CaseError under a name that is one, which the
    // reports and every reader of them accept (results/file_name.h).
    if (const std::string problem = caseNameProblem(f.name); !problem.empty()) {
      const std::string stand_in = caseNameFor(f.name);
      f.errors.push_back(
          nameError(f, "is no case name: " + problem + "; reported as '" + stand_in + "'"));
      f.name = stand_in;
    }
    if (const auto same = at.find(f.name); same != at.end()) {
      CaseFile& first = out[same->second];
      first.errors.push_back(
          nameError(first, "is made twice: by " + first.path + " and by " + f.path));
      continue;
    }
    at[f.name] = out.size();
    out.push_back(std::move(f));
  }
  // A name that is a folder of another: each of a name's '/'-prefixes looked up.
  for (CaseFile& inner : out)
    for (size_t slash = inner.name.find('/'); slash != std::string::npos;
         slash = inner.name.find('/', slash + 1)) {
      const auto folder = at.find(inner.name.substr(0, slash));
      if (folder == at.end()) continue;
      CaseFile& outer = out[folder->second];
      outer.errors.push_back(
          nameError(outer, "is a folder of case '" + inner.name + "' (" + inner.path +
                               "): its bundles would lie inside this case's folder"));
      inner.errors.push_back(nameError(
          inner, "lies inside the folder of case '" + outer.name + "' (" + outer.path + ")"));
    }
  files = std::move(out);
}

std::vector<CaseFile> caseFilesFor(const std::string& path, const std::string& cases_dir) {
  const std::string name = nameOf(path, cases_dir);
  if (!isSweepFile(path)) return {CaseFile{path, name, false, {}, {}}};
  return expand(path, name);
}

bool caseMatches(const CaseFile& f, const std::string& dir, const std::string& glob) {
  const bool whole = f.generated && fnmatch(glob.c_str(), nameOf(f.path, dir).c_str(), 0) == 0;
  return whole || fnmatch(glob.c_str(), f.name.c_str(), 0) == 0;
}

std::vector<CaseFile> findCases(const std::string& dir, const std::string& glob) {
  std::vector<CaseFile> out;
  std::error_code ec;
  std::vector<fs::path> paths;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file() && it->path().extension() == ".yaml") paths.push_back(it->path());
  std::vector<CaseFile> all;  // every case of the folder: names are checked against each other
  for (const fs::path& p : paths) {
    const std::string name = nameOf(p.string(), dir);
    if (!isSweepFile(p.string())) {
      all.push_back(CaseFile{p.string(), name, false, {}, {}});
      continue;
    }
    for (CaseFile& f : expand(p.string(), name)) all.push_back(std::move(f));
  }
  checkCaseNames(all);
  for (CaseFile& f : all)
    if (caseMatches(f, dir, glob)) out.push_back(std::move(f));
  std::sort(out.begin(), out.end(),
            [](const CaseFile& a, const CaseFile& b) { return a.name < b.name; });
  return out;
}

std::vector<CaseFile> findCasesAny(const std::string& dir, const std::vector<std::string>& globs) {
  std::vector<CaseFile> out;
  for (const std::string& glob : globs)
    for (CaseFile& f : findCases(dir, glob)) out.push_back(std::move(f));
  std::stable_sort(out.begin(), out.end(),
                   [](const CaseFile& a, const CaseFile& b) { return a.name < b.name; });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const CaseFile& a, const CaseFile& b) { return a.name == b.name; }),
            out.end());
  return out;
}

std::optional<CaseFile> findCase(const std::string& name, const std::string& file,
                                 const std::string& cases_dir) {
  std::error_code ec;
  std::vector<CaseFile> files;
  if (!file.empty() && fs::is_regular_file(file, ec))
    files = caseFilesFor(file, cases_dir);
  else
    files = findCases(cases_dir, name);
  for (CaseFile& f : files)
    if (f.name == name || files.size() == 1) return std::move(f);
  return std::nullopt;
}

ParseResult loadCase(const CaseFile& f, const std::string& cases_dir,
                     const std::vector<std::string>* catalog) {
  if (!f.errors.empty()) {
    ParseResult r;
    r.errors = f.errors;
    return r;
  }
  if (f.generated) return parseCaseText(f.text, f.path, f.name, catalog);
  return parseCaseFile(f.path, cases_dir, catalog);
}

}  // namespace rayspec
