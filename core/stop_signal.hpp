#pragma once
// Ctrl-C (SIGINT), SIGTERM and SIGHUP during a command that writes an output folder: the work
// stops at its next frame and unwinds, so the folder being written (<dir>.partial) is removed as
// on any error and a folder being replaced is left as it was. Without this the process died where
// it stood and left the .partial folder (a ROS bag: 100 MB and more) until a later run into the
// same path recovered it.
//
// A command opts in with a StopOnSignal guard; the work calls throw_if_stop_requested() where
// stopping is safe (once a frame), and AtomicDirectory::commit() calls it last, so a signal is
// honoured at the latest before the output is put in place. With no guard the signals keep their
// action, and a signal the caller ignores (nohup) stays ignored. A second signal while the first
// is being honoured ends the process at once; one that comes after the commit ends it when the
// guard goes.

#include <string>

#include "core/error.hpp"

namespace wifislam {

/// Thrown by throw_if_stop_requested(): the work was asked to stop by `signal()`.
class StoppedBySignal : public Error {
 public:
  explicit StoppedBySignal(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

/// While alive, SIGINT, SIGTERM and SIGHUP only record that the work should stop; the previous
/// actions come back when it is destroyed. One at a time (the command's).
class StopOnSignal {
 public:
  StopOnSignal();
  ~StopOnSignal();
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;
};

/// Throws StoppedBySignal when one of the signals arrived under a StopOnSignal guard.
void throw_if_stop_requested();

/// The signal that asked to stop under a StopOnSignal guard, else 0: for a wait that cannot throw
/// in the middle (interop's process runner passes it on to the program it waits for).
int stop_requested_signal();

}  // namespace wifislam
