// One run of `rayspec reduce --device-command CMD`: `/bin/sh -c CMD` (CMD is
// never joined with other text into a shell line), with the variant's paths
// as environment variables, standard input from /dev/null, standard output
// and error into a log file (by file descriptor: the log's path is no shell
// text), in a process group of its own that the timeout (--timeout) or an
// interrupt kills whole.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "run/child_process.h"

namespace rayspec {

struct DeviceCommand {
  std::string command;                                   // CMD, as given
  std::vector<std::pair<std::string, std::string>> env;  // set for it (replacing ours)
  std::string log;                                       // its standard output and error
  double timeout_seconds = 0;                            // 0: none
};

// How it ended (ChildEnd::How::Exited with its exit status, Signaled,
// TimedOut, Interrupted, or NotStarted with why).
ChildEnd runDeviceCommand(const DeviceCommand& c);

// Why a run is no use (it ended badly and left no results, or ran out of
// time), for people: "the device command `CMD` exited with status 3 and left
// no results (its log: LOG)"; "... ran longer than --timeout 2 s: killed with
// its process group (its log: LOG)".
std::string deviceCommandFailure(const DeviceCommand& c, const ChildEnd& end);

}  // namespace rayspec
