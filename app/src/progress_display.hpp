// What a long run says on stderr while it works.
//
// On a terminal, the stage and the time it has run so far, on one line rewritten in place (from a
// second into the run; the line is cleared when the run ends). Elsewhere nothing, unless
// --progress asks for one line per stage (what a log file wants). The stage is also what the
// one-line message of a stopped run names (interrupt.hpp).
#pragma once

#include <hlr/export/jobs.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

namespace hlr::app {

class ProgressDisplay {
 public:
  enum class Mode { quiet, lines, live };
  // live on a terminal; lines with --progress elsewhere; quiet otherwise.
  static Mode mode_for(bool progress_option);

  explicit ProgressDisplay(Mode mode);
  ~ProgressDisplay();
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;

  // The Progress a job reports to (and polls the run's stop flag through).
  exporter::Progress progress();
  // A stage of the command itself ("view front (1 of 3)", "writing 3 outputs"); "" when the
  // work is done and the summary follows.
  void stage(std::string_view what);

 private:
  void show_live(const std::string& what);  // with mutex_ held
  Mode mode_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::string stage_;
  bool shown_ = false, done_ = false;
  std::thread ticker_;
};

}  // namespace hlr::app
