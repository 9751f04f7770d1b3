// `hlr draw MESH... --view V -o OUT.svg|OUT.pdf|OUT.dxf|OUT.json|OUT.png [--crease DEG] [sheet
//            options: style_options.hpp] [--kernel exact|epick|double | --raster N [--dash arc|paper]]`
#include "atomic_file.hpp"
#include "errors.hpp"
#include "light_options.hpp"
#include "line_options.hpp"
#include "program_allocator.hpp"
#include "run_scope.hpp"
#include "style_options.hpp"
#include "subcommand.hpp"

#include <hlr/export/check.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

namespace hlr::app {
namespace {

struct DrawOptions {
  SceneOptions scene;
  std::vector<std::string> outputs;
  exporter::DrawOptions lines;
  StyleOptions style;
  int raster = 0;  // pixels; 0: the exact path (or --kernel)
  std::string dash = "arc";
  std::vector<std::string> suns;          // --sun: shadows as surface detail
  std::vector<std::string> point_lights;  // --point-light: likewise
  // The first light option as typed, for errors: "--sun 1,2,-4".
  std::string first_light() const {
    return suns.empty() ? "--point-light " + point_lights.front() : "--sun " + suns.front();
  }
  bool lights() const { return !suns.empty() || !point_lights.empty(); }
};

enum class Format { json, svg, pdf, dxf, png };

Format format_of(const std::string& path) {
  if (has_extension(path, ".json")) return Format::json;
  if (has_extension(path, ".svg")) return Format::svg;
  if (has_extension(path, ".pdf")) return Format::pdf;
  if (has_extension(path, ".dxf")) return Format::dxf;
  if (has_extension(path, ".png")) return Format::png;
  throw UserError(path, "unknown output format (the name must end in .svg, .pdf, .dxf, .json or .png)");
}

int solve(const DrawOptions& options, const View& view, const exporter::DrawingStyle& style) {
  // Before the clock: the thread pool's one-time set-up (RunScope: TBB loads its allocator and
  // starts its workers, up to a millisecond) is the process starting, as its loading is, not the
  // work the stats time.
  RunScope run(options.scene.limits, options.scene.threads);
  const auto start = std::chrono::steady_clock::now();
  KernelKind kind = KernelKind::exact;
  parse_kernel_kind(options.scene.kernel, kind);
  // Every output is checked and opened before the work starts, and all are committed together at
  // the end: a bad path fails fast, and a failed run leaves no output at all.
  std::vector<Format> formats;
  for (const auto& out : options.outputs) {
    formats.push_back(format_of(out));
    if (formats.back() == Format::png && options.raster == 0)
      throw UserError(out, "a PNG is drawn by the raster path: add --raster N (pixels, such as 2048)");
  }
  OutputFiles files(options.outputs);
  const Scene scene = run.read(options.scene.meshes, options.scene.cad);
  check_view_of(scene, view);
  const double read = seconds_since(start);
  exporter::DrawOptions job = options.lines;
  job.kernel = kind;
  job.shadow_lights = parse_suns(options.suns);
  for (const auto& light : parse_point_lights(options.point_lights)) job.shadow_lights.push_back(light);
  if (!job.shadow_lights.empty() && (kind != KernelKind::exact || options.raster > 0))
    throw UsageError(options.first_light() + ": shadows are drawn by the exact path only");
  check_point_lights(scene.meshes, options.point_lights);
  job.progress = run.progress();
  job.free_at_exit = true;  // the run ends with the outputs
  // A large drawing's outputs are made in the pages its lines stage frees, handed back to the
  // operating system. Below this many faces a run's memory is small, and freeing and faulting
  // pages in again would cost more time than they save.
  constexpr std::size_t kFacesToReturnPages = 100000;
  if (scene.input.faces >= kFacesToReturnPages) {
    use_small_pages();
    job.lines_stage_begins = release_free_pages;
    job.output_stage_begins = return_freed_pages;
    job.drawing_rounded = keep_freed_pages;
    job.free_once_drawn = true;
  }
  exporter::RasterRun raster;
  exporter::LineDrawing drawing;
  if (options.raster > 0) {
    raster = exporter::draw_raster(scene, view, options.raster, job);
    drawing = std::move(raster.drawing);
  } else {
    drawing = exporter::draw_lines(scene, view, job);
  }
  drawing.times.read = read;
  drawing.times.total += read;

  // The output stage (stats.stage_seconds.write): the rounding of the exact drawing, timed in
  // drawing.times.write, then from here the sheet lines, every output but the JSON, and the JSON
  // up to its stats. The JSON comes last so that it can count the others; its last block, and the
  // flushing of every file to disk, come after it and are in the summary's total only.
  const auto write_start = std::chrono::steady_clock::now();
  auto write_seconds = [&] { return drawing.times.write + seconds_since(write_start); };
  // What the SVG, PDF and DXF draw, worked out once for all, and what they merge and recover, for
  // the JSON's stats and the summary (without a sheet, the merge alone, beside the JSON's pieces).
  const bool on_sheet = std::any_of(formats.begin(), formats.end(), [](Format f) {
    return f == Format::svg || f == Format::pdf || f == Format::dxf;
  });
  exporter::SheetLines sheet;
  bool counted = false;  // the sheet's counts are in the drawing's stats
  if (on_sheet) {
    sheet = exporter::sheet_lines(drawing, style);
    if (style.scale)
      if (const auto overflow = exporter::sheet_overflow(sheet, style))
        throw UsageError("--scale " + options.style.scale + ": " + *overflow);
    drawing.curves = exporter::LineDrawing::CurveCounts{sheet.curves.circles.size(), sheet.curves.arcs};
    exporter::record_sheet_counts(drawing, sheet.merged, style);
    counted = true;
  }
  run.stage("writing " + std::to_string(files.size()) + (files.size() == 1 ? " output" : " outputs"));
  for (const bool json : {false, true}) {
    for (std::size_t i = 0; i < files.size(); ++i) {
      if ((formats[i] == Format::json) != json) continue;
      switch (formats[i]) {
        case Format::json: {
          auto sink = [&](std::string_view text) { files[i].write(text); };
          if (counted) {
            exporter::write_lines_json(drawing, sink, write_seconds);
          } else {  // the merge, for the stats alone, beside the pieces
            sheet.merged = exporter::write_lines_json_merging(drawing, style, sink, write_seconds);
            counted = true;
          }
          break;
        }
        case Format::svg: files[i].write(exporter::lines_svg(drawing, style, sheet)); break;
        case Format::pdf: files[i].write(exporter::lines_pdf(drawing, style, sheet)); break;
        case Format::dxf: files[i].write(exporter::lines_dxf(drawing, style, sheet)); break;
        case Format::png:
          files[i].write(exporter::png_document(raster.raster->pbuffer(
              options.dash == "paper" ? hidden_line::DashPattern::paper : hidden_line::DashPattern::arc_length)));
          break;
      }
    }
  }
  if (!counted) {
    sheet.merged = exporter::sheet_segments(drawing, style);
    exporter::record_sheet_counts(drawing, sheet.merged, style);
  }
  const std::size_t merged = sheet.merged.merged;
  files.commit();
  const double written = write_seconds();
  run.finish(scene);

  const auto& st = drawing.stats;
  auto kind_count = [&](FeatureKind k) { return st.by_kind[static_cast<int>(k)]; };
  const std::string method =
      options.raster > 0 ? "raster " + std::to_string(options.raster) + " px" : "kernel " + std::string(kernel_name(kind));
  std::cout << "hlr draw: " << scene.input.faces << " faces, view " << view.name << ", " << method << '\n'
            << "  " << st.lines << " feature lines (" << kind_count(FeatureKind::silhouette) << " silhouette, "
            << kind_count(FeatureKind::crease) << " crease, " << kind_count(FeatureKind::boundary) << " boundary, "
            << kind_count(FeatureKind::group) << " group, " << kind_count(FeatureKind::intersection) << " intersection"
            << (kind_count(FeatureKind::smooth) ? ", " + std::to_string(kind_count(FeatureKind::smooth)) + " smooth" : "")
            << ")\n"
            << "  " << st.visible_pieces << " visible and " << st.hidden_pieces << " hidden pieces in "
            << drawing.times.total << " s\n";
  if (merged > 0)
    std::cout << "  " << merged << " segments merged on the sheet (lines within " << style.merge_distance
              << " mm of a line drawn already)\n";
  if (sheet.merged.contact > 0)
    std::cout << "  " << sheet.merged.contact << " intersection segments left off the sheet (surfaces meeting at under "
              << style.contact_degrees << " degrees: contact of nearly tangent surfaces)\n";
  const auto& source = sheet.curves.from_source;
  if (source.circles + source.arcs + sheet.curves.ellipses.size() > 0)
    std::cout << "  " << source.circles << " circles, " << source.arcs << " arcs and " << sheet.curves.ellipses.size()
              << " ellipses from the model's own curves\n";
  if (sheet.curves.circles.size() > source.circles || sheet.curves.arcs > source.arcs)
    std::cout << "  " << sheet.curves.circles.size() - source.circles << " circles and " << sheet.curves.arcs - source.arcs
              << " arcs drawn as such (vertices within " << style.merge_distance << " mm of a circle on the sheet)\n";
  std::cout << "  outputs written in " << written << " s (" << drawing.times.total + written << " s in all)\n";
  for (const auto& out : options.outputs) std::cout << "wrote " << out << '\n';
  return kExitOk;
}

int run(const DrawOptions& options) {
  const std::optional<View> view = resolve_view(options.scene);
  if (!view) return kExitUsage;
  if (view->eye && options.lights()) {
    std::cerr << "hlr: " << options.first_light()
              << ": shadows are not supported with --eye yet (they are drawn in orthographic views)" << std::endl;
    return kExitUsage;
  }
  const std::optional<exporter::DrawingStyle> style = resolve_style(options.style);
  if (!style) return kExitUsage;
  if (options.raster > 0 && options.scene.kernel != "exact") {
    std::cerr << "hlr: --raster and --kernel " << options.scene.kernel
              << " exclude each other (the raster path decides visibility by depth tests, not by a kernel)"
              << std::endl;
    return kExitUsage;
  }
  return solve(options, *view, *style);
}

}  // namespace

Subcommand add_draw_command(CLI::App& parent) {
  auto options = std::make_shared<DrawOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "draw", "Draw a mesh as an engineering line drawing: visible lines solid, hidden lines dashed, exactly.");
  add_scene_options(*cmd, options->scene);
  cmd->add_option("-o,--output", options->outputs,
                  "file to write, by extension: .svg or .pdf (a sheet, in mm), .dxf (R2000, model units), .json "
                  "(hlr-lines/1) or .png (with --raster); may be given several times")
      ->required()
      ->type_name("OUT");
  add_line_options(*cmd, options->lines);
  add_style_options(*cmd, options->style);
  cmd->add_option("--raster", options->raster,
                  "decide visibility in image space instead (the P-buffer path, inexact): a Z-buffer N pixels "
                  "along the longer side; needed for .png output")
      ->check(CLI::Range(16, 8192))
      ->type_name("N");
  cmd->add_option("--sun", options->suns,
                  "draw the shadows of a directional light whose rays travel along DX,DY,DZ as surface detail "
                  "(filled light grey; DXF: HATCH on layer SHADOW); may be given several times")
      ->type_name("DX,DY,DZ");
  cmd->add_option("--point-light", options->point_lights,
                  "draw the shadows of a point light at X,Y,Z (outside the scene, as for hlr shadows) likewise; "
                  "may be given several times")
      ->type_name("X,Y,Z");
  cmd->add_option("--dash", options->dash,
                  "hidden-line dashes in the PNG: arc (by arc length along each line) or paper (the P-buffer "
                  "paper's 8x8 screen pattern, which breaks up on diagonal lines)")
      ->check(CLI::IsMember({"arc", "paper"}))
      ->capture_default_str()
      ->type_name("STYLE");
  cmd->footer(
      "Example:\n"
      "  hlr draw fixtures/scenes/l_bracket.off --view iso -o out/bracket.svg -o out/bracket.dxf\n"
      "  hlr draw fixtures/parts/anchor.off --view iso --raster 2048 -o out/anchor.png\n"
      "\n"
      "Feature lines are boundary, crease, silhouette, group and intersection lines (smooth ones too with\n"
      "--smooth-edges thin, drawn thin); each is split into visible and hidden pieces exactly. Model units\n"
      "are millimetres unless --units says otherwise.\n"
      "Formats: docs/FORMATS.md.");
  return {cmd, [options] { return run(*options); }};
}

}  // namespace hlr::app
