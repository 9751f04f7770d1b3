// `hlr batch MANIFEST.json [--jobs N] [--threads N] [--timeout S] [--job-timeout S] [--list]`: the
// jobs of an hlr-batch/1 manifest (batch_manifest.hpp) on a local pool.
//
// Each job is a child process of this same program (/proc/self/exe) with the job's command line,
// started in the manifest's folder. So a job's files are the ones `hlr COMMAND ...` writes, by
// construction; a job that fails, or crashes, is one failed job and the others go on; and each job
// has the process a single run has (its own memory, --threads, --timeout, signals, atomic
// outputs). At most --jobs children run at once: the pool is this process waiting for any child to
// finish. A signal that ends the batch is passed on to the running jobs first.
//
// --timeout bounds the whole batch: when it expires, the running jobs get SIGTERM and stop as a
// single run stopped by a signal does (no file written), the jobs not started are not run, and the
// batch exits 124 as a run at its --timeout does. --job-timeout is every job's own --timeout.
//
// stdout gets one line per job as it finishes, "job K ok: OUTPUT..." or "job K failed: PROBLEM"
// (the job's own one-line error, without "hlr: "), and at a --timeout "job K stopped: ..." and
// "job K not run: ..."; stderr gets the jobs' warnings and a summary. The exit status is 1 when
// any job failed. `--list` prints the jobs instead of running them, one JSON object a line,
// {"job": K, "arguments": [...], "inputs": [...], "outputs": [...]} (which arguments are input and
// output paths): hlrdraw.batch runs them on Dask from that.
#include "batch_manifest.hpp"
#include "errors.hpp"
#include "subcommand.hpp"

