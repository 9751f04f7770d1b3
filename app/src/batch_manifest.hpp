// The hlr-batch/1 manifest (DESIGN.md, "The library and its entry points"): many jobs, each the
// command line of one run of hlr.
//
//   {"format": "hlr-batch/1", "jobs": [{"command": "draw", "meshes": ["a.off"], "view": "iso",
//     "options": ["--crease", "40"], "outputs": ["out/a_iso.svg", "out/a_iso.json"]}]}
//
// A job is `hlr COMMAND MESH... [--view VIEW] OPTION... -o OUTPUT...` (for `sheet`, VIEW is the
// --views list), run in the manifest's folder, so that relative paths are relative to it. Only
// the commands that draw a scene are jobs: draw, sheet and surfaces. The manifest is checked
// whole before any job runs: its shape, every key and value, and that no two jobs write the same
// file (they would race); the jobs' own options are checked by the job, as on the command line.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace hlr::app {

struct BatchJob {
  std::vector<std::string> arguments;       // after the program's name: {"draw", "a.off", ...}
  std::vector<std::size_t> mesh_arguments;  // which arguments are mesh paths
  std::vector<std::size_t> output_arguments;  // which arguments are output paths
  bool sets_threads = false;                // the options have their own --threads
};

struct BatchManifest {
  std::string folder;  // the manifest's folder: the jobs run there ("." for a bare file name)
  std::vector<BatchJob> jobs;
};

// Reads and checks the manifest at `path`. Throws UserError(path, problem), problem naming the job
// ("job 3: \"outputs\" is missing").
BatchManifest read_batch_manifest(const std::string& path);

}  // namespace hlr::app
