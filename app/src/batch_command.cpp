// `hlr batch MANIFEST.json [--jobs N] [--threads N] [--list]`: the jobs of an hlr-batch/1 manifest
// (batch_manifest.hpp) on a local pool.
//
// Each job is a child process of this same program (/proc/self/exe) with the job's command line,
// started in the manifest's folder. So a job's files are the ones `hlr COMMAND ...` writes, by
// construction; a job that fails, or crashes, is one failed job and the others go on; and each job
// has the process a single run has (its own memory, --threads, signals, atomic outputs). At most
// --jobs children run at once: the pool is this process waiting for any child to finish. A signal
// that ends the batch is passed on to the running jobs first.
//
// stdout gets one line per job as it finishes, "job K ok: OUTPUT..." or "job K failed: PROBLEM"
// (the job's own one-line error, without "hlr: "); stderr gets the jobs' warnings and a summary.
// The exit status is 1 when any job failed. `--list` prints the jobs instead of running them, one
// JSON object a line, {"job": K, "arguments": [...], "meshes": [...], "outputs": [...]} (which
// arguments are mesh and output paths): hlrdraw.batch runs them on Dask from that.
#include "batch_manifest.hpp"
#include "errors.hpp"
#include "subcommand.hpp"

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
  bool list = false;
};

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

class Pool {
 public:
  Pool(const BatchManifest& manifest, const BatchOptions& options)
      : manifest_(manifest), options_(options), program_(own_executable()) {}

  // Runs every job; returns how many failed.
  std::size_t run() {
    const std::size_t limit =
        options_.jobs > 0 ? std::size_t(options_.jobs) : std::max(1u, std::thread::hardware_concurrency());
    std::size_t next = 0;
    while (next < manifest_.jobs.size() || !running_.empty()) {
      while (running_.size() < limit && next < manifest_.jobs.size()) start(next++);
      if (running_.empty()) continue;
      int status = 0;
      const pid_t pid = ::waitpid(-1, &status, 0);
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
    }
    return failed_;
  }

 private:
  std::vector<std::string> command_line(const BatchJob& job) const {
    std::vector<std::string> argv{program_};
    argv.insert(argv.end(), job.arguments.begin(), job.arguments.end());
    if (options_.threads > 0 && !job.sets_threads) {
      argv.push_back("--threads");
      argv.push_back(std::to_string(options_.threads));
    }
    return argv;
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
    std::string text;
    std::rewind(done.stderr_file);
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, done.stderr_file)) > 0;) text.append(buffer, n);
    std::fclose(done.stderr_file);

    std::vector<std::string> lines;
    for (std::size_t at = 0; at < text.size();) {
      std::size_t end = text.find('\n', at);
      if (end == std::string::npos) end = text.size();
      if (end > at) lines.push_back(text.substr(at, end - at));
      at = end + 1;
    }
    const std::string job = "job " + std::to_string(done.job);
    auto without_prefix = [](const std::string& line) { return line.rfind("hlr: ", 0) == 0 ? line.substr(5) : line; };

    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      for (const auto& line : lines) std::cerr << "hlr batch: " << job << ": " << without_prefix(line) << '\n';
      std::string outputs;
      const BatchJob& j = manifest_.jobs[done.job];
      for (std::size_t a : j.output_arguments) outputs += " " + j.arguments[a];
      std::cout << job << " ok:" << outputs << std::endl;
      ++ok_;
      return;
    }
    // The job's error is its last line; the lines before it are its warnings.
    for (std::size_t i = 0; i + 1 < lines.size(); ++i)
      std::cerr << "hlr batch: " << job << ": " << without_prefix(lines[i]) << '\n';
    std::string problem;
    if (WIFSIGNALED(status))
      problem = "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
    else if (!lines.empty())
      problem = without_prefix(lines.back());
    else
      problem = "exit status " + std::to_string(WEXITSTATUS(status));
    report_failure(done.job, problem);
  }

  void report_failure(std::size_t index, const std::string& problem) {
    std::cout << "job " << index << " failed: " << problem << std::endl;
    ++failed_;
  }

  const BatchManifest& manifest_;
  const BatchOptions& options_;
  const std::string program_;
  std::map<pid_t, Running> running_;
  std::size_t ok_ = 0, failed_ = 0;
};

void list_jobs(const BatchManifest& manifest, const BatchOptions& options) {
  for (std::size_t i = 0; i < manifest.jobs.size(); ++i) {
    const BatchJob& job = manifest.jobs[i];
    std::vector<std::string> arguments = job.arguments;
    if (options.threads > 0 && !job.sets_threads) arguments.insert(arguments.end(), {"--threads", std::to_string(options.threads)});
    const nlohmann::json line = {
        {"job", i}, {"arguments", arguments}, {"meshes", job.mesh_arguments}, {"outputs", job.output_arguments}};
    std::cout << line.dump() << '\n';
  }
  std::cout.flush();
}

int run(const BatchOptions& options) {
  const BatchManifest manifest = read_batch_manifest(options.manifest);
  if (options.list) {
    list_jobs(manifest, options);
    return kExitOk;
  }
  const auto start = std::chrono::steady_clock::now();
  install_signal_forwarding();
  const std::size_t failed = Pool(manifest, options).run();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "hlr batch: " << manifest.jobs.size() - failed << " of " << manifest.jobs.size() << " jobs ok, " << failed
            << " failed, in " << std::setprecision(3) << seconds << " s\n";
  return failed > 0 ? kExitInputError : kExitOk;
}

}  // namespace

Subcommand add_batch_command(CLI::App& parent) {
  auto options = std::make_shared<BatchOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "batch", "Run the jobs of an hlr-batch/1 manifest (draw, sheet, surfaces) on a local pool of processes.");
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
  cmd->add_flag("--list", options->list,
                "print the jobs' command lines as JSON, one job a line, instead of running them");
  cmd->footer(
      "Example:\n"
      "  hlr batch catalogue.json --jobs 4\n"
      "\n"
      "A job is {\"command\": \"draw\", \"meshes\": [\"a.off\"], \"view\": \"iso\", \"options\": [\"--crease\", \"40\"],\n"
      "\"outputs\": [\"out/a_iso.svg\"]}: hlr COMMAND MESH... --view VIEW OPTION... -o OUTPUT..., run in the\n"
      "manifest's folder. One line per job on stdout (\"job K ok: ...\" or \"job K failed: ...\"); exit status 1\n"
      "when any job failed. The same manifest runs on Dask: python3 -m hlrdraw.batch MANIFEST --scheduler ADDRESS.\n"
      "Format: docs/FORMATS.md (hlr-batch/1).");
  return {cmd, [options] { return run(*options); }};
}

}  // namespace hlr::app
