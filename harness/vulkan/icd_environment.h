// `--icd FILE`: the Vulkan loader loads only these driver manifests. Sets
// VK_DRIVER_FILES (loader 1.3.207 and later) and VK_ICD_FILENAMES (older
// loaders) in this process's environment, and clears VK_ADD_DRIVER_FILES, so
// that every Vulkan call after it, and every child process forked after it,
// sees only these drivers. Call it before any Vulkan call.
#pragma once

#include <string>
#include <vector>

namespace rayspec {

struct IcdSelection {
  std::string error;  // a file missing or not a readable manifest: names it (a setup error)
  std::vector<std::string> notes;  // variables of the user's environment that --icd overrides
  std::vector<std::string> files;  // the manifests, absolute
};

IcdSelection useIcdFiles(const std::vector<std::string>& files);

}  // namespace rayspec