#include <hlr/export/polygons.hpp>  // number_text

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace hlr::app {
namespace {

namespace fs = std::filesystem;

struct BatchOptions {
  std::string manifest;
  int jobs = 0;     // 0: one per core
  int threads = 0;  // 0: what each job says (else every core)
  double timeout = 0;      // seconds of wall clock for the whole batch; 0: none
  double job_timeout = 0;  // every job's --timeout, unless its options have one; 0: none
  bool list = false;
};

using Clock = std::chrono::steady_clock;

// The program's own file: the children run the same build of hlr as the batch.
std::string own_executable() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot find the hlr program itself (/proc/self/exe: " + ec.message() + ")");
  return self.string();
}

// A signal that ends the batch (SIGINT, SIGTERM, SIGHUP) is passed on to the running jobs before
// the batch ends with it, so that each job stops as a single run does (removing its temporary
// files) instead of running on unwatched. At a terminal, Ctrl-C reaches the jobs anyway (they are
// in its process group); a SIGTERM to the batch alone does not. The handler only reads this table
// and calls kill(): async-signal-safe.
constexpr std::size_t kMaxRunning = 1024;  // --jobs is at most 1024
std::atomic<pid_t> g_running[kMaxRunning];

extern "C" void pass_signal_to_jobs(int signo) {
  for (auto& slot : g_running)
    if (const pid_t pid = slot.load(); pid > 0) ::kill(pid, signo);
  std::signal(signo, SIG_DFL);
  std::raise(signo);
}

void install_signal_forwarding() {
  for (int signo : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction previous {};
    sigaction(signo, nullptr, &previous);
    if (previous.sa_handler == SIG_IGN) continue;  // started under nohup: keep ignoring
    struct sigaction action {};
    action.sa_handler = pass_signal_to_jobs;
    sigemptyset(&action.sa_mask);
    sigaction(signo, &action, nullptr);
  }
}

void set_running(pid_t pid, bool running) {
  for (auto& slot : g_running) {
    pid_t expected = running ? 0 : pid;
    if (slot.compare_exchange_strong(expected, running ? pid : 0)) return;
  }
}

struct Running {
  std::size_t job = 0;
  std::FILE* stderr_file = nullptr;  // the child's stderr, read when it has finished
};

// How the jobs went.
struct Tally {
  std::size_t ok = 0, failed = 0, stopped = 0, not_run = 0;
  bool timed_out = false;
};

// SIGCHLD is blocked while the pool runs, so that a child that ends before the pool waits leaves
// it pending (Linux keeps a blocked signal pending even when its action is to ignore it) and
// sigtimedwait sees it: a wait with a deadline and no race. The children start with no signal
// blocked (posix_spawnattr_setsigmask).
sigset_t child_signal() {
  sigset_t child;
  sigemptyset(&child);
  sigaddset(&child, SIGCHLD);
  return child;
}

class BlockChildSignal {
 public:
  BlockChildSignal() {
    const sigset_t child = child_signal();
    ::pthread_sigmask(SIG_BLOCK, &child, &previous_);
  }
  ~BlockChildSignal() { ::pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
  BlockChildSignal(const BlockChildSignal&) = delete;
  BlockChildSignal& operator=(const BlockChildSignal&) = delete;

 private:
  sigset_t previous_;
};

// Waits for a SIGCHLD until `until` (none: for ever); false when `until` came first.
bool wait_for_child_signal(std::optional<Clock::time_point> until) {
  const sigset_t child = child_signal();
  for (;;) {
    timespec bound{};
    if (until) {
      const auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(*until - Clock::now()).count();
      if (left > 0) bound = {time_t(left / 1'000'000'000), long(left % 1'000'000'000)};
    }
    if (::sigtimedwait(&child, nullptr, until ? &bound : nullptr) == SIGCHLD) return true;
    if (errno == EAGAIN) return false;
    if (errno != EINTR) throw std::runtime_error(std::string("sigtimedwait: ") + std::strerror(errno));
  }
}

// The child's stderr, line by line (empty lines left out).
std::vector<std::string> read_lines(std::FILE* file) {
  std::string text;
  std::rewind(file);
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;) text.append(buffer, n);
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    if (end > at) lines.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  return lines;
}

std::string without_prefix(const std::string& line) { return line.rfind("hlr: ", 0) == 0 ? line.substr(5) : line; }

class Pool {
 public:
  Pool(const BatchManifest& manifest, const BatchOptions& options)
      : manifest_(manifest), options_(options), program_(own_executable()) {}

  // Runs every job, or as many as --timeout leaves time for.
  Tally run() {
    const std::size_t limit =
        options_.jobs > 0 ? std::size_t(options_.jobs) : std::max(1u, std::thread::hardware_concurrency());
    std::optional<Clock::time_point> until;
    if (options_.timeout > 0)
      until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options_.timeout));
    const BlockChildSignal blocked;
    std::size_t next = 0;
    while (next < manifest_.jobs.size() || !running_.empty()) {
      if (until && Clock::now() >= *until) {
        tally_.timed_out = true;
        break;
      }
      while (running_.size() < limit && next < manifest_.jobs.size()) start(next++);
      if (!running_.empty() && !wait_for_jobs(until)) tally_.timed_out = true;
    }
    if (tally_.timed_out) {
      stop_running();
      for (; next < manifest_.jobs.size(); ++next, ++tally_.not_run)
        report(next, "not run", "the batch's " + timeout_text() + " expired");
    }
    return tally_;
  }

  std::string timeout_text() const { return "--timeout " + exporter::number_text(options_.timeout); }

 private:
  // How long a job has to stop after SIGTERM before it gets the next signal.
  static constexpr std::chrono::seconds kGrace{5};

  std::vector<std::string> command_line(const BatchJob& job) const {
    std::vector<std::string> argv = job_command_line(job, options_.threads, options_.job_timeout);
    argv.insert(argv.begin(), program_);
    return argv;
  }

  // Reports every job that has ended; false when none had.
  bool reap() {
    bool any = false;
    for (;;) {
      int status = 0;
      const pid_t pid = ::waitpid(-1, &status, WNOHANG);
      if (pid == 0 || (pid < 0 && errno == ECHILD)) return any;
      if (pid < 0) {
        if (errno == EINTR) continue;
        throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
      }
      const auto it = running_.find(pid);
      if (it == running_.end()) continue;  // not a job (nothing else is started; be safe)
      const Running done = it->second;
      running_.erase(it);
      set_running(pid, false);
      finish(done, status);
      any = true;
    }
  }

  // Waits until a job has ended and reports it (and any other that ended with it); false when
  // `until` came first.
  bool wait_for_jobs(std::optional<Clock::time_point> until) {
    while (!reap())
      if (!wait_for_child_signal(until)) return reap();
    return true;
  }

  // The batch's --timeout has come: each running job gets SIGTERM and stops as a run stopped by a
  // signal does, removing its temporary files. One still running kGrace later gets a second
  // SIGTERM, at which a run exits at once, still removing them (interrupt.hpp); SIGKILL after
  // another kGrace is for a job stuck where no handler runs.
  void stop_running() {
    stopping_ = true;
    for (int step = 0; !running_.empty(); ++step) {
      const bool last = step == 2;
      for (const auto& [pid, job] : running_) ::kill(pid, last ? SIGKILL : SIGTERM);
      std::optional<Clock::time_point> until;
      if (!last) until = Clock::now() + kGrace;
      while (!running_.empty() && wait_for_jobs(until)) {
      }
    }
  }

  void start(std::size_t index) {
    const BatchJob& job = manifest_.jobs[index];
    // The CLI writes into folders that exist; a batch makes its outputs' folders first.
    for (std::size_t a : job.output_arguments) {
      const fs::path output = job.arguments[a];
      const fs::path parent = (output.is_absolute() ? output : fs::path(manifest_.folder) / output).parent_path();
      std::error_code ec;
      if (!parent.empty()) fs::create_directories(parent, ec);
      if (ec) return report_failure(index, job.arguments[a] + ": cannot make its folder (" + ec.message() + ")");
    }
    std::vector<std::string> argv_strings = command_line(job);
    std::vector<char*> argv;
    for (auto& s : argv_strings) argv.push_back(s.data());
    argv.push_back(nullptr);

    std::FILE* err = std::tmpfile();
    if (!err) return report_failure(index, std::string("cannot make a temporary file (") + std::strerror(errno) + ")");
    ::fcntl(::fileno(err), F_SETFD, FD_CLOEXEC);  // this child's stderr only (dup2 clears the flag on its fd 2)
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);  // the summary: results are files
    posix_spawn_file_actions_adddup2(&actions, ::fileno(err), 2);
    posix_spawn_file_actions_addchdir_np(&actions, manifest_.folder.c_str());
    // The signals that end the batch wait while a child starts, until its pid is in the table the
    // handler reads; the child starts with none blocked.
    sigset_t ending, previous, none;
    sigemptyset(&ending);
    for (int signo : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&ending, signo);
    sigemptyset(&none);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
    ::pthread_sigmask(SIG_BLOCK, &ending, &previous);
    pid_t pid = 0;
    const int rc = ::posix_spawn(&pid, program_.c_str(), &actions, &attributes, argv.data(), environ);
    if (rc == 0) set_running(pid, true);
    ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) {
      std::fclose(err);
      return report_failure(index, "cannot start " + program_ + " (" + std::strerror(rc) + ")");
    }
    running_[pid] = {index, err};
  }

  void finish(const Running& done, int status) {
    const std::vector<std::string> lines = read_lines(done.stderr_file);
    std::fclose(done.stderr_file);
    const std::string job = "job " + std::to_string(done.job);

    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      for (const auto& line : lines) std::cerr << "hlr batch: " << job << ": " << without_prefix(line) << '\n';
      std::string outputs;
      const BatchJob& j = manifest_.jobs[done.job];
      for (std::size_t a : j.output_arguments) outputs += " " + j.arguments[a];
      std::cout << job << " ok:" << outputs << std::endl;
      ++tally_.ok;
      return;
    }
    // The job's error is its last line; the lines before it are its warnings.
    for (std::size_t i = 0; i + 1 < lines.size(); ++i)
      std::cerr << "hlr batch: " << job << ": " << without_prefix(lines[i]) << '\n';
    // Once the batch is stopping, a job that ends without success was stopped by it (its last line
    // says it was terminated; one that failed on its own in those seconds is counted stopped too).
    if (stopping_) {
      ++tally_.stopped;
      return report(done.job, "stopped", "the batch's " + timeout_text() + " expired; no file written");
    }
    std::string problem;
    if (WIFSIGNALED(status))
      problem = "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
    else if (!lines.empty())
      problem = without_prefix(lines.back());
    else
      problem = "exit status " + std::to_string(WEXITSTATUS(status));
    report_failure(done.job, problem);
  }

  void report(std::size_t index, const char* outcome, const std::string& problem) {
    std::cout << "job " << index << " " << outcome << ": " << problem << std::endl;
  }

  void report_failure(std::size_t index, const std::string& problem) {
    report(index, "failed", problem);
    ++tally_.failed;
  }

  const BatchManifest& manifest_;
  const BatchOptions& options_;
  const std::string program_;
  std::map<pid_t, Running> running_;
  Tally tally_;
  bool stopping_ = false;  // the batch's --timeout has come
};

