// What a command that writes a run folder (run, merge, compare) writes in
// it: the paths its output folder is claimed for (base/output_folder.h).
#pragma once

#include <string>
#include <vector>

namespace rayspec {

// The reports (report/write_reports.h), the case journal and each case's
// folder (its name as a relative path; an empty name, the one case of a
// compare of two bundles, writes its outputs in the folder itself).
std::vector<std::string> runFolderWrites(const std::vector<std::string>& case_names);

}  // namespace rayspec
