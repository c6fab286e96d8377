// Vulkan driver (ICD) manifests: the JSON files through which the Vulkan
// loader finds driver libraries. Read one, find the ones the loader would
// read (VK_DRIVER_FILES / VK_ICD_FILENAMES when set, else its standard
// folders), tell which manifest a loaded driver library came from, and say
// why a manifest's driver cannot be loaded.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/result.h"

namespace rayspec {

struct IcdManifest {
  std::string path;          // the manifest file (absolute)
  std::string library_path;  // ICD.library_path as written
  std::string api_version;   // ICD.api_version ("" when absent)
};

// Reads one manifest, or the error naming the file and what is wrong
// (missing, unreadable, larger than kMaxIcdManifestBytes, not JSON, no
// ICD.library_path).
Result<IcdManifest> readIcdManifest(const std::string& path);
constexpr uint64_t kMaxIcdManifestBytes = 1u << 20;  // Mesa's are under 200 bytes

// Where the manifests were found and what was wrong with some of them.
enum class IcdSource { DriverFilesVariable, IcdFilenamesVariable, StandardFolders };

struct IcdSearch {
  IcdSource source = IcdSource::StandardFolders;
  std::vector<std::string> places;  // the variable's entries, or the folders searched
  std::vector<IcdManifest> manifests;
  std::vector<std::string> errors;  // manifests that could not be read, one message each
};

// The manifests the loader would read now: VK_DRIVER_FILES (or, when that is
// unset, VK_ICD_FILENAMES) as a ':'-separated list of files or folders, plus
// VK_ADD_DRIVER_FILES; else $XDG_CONFIG_HOME, $XDG_CONFIG_DIRS, /etc,
// $XDG_DATA_HOME and $XDG_DATA_DIRS, each with vulkan/icd.d. A manifest met
// twice (by its real path) is listed once; a folder's manifests are sorted.
IcdSearch findIcdManifests();
std::string icdSourceName(IcdSource s);  // "VK_DRIVER_FILES", ..., "the loader's standard folders"

// The library the loader opens: a library_path with a '/' relative to the
// manifest's folder, else the bare name (the dynamic linker searches it).
std::string icdLibraryToLoad(const IcdManifest& m);

// Does `loaded` (a loaded library's path, e.g. from dladdr) come from m?
bool icdLibraryMatches(const IcdManifest& m, const std::string& loaded);

// The manifest among `manifests` whose library is `loaded`; nullptr if none.
const IcdManifest* manifestOfLibrary(const std::vector<IcdManifest>& manifests,
                                     const std::string& loaded);

// Why m's driver cannot serve the loader: the library cannot be opened (the
// dynamic linker's message) or lacks vk_icdGetInstanceProcAddr; "" when it
// opens and has it. Opens the library in this process: call it in a child.
std::string icdLoadFailure(const IcdManifest& m);

}  // namespace rayspec
