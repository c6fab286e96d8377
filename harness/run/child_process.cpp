#include "run/child_process.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#define RAYSPEC_LSAN_CHECK 1
#endif

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>
#include <sstream>
#include <thread>

#include "run/interrupt.h"

namespace rayspec {

bool memoryLimitApplies() {
  return !kAddressSanitizer;
}

bool childLeaked() {
#if defined(RAYSPEC_LSAN_CHECK)
  return __lsan_do_recoverable_leak_check() != 0;
#else
  return false;
#endif
}

namespace {

void outOfMemory() {
  static const char text[] = "rayspec: out of memory under the memory limit\n";
  [[maybe_unused]] ssize_t n = write(STDERR_FILENO, text, sizeof text - 1);
  _exit(kChildOutOfMemory);
}

void writeAll(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<size_t>(n);
  }
}

// Reads what is there now (the pipe is non-blocking); true at end of file.
bool drain(int fd, std::string& into) {
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n > 0) {
      into.append(buffer, static_cast<size_t>(n));
      continue;
    }
    if (n == 0) return true;
    return !(errno == EAGAIN || errno == EINTR);
  }
}

}  // namespace

void prepareChild(pid_t parent, const ChildLimits& limits) {
  // Dies with the parent; a parent already gone before prctl is caught by getppid().
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(kChildOrphaned);
  defaultInterrupts();
  // Under AddressSanitizer (the asan preset) the shadow memory alone is far
  // beyond any data limit: there the limit is not set.
  if (limits.memory_limit && memoryLimitApplies()) {
    const rlimit rl{limits.memory_limit, limits.memory_limit};
    setrlimit(RLIMIT_DATA, &rl);
  }
  std::set_new_handler(outOfMemory);
}

namespace {

[[noreturn]] void childMain(pid_t parent, int fd, const std::function<int(std::string&)>& body,
                            const ChildLimits& limits) {
  prepareChild(parent, limits);
  std::string message;
  int code = 0;
  try {
    code = body(message);
  } catch (const std::exception& e) {
    message = e.what();
    code = kChildException;
  }
  // _exit skips LeakSanitizer's check at exit: under AddressSanitizer the
  // child checks before it goes (tools/sanitizers/lsan.supp).
  if (kAddressSanitizer && code == 0 && childLeaked()) code = kChildLeaked;
  writeAll(fd, message);
  close(fd);
  std::fflush(nullptr);
  _exit(code);
}

}  // namespace

ChildEnd runChild(const std::function<int(std::string& message)>& body, const ChildLimits& limits) {
  ChildEnd end;
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    end.error = std::string("pipe failed: ") + std::strerror(errno);
    return end;
  }
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::fflush(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    end.error = std::string("fork failed: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return end;
  }
  if (pid == 0) {
    close(fds[0]);
    if (limits.process_group) setpgid(0, 0);
    childMain(parent, fds[1], body, limits);
  }
  if (limits.process_group) setpgid(pid, pid);  // both sides: whichever runs first
  close(fds[1]);
  fcntl(fds[0], F_SETFL, O_NONBLOCK);

  int wstatus = 0;
  bool eof = false;
  MemoryWatch memory(pid, limits.memory_limit);
  for (;;) {
    if (!eof) eof = drain(fds[0], end.message);
    const pid_t done = waitpid(pid, &wstatus, WNOHANG);
    if (done == pid) break;
    const bool lost = done < 0 && errno != EINTR;
    const bool interrupted = interruptSignal() != 0;
    const bool late = limits.timeout_seconds > 0 && elapsed() > limits.timeout_seconds;
    const bool too_big = !lost && !interrupted && !late && memory.over();
    if (lost || interrupted || late || too_big) {
      kill(limits.process_group ? -pid : pid, SIGKILL);
      while (waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
      }
      close(fds[0]);
      end.how = interrupted ? ChildEnd::How::Interrupted
                : late      ? ChildEnd::How::TimedOut
                : too_big   ? ChildEnd::How::Exited
                            : ChildEnd::How::NotStarted;
      if (too_big) end.code = kChildOutOfMemory;
      if (end.how == ChildEnd::How::NotStarted) end.error = "lost the child process";
      end.seconds = elapsed();
      return end;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  while (!eof) eof = drain(fds[0], end.message);
  close(fds[0]);
  end.seconds = elapsed();
  if (WIFSIGNALED(wstatus)) {
    end.how = ChildEnd::How::Signaled;
    end.code = WTERMSIG(wstatus);
  } else {
    end.how = ChildEnd::How::Exited;
    end.code = WEXITSTATUS(wstatus);
  }
  // A child killed by the terminal's SIGINT with the rest of the process group.
  if (interruptSignal() != 0 && !end.ok()) end.how = ChildEnd::How::Interrupted;
  return end;
}

uint64_t residentBytes(pid_t pid) {
  std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
  uint64_t size = 0, resident = 0;
  if (!(statm >> size >> resident)) return 0;
  return resident * static_cast<uint64_t>(sysconf(_SC_PAGESIZE));
}

bool MemoryWatch::over() {
  if (!limit_ || !memoryLimitApplies()) return false;
  const double now =
      std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  if (last_ >= 0 && now - last_ < 0.05) return false;
  last_ = now;
  return residentBytes(pid_) > limit_;
}

std::string formatBytes(uint64_t bytes) {
  std::ostringstream s;
  if (bytes >= (uint64_t(1) << 30) && bytes % (uint64_t(1) << 30) == 0)
    s << (bytes >> 30) << " GiB";
  else if (bytes >= (uint64_t(1) << 20))
    s << (bytes >> 20) << " MiB";
  else
    s << bytes << " bytes";
  return s.str();
}

std::string describeChildEnd(const ChildEnd& end, const std::string& who,
                             const ChildLimits& limits) {
  std::ostringstream s;
  switch (end.how) {
    case ChildEnd::How::Exited:
      if (end.code == 0) return {};
      if (end.code == kChildOutOfMemory)
        s << who << " ran out of memory (--memory-limit " << formatBytes(limits.memory_limit)
          << ")";
      else if (end.code == kChildException)
        s << who << " threw: " << end.message;
      else if (end.code == kChildLeaked)
        s << who << " leaked memory (LeakSanitizer's report is on its standard error)";
      else
        s << who << " exited with status " << end.code;
      break;
    case ChildEnd::How::Signaled:
      s << who << " died of signal " << end.code << " (" << strsignal(end.code) << ")";
      break;
    case ChildEnd::How::TimedOut:
      s << who << " ran longer than " << limits.timeout_seconds << " s (killed)";
      break;
    case ChildEnd::How::Interrupted:
      s << who << " was stopped: the run was interrupted";
      break;
    case ChildEnd::How::NotStarted:
      s << who << " could not run: " << end.error;
      break;
  }
  return s.str();
}

}  // namespace rayspec
