#include "fuzz/saved_cases.h"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "base/whole_file.h"
#include "bundle/results_io.h"
#include "fuzz/content_features.h"
#include "results/content_hash.h"
#include "run/device_results.h"

namespace rayspec {
namespace {

namespace fs = std::filesystem;

constexpr uint64_t kMaxCaseBytes = uint64_t(1) << 20;  // as the fuzzer keeps a finding's case

Error placeError(const std::string& file, const std::string& field, std::string message) {
  SourceLoc at;
  at.file = file;
  at.field = field;
  return Error{at, std::move(message)};
}

// The bundle of the case in `device_results`, if saved there, must have run `text`.
Result<void> matchesBundle(const std::string& device_results, const std::string& name,
                           const std::string& file, const std::string& text) {
  const std::string json = savedBundleDir(device_results, name) + "/results.json";
  std::error_code ec;
  if (!fs::exists(json, ec)) return {};  // not run there: the run says so (NotSupported)
  const Result<std::string> saved = readWholeFile(json, kMaxResultsJsonBytes);
  if (!saved) return saved.error();
  const nlohmann::json j = nlohmann::json::parse(*saved, nullptr, false);
  if (j.is_discarded() || !j.contains("case_hash") || !j["case_hash"].is_string())
    return placeError(json, "case_hash", "missing or not a string: cannot tell which text ran");
  const std::string ran = j["case_hash"], here = contentHashText(contentHash(text));
  if (ran != here)
    return placeError(json, "case_hash",
                      ran + ", but the saved case " + file + " hashes to " + here +
                          ": the device ran another text than the one saved; judge it with the "
                          "cases that run was made from");
  return {};
}

}  // namespace

Result<GeneratedCase> savedCase(const std::string& cases, const std::string& device_results,
                                uint64_t seed) {
  GeneratedCase g;
  g.seed = seed;
  g.name = fuzzCaseName(seed);
  const std::string file = (fs::path(cases) / (g.name + ".yaml")).string();
  std::error_code ec;
  if (!fs::exists(file, ec))
    return placeError(file, "",
                      "no saved case text for seed " + std::to_string(seed) +
                          " (--saved-cases): the device run is judged only against the texts "
                          "it ran, never a regeneration; not judged");
  Result<std::string> text = readWholeFile(file, kMaxCaseBytes);
  if (!text) return text.error();
  RAYSPEC_TRY_VOID(matchesBundle(device_results, g.name, file, *text));
  g.yaml = std::move(*text);
  g.features = contentFeatures(g.yaml);
  return g;
}

}  // namespace rayspec