void list_jobs(const BatchManifest& manifest, const BatchOptions& options) {
  for (std::size_t i = 0; i < manifest.jobs.size(); ++i) {
    const BatchJob& job = manifest.jobs[i];
    const nlohmann::json line = {{"job", i},
                                 {"arguments", job_command_line(job, options.threads, options.job_timeout)},
                                 {"inputs", job.input_arguments},
                                 {"outputs", job.output_arguments}};
    std::cout << line.dump() << '\n';
  }
  std::cout.flush();
}

// The summary line on stderr, and the exit status.
int summarize(const Tally& tally, std::size_t jobs, double seconds, const std::string& timeout) {
  std::cerr << "hlr batch: ";
  if (tally.timed_out)
    std::cerr << timeout << ": the batch stopped after " << std::setprecision(3) << seconds << " s; " << tally.ok << " of "
              << jobs << " jobs ok, " << tally.failed << " failed, " << tally.stopped << " stopped, " << tally.not_run
              << " not run" << std::endl;
  else
    std::cerr << tally.ok << " of " << jobs << " jobs ok, " << tally.failed << " failed, in " << std::setprecision(3)
              << seconds << " s" << std::endl;
  return tally.timed_out ? kExitTimeout : tally.failed > 0 ? kExitInputError : kExitOk;
}

