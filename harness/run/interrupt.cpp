#include "run/interrupt.h"

#include <csignal>

namespace rayspec {
namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void onInterrupt(int sig) {
  g_signal = sig;
}

}  // namespace

void catchInterrupts() {
  struct sigaction sa {};
  sa.sa_handler = onInterrupt;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;  // no SA_RESTART: a blocking wait returns EINTR
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

void defaultInterrupts() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

int interruptSignal() {
  return g_signal;
}

}  // namespace rayspec
