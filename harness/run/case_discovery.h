// Finds case files under a folder and filters them by a name glob.
#pragma once

#include <string>
#include <vector>

namespace rayspec {

struct CaseFile {
  std::string path;  // file path
  std::string name;  // path under the cases folder, without .yaml
};

// All *.yaml files under dir (sorted by name) whose name matches glob.
std::vector<CaseFile> findCases(const std::string& dir, const std::string& glob);

// A case file given on the command line: its name relative to cases_dir when
// it lies under it, else its stem.
CaseFile caseFileFor(const std::string& path, const std::string& cases_dir);

}  // namespace rayspec
