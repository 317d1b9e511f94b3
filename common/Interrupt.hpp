// Ctrl-C and SIGTERM as a request, not a kill: while an InterruptGuard
// lives, the first SIGINT or SIGTERM only sets a flag that long loops poll
// (a run then ends after the frame in flight and writes what it finished);
// a second one kills the process as usual, so a stuck program still stops.
#pragma once

namespace arp {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handlers, clears the flag
  ~InterruptGuard();  // restores the previous handlers
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

// The signal that asked to stop (SIGINT or SIGTERM), 0 if none.
int interrupt_signal();
inline bool interrupt_requested() { return interrupt_signal() != 0; }

// The exit status of a program stopped by `signal`: 128 + its number, as a shell reports it.
inline int interrupted_exit_status(int signal) { return 128 + signal; }

}  // namespace arp
