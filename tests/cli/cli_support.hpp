// What the end-to-end tests of the hlr program share: starting a process with its output in files,
// a finished run's exit code and output, and small file helpers.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace hlr::cli_test {

// A finished run: the exit code (128 + N when signal N ended it), stdout and stderr.
struct Outcome {
  int exit_code = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void spit(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// A bumpy grid of n x n vertices, 2 (n - 1)^2 triangles, written to `path`: no two of them
// coplanar, so that the area sort and the line classification have real work (at n = 300,
// `hlr draw` about 1 s on this project's 2-core machine).
inline std::filesystem::path write_bumpy_grid(const std::filesystem::path& path, int n) {
  std::ofstream off(path);
  off << "OFF\n" << n * n << ' ' << 2 * (n - 1) * (n - 1) << " 0\n";
  std::uint64_t state = 12345;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      off << x << ' ' << y << ' ' << static_cast<double>(state >> 40) / double(1 << 24) << '\n';
    }
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const int v = y * n + x;
      off << "3 " << v << ' ' << v + 1 << ' ' << v + n + 1 << "\n3 " << v << ' ' << v + n + 1 << ' ' << v + n << '\n';
    }
  return path;
}

// The names in a folder, hidden files included, sorted.
inline std::vector<std::string> entries(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  if (!std::filesystem::exists(dir)) return names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A new folder PREFIX-XXXXXX in the temporary directory, with the given subfolders; empty when it
// cannot be made.
inline std::filesystem::path make_temp_dir(const std::string& prefix, std::initializer_list<const char*> subfolders) {
  std::string templ = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
  if (::mkdtemp(templ.data()) == nullptr) return {};
  const std::filesystem::path dir = templ;
  for (const char* sub : subfolders) std::filesystem::create_directories(dir / sub);
  return dir;
}

// A started process whose stdout and stderr go to `stdout` and `stderr` in a folder.
struct Started {
  pid_t pid = -1;
  std::filesystem::path log_dir;
};

// argv[0] is the program's path. A program that cannot be started fails the test; pid stays -1.
inline Started start_process(std::vector<std::string> argv_strings, const std::filesystem::path& log_dir) {
  std::vector<char*> argv;
  for (auto& s : argv_strings) argv.push_back(s.data());
  argv.push_back(nullptr);
  const std::string out_log = (log_dir / "stdout").string(), err_log = (log_dir / "stderr").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out_log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err_log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  Started started{-1, log_dir};
  const int rc = posix_spawn(&started.pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    ADD_FAILURE() << "cannot start " << argv_strings[0];
    started.pid = -1;
  }
  return started;
}

// Waits for the process and reads what it wrote.
inline Outcome finish_process(const Started& started) {
  Outcome run;
  if (started.pid < 0) return run;
  int status = 0;
  waitpid(started.pid, &status, 0);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.out = slurp(started.log_dir / "stdout");
  run.err = slurp(started.log_dir / "stderr");
  return run;
}

inline Outcome run_process(std::vector<std::string> argv, const std::filesystem::path& log_dir) {
  return finish_process(start_process(std::move(argv), log_dir));
}

inline std::size_t count_lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

}  // namespace hlr::cli_test
