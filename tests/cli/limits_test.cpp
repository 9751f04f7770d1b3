// End-to-end tests of how a run ends early or says what it does: --timeout, --max-faces, SIGINT and
// SIGTERM during the work, the progress line on a terminal and with --progress, and errors that
// stay one line when the import had warnings. A run that stops leaves no output and no temporary
// file behind, whatever the number of outputs.
#include "cli_support.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>


namespace {

namespace fs = std::filesystem;

using namespace hlr::cli_test;

class CliLimits : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("hlr-limits-test", {"out"});
    ASSERT_FALSE(dir_.empty());
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  // A bumpy grid (cli_support.hpp) of n x n vertices; with --sun, which sorts and casts shadows,
  // n = 300 takes some 30 s.
  fs::path bumpy_grid(int n) const { return write_bumpy_grid(dir_ / "grid.off", n); }

  Started start(std::vector<std::string> args) const {
    args.insert(args.begin(), HLR_BINARY);
    return start_process(std::move(args), dir_);
  }
  static Outcome finish(const Started& started) { return finish_process(started); }

  Outcome hlr(const std::vector<std::string>& args) const { return finish(start(args)); }

  // With a sun's shadows, so that a stop always comes while the run works, however fast the
  // drawing alone becomes.
  std::vector<std::string> draw_args(const fs::path& mesh) const {
    return {"draw", mesh.string(), "--view", "iso", "--sun", "1,2,-3", "-o", out("a.svg"),
            "-o", out("a.json"), "-o", out("a.dxf")};
  }
  std::string out(const std::string& name) const { return (dir_ / "out" / name).string(); }

  // Nothing in the output folder: no output, no temporary file.
  void expect_nothing_written() const {
    EXPECT_TRUE(entries(dir_ / "out").empty()) << "left behind: " << ::testing::PrintToString(entries(dir_ / "out"));
  }

  fs::path dir_;
};

TEST_F(CliLimits, TimeoutStopsTheRunWithOneLineAndNoFile) {
  const fs::path grid = bumpy_grid(300);
  auto args = draw_args(grid);
  args.insert(args.end(), {"--timeout", "0.5"});
  const auto begin = std::chrono::steady_clock::now();
  const Outcome run = hlr(args);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  EXPECT_EQ(run.exit_code, 124) << run.err;
  EXPECT_EQ(count_lines(run.err), 1u) << run.err;
  EXPECT_EQ(run.err.rfind("hlr: --timeout 0.5: the run stopped after 0.5 s while ", 0), 0u) << run.err;
  EXPECT_NE(run.err.find("; no file written"), std::string::npos) << run.err;
  EXPECT_LT(seconds, 5.0) << "the run went on after its timeout";  // a whole run takes several times that
  expect_nothing_written();
}

