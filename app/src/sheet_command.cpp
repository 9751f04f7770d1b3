// `hlr sheet MESH... [--views front,top,right,iso] [--dir X,Y,Z [--up X,Y,Z]] [--projection
//             first|third] [sheet options: style_options.hpp] [--title T --number N --author A
//             --date D --revision R] [--sun DX,DY,DZ ...] [--point-light X,Y,Z ...]
//             -o OUT.svg|OUT.pdf|OUT.dxf [-o ...]`
//
// Several views of one scene on one sheet: each view is drawn exactly as `hlr draw --view NAME`
// draws it (exporter::draw_lines: the same job, one intersection search for all views, and with
// lights their shadows solved once for all views), then laid out by the export library
// (hlr/export/sheet.hpp) and written in every format asked for.
#include "atomic_file.hpp"
#include "errors.hpp"
#include "light_options.hpp"
#include "line_options.hpp"
#include "run_scope.hpp"
#include "style_options.hpp"
#include "subcommand.hpp"

#include <hlr/export/sheet.hpp>

#include <iostream>
#include <memory>

namespace hlr::app {
namespace {

struct SheetOptions {
  std::vector<std::string> meshes, outputs;
  std::string views = "front,top,right,iso";
  std::vector<double> direction, up;
  std::string eye;  // --eye: refused (perspective sheets are not laid out yet)
  std::string projection = "third";
  std::string kernel = "exact";
  int threads = 0;
  RunLimits limits;
  cad::CadOptions cad;
  exporter::DrawOptions lines;
  StyleOptions style;
  exporter::SheetFields fields;
  std::vector<std::string> suns, point_lights;  // shadows as surface detail of every view
};

enum class Format { svg, pdf, dxf };

Format format_of(const std::string& path) {
  if (has_extension(path, ".svg")) return Format::svg;
  if (has_extension(path, ".pdf")) return Format::pdf;
  if (has_extension(path, ".dxf")) return Format::dxf;
  throw UserError(path, "unknown output format (the name must end in .svg, .pdf or .dxf)");
}

// The views to draw, by name, or nothing after a one-line usage error.
std::optional<std::vector<View>> resolve_views(const SheetOptions& options) {
  std::vector<View> views;
  std::vector<std::string> names;
  for (std::size_t start = 0;;) {
    const std::size_t comma = options.views.find(',', start);
    names.push_back(options.views.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (options.views.empty()) names.clear();
  for (const auto& name : names) {
    View view;
    if (!named_view(name, view)) {
      std::cerr << "hlr: --views: unknown view \"" << name << "\" (use " << named_view_list << ")" << std::endl;
      return std::nullopt;
    }
    for (const auto& v : views)
      if (v.name == view.name) {
        std::cerr << "hlr: --views: view \"" << name << "\" is listed twice" << std::endl;
        return std::nullopt;
      }
    views.push_back(view);
  }
  if (!options.direction.empty()) {
    SceneOptions scene;
    scene.direction = options.direction;
    scene.up = options.up;
    const auto view = resolve_view(scene);  // "custom", checked
    if (!view) return std::nullopt;
    views.push_back(*view);
  }
  if (views.empty()) {
    std::cerr << "hlr: --views: no view to draw" << std::endl;
    return std::nullopt;
  }
  return views;
}

int run(const SheetOptions& options) {
  if (!options.eye.empty()) {
    std::cerr << "hlr: --eye is not supported by hlr sheet yet (draw a perspective view with hlr draw --eye)" << std::endl;
    return kExitUsage;
  }
  const auto views = resolve_views(options);
  if (!views) return kExitUsage;
  const auto style = resolve_style(options.style);
  if (!style) return kExitUsage;
  KernelKind kind = KernelKind::exact;
  parse_kernel_kind(options.kernel, kind);

  // Before the clock: the thread pool's one-time set-up is the process starting (draw_command.cpp).
  RunScope run(options.limits, options.threads);
  const auto start = std::chrono::steady_clock::now();
  std::vector<Format> formats;
  for (const auto& out : options.outputs) formats.push_back(format_of(out));
  // Every output is opened before the work starts and all are committed together at the end.
  OutputFiles files(options.outputs);
  const Scene scene = run.read(options.meshes, options.cad);
  exporter::DrawOptions job = options.lines;
  job.kernel = kind;
  job.progress = run.progress();
  // Shadows: every light solved once, from the light; each view then takes the shadow polygons
  // into itself (exporter::draw_lines with DrawOptions::shadows).
  job.shadow_lights = parse_suns(options.suns);
  for (const auto& light : parse_point_lights(options.point_lights)) job.shadow_lights.push_back(light);
  std::optional<hidden_line::ShadowResult> shadows;
  if (!job.shadow_lights.empty()) {
    const std::string first = options.suns.empty() ? "--point-light " + options.point_lights.front() : "--sun " + options.suns.front();
    if (kind != KernelKind::exact) throw UsageError(first + ": shadows are drawn by the exact path only");
    check_point_lights(scene.meshes, options.point_lights);
    run.stage("shadows of " + std::to_string(job.shadow_lights.size()) + " light(s)");
    hidden_line::ShadowOptions shadow_options;
    shadow_options.light_views = false;
    shadow_options.progress = job.progress;
    shadows = hidden_line::cast_shadows(scene, job.shadow_lights, shadow_options);
    job.shadows = &*shadows;
  }
  const exporter::SceneIntersections intersections(scene, job.intersections, job.progress);  // found once, for all views
  std::vector<exporter::LineDrawing> drawings;
  drawings.reserve(views->size());
  for (std::size_t i = 0; i < views->size(); ++i) {
    run.stage("view " + (*views)[i].name + " (" + std::to_string(i + 1) + " of " + std::to_string(views->size()) + ")");
    drawings.push_back(exporter::draw_lines(scene, (*views)[i], job, &intersections));
  }
  const double solved = seconds_since(start);

  const auto write_start = std::chrono::steady_clock::now();
  exporter::SheetSpec spec;
  spec.style = *style;
  spec.projection = options.projection == "first" ? exporter::Projection::first_angle : exporter::Projection::third_angle;
  spec.fields = options.fields;
  std::vector<exporter::SheetViewInput> inputs;
  for (std::size_t i = 0; i < views->size(); ++i) inputs.push_back({(*views)[i].name, &drawings[i]});
  exporter::SheetLayout layout;
  try {
    layout = exporter::lay_out_sheet(inputs, spec);
  } catch (const exporter::SheetError& e) {
    throw UsageError(e.what());
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    switch (formats[i]) {
      case Format::svg: files[i].write(exporter::sheet_svg(layout, spec)); break;
      case Format::pdf: files[i].write(exporter::sheet_pdf(layout, spec)); break;
      case Format::dxf: files[i].write(exporter::sheet_dxf(layout, spec)); break;
    }
  }
  files.commit();
  const double written = seconds_since(write_start);

  std::cout << "hlr sheet: " << scene.input.faces << " faces, " << views->size() << " views, "
            << (spec.projection == exporter::Projection::first_angle ? "first" : "third") << " angle, "
            << style->sheet.name << " at " << exporter::scale_label(layout.ratio) << '\n';
  for (const auto& v : layout.views) {
    const auto& st = v.drawing->stats;
    std::cout << "  " << v.name << ": " << st.visible_pieces << " visible and " << st.hidden_pieces << " hidden pieces, "
              << v.lines.curves.circles.size() << " circles, " << v.lines.curves.arcs << " arcs, "
              << v.lines.centre_lines.size() << " centre lines\n";
  }
  std::cout << "  outputs written in " << written << " s (" << solved + written << " s in all)\n";
  for (const auto& out : options.outputs) std::cout << "wrote " << out << '\n';
  run.finish(scene);
  return kExitOk;
}

}  // namespace

Subcommand add_sheet_command(CLI::App& parent) {
  auto options = std::make_shared<SheetOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "sheet", "Draw several views of a scene on one sheet: aligned after ISO 5456-2, one scale, a title block.");
  cmd->add_option("meshes", options->meshes, std::string(kInputKinds) + ", drawn together as one scene")
      ->required()
      ->type_name("MESH...");
  cmd->add_option("-o,--output", options->outputs,
                  "file to write, by extension: .svg or .pdf (the sheet in mm) or .dxf (R2000, mm: a block per "
                  "view); may be given several times")
      ->required()
      ->type_name("OUT");
  cmd->add_option("--views", options->views,
                  std::string("views to draw, separated by commas: any of ") + named_view_list +
                      " (the principal ones placed after ISO 5456-2, the others in free corners)")
      ->capture_default_str()
      ->type_name("LIST");
  auto* dir = cmd->add_option("--dir", options->direction, "one more view, looking along this direction (in a free corner)")
                  ->delimiter(',')
                  ->expected(3)
                  ->type_name("X,Y,Z");
  cmd->add_option("--up", options->up, "up vector for --dir (default +Z, or +Y when looking along Z)")
      ->delimiter(',')
      ->expected(3)
      ->needs(dir)
      ->type_name("X,Y,Z");
  cmd->add_option("--eye", options->eye, "perspective views are not laid out on sheets yet (refused)")->type_name("X,Y,Z");
  cmd->add_option("--projection", options->projection,
                  "ISO 5456-2 method: third (top view above the front view, right view to its right) or first "
                  "(top view below, right view to the left)")
      ->check(CLI::IsMember({"first", "third"}))
      ->capture_default_str()
      ->type_name("METHOD");
  add_line_options(*cmd, options->lines);
  add_limit_options(*cmd, options->limits);
  add_cad_options(*cmd, options->cad);
  options->style.sheet = "A3";
  add_style_options(*cmd, options->style);
  cmd->add_option("--sun", options->suns,
                  "draw the shadows of a directional light whose rays travel along DX,DY,DZ on every view "
                  "(as hlr draw --sun: filled light grey; DXF: HATCH on layer SHADOW); may be given several times")
      ->type_name("DX,DY,DZ");
  cmd->add_option("--point-light", options->point_lights,
                  "draw the shadows of a point light at X,Y,Z on every view likewise; may be given several times")
      ->type_name("X,Y,Z");
  cmd->add_option("--title", options->fields.title, "title block: title")->type_name("TEXT");
  cmd->add_option("--number", options->fields.number, "title block: drawing number")->type_name("TEXT");
  cmd->add_option("--author", options->fields.author, "title block: created by")->type_name("TEXT");
  cmd->add_option("--date", options->fields.date, "title block: date of issue")->type_name("TEXT");
  cmd->add_option("--revision", options->fields.revision, "title block: revision")->type_name("TEXT");
  add_kernel_option(*cmd, options->kernel);
  add_threads_option(*cmd, options->threads);
  cmd->footer(
      "Example:\n"
      "  hlr sheet fixtures/parts/flange.off --views front,top,right,iso --projection first --sheet A3 \\\n"
      "            --title Flange --number HLR-001 -o out/flange.pdf -o out/flange.dxf\n"
      "\n"
      "Each view is drawn as 'hlr draw --view NAME' draws it. Formats: docs/FORMATS.md, \"hlr sheet\".");
  return {cmd, [options] { return run(*options); }};
}

}  // namespace hlr::app
