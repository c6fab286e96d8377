#include "vulkan/icd_environment.h"

#include <cstdlib>
#include <optional>

#include "vulkan/icd_manifest.h"

namespace rayspec {

IcdSelection useIcdFiles(const std::vector<std::string>& files) {
  IcdSelection s;
  std::string list;
  for (const std::string& f : files) {
    Result<IcdManifest> m = readIcdManifest(f);
    if (!m) {
      s.error = m.error().format();
      return s;
    }
    s.files.push_back(m->path);
    list += (list.empty() ? "" : ":") + m->path;
  }
  if (list.empty()) return s;
  for (const char* name : {"VK_DRIVER_FILES", "VK_ICD_FILENAMES", "VK_ADD_DRIVER_FILES"})
    if (const char* old = std::getenv(name); old && *old)
      s.notes.push_back(std::string("--icd overrides ") + name + "=" + old +
                        " from the environment");
  setenv("VK_DRIVER_FILES", list.c_str(), 1);
  setenv("VK_ICD_FILENAMES", list.c_str(), 1);
  unsetenv("VK_ADD_DRIVER_FILES");
  return s;
}

}  // namespace rayspec
