#include "vulkan/icd_manifest.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "base/whole_file.h"

namespace rayspec {
namespace fs = std::filesystem;
namespace {

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(':', start), text.size());
    if (end > start) out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? v : "";
}

std::string orDefault(const std::string& value, const std::string& fallback) {
  return value.empty() ? fallback : value;
}

// The loader's standard folders (Linux), in its order.
std::vector<std::string> standardFolders() {
  const std::string home = env("HOME");
  std::vector<std::string> bases;
  bases.push_back(orDefault(env("XDG_CONFIG_HOME"), home.empty() ? "" : home + "/.config"));
  for (const std::string& d : splitList(orDefault(env("XDG_CONFIG_DIRS"), "/etc/xdg")))
    bases.push_back(d);
  bases.push_back("/etc");
  bases.push_back(orDefault(env("XDG_DATA_HOME"), home.empty() ? "" : home + "/.local/share"));
  for (const std::string& d :
       splitList(orDefault(env("XDG_DATA_DIRS"), "/usr/local/share:/usr/share")))
    bases.push_back(d);
  std::vector<std::string> out;
  for (const std::string& b : bases)
    if (!b.empty()) out.push_back(b + "/vulkan/icd.d");
  return out;
}

// A list entry: a manifest file, or a folder of them (*.json, sorted).
void addEntry(const std::string& entry, bool from_folder_search, IcdSearch& search,
              std::set<std::string>& seen) {
  std::error_code ec;
  std::vector<std::string> files;
  if (fs::is_directory(entry, ec)) {
    for (const fs::directory_entry& e : fs::directory_iterator(entry, ec))
      if (e.path().extension() == ".json") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
  } else if (!from_folder_search) {
    files.push_back(entry);
  }
  for (const std::string& f : files) {
    const std::string key = fs::weakly_canonical(f, ec).string();
    if (!seen.insert(key.empty() ? f : key).second) continue;
    if (Result<IcdManifest> m = readIcdManifest(f))
      search.manifests.push_back(*m);
    else
      search.errors.push_back(m.error().format());
  }
}

}  // namespace

Result<IcdManifest> readIcdManifest(const std::string& path) {
  auto fail = [&](const std::string& why) {
    return errorMessage("ICD manifest " + path + ": " + why);
  };
  std::error_code ec;
  if (!fs::exists(path, ec)) return fail("no such file");
  if (fs::is_directory(path, ec)) return fail("a folder, not a manifest file");
  const Result<std::string> text = readWholeFile(path, kMaxIcdManifestBytes);
  if (!text) return fail(text.error().message);
  const nlohmann::json j = nlohmann::json::parse(*text, nullptr, false);
  if (j.is_discarded()) return fail("not JSON");
  if (!j.is_object() || !j.contains("ICD") || !j["ICD"].is_object())
    return fail("not a Vulkan driver manifest (no \"ICD\" object)");
  const nlohmann::json& icd = j["ICD"];
  if (!icd.contains("library_path") || !icd["library_path"].is_string() ||
      icd["library_path"].get<std::string>().empty())
    return fail("no ICD.library_path");
  IcdManifest m;
  m.path = fs::absolute(path, ec).lexically_normal().string();
  m.library_path = icd["library_path"];
  if (icd.contains("api_version") && icd["api_version"].is_string())
    m.api_version = icd["api_version"];
  return m;
}

IcdSearch findIcdManifests() {
  IcdSearch search;
  std::set<std::string> seen;
  const std::string driver_files = env("VK_DRIVER_FILES"), icd_filenames = env("VK_ICD_FILENAMES");
  if (!driver_files.empty() || !icd_filenames.empty()) {
    search.source =
        driver_files.empty() ? IcdSource::IcdFilenamesVariable : IcdSource::DriverFilesVariable;
    search.places = splitList(driver_files.empty() ? icd_filenames : driver_files);
  } else {
    search.places = standardFolders();
  }
  for (const std::string& added : splitList(env("VK_ADD_DRIVER_FILES")))
    addEntry(added, false, search, seen);
  for (const std::string& place : search.places)
    addEntry(place, search.source == IcdSource::StandardFolders, search, seen);
  return search;
}

std::string icdSourceName(IcdSource s) {
  switch (s) {
    case IcdSource::DriverFilesVariable:
      return "VK_DRIVER_FILES";
    case IcdSource::IcdFilenamesVariable:
      return "VK_ICD_FILENAMES";
    case IcdSource::StandardFolders:
      break;
  }
  return "the loader's standard folders";
}

std::string icdLibraryToLoad(const IcdManifest& m) {
  if (m.library_path.find('/') == std::string::npos) return m.library_path;
  const fs::path lib(m.library_path);
  return (lib.is_absolute() ? lib : fs::path(m.path).parent_path() / lib)
      .lexically_normal()
      .string();
}

bool icdLibraryMatches(const IcdManifest& m, const std::string& loaded) {
  const std::string wanted = icdLibraryToLoad(m);
  if (wanted.find('/') == std::string::npos) return fs::path(loaded).filename() == wanted;
  std::error_code a, b;
  const fs::path x = fs::canonical(wanted, a), y = fs::canonical(loaded, b);
  return !a && !b && x == y;
}

const IcdManifest* manifestOfLibrary(const std::vector<IcdManifest>& manifests,
                                     const std::string& loaded) {
  if (loaded.empty()) return nullptr;
  for (const IcdManifest& m : manifests)
    if (icdLibraryMatches(m, loaded)) return &m;
  return nullptr;
}

std::string icdLoadFailure(const IcdManifest& m) {
  const std::string lib = icdLibraryToLoad(m);
  void* handle = dlopen(lib.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    return "the driver library " + lib +
           " could not be loaded: " + (why ? why : "(no reason given)");
  }
  const bool entry = dlsym(handle, "vk_icdGetInstanceProcAddr") != nullptr;
  dlclose(handle);
  if (!entry)
    return "the driver library " + lib + " has no vk_icdGetInstanceProcAddr (not a Vulkan driver)";
  return {};
}

}  // namespace rayspec
