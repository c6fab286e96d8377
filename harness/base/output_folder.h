// The folder a command writes (--out): made when missing, held by one
// rayspec at a time, and checked so that nothing is written, replaced or
// deleted through a link. rayspec never removes an entry of the folder it
// did not write: a path it would write through a link, a FIFO or a socket
// makes the command refuse, naming the entry, and leaves it as it was.
#pragma once

#include <string>
#include <vector>

#include "base/result.h"

namespace rayspec {

// The lock file each command holds in its output folder, and the most of it
// that is read back to name a holder.
inline constexpr const char* kOutputLockFile = ".rayspec-lock";
inline constexpr size_t kMaxLockHolderBytes = 1024;

// Empty when `dir` can be an output folder as given: not empty, not the
// filesystem root, not a file. Changes nothing (CLI11 calls it while parsing
// the options, before the command's own checks).
std::string outputFolderProblem(const std::string& dir);

// A held output folder: the lock is released when the last holder in this
// process lets go (a command that runs another in-process into the same
// folder holds it twice).
class OutputFolder {
 public:
  OutputFolder() = default;
  OutputFolder(OutputFolder&& other) noexcept;
  OutputFolder& operator=(OutputFolder&& other) noexcept;
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  ~OutputFolder();

 private:
  friend Result<OutputFolder> claimOutputFolder(const std::string&, const std::vector<std::string>&,
                                                const std::string&);
  std::string key_;  // the held lock file's device and inode; empty: nothing held
};

// Claims `dir` for `command` ("run", "merge" ...): creates it (and its
// parents) when missing, takes its lock (another process holding it: an
// error naming the holder), and checks every entry the command writes:
// `writes` holds paths relative to `dir` ("summary.json", a case name); each
// folder on the way to one, and everything below it, must be a regular file
// or a folder, else an error naming the entry. Nothing is removed. A write
// that names no safe relative path (empty, absolute, "..") is left to the
// command's own checks.
Result<OutputFolder> claimOutputFolder(const std::string& dir,
                                       const std::vector<std::string>& writes,
                                       const std::string& command);

}  // namespace rayspec
