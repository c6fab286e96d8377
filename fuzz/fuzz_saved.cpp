// libFuzzer target: any bytes as one of the files rayspec reads besides case
// files. The first byte picks the format, the rest is the file:
//   0  a baseline CSV                   report/baseline.h
//   1  a flakes or skips file           (then matched against a few names)
//   2  a results bundle                 results.json; after the first NUL byte
//                                       two bytes (little-endian) give the
//                                       length of img.raw, which follows; the
//                                       rest is records.bin
//   3  a run folder's summary.json      report/outcome_json.h
// Every input must end in a value or an error: never a crash, a hang, a leak
// or undefined behaviour. And the path-escape property: whatever a reader
// accepts is safe to make paths of (case names, image names) and sized as
// results.json says; a violation aborts, which libFuzzer reports.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "report/baseline.h"
#include "report/outcome_json.h"
#include "results/file_name.h"
#include "results/record_layout.h"
#include "results/results_io.h"

namespace {
namespace fs = std::filesystem;

// A folder of this process's own, emptied for each input.
const fs::path& workDir() {
  static const fs::path dir =
      fs::temp_directory_path() / ("rayspec-fuzz-saved-" + std::to_string(getpid()));
  return dir;
}

void write(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

void require(bool property) {
  if (!property) std::abort();
}

void baselineFile(const std::string& text) {
  write(workDir() / "b.csv", text);
  const auto b = rayspec::loadBaseline((workDir() / "b.csv").string());
  if (!b) return;
  for (const auto& [name, status] : b->expected) require(rayspec::caseNameProblem(name).empty());
}

void patternsFile(const std::string& text) {
  write(workDir() / "p.txt", text);
  const auto loaded = rayspec::loadNamePatterns((workDir() / "p.txt").string());
  if (!loaded) return;
  const std::vector<rayspec::NamePattern>& patterns = *loaded;
  for (const char* name :
       {"anyhit/ignore-odd-primitives", "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa!", ""})
    (void)rayspec::findPattern(patterns, name);
}

void resultsBundle(const std::string& text) {
  const size_t nul = text.find('\0');
  write(workDir() / "results.json", text.substr(0, nul));
  std::string rest = nul == std::string::npos ? std::string() : text.substr(nul + 1);
  const size_t image_bytes =
      rest.size() >= 2 ? static_cast<uint8_t>(rest[0]) | static_cast<uint8_t>(rest[1]) << 8 : 0;
  rest = rest.size() >= 2 ? rest.substr(2) : std::string();
  write(workDir() / "img.raw", rest.substr(0, image_bytes));
  write(workDir() / "records.bin",
        rest.size() > image_bytes ? rest.substr(image_bytes) : std::string());
  const rayspec::Result<rayspec::Results> read = rayspec::readResults(workDir().string());
  if (!read) return;
  const rayspec::Results& r = *read;
  require(rayspec::caseNameProblem(r.case_name).empty());
  for (const rayspec::Image& im : r.images) {
    require(rayspec::fileNameProblem(im.name).empty());
    require(im.texels.size() == uint64_t(im.width) * im.height * im.channels);
  }
  require(r.records.empty() ||
          r.records.size() == uint64_t(r.width) * r.height * rayspec::recordWords());
}

void summaryFile(const std::string& text) {
  write(workDir() / "summary.json", text);
  const rayspec::Result<rayspec::SavedRun> run = rayspec::readSavedRun(workDir().string());
  if (!run) return;
  for (const rayspec::CaseOutcome& o : run->outcomes)
    require(rayspec::caseNameProblem(o.name).empty());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  std::error_code ec;
  fs::remove_all(workDir(), ec);
  fs::create_directories(workDir(), ec);
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  switch (data[0] % 4) {
    case 0:
      baselineFile(text);
      break;
    case 1:
      patternsFile(text);
      break;
    case 2:
      resultsBundle(text);
      break;
    default:
      summaryFile(text);
      break;
  }
  return 0;
}
