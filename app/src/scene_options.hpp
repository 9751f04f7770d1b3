// What the scene subcommands (surfaces, draw) share: the mesh arguments, the view options, the
// kernel option, and reading the meshes.
#pragma once

#include "errors.hpp"

#include <hlr/hidden_line/jobs.hpp>
#include <hlr/kernel/view.hpp>

#include <CLI/CLI.hpp>

#include <tbb/global_control.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hlr::app {

struct SceneOptions {
  std::vector<std::string> meshes;
  std::string view = "iso";
  std::vector<double> direction, up;
  std::string kernel = "exact";
  int threads = 0;  // 0: every core
};

// MESH... (positional), --view, --dir, --up, --threads and, unless `kernel` is false, --kernel.
void add_scene_options(CLI::App& cmd, SceneOptions& options, bool kernel = true);

// Limits oneTBB to options.threads for as long as the returned object lives (0: no limit). The
// output does not depend on it.
std::unique_ptr<tbb::global_control> thread_limit(const SceneOptions& options);

// The view the options name, or nothing after a one-line usage error on stderr.
std::optional<View> resolve_view(const SceneOptions& options);

// Reads every mesh (hlr::load_scene: throws ImportError) and prints the importer's warnings.
Scene read_scene(const std::vector<std::string>& paths);

// Whether a path ends in `extension` (".svg"), in any letter case.
bool has_extension(const std::string& path, const std::string& extension);

using hidden_line::seconds_since;

}  // namespace hlr::app
