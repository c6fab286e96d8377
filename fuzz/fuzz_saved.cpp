// libFuzzer target: any bytes as one of the files rayspec reads besides case
// files. The first byte picks the format, the rest is the file:
//   0  a baseline CSV                   report/baseline.h
//   1  a flakes or skips file           (then matched against a few names)
//   2  a results bundle                 results.json (seeded as written, and
//                                       with floats, negatives and values
//                                       too large for counters, sizes, rays
//                                       and ids); after the first NUL byte
//                                       two bytes (little-endian) give the
//                                       length of img.raw, which follows; the
//                                       rest is records.bin
//   3  a run folder's summary.json      report/outcome_json.h
//   4  a SPIR-V cache entry             spirv/spirv_cache.h: up to the first
//                                       NUL byte the .sum file, the rest the
//                                       .spv module; the property: it is a
//                                       miss (no sum of the fuzzer's can match
//                                       HMAC-SHA-256 of the key and module
//                                       under a secret it never sees), also
//                                       with the sum anyone can make (plain
//                                       SHA-256 of the key and module, the
//                                       format before the secret); what the
//                                       cache itself writes reads back
//   5  a shard to merge                 report/merge_runs.h: the input is its
//                                       summary.json; every case it names has
//                                       its folder as a link to a folder
//                                       outside; the property: the merged
//                                       output never holds that folder's file
//   6  a run folder's case journal      report/case_journal.h (outcomes.jsonl);
//                                       the property: a journal that reads
//                                       reads again after an append (a
//                                       resumed run's, after whatever half
//                                       line a kill left), with the case
//                                       appended
//   7  an output folder's lock file     base/output_folder.h, held by another
//                                       open file (as another process would);
//                                       the property: the claim is refused
//                                       naming the holder in one visible line
//                                       of bounded length, and succeeds once
//                                       the holder lets go
// Every input must end in a value or an error: never a crash, a hang, a leak
// or undefined behaviour. And the path-escape property: whatever a reader
// accepts is safe to make paths of (case names, image names) and sized as
// results.json says; a violation aborts, which libFuzzer reports.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "base/output_folder.h"
#include "bundle/results_io.h"
#include "report/baseline.h"
#include "report/case_journal.h"
#include "report/merge_runs.h"
#include "report/outcome_json.h"
#include "results/file_name.h"
#include "results/record_layout.h"
#include "results/sha256.h"
#include "spirv/compile_glsl.h"
#include "spirv/spirv_cache.h"

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
  const rayspec::NamePatterns& patterns = *loaded;
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

bool holds(const std::vector<rayspec::CaseOutcome>& outcomes, const std::string& name) {
  for (const rayspec::CaseOutcome& o : outcomes)
    if (o.name == name) return true;
  return false;
}

void caseJournal(const std::string& text) {
  write(workDir() / rayspec::kJournalFile, text);
  const auto outcomes = rayspec::readJournal(workDir().string());
  if (!outcomes || !*outcomes) return;
  for (const rayspec::CaseOutcome& o : **outcomes)
    require(rayspec::caseNameProblem(o.name).empty());
  rayspec::CaseOutcome appended;
  appended.name = "fuzz/appended";
  appended.verdict.add({rayspec::Status::Pass, "R-MISS", "passed", {}, 0});
  appended.deriveFromVerdict();
  require(static_cast<bool>(rayspec::appendJournal(appended, workDir().string())));
  const auto again = rayspec::readJournal(workDir().string());
  require(again && *again && holds(**again, appended.name));
  require((*again)->size() == (*outcomes)->size() + !holds(**outcomes, appended.name));
}

// The secret of the SPIR-V cache (spirv/cache_secret.h) outside the cache
// folder, as a user's is: the fuzzer writes only the folder.
void useOwnConfigDir() {
  static const fs::path dir =
      fs::temp_directory_path() / ("rayspec-fuzz-saved-config-" + std::to_string(getpid()));
  setenv("RAYSPEC_CONFIG_DIR", dir.c_str(), 1);
}

