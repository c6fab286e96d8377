#include <sys/stat.h>
#include <unistd.h>
#include <csignal>
#include <cstdio>
#include <functional>
#include <string>

#include <fcntl.h>

#include "fault/planted_fault.h"

namespace rayspec {
namespace {

void crash() {
  std::signal(SIGSEGV, SIG_DFL);
  std::raise(SIGSEGV);
}

// True the first time a case asks in this run folder: a marker file there
// records it.
bool firstTimeInThisRun(const std::string& run_dir, const std::string& case_name) {
  const std::string marker =
      run_dir + "/.crash-once-" + std::to_string(std::hash<std::string>{}(case_name));
  const int fd = open(marker.c_str(), O_CREAT | O_EXCL | O_WRONLY, 0600);
  if (fd < 0) return false;
  close(fd);
  return true;
}

// How many cases asked this process for crash-if-reused so far: the state an
// earlier case leaves behind in a driver (lavapipe 26.2.6 reads BVH slots it
// never wrote; after other cases they hold stale data).
int& casesSeenInThisProcess() {
  static int seen = 0;
  return seen;
}

}  // namespace

void raiseProcessFault(const std::string& name, const std::string& case_name,
                       const std::string& run_dir) {
  if (name == "crash") crash();
  if (name == "crash-once" && firstTimeInThisRun(run_dir, case_name)) crash();
  if (name == "crash-if-reused" && casesSeenInThisProcess()++ > 0) crash();
  if (name == "hang")
    for (;;) pause();
}

}  // namespace rayspec
