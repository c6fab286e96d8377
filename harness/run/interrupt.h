// SIGINT / SIGTERM during a run: the handler only records the signal; the
// run loop stops at the next point it checks (a child being waited on is
// killed), writes the reports of what it measured, marked interrupted, and
// exits 128 + the signal.
#pragma once

namespace rayspec {

// Installs the handlers (idempotent).
void catchInterrupts();
// Puts the default dispositions back (in a child process after fork).
void defaultInterrupts();
// The signal that asked the run to stop, or 0.
int interruptSignal();

}  // namespace rayspec
