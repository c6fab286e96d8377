// Finds the cases of a folder: each *.yaml file is one case, each
// *.sweep.yaml file (library/expand_sweep.h) as many as it has variants.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "parse/parse_case.h"

namespace rayspec {

struct CaseFile {
  std::string path;        // file path
  std::string name;        // path under the cases folder without .yaml (a sweep: plus /<variant>)
  bool generated = false;  // a sweep's variant: `text` holds it
  std::string text;        // a variant's substituted text
  std::vector<Error> errors;  // a sweep file that does not expand (then it is one entry)
  std::vector<std::pair<std::string, std::string>>
      params;  // a variant's sweep parameters (value text)
};

// Every case under dir (sorted by name) whose name matches glob. A sweep's
// variant matches by its own name or by the sweep's (`sbt/indexing` runs all).
// Names are checked over the whole folder (checkCaseNames).
std::vector<CaseFile> findCases(const std::string& dir, const std::string& glob);
// Whether findCases(dir, glob) takes `f` (one of dir's cases): to match many
// globs against the folder's cases listed once.
bool caseMatches(const CaseFile& f, const std::string& dir, const std::string& glob);
// The cases matching any of the globs, sorted by name, each once.
std::vector<CaseFile> findCasesAny(const std::string& dir, const std::vector<std::string>& globs);

// A case file given on the command line, named relative to cases_dir when it
// lies under it, else by its stem; a sweep file gives each of its variants.
std::vector<CaseFile> caseFilesFor(const std::string& path, const std::string& cases_dir);

// Case names become folders of a run: a name that is no case name (an empty
// variant, a part that is "..", a space, bytes that are not UTF-8), a name two
// files make, or a name that is a folder of another case (fam/a and
// fam/a/device: the second's bundles would lie inside the first's folder)
// makes its entries errors naming the files. A name that is no case name is
// replaced by caseNameFor's (results/file_name.h), the name its CaseError is
// reported under. Keeps the order and one entry per name (the first).
void checkCaseNames(std::vector<CaseFile>& files);

// The case called `name`: from `file` when given (a case file or a sweep
// file holding that variant), else looked up by name under cases_dir. Empty
// when there is none.
std::optional<CaseFile> findCase(const std::string& name, const std::string& file,
                                 const std::string& cases_dir);

// The case of a CaseFile, parsed (and checked against the catalog when given).
ParseResult loadCase(const CaseFile& f, const std::string& cases_dir,
                     const std::vector<std::string>* catalog = nullptr);

}  // namespace rayspec
