#include "base/output_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <map>
#include <mutex>
#include <utility>

#include "base/plain_tree.h"
#include "base/visible_text.h"

namespace rayspec {
namespace fs = std::filesystem;
namespace {

// The output folders this process holds: each lock file (by device and
// inode) with its descriptor and how many claims hold it.
struct HeldLock {
  int fd = -1;
  int holders = 0;
};
std::mutex held_mutex;
std::map<std::string, HeldLock> held;

void letGo(const std::string& key) {
  if (key.empty()) return;
  std::lock_guard<std::mutex> lock(held_mutex);
  auto it = held.find(key);
  if (it == held.end() || --it->second.holders > 0) return;
  close(it->second.fd);  // releases the flock
  held.erase(it);
}

std::string errnoText(int error) {
  return std::strerror(error);
}

// The lock file opened without following a link or blocking on a FIFO;
// its descriptor, or the error naming it.
Result<int> openLockFile(const std::string& path) {
  const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK, 0644);
  if (fd < 0 && errno == ELOOP)
    return errorMessage(path + " is a symbolic link: rayspec writes no file through a link");
  if (fd < 0) return errorMessage(path + " cannot be written: " + errnoText(errno));
  struct stat st {};
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    close(fd);
    return errorMessage(path +
                        " is neither a regular file nor a folder (a FIFO, socket or device)");
  }
  return fd;
}

std::string lockKey(int fd) {
  struct stat st {};
  fstat(fd, &st);
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
}

// What the holder of a lock file wrote of itself, as visible text.
std::string holderOf(int fd) {
  std::string text(kMaxLockHolderBytes, '\0');
  const ssize_t n = pread(fd, text.data(), text.size(), 0);
  text.resize(n > 0 ? static_cast<size_t>(n) : 0);
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text.empty() ? "a process that has not said who it is" : visibleLine(text);
}

void writeHolder(int fd, const std::string& command) {
  char when[64];
  const std::time_t t = std::time(nullptr);
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&t));
  const std::string text =
      "rayspec " + command + ", process " + std::to_string(getpid()) + ", since " + when + "\n";
  if (ftruncate(fd, 0) == 0) (void)!pwrite(fd, text.data(), text.size(), 0);
}

// Takes the lock of `dir` for this process (again, when it holds it
// already); the key of the lock held, or who holds it.
Result<std::string> takeLock(const std::string& dir, const std::string& command) {
  RAYSPEC_TRY(const int fd, openLockFile((fs::path(dir) / kOutputLockFile).string()));
  const std::string key = lockKey(fd);
  std::lock_guard<std::mutex> lock(held_mutex);
  if (auto it = held.find(key); it != held.end()) {
    close(fd);
    ++it->second.holders;
    return key;
  }
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const std::string holder = holderOf(fd);
    close(fd);
    if (error == EWOULDBLOCK)
      return errorMessage(dir + " is in use by another " + holder +
                          ": wait for it to end, or give another --out");
    return errorMessage(dir + " cannot be locked: " + errnoText(error));
  }
  writeHolder(fd, command);
  held[key] = HeldLock{fd, 1};
  return key;
}

// A relative path of folders and file names, with no "..", no root.
bool safeRelative(const std::string& path) {
  const fs::path p(path);
  if (path.empty() || p.has_root_path()) return false;
  for (const fs::path& part : p)
    if (part == "..") return false;
  return true;
}

}  // namespace

std::string outputFolderProblem(const std::string& dir) {
  if (dir.empty()) return "the output folder is empty (give a folder)";
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(fs::absolute(dir), ec);
  if (!ec && canonical == canonical.root_path())
    return "the output folder " + dir + " is the filesystem root";
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    return "the output folder " + dir + " is not a folder";
  return "";
}

OutputFolder::OutputFolder(OutputFolder&& other) noexcept : key_(std::move(other.key_)) {
  other.key_.clear();
}

OutputFolder& OutputFolder::operator=(OutputFolder&& other) noexcept {
  if (this != &other) {
    letGo(key_);
    key_ = std::move(other.key_);
    other.key_.clear();
  }
  return *this;
}

OutputFolder::~OutputFolder() {
  letGo(key_);
}

Result<OutputFolder> claimOutputFolder(const std::string& dir,
                                       const std::vector<std::string>& writes,
                                       const std::string& command) {
  if (const std::string problem = outputFolderProblem(dir); !problem.empty())
    return errorMessage(problem);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return errorMessage("the output folder " + dir + " cannot be created: " + ec.message());
  OutputFolder folder;
  RAYSPEC_TRY(folder.key_, takeLock(dir, command));
  for (const std::string& path : writes) {
    if (!safeRelative(path)) continue;
    if (const std::string odd = plainPathProblem(dir, path); !odd.empty())
      return errorMessage(odd + ": rayspec " + command +
                          " would write through it; it is left as it is: move it, or give "
                          "another --out");
  }
  return folder;
}

}  // namespace rayspec
