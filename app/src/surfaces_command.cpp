// `hlr surfaces MESH... --view V -o OUT.json|OUT.svg [--kernel exact|epick|double] [--exact]`
#include "atomic_file.hpp"
#include "errors.hpp"
#include "subcommand.hpp"

#include <hlr/export/surfaces.hpp>

#include <chrono>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace hlr::app {
namespace {

struct SurfacesOptions {
  std::vector<std::string> meshes, outputs;
  std::string view = "iso";
  std::vector<double> direction, up;
  std::string kernel = "exact";
  bool exact = false;
  bool keep_back_faces = false;
  bool no_consolidation = false;
};

enum class Format { json, svg };

Format format_of(const std::string& path) {
  auto ends_with = [&](const char* ext) {
    const std::string e(ext);
    return path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0;
  };
  if (ends_with(".json")) return Format::json;
  if (ends_with(".svg")) return Format::svg;
  throw UserError(path, "unknown output format (the name must end in .json or .svg)");
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <class K>
int solve(const SurfacesOptions& options, const View& view, KernelKind kind) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Format> formats;
  for (const auto& out : options.outputs) formats.push_back(format_of(out));

  exporter::InputInfo input;
  std::vector<Mesh> meshes;
  for (const auto& path : options.meshes) {
    ImportReport report;
    meshes.push_back(load_mesh(path, report));
    for (const auto& w : report.warnings) std::cerr << "hlr: warning: " << w << '\n';
    input.files.push_back(path);
    input.faces += meshes.back().faces.size();
    input.vertices += meshes.back().vertices.size();
  }
  exporter::StageTimes times;
  times.read = seconds_since(start);
  // Large scenes take seconds: say what is happening.
  const bool progress = input.faces >= 20000;
  if (progress) std::cerr << "hlr surfaces: " << input.faces << " faces read; building polygons\n";

  const ViewFrame<K> frame(view);
  hidden_line::SourceOptions source_options;
  source_options.remove_back_faces = !options.keep_back_faces;
  source_options.consolidate = !options.no_consolidation;
  auto mark = std::chrono::steady_clock::now();
  hidden_line::Sources<K> sources;
  hidden_line::VisibilityMap<K> map;
  try {
    sources = hidden_line::build_sources<K>(meshes, frame, source_options);
    times.sources = seconds_since(mark);
    if (progress) std::cerr << "hlr surfaces: sorting " << sources.polygons.size() << " polygons\n";
    mark = std::chrono::steady_clock::now();
    map = hidden_line::area_sort<K>(sources);
    times.sort = seconds_since(mark);
  } catch (const clip::ClipError& e) {
    // Only the inexact kernels get here: their rounded decisions can contradict each other.
    throw UserError(options.meshes.front(), std::string("the ") + kernel_name(kind) +
                                                " kernel failed on this view (" + e.what() +
                                                "); the exact kernel does not");
  }
  times.total = seconds_since(start);

  const exporter::SurfacesDocument<K> doc{input, meshes, frame, sources, map, kind, times};
  for (std::size_t i = 0; i < options.outputs.size(); ++i) {
    AtomicFile file(options.outputs[i]);
    file.write(formats[i] == Format::json ? exporter::surfaces_json(doc, options.exact) : exporter::surfaces_svg(doc));
    file.commit();
  }
  const auto& st = sources.stats;
  if (st.non_simple_faces_skipped > 0)
    std::cerr << "hlr: warning: " << st.non_simple_faces_skipped
              << " polygon faces skipped: their projection in this view is not a simple polygon\n";
  std::cout << "hlr surfaces: " << input.faces << " faces, view " << view.name << ", kernel " << kernel_name(kind) << '\n'
            << "  " << st.back_faces_removed << " back faces and " << st.edge_on_faces_removed
            << " edge-on faces removed; " << st.faces_consolidated << " faces consolidated; " << st.sources
            << " polygons sorted\n"
            << "  " << map.visible.size() << " visible and " << map.hidden.size() << " hidden polygons ("
            << map.stats.penetration_splits << " penetration splits, " << map.stats.coplanar_ties
            << " coplanar ties) in " << times.total << " s\n";
  for (const auto& out : options.outputs) std::cout << "wrote " << out << '\n';
  return kExitOk;
}

int run(const SurfacesOptions& options) {
  View view;
  if (!options.direction.empty()) {
    view.name = "custom";
    view.direction = {options.direction[0], options.direction[1], options.direction[2]};
    view.up = options.up.empty() ? Vec3{0, 0, 1} : Vec3{options.up[0], options.up[1], options.up[2]};
    // The default up is +Z (CAD convention); looking straight along Z, take +Y instead.
    if (options.up.empty() && view.direction[0] == 0 && view.direction[1] == 0) view.up = {0, 1, 0};
  } else if (!named_view(options.view, view)) {
    std::cerr << "hlr: --view: unknown view \"" << options.view << "\" (use " << named_view_list
              << ", or --dir X,Y,Z)" << std::endl;
    return kExitUsage;
  }
  if (auto defect = view_defect(view)) {
    std::cerr << "hlr: " << (options.direction.empty() ? "--view" : "--dir/--up") << ": " << *defect << std::endl;
    return kExitUsage;
  }
  KernelKind kind = KernelKind::exact;
  parse_kernel_kind(options.kernel, kind);
  switch (kind) {
    case KernelKind::epick: return solve<EpickKernel>(options, view, kind);
    case KernelKind::floating: return solve<DoubleKernel>(options, view, kind);
    case KernelKind::exact: break;
  }
  return solve<ExactKernel>(options, view, kind);
}

}  // namespace

Subcommand add_surfaces_command(CLI::App& parent) {
  auto options = std::make_shared<SurfacesOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "surfaces", "Solve which parts of every face are visible and which are hidden, exactly, in one view.");
  cmd->add_option("meshes", options->meshes, "mesh files (OFF, OBJ, STL, PLY), drawn together as one scene")
      ->required()
      ->type_name("MESH...");
  cmd->add_option("-o,--output", options->outputs,
                  "file to write: .json (hlr-surfaces/1) or .svg (a picture); may be given several times")
      ->required()
      ->type_name("OUT");
  auto* view = cmd->add_option("--view", options->view, std::string("named view: ") + named_view_list)
                   ->capture_default_str()
                   ->type_name("NAME");
  auto* dir = cmd->add_option("--dir", options->direction, "look direction instead of a named view")
                  ->delimiter(',')
                  ->expected(3)
                  ->type_name("X,Y,Z");
  dir->excludes(view);
  cmd->add_option("--up", options->up, "up vector for --dir (default +Z, or +Y when looking along Z)")
      ->delimiter(',')
      ->expected(3)
      ->needs(dir)
      ->type_name("X,Y,Z");
  add_kernel_option(*cmd, options->kernel);
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
