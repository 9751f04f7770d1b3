// What the scene subcommands (surfaces, draw) share: the mesh arguments, the view options, the
// kernel option, and reading the meshes.
#pragma once

#include <hlr/export/surfaces.hpp>
#include <hlr/kernel/view.hpp>

#include <CLI/CLI.hpp>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace hlr::app {

struct SceneOptions {
  std::vector<std::string> meshes;
  std::string view = "iso";
  std::vector<double> direction, up;
  std::string kernel = "exact";
};

// MESH... (positional), --view, --dir, --up and --kernel.
void add_scene_options(CLI::App& cmd, SceneOptions& options);

// The view the options name, or nothing after a one-line usage error on stderr.
std::optional<View> resolve_view(const SceneOptions& options);

struct Scene {
  std::vector<Mesh> meshes;
  exporter::InputInfo input;
};

// Reads every mesh (throws ImportError) and prints the importer's warnings.
Scene load_scene(const std::vector<std::string>& paths);

// Whether a path ends in `extension` (".svg"), in any letter case.
bool has_extension(const std::string& path, const std::string& extension);

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace hlr::app
