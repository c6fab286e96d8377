// A write that really fails, as on a full disk: while a FileSizeLimit lives,
// this process may write no file past `bytes` (RLIMIT_FSIZE; write(2) then
// fails with EFBIG, whoever the user is, root included), and SIGXFSZ, which
// would kill it, is ignored.
#pragma once

#include <sys/resource.h>

#include <csignal>
#include <cstdint>

namespace rayspec {

class FileSizeLimit {
 public:
  explicit FileSizeLimit(uint64_t bytes) {
    getrlimit(RLIMIT_FSIZE, &was_);
    signal_was_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit now = was_;
    now.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &now);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &was_);
    std::signal(SIGXFSZ, signal_was_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit was_{};
  void (*signal_was_)(int) = SIG_DFL;
};

}  // namespace rayspec
