#include "report/run_folder_writes.h"

#include "report/case_journal.h"
#include "report/write_reports.h"
#include "results/file_name.h"

namespace rayspec {

std::vector<std::string> runFolderWrites(const std::vector<std::string>& case_names) {
  std::vector<std::string> writes(kReportFiles.begin(), kReportFiles.end());
  writes.push_back(kJournalFile);
  for (const std::string& name : case_names)
    if (name.empty())  // one bundle's case: its outputs in the folder itself
      writes.insert(writes.end(), kCaseOutputs.begin(), kCaseOutputs.end());
    else
      writes.push_back(name);
  return writes;
}

}  // namespace rayspec
