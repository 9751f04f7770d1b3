// Errors the library's jobs throw to their caller (the hlr program prints them as one line).
#pragma once

#include <atomic>
#include <stdexcept>
#include <string>

namespace hlr {

// A problem with a file the user named, or with input standing for one (an input that is not
// valid, an output that cannot be written). what() is "FILE: problem", one line.
struct UserError : std::runtime_error {
  UserError(const std::string& file, const std::string& problem) : std::runtime_error(file + ": " + problem) {}
};

// A job stopped because its caller asked it to (a StopToken, or Progress::cancelled in
// hidden_line/jobs.hpp).
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

// A flag that asks the work to stop, as the long stages poll it (every so many items, so that a
// stop takes effect within a fraction of a second); a default token never stops. The flag is the
// caller's (a signal handler's, a timer's, a Python caller's) and must outlive the work.
class StopToken {
 public:
  StopToken() = default;
  explicit StopToken(const std::atomic<bool>* flag) : flag_(flag) {}
  bool requested() const { return flag_ && flag_->load(std::memory_order_relaxed); }
  void check() const {
    if (requested()) throw Cancelled();
  }
  // check() once every `period` calls, counted in `count`: for the innermost loops.
  void check_every(std::size_t& count, std::size_t period) const {
    if (flag_ && ++count % period == 0) check();
  }

 private:
  const std::atomic<bool>* flag_ = nullptr;
};

}  // namespace hlr
