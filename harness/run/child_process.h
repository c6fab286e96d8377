// Runs a function in a forked child process under limits, so that whatever
// it does (crash, hang, exhaust memory) ends only the child. The child dies
// with its parent (PR_SET_PDEATHSIG, checked against the race with the
// parent's death), gets the default SIGINT / SIGTERM dispositions back, and
// may hold at most `memory_limit` bytes, bounded twice: RLIMIT_DATA in the
// child (heap, anonymous maps, thread stacks: an `operator new` beyond it
// ends the child with kChildOutOfMemory; address space only reserved, as
// glibc's malloc arenas and Embree reserve it, does not count), and the
// parent's watch of its resident set (shared mappings included, which
// RLIMIT_DATA leaves out and lavapipe uses): read every 50 ms, beyond the
// limit the parent kills the child and it ends as kChildOutOfMemory too. The
// parent kills the child after `timeout_seconds`, or at once when the run
// was interrupted (run/interrupt.h); with ChildLimits::process_group, its
// whole process group.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <functional>
#include <string>

namespace rayspec {

// Built with AddressSanitizer (the asan preset)?
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

// Whether ChildLimits::memory_limit is set on children: not under
// AddressSanitizer, whose shadow memory alone is beyond any data limit.
bool memoryLimitApplies();

struct ChildLimits {
  double timeout_seconds = 0;  // 0: none
  uint64_t memory_limit = 0;   // bytes (RLIMIT_DATA and the resident set); 0: none
  // The child leads a process group of its own, and a timeout or an
  // interrupt kills the whole group: what a shell command it runs started
  // goes with it. (Then the terminal's Ctrl-C reaches the parent alone.)
  bool process_group = false;
};

// Exit statuses the child itself chooses.
inline constexpr int kChildOutOfMemory = 113;  // operator new failed under the memory limit
// The body failed: it returned this with the error as its message, or an
// exception escaped it (message: what()).
inline constexpr int kChildException = 114;
inline constexpr int kChildOrphaned = 115;  // the parent was gone before the child started
inline constexpr int kChildLeaked = 116;    // AddressSanitizer build: LeakSanitizer found a leak

struct ChildEnd {
  enum class How { Exited, Signaled, TimedOut, Interrupted, NotStarted };
  How how = How::NotStarted;
  int code = 0;  // Exited: the exit status; Signaled: the signal
  double seconds = 0;
  std::string message;  // what the body left in its `message` argument
  std::string error;    // NotStarted: why (fork or pipe failed)
  bool ok() const { return how == How::Exited && code == 0; }
};

// What every child process does first (runChild's and run/worker.h's): dies
// with the thread of `parent` that forked it, takes the default SIGINT /
// SIGTERM, and holds at most the memory limit (operator new beyond it exits
// with kChildOutOfMemory). Exits kChildOrphaned when the parent is gone.
void prepareChild(pid_t parent, const ChildLimits& limits);
// AddressSanitizer build: LeakSanitizer finds a leak now (a child checks
// before _exit, which skips the check at exit). Elsewhere false.
bool childLeaked();

// `body` runs in the child; its return value is the child's exit status and
// the text it leaves in `message` reaches the parent through a pipe.
ChildEnd runChild(const std::function<int(std::string& message)>& body, const ChildLimits& limits);

// Why a child that did not end well ended, for people: "the model process
// died of signal 11 (Segmentation fault)". `who` names the process.
std::string describeChildEnd(const ChildEnd& end, const std::string& who,
                             const ChildLimits& limits);

// "8 GiB", "512 MiB".
std::string formatBytes(uint64_t bytes);

// The parent's watch of a child's resident set (/proc/PID/statm), read at
// most every 50 ms: over() when the limit applies and the child holds more.
class MemoryWatch {
 public:
  MemoryWatch(pid_t pid, uint64_t limit) : pid_(pid), limit_(limit) {}
  bool over();

 private:
  pid_t pid_;
  uint64_t limit_;
  double last_ = -1;  // seconds on the steady clock of the last read
};
// Bytes resident in `pid`'s memory now (0 when it cannot be read).
uint64_t residentBytes(pid_t pid);

}  // namespace rayspec