TEST_F(CliLimits, BatchTimeoutStopsTheRunningJobsAndRunsNoMore) {
  // One job at a time: a tetrahedron, done at once, then two long ones. At the batch's --timeout
  // the first long one is stopped (no file, no temporary file) and the second is not run. Nothing
  // is asserted on speed but that a tetrahedron takes less than the timeout and the grid with its
  // shadows far more (about 30 s on one thread in 2026; the drawing alone took 3 s, too close).
  bumpy_grid(300);
  spit(dir_ / "tetra.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  spit(dir_ / "batch.json", R"({"format": "hlr-batch/1", "jobs": [
      {"command": "draw", "meshes": ["tetra.off"], "outputs": ["out/tetra.svg"]},
      {"command": "draw", "meshes": ["grid.off"], "options": ["--threads", "1", "--sun", "1,2,-3"],
       "outputs": ["out/a.svg", "out/a.json", "out/a.dxf"]},
      {"command": "surfaces", "meshes": ["grid.off"], "outputs": ["out/b.json"]}]})");
  const Outcome run = hlr({"batch", (dir_ / "batch.json").string(), "--jobs", "1", "--timeout", "4"});
  EXPECT_EQ(run.exit_code, 124) << run.err;
  EXPECT_EQ(run.out,
            "job 0 ok: out/tetra.svg\n"
            "job 1 stopped: the batch's --timeout 4 expired; no file written\n"
            "job 2 not run: the batch's --timeout 4 expired\n");
  EXPECT_EQ(count_lines(run.err), 1u) << run.err;
  EXPECT_EQ(run.err.rfind("hlr batch: --timeout 4: the batch stopped after ", 0), 0u) << run.err;
  EXPECT_NE(run.err.find(" s; 1 of 3 jobs ok, 0 failed, 1 stopped, 1 not run\n"), std::string::npos) << run.err;
  EXPECT_EQ(entries(dir_ / "out"), std::vector<std::string>{"tetra.svg"});
}

TEST_F(CliLimits, BatchJobTimeoutFailsTheJobAsItsOwnTimeoutWould) {
  bumpy_grid(300);
  spit(dir_ / "batch.json", R"({"format": "hlr-batch/1", "jobs": [
      {"command": "draw", "meshes": ["grid.off"], "options": ["--sun", "1,2,-3"],
       "outputs": ["out/a.svg", "out/a.json"]}]})");
  const Outcome run = hlr({"batch", (dir_ / "batch.json").string(), "--job-timeout", "0.5"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(run.out.rfind("job 0 failed: --timeout 0.5: the run stopped after 0.5 s while ", 0), 0u) << run.out;
  EXPECT_NE(run.err.find("hlr batch: 0 of 1 jobs ok, 1 failed"), std::string::npos) << run.err;
  expect_nothing_written();
}

TEST_F(CliLimits, SigintStopsTheWorkAndRemovesEveryTemporaryFile) {
  const fs::path grid = bumpy_grid(300);
  for (const int signo : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(signo);
    // Signalled once the run reports the polygons (--progress: one line per stage), not after a fixed
    // sleep, which a loaded machine can make too short for the run to have started.
    std::vector<std::string> args = draw_args(grid);
    args.push_back("--progress");
    const Started started = start(args);
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (slurp(started.log_dir / "stderr").find("building polygons") == std::string::npos &&
           std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ::kill(started.pid, signo);
    const Outcome run = finish(started);
    EXPECT_EQ(run.exit_code, 128 + signo) << run.err;
    // The last line is the stop (a stage may have begun before the signal arrived).
    const std::string stop = run.err.substr(run.err.rfind('\n', run.err.size() - 2) + 1);
    EXPECT_EQ(count_lines(stop), 1u) << run.err;
    EXPECT_EQ(stop.rfind(signo == SIGINT ? "hlr: interrupted (SIGINT)" : "hlr: terminated (SIGTERM)", 0), 0u)
        << run.err;
    EXPECT_NE(stop.find("no file written"), std::string::npos) << run.err;
    expect_nothing_written();
  }
}

TEST_F(CliLimits, MaxFacesRefusesALargerScene) {
  const fs::path cube = fs::path(HLR_SCENE_FIXTURES) / "cube.off";
  const Outcome run = hlr({"draw", cube.string(), "--max-faces", "5", "-o", out("a.svg")});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(count_lines(run.err), 1u) << run.err;
  EXPECT_NE(run.err.find(cube.string() + ": "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("more than --max-faces 5"), std::string::npos) << run.err;
  expect_nothing_written();
  EXPECT_EQ(hlr({"draw", cube.string(), "--max-faces", "12", "-o", out("a.svg")}).exit_code, 0);
}

TEST_F(CliLimits, ProgressLinesOnlyWhenAskedOffATerminal) {
  const fs::path cube = fs::path(HLR_SCENE_FIXTURES) / "cube.off";
  const Outcome quiet = hlr({"draw", cube.string(), "-o", out("a.svg")});
  EXPECT_EQ(quiet.exit_code, 0);
  EXPECT_EQ(quiet.err, "");
  const Outcome lines = hlr({"draw", cube.string(), "-o", out("b.svg"), "--progress"});
  EXPECT_EQ(lines.exit_code, 0);
  for (const char* stage : {"hlr: reading 1 mesh\n", "building polygons", "hlr: classifying feature lines\n",
                            "hlr: writing 1 output\n"})
    EXPECT_NE(lines.err.find(stage), std::string::npos) << stage << " in:\n" << lines.err;
  const Outcome two = hlr({"draw", cube.string(), cube.string(), "-o", out("c.svg"), "--progress"});
  EXPECT_EQ(two.exit_code, 0);
  EXPECT_NE(two.err.find("hlr: reading 2 meshes\n"), std::string::npos) << two.err;
}

TEST_F(CliLimits, ALiveProgressLineOnATerminal) {
  // script(1) runs hlr on a pseudo-terminal and copies what it shows.
  if (::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "script(1) is not installed";
  const fs::path grid = bumpy_grid(300);
  // With a sun: long enough for the live line (shown after a second) before the timeout stops it.
  const std::string command = std::string(HLR_BINARY) + " draw " + grid.string() + " -o " + out("a.svg") +
                              " --sun 1,2,-3 --timeout 2.5 >/dev/null";
  const std::string shown = (dir_ / "terminal").string();
  const std::string script = "script -qec '" + command + "' " + shown + " >/dev/null 2>&1";
  EXPECT_NE(::system(script.c_str()), -1);
  const std::string text = slurp(shown);
  EXPECT_NE(text.find("\r\033[Khlr: "), std::string::npos) << text;
  EXPECT_NE(text.find(" s)"), std::string::npos) << text;
  EXPECT_NE(text.find("hlr: --timeout 2.5: the run stopped"), std::string::npos) << text;
  expect_nothing_written();
}

TEST_F(CliLimits, AnErrorAfterImportWarningsIsStillOneLine) {
  // The inward box warns at import; the scale does not fit the sheet, found after solving.
  const fs::path box = fs::path(HLR_SCENE_FIXTURES) / "inward_box.off";
  const Outcome run = hlr({"draw", box.string(), "--scale", "1000:1", "-o", out("a.svg")});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(count_lines(run.err), 1u) << run.err;
  EXPECT_EQ(run.err.rfind("hlr: --scale 1000:1: ", 0), 0u) << run.err;
  const Outcome ok = hlr({"draw", box.string(), "-o", out("a.svg")});
  EXPECT_EQ(ok.exit_code, 0);
  EXPECT_NE(ok.err.find("hlr: warning: "), std::string::npos) << "the warning is still printed on success";
}

}  // namespace