void spirvCacheEntry(const std::string& text) {
  const size_t nul = text.find('\0');
  const std::string key = rayspec::spirvCacheKey("fuzz", rayspec::Stage::Miss);
  const std::string module = nul == std::string::npos ? std::string() : text.substr(nul + 1);
  write(workDir() / rayspec::spirvCacheSumName(key), text.substr(0, nul));
  write(workDir() / rayspec::spirvCacheFileName(key), module);
  useOwnConfigDir();
  require(rayspec::setSpirvCacheDir(workDir().string()).ok());
  rayspec::clearSpirvMemoryCache();
  std::vector<uint32_t> words;
  require(!rayspec::spirvCacheLookup(key, words));
  // The fuzzer's module under the sum anyone can make.
  const auto plain = rayspec::sha256Hex({key, "\n", module});
  write(workDir() / rayspec::spirvCacheSumName(key), plain ? *plain + "\n" : std::string());
  require(!rayspec::spirvCacheLookup(key, words));
  // What the cache itself writes reads back.
  const std::vector<uint32_t> written = {0x07230203u, 0x00010400u, 0u, 1u, 0u};
  rayspec::spirvCacheStore(key, written);
  rayspec::clearSpirvMemoryCache();
  require(rayspec::spirvCacheLookup(key, words) && words == written);
  (void)rayspec::setSpirvCacheDir("");
}

void mergedShard(const std::string& text) {
  const fs::path shard = workDir() / "shard", outside = workDir() / "outside",
                 out = workDir() / "merged";
  fs::create_directories(shard);
  fs::create_directories(outside);
  write(outside / "secret.txt", "secret");
  write(shard / "summary.json", text);
  const rayspec::Result<rayspec::SavedRun> run = rayspec::readSavedRun(shard.string());
  if (!run) return;
  std::error_code ec;
  for (const rayspec::CaseOutcome& o : run->outcomes) {
    fs::create_directories((shard / o.name).parent_path(), ec);
    fs::create_directory_symlink(outside, shard / o.name, ec);
  }
  // Each case as its summary says (the merge's own judge needs the case
  // files): the property is of the links.
  const rayspec::ShardCaseJudge as_claimed =
      [](const std::string&, const rayspec::RunInfo&, const rayspec::CaseOutcome& claimed,
         bool rerun) -> rayspec::Result<std::optional<rayspec::CaseOutcome>> {
    if (rerun) return std::optional<rayspec::CaseOutcome>();
    return std::optional<rayspec::CaseOutcome>(claimed);
  };
  (void)rayspec::mergeRuns({shard.string()}, out.string(), rayspec::Baseline{}, {}, as_claimed);
  for (fs::recursive_directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec))
    require(it->path().filename() != "secret.txt");
}

void lockFile(const std::string& text) {
  const fs::path out = workDir() / "out";
  fs::create_directories(out);
  write(out / rayspec::kOutputLockFile, text);
  const int holder = open((out / rayspec::kOutputLockFile).c_str(), O_RDWR);
  require(holder >= 0 && flock(holder, LOCK_EX | LOCK_NB) == 0);
  {
    const auto refused = rayspec::claimOutputFolder(out.string(), {}, "fuzz");
    require(!refused);
    const std::string message = refused.error().format();
    require(message.find("in use by another") != std::string::npos);
    require(message.size() < 4 * rayspec::kMaxLockHolderBytes + 512);
    for (unsigned char c : message) require((c >= 0x20 && c < 0x7F) || c == '\t');
  }
  close(holder);
  require(static_cast<bool>(rayspec::claimOutputFolder(out.string(), {}, "fuzz")));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  std::error_code ec;
  fs::remove_all(workDir(), ec);
  fs::create_directories(workDir(), ec);
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  switch (data[0] % 8) {
    case 0:
      baselineFile(text);
      break;
    case 1:
      patternsFile(text);
      break;
    case 2:
      resultsBundle(text);
      break;
    case 3:
      summaryFile(text);
      break;
    case 4:
      spirvCacheEntry(text);
      break;
    case 5:
      mergedShard(text);
      break;
    case 6:
      caseJournal(text);
      break;
    default:
      lockFile(text);
      break;
  }
  return 0;
}
