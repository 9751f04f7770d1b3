#include "interrupt.hpp"

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

#include <unistd.h>

namespace hlr::app {
namespace {

std::atomic<bool> g_stop = false;
volatile std::sig_atomic_t g_signal = 0;
std::atomic<int> g_jobs = 0;
std::atomic<double> g_timeout_reached = 0;
std::array<std::atomic<const char*>, 256> g_temporaries{};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<const char*>::is_always_lock_free,
              "the signal handler needs lock-free atomics");

std::mutex g_stage_mutex;
std::string g_stage;

void write_stderr(const char* text) {
  const std::size_t n = std::strlen(text);
  for (std::size_t done = 0; done < n;) {
    const ssize_t w = ::write(STDERR_FILENO, text + done, n - done);
    if (w <= 0) return;
    done += static_cast<std::size_t>(w);
  }
}

extern "C" void on_stop_signal(int signo) {
  const bool first = g_signal == 0;
  if (first) g_signal = signo;
  if (first && g_jobs.load() > 0) {
    g_stop.store(true);  // the job stops at its next check; main reports it
    return;
  }
  for (auto& slot : g_temporaries)
    if (const char* path = slot.load()) ::unlink(path);
  write_stderr(signo == SIGINT    ? "hlr: interrupted (SIGINT); no file written\n"
               : signo == SIGTERM ? "hlr: terminated (SIGTERM); no file written\n"
                                  : "hlr: hung up (SIGHUP); no file written\n");
  ::_exit(128 + signo);
}

}  // namespace

void install_signal_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int signo : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction previous {};
      sigaction(signo, nullptr, &previous);
      if (previous.sa_handler == SIG_IGN) continue;  // e.g. started under nohup: keep ignoring
      struct sigaction action {};
      action.sa_handler = on_stop_signal;
      sigemptyset(&action.sa_mask);
      sigaction(signo, &action, nullptr);
    }
  });
}

StopToken stop_token() { return StopToken(&g_stop); }

int stop_signal() { return g_signal; }

JobScope::JobScope() { ++g_jobs; }
JobScope::~JobScope() { --g_jobs; }

StopAtOnce::StopAtOnce() { --g_jobs; }
StopAtOnce::~StopAtOnce() {
  ++g_jobs;
  if (g_signal != 0) g_stop.store(true);  // a signal may have come as the span ended
}

void register_temporary(const char* path) {
  for (auto& slot : g_temporaries) {
    const char* empty = nullptr;
    if (slot.compare_exchange_strong(empty, path)) return;
  }
}

void unregister_temporary(const char* path) {
  for (auto& slot : g_temporaries) {
    const char* expected = path;
    if (slot.compare_exchange_strong(expected, nullptr)) return;
  }
}

Deadline::Deadline(double seconds) : seconds_(seconds) {
  if (seconds <= 0) return;
  timer_ = std::thread([this] {
    std::unique_lock lock(mutex_);
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds_);
    if (!wake_.wait_until(lock, until, [this] { return done_; })) {
      g_timeout_reached.store(seconds_);
      g_stop.store(true);
    }
  });
}

Deadline::~Deadline() {
  if (!timer_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  wake_.notify_one();
  timer_.join();
}

double timeout_reached() { return g_timeout_reached.load(); }

void set_current_stage(std::string_view stage) {
  std::lock_guard lock(g_stage_mutex);
  g_stage = stage;
}

std::string current_stage() {
  std::lock_guard lock(g_stage_mutex);
  return g_stage;
}

}  // namespace hlr::app
