#include <csignal>
#include <unistd.h>

#include "fault/planted_fault.h"

namespace rayspec {

void raiseProcessFault(const std::string& name) {
  if (name == "crash") {
    std::signal(SIGSEGV, SIG_DFL);
    std::raise(SIGSEGV);
  }
  if (name == "hang")
    for (;;) pause();
}

}  // namespace rayspec