int run(const BatchOptions& options) {
  const BatchManifest manifest = read_batch_manifest(options.manifest);
  if (options.list) {
    list_jobs(manifest, options);
    return kExitOk;
  }
  const auto start = Clock::now();
  install_signal_forwarding();
  Pool pool(manifest, options);
  const Tally tally = pool.run();
  return summarize(tally, manifest.jobs.size(), std::chrono::duration<double>(Clock::now() - start).count(),
                   pool.timeout_text());
}

}  // namespace

Subcommand add_batch_command(CLI::App& parent) {
  auto options = std::make_shared<BatchOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "batch", "Run the jobs of an hlr-batch/1 manifest (draw, sheet, surfaces, check, shadows, mesh, clip) on a local pool of processes.");
  cmd->add_option("manifest", options->manifest, "hlr-batch/1 file; the jobs' paths are relative to its folder")
      ->required()
      ->type_name("MANIFEST.json");
  cmd->add_option("--jobs", options->jobs, "jobs to run at once (0: one per core)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str()
      ->type_name("N");
  cmd->add_option("--threads", options->threads,
                  "threads of each job, passed on as its --threads unless its options have one (0: as the job says)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str()
      ->type_name("N");
  cmd->add_option("--timeout", options->timeout,
                  "stop the batch after SECONDS of wall clock: the running jobs are stopped (no file written), "
                  "the others not run; exit 124 (0: no limit)")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str()
      ->type_name("SECONDS");
  cmd->add_option("--job-timeout", options->job_timeout,
                  "every job's --timeout, unless its options have one (0: as the job says)")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str()
      ->type_name("SECONDS");
  cmd->add_flag("--list", options->list,
                "print the jobs' command lines as JSON, one job a line, instead of running them");
  cmd->footer(
      "Example:\n"
      "  hlr batch catalogue.json --jobs 4\n"
      "\n"
      "A job is {\"command\": \"draw\", \"meshes\": [\"a.off\"], \"view\": \"iso\", \"options\": [\"--crease\", \"40\"],\n"
      "\"outputs\": [\"out/a_iso.svg\"]}: hlr COMMAND MESH... --view VIEW OPTION... -o OUTPUT..., run in the\n"
      "manifest's folder. A check job's outputs are its --diff .png and --json .json; shadows and mesh\n"
      "jobs have no view (lights are shadows options); a clip job has \"inputs\": [\"SUBJECT.json\",\n"
      "\"CLIP.json\"] instead of meshes and no view. One line per job on stdout\n"
      "(\"job K ok: ...\" or \"job K failed: ...\"; at --timeout \"job K stopped: ...\", \"job K not run: ...\");\n"
      "exit status 1 when any job failed, 124 at --timeout. The same manifest runs on Dask:\n"
      "python3 -m hlrdraw.batch MANIFEST --scheduler ADDRESS.\n"
      "Format: docs/FORMATS.md (hlr-batch/1).");
  return {cmd, [options] { return run(*options); }};
}

}  // namespace hlr::app
