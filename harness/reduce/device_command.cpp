#include "reduce/device_command.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>

#include "base/visible_text.h"

extern char** environ;

namespace rayspec {
namespace {

// Our environment, without the names c sets, then c's.
std::vector<std::string> commandEnvironment(const DeviceCommand& c) {
  std::vector<std::string> out;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    bool replaced = false;
    for (const auto& [name, value] : c.env) replaced |= entry.rfind(name + "=", 0) == 0;
    if (!replaced) out.push_back(entry);
  }
  for (const auto& [name, value] : c.env) out.push_back(name + "=" + value);
  return out;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> out;
  for (std::string& s : strings) out.push_back(s.data());
  out.push_back(nullptr);
  return out;
}

}  // namespace

ChildEnd runDeviceCommand(const DeviceCommand& c) {
  // Made before the fork: the child only opens, duplicates and executes.
  std::vector<std::string> args = {"sh", "-c", c.command}, env = commandEnvironment(c);
  const std::vector<char*> argv = pointers(args), envp = pointers(env);
  const std::string log = c.log;
  ChildLimits limits;
  limits.timeout_seconds = c.timeout_seconds;
  limits.process_group = true;
  return runChild(
      [&](std::string& message) {
        const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        const int in = open("/dev/null", O_RDONLY | O_CLOEXEC);
        if (out < 0 || in < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(out, 2) < 0) {
          message = "cannot write " + log + ": " + std::strerror(errno);
          return 127;
        }
        execve("/bin/sh", argv.data(), envp.data());
        message = std::string("cannot run /bin/sh: ") + std::strerror(errno);
        return 127;
      },
      limits);
}

std::string deviceCommandFailure(const DeviceCommand& c, const ChildEnd& end) {
  std::ostringstream s;
  s << "the device command `" << visibleLine(c.command) << "` ";
  switch (end.how) {
    case ChildEnd::How::Exited:
      s << "exited with status " << end.code;
      break;
    case ChildEnd::How::Signaled:
      s << "died of signal " << end.code << " (" << strsignal(end.code) << ")";
      break;
    case ChildEnd::How::TimedOut:
      s << "ran longer than --timeout " << c.timeout_seconds << " s: killed with its process group";
      break;
    case ChildEnd::How::Interrupted:
      s << "was stopped: the reduction was interrupted";
      break;
    case ChildEnd::How::NotStarted:
      s << "could not run: " << end.error;
      break;
  }
  if (!end.message.empty()) s << ": " << visibleLine(end.message);
  if (end.how != ChildEnd::How::TimedOut) s << " and left no results";
  s << " (its log: " << visibleLine(c.log) << ")";
  return s.str();
}

}  // namespace rayspec
