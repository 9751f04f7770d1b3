#include "progress_display.hpp"

#include "interrupt.hpp"

#include <cstdio>
#include <iostream>

#include <unistd.h>

namespace hlr::app {

ProgressDisplay::Mode ProgressDisplay::mode_for(bool progress_option) {
  if (::isatty(STDERR_FILENO)) return Mode::live;
  return progress_option ? Mode::lines : Mode::quiet;
}

ProgressDisplay::ProgressDisplay(Mode mode) : mode_(mode), start_(std::chrono::steady_clock::now()) {
  if (mode_ != Mode::live) return;
  // Rewrites the line every quarter second, from a second into the run: short runs print nothing.
  ticker_ = std::thread([this] {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return done_; }))
      if (std::chrono::steady_clock::now() - start_ >= std::chrono::seconds(1)) show_live(stage_);
  });
}

ProgressDisplay::~ProgressDisplay() {
  if (!ticker_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    done_ = true;
    if (shown_) std::cerr << "\r\033[K" << std::flush;
  }
  wake_.notify_one();
  ticker_.join();
}

void ProgressDisplay::show_live(const std::string& what) {
  if (what.empty()) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.1f s", elapsed);
  std::cerr << "\r\033[Khlr: " << what << " (" << seconds << ")" << std::flush;
  shown_ = true;
}

void ProgressDisplay::stage(std::string_view what) {
  set_current_stage(what);
  std::lock_guard lock(mutex_);
  stage_ = what;
  if (mode_ == Mode::lines && !what.empty()) std::cerr << ("hlr: " + std::string(what) + '\n') << std::flush;
  if (mode_ == Mode::live && what.empty() && shown_) {  // the work is done: the summary follows
    std::cerr << "\r\033[K" << std::flush;
    shown_ = false;
  }
}

exporter::Progress ProgressDisplay::progress() {
  exporter::Progress progress;
  progress.stage = [this](std::string_view what) { stage(what); };
  progress.stop = stop_token();
  return progress;
}

}  // namespace hlr::app
