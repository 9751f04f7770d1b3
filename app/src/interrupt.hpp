// Stopping a run early, cleanly: SIGINT, SIGTERM and SIGHUP, and --timeout.
//
// While a job runs (a JobScope is alive), a first signal or the deadline sets the stop flag that
// the library's jobs poll (Progress::stop): the work stops at its next check, the exception
// unwinds, every output's temporary file is removed, and main reports one line. Outside a job
// (reading meshes, writing files), and at a second signal, the handler removes the temporary
// files itself and exits at once. Exit codes: 128 + the signal's number (130 for SIGINT, 143
// for SIGTERM, 129 for SIGHUP), kExitTimeout for --timeout.
#pragma once

#include <hlr/kernel/errors.hpp>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace hlr::app {

// Installs the handlers (once; signals ignored at start, as under nohup, stay ignored).
void install_signal_handlers();

// The flag jobs poll, set by a signal or the deadline.
StopToken stop_token();

// The signal that stopped the run, or 0.
int stop_signal();

// Marks the span in which a signal stops the work through the flag rather than at once.
class JobScope {
 public:
  JobScope();
  ~JobScope();
  JobScope(const JobScope&) = delete;
  JobScope& operator=(const JobScope&) = delete;
};

// Marks a span inside a JobScope that does not poll the flag (reading meshes): there a signal
// stops the run at once.
class StopAtOnce {
 public:
  StopAtOnce();
  ~StopAtOnce();
  StopAtOnce(const StopAtOnce&) = delete;
  StopAtOnce& operator=(const StopAtOnce&) = delete;
};

// The temporary file of an output being written: removed by the handler when the run is stopped
// at once. Up to 256 at a time (more are still removed by their AtomicFile when the work stops
// through the flag).
void register_temporary(const char* path);
void unregister_temporary(const char* path);

// --timeout SECONDS: sets the stop flag when the time is up.
class Deadline {
 public:
  explicit Deadline(double seconds);  // <= 0: none
  ~Deadline();
  Deadline(const Deadline&) = delete;
  Deadline& operator=(const Deadline&) = delete;

 private:
  double seconds_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread timer_;
};

// The --timeout that stopped the run (seconds), or 0.
double timeout_reached();

// The stage a run is in, for the one line that says where it stopped.
void set_current_stage(std::string_view stage);
std::string current_stage();

}  // namespace hlr::app
