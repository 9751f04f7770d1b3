// What the scene subcommands (surfaces, draw) share: the mesh arguments, the view options, the
// kernel option, and reading the meshes.
#pragma once

#include "errors.hpp"

#include <hlr/export/surfaces.hpp>
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

struct Scene {
  std::vector<Mesh> meshes;
  exporter::InputInfo input;
};

// Reads every mesh (throws ImportError) and prints the importer's warnings.
Scene load_scene(const std::vector<std::string>& paths);

// Calls solve.template operator()<K>(kind) with the kernel type of `kind`.
template <class Solve>
decltype(auto) with_kernel(KernelKind kind, Solve&& solve) {
  switch (kind) {
    case KernelKind::epick: return solve.template operator()<EpickKernel>(kind);
    case KernelKind::floating: return solve.template operator()<DoubleKernel>(kind);
    case KernelKind::exact: break;
  }
  return solve.template operator()<ExactKernel>(kind);
}

// The same, with the kernel the options name.
template <class Solve>
int with_kernel(const SceneOptions& options, Solve&& solve) {
  KernelKind kind = KernelKind::exact;
  parse_kernel_kind(options.kernel, kind);
  return with_kernel(kind, std::forward<Solve>(solve));
}

// The error for a run whose inexact kernel contradicted itself (a ClipError: the exact kernel
// never throws one on valid input).
UserError inexact_kernel_failure(const SceneOptions& options, KernelKind kind, const std::exception& e);

// Whether a path ends in `extension` (".svg"), in any letter case.
bool has_extension(const std::string& path, const std::string& extension);

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace hlr::app
