// `hlr surfaces MESH... --view V -o OUT.json|OUT.svg [--kernel exact|epick|double] [--exact]`
#include "atomic_file.hpp"
#include "errors.hpp"
#include "run_scope.hpp"
#include "scene_options.hpp"
#include "subcommand.hpp"

#include <hlr/export/jobs.hpp>

#include <chrono>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace hlr::app {
namespace {

struct SurfacesOptions {
  SceneOptions scene;
  std::vector<std::string> outputs;
  bool exact = false;
  bool keep_back_faces = false;
  bool no_consolidation = false;
};

enum class Format { json, svg };

Format format_of(const std::string& path) {
  if (has_extension(path, ".json")) return Format::json;
  if (has_extension(path, ".svg")) return Format::svg;
  throw UserError(path, "unknown output format (the name must end in .json or .svg)");
}

int solve(const SurfacesOptions& options, const View& view) {
  // Before the clock: the thread pool's one-time set-up is the process starting (draw_command.cpp).
  RunScope run(options.scene.limits, options.scene.threads);
  const auto start = std::chrono::steady_clock::now();
  std::vector<Format> formats;
  for (const auto& out : options.outputs) formats.push_back(format_of(out));

  OutputFiles files(options.outputs);
  const Scene scene = run.read(options.scene.meshes, options.scene.cad);
  check_view_of(scene, view);
  exporter::SurfacesOptions job;
  parse_kernel_kind(options.scene.kernel, job.kernel);
  job.sources.remove_back_faces = !options.keep_back_faces;
  job.sources.consolidate = !options.no_consolidation;
  job.progress = run.progress();
  const exporter::SurfacesSolution solution = exporter::solve_surfaces(scene, view, job, seconds_since(start));

  // The pictures first, so that the JSON's write stage can count them.
  const auto write_start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < files.size(); ++i)
    if (formats[i] != Format::json) files[i].write(solution.svg());
  const double pictures = seconds_since(write_start);
  for (std::size_t i = 0; i < files.size(); ++i)
    if (formats[i] == Format::json)
      solution.write_json(options.exact, pictures, [&](std::string_view part) { files[i].write(part); });
  files.commit();
  run.finish(scene);
  const auto& st = solution.summary().sources;
  const auto& sort = solution.summary().sort;
  std::cout << "hlr surfaces: " << scene.input.faces << " faces, view " << view.name << ", kernel "
            << kernel_name(job.kernel) << '\n'
            << "  " << st.back_faces_removed << " back faces and " << st.edge_on_faces_removed
            << " edge-on faces removed; " << st.faces_consolidated << " faces consolidated; " << st.sources
            << " polygons sorted\n"
            << "  " << solution.summary().visible << " visible and " << solution.summary().hidden << " hidden polygons ("
            << sort.penetration_splits << " penetration splits, " << sort.coplanar_ties << " coplanar ties) in "
            << solution.times().total << " s\n";
  for (const auto& out : options.outputs) std::cout << "wrote " << out << '\n';
  return kExitOk;
}

int run(const SurfacesOptions& options) {
  const std::optional<View> view = resolve_view(options.scene);
  if (!view) return kExitUsage;
  return solve(options, *view);
}

}  // namespace

Subcommand add_surfaces_command(CLI::App& parent) {
  auto options = std::make_shared<SurfacesOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "surfaces", "Solve which parts of every face are visible and which are hidden, exactly, in one view.");
  add_scene_options(*cmd, options->scene);
  cmd->add_option("-o,--output", options->outputs,
                  "file to write: .json (hlr-surfaces/1) or .svg (a picture); may be given several times")
      ->required()
      ->type_name("OUT");
  cmd->add_flag("--exact", options->exact, "JSON: also write exact coordinates and planes as \"p/q\" strings");
  cmd->add_flag("--keep-back-faces", options->keep_back_faces, "do not remove back faces of closed meshes");
  cmd->add_flag("--no-consolidation", options->no_consolidation, "do not merge coplanar faces into polygons");
  cmd->footer(
      "Example:\n"
      "  hlr surfaces fixtures/scenes/l_bracket.off --view iso -o out/bracket.svg -o out/bracket.json\n"
      "\n"
      "Visible polygons do not overlap and cover the projected scene; every face's visible and hidden\n"
      "polygons together are exactly its projection. Format: docs/FORMATS.md (hlr-surfaces/1).");
  return {cmd, [options] { return run(*options); }};
}

}  // namespace hlr::app
