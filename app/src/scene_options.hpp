// What the scene subcommands (surfaces, draw) share: the mesh arguments, the view options, the
// kernel option, and reading the meshes.
#pragma once

#include "errors.hpp"

#include <hlr/cad/cad.hpp>
#include <hlr/hidden_line/jobs.hpp>
#include <hlr/kernel/view.hpp>

#include <CLI/CLI.hpp>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace hlr::app {

// Every subcommand's limits: --timeout, --max-faces (commands that read meshes) and --progress.
struct RunLimits {
  double timeout = 0;  // seconds of wall clock; 0: none
  // About 5.5 GB of memory at the 1.1 KB per face measured at 1M faces (docs/BENCHMARKS.md): beyond
  // it a run would fail for memory after a long time on most machines, so it is refused at once.
  std::size_t max_faces = 5'000'000;
  bool progress = false;  // one line per stage on stderr when it is not a terminal
};
void add_limit_options(CLI::App& cmd, RunLimits& limits, bool faces = true);

struct SceneOptions {
  std::vector<std::string> meshes;
  std::string view = "iso";
  std::vector<double> direction, up;
  std::vector<double> eye, target;  // a perspective view: --eye with --target or --dir
  double near = 0;                  // --near: the near plane's fraction of the deepest vertex (0: 1/1000)
  std::string kernel = "exact";
  int threads = 0;  // 0: every core
  RunLimits limits;
  cad::CadOptions cad;
};

// --deflection and --angular-deflection: how CAD models (STEP, IGES, BREP) are tessellated.
void add_cad_options(CLI::App& cmd, cad::CadOptions& cad);

// What the MESH... argument reads, for its help line.
inline constexpr const char* kInputKinds = "mesh files (OFF, OBJ, STL, PLY) or CAD models (STEP, IGES, BREP)";

// MESH... (positional), --view, --dir, --up, --eye, --target, --near, --threads, the limits, the
// CAD options and, unless `kernel` is false, --kernel.
void add_scene_options(CLI::App& cmd, SceneOptions& options, bool kernel = true);

// --threads N, 0 to 1024 (0: every core).
void add_threads_option(CLI::App& cmd, int& threads);

// The view the options name, or nothing after a one-line usage error on stderr.
std::optional<View> resolve_view(const SceneOptions& options);

// Refuses a perspective view that cannot be drawn of this scene (near_plane.hpp
// perspective_defect): a UsageError naming --eye.
void check_view_of(const Scene& scene, const View& view);

// Reads every mesh and CAD model (hlr::cad::load_scene: throws ImportError) and refuses a scene
// beyond limits.max_faces (UserError).
Scene read_scene(const std::vector<std::string>& paths, const RunLimits& limits, const cad::CadOptions& cad);

// The importer's warnings, printed once a run has succeeded (a failed run prints one line: its
// error).
void print_warnings(const Scene& scene);

// Whether a path ends in `extension` (".svg"), in any letter case.
bool has_extension(const std::string& path, const std::string& extension);

using hidden_line::seconds_since;

}  // namespace hlr::app
