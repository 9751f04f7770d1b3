// The hlr-batch/1 manifest (DESIGN.md, "The library and its entry points"): many jobs, each the
// command line of one run of hlr.
//
//   {"format": "hlr-batch/1", "jobs": [{"command": "draw", "meshes": ["a.off"], "view": "iso",
//     "options": ["--crease", "40"], "outputs": ["out/a_iso.svg", "out/a_iso.json"]}]}
//
// A job is `hlr COMMAND MESH... [--view VIEW] OPTION... -o OUTPUT...` (for `sheet`, VIEW is the
// --views list), run in the manifest's folder, so that relative paths are relative to it. The
// commands that draw a scene are jobs (draw, sheet, surfaces), and the two that read other things
// or write other outputs: `check` (its outputs are its --diff .png and --json .json, by their
// extensions) and `clip` (its "inputs" are SUBJECT.json and CLIP.json, its one output the -o
// file). The manifest is checked whole before any job runs: its shape, every key and value, and
// that no two jobs write the same file (they would race); the jobs' own options are checked by
// the job, as on the command line.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace hlr::app {

struct BatchJob {
  std::vector<std::string> arguments;          // after the program's name: {"draw", "a.off", ...}
  std::vector<std::size_t> input_arguments;    // which arguments are input paths (meshes, polygons)
  std::vector<std::size_t> output_arguments;   // which arguments are output paths
  // Whether the batch's --threads and --job-timeout reach the job: the command has the option
  // (clip has no --threads) and the job's own options do not set it.
  bool takes_threads = false;
  bool takes_timeout = false;
};

struct BatchManifest {
  std::string folder;  // the manifest's folder: the jobs run there ("." for a bare file name)
  std::vector<BatchJob> jobs;
};

// Reads and checks the manifest at `path`. Throws UserError(path, problem), problem naming the job
// ("job 3: \"outputs\" is missing").
BatchManifest read_batch_manifest(const std::string& path);

// What the batch adds to every job's command line: --threads `threads` and --timeout
// `job_timeout` (each when not 0 and the job takes it). The arguments after the program's name.
std::vector<std::string> job_command_line(const BatchJob& job, int threads, double job_timeout);

}  // namespace hlr::app
