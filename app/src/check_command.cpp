// `hlr check MESH... --view V [--raster N,...] [--kernels epick,double] [--diff OUT.png] [--json OUT.json]`
// `hlr check MESH... (--sun DX,DY,DZ | --point-light X,Y,Z)... [--raster N,...] [--json OUT.json]`
//
// Draws the scene exactly, then by every method asked for, and reports how each one classifies
// the same lines: the fraction of line length classified alike, and the pieces that differ.
// The exact drawing is the reference (docs/STABILITY.md says why, case by case).
// With lights it checks shadows instead: the exact lit area of every face against the raster
// shadow map's sunlit fraction at each resolution (exporter::check_shadows).
#include "atomic_file.hpp"
#include "errors.hpp"
#include "light_options.hpp"
#include "line_options.hpp"
#include "run_scope.hpp"
#include "subcommand.hpp"

#include <hlr/export/check.hpp>
#include <hlr/export/shadow_check.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace hlr::app {
namespace {

struct CheckOptions {
  SceneOptions scene;
  std::vector<int> rasters;
  std::vector<std::string> kernels;
  std::string diff, json;
  exporter::DrawOptions lines;
  std::vector<std::string> suns, point_lights;  // a shadow check
  bool view_given = false;                      // --view, --dir or --eye on the command line
  bool lights() const { return !suns.empty() || !point_lights.empty(); }
  std::string first_light() const {
    return suns.empty() ? "--point-light " + point_lights.front() : "--sun " + suns.front();
  }
};

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4f%%", 100 * fraction);
  return text;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

std::string light_name(const hidden_line::Light& light) {
  const auto& v = light.vector;
  return (light.kind == hidden_line::Light::directional ? "sun " : "point light ") + number(v[0]) + "," +
         number(v[1]) + "," + number(v[2]);
}

// The shadow check: exact shadows against the raster shadow map (exporter::check_shadows).
int run_shadows(CheckOptions options) {
  if (options.view_given)
    throw UsageError(options.first_light() + ": the shadow check has no view (give no --view, --dir or --eye)");
  if (!options.kernels.empty())
    throw UsageError("--kernels: the shadow check compares the raster shadow map only (not with " +
                     options.first_light() + ")");
  if (!options.diff.empty()) throw UsageError("--diff: draws the line check only (not with " + options.first_light() + ")");
  std::vector<hidden_line::Light> lights = parse_suns(options.suns);
  for (const auto& light : parse_point_lights(options.point_lights)) lights.push_back(light);
  if (options.rasters.empty()) options.rasters = {1024};
  std::unique_ptr<AtomicFile> json_file;
  if (!options.json.empty()) {
    if (!has_extension(options.json, ".json")) throw UserError(options.json, "the report must be a .json");
    json_file = std::make_unique<AtomicFile>(options.json);
  }

  RunScope run(options.scene.limits, options.scene.threads);
  const Scene scene = run.read(options.scene.meshes, options.scene.cad);
  check_point_lights(scene.meshes, options.point_lights);
  // The shadow map is one view per light: a point light among the geometry, which the exact path
  // solves in a cube of six views, has none.
  for (std::size_t i = 0; i < options.point_lights.size(); ++i)
    if (!hidden_line::point_light_view(scene.meshes, lights[options.suns.size() + i]))
      throw UsageError("--point-light " + options.point_lights[i] +
                       ": the raster shadow map takes a light that one perspective view serves, not one among the geometry");
  const exporter::ShadowCheckReport report = exporter::check_shadows(scene, lights, options.rasters, run.progress());
  if (json_file) {
    json_file->write(exporter::shadow_check_json(report));
    json_file->commit();
  }
  run.finish(scene);

  std::cout << "hlr check: " << scene.input.faces << " faces, " << lights.size()
            << " light(s), shadows; exact in " << number(report.reference_seconds) << " s\n";
  const exporter::ShadowCheckedMethod* worst = nullptr;
  std::size_t worst_light = 0;
  for (const exporter::ShadowCheckedMethod& m : report.methods) {
    for (std::size_t k = 0; k < m.lights.size(); ++k) {
      const exporter::ShadowAgreement& a = m.lights[k];
      std::cout << "  raster " << m.resolution << ", " << light_name(lights[k]) << ": lit area "
                << number(a.raster_lit_area) << " against " << number(a.exact_lit_area) << ", error "
                << number(a.lit_area_error) << " (" << percent(a.relative_error()) << " of " << number(a.area)
                << "); sunlit fraction per face: max difference " << number(a.max_difference) << " (mesh "
                << a.max_mesh << " face " << a.max_face << "), mean " << number(a.mean_difference) << "; "
                << a.samples << " samples\n";
      if (!worst || a.relative_error() > worst->lights[worst_light].relative_error()) worst = &m, worst_light = k;
    }
    std::cout << "  raster " << m.resolution << ": " << number(m.seconds) << " s\n";
  }
  if (json_file) std::cout << "wrote " << options.json << '\n';
  std::cout << "check: raster " << worst->resolution << " misses " << percent(worst->lights[worst_light].relative_error())
            << " of the surface's lit area (" << light_name(lights[worst_light]) << ")";
  if (report.methods.size() * lights.size() > 1) std::cout << "; the most of " << report.methods.size() * lights.size() << " runs";
  std::cout << std::endl;
  return kExitOk;
}

int run(CheckOptions options) {
  if (options.lights()) return run_shadows(std::move(options));
  const std::optional<View> view = resolve_view(options.scene);
  if (!view) return kExitUsage;
  if (options.rasters.empty() && options.kernels.empty()) options.rasters = {1024};
  if (!options.diff.empty() && options.rasters.size() + options.kernels.size() != 1) {
    std::cerr << "hlr: --diff draws one comparison: give one method (one --raster N or one --kernels K)" << std::endl;
    return kExitUsage;
  }
  std::unique_ptr<AtomicFile> diff_file, json_file;
  if (!options.diff.empty()) {
    if (!has_extension(options.diff, ".png")) throw UserError(options.diff, "the difference image must be a .png");
    diff_file = std::make_unique<AtomicFile>(options.diff);
  }
  if (!options.json.empty()) {
    if (!has_extension(options.json, ".json")) throw UserError(options.json, "the report must be a .json");
    json_file = std::make_unique<AtomicFile>(options.json);
  }

  RunScope run(options.scene.limits, options.scene.threads);
  const Scene scene = run.read(options.scene.meshes, options.scene.cad);
  check_view_of(scene, *view);
  exporter::DrawOptions job = options.lines;
  job.progress = run.progress();
  const exporter::SceneIntersections intersections(scene, job.intersections, job.progress);  // for every method
  const exporter::LineDrawing reference = exporter::draw_lines(scene, *view, job, &intersections);

  exporter::CheckReport report;
  report.input = scene.input;
  report.view = reference.view;
  report.reference_seconds = reference.times.total;
  report.reference_visible_length = reference.visible_length();
  report.reference_hidden_length = reference.hidden_length();
  const int image_resolution = options.rasters.empty() ? 1024 : options.rasters.front();
  for (const std::string& name : options.kernels) {
    exporter::CheckedMethod m;
    m.method = name;
    exporter::DrawOptions method = job;
    parse_kernel_kind(name, method.kernel);
    try {
      const exporter::LineDrawing drawing = exporter::draw_lines(scene, *view, method, &intersections);
      m.seconds = drawing.times.total;
      m.agreement = exporter::compare_drawings(reference, drawing);
    } catch (const UserError& e) {  // the kernel's own failure is a finding, not an error of the check
      m.failure = e.what();
    }
    report.methods.push_back(std::move(m));
  }
  for (int resolution : options.rasters) {
    exporter::CheckedMethod m;
    m.method = "raster";
    m.resolution = resolution;
    const exporter::RasterRun run = exporter::draw_raster(scene, *view, resolution, job, &intersections);
    m.seconds = run.drawing.times.total;
    m.agreement = exporter::compare_drawings(reference, run.drawing);
    report.methods.push_back(std::move(m));
  }

  if (diff_file) {
    const auto& agreement = report.methods.front().agreement;
    diff_file->write(exporter::png_document(exporter::difference_image(reference, agreement, image_resolution)));
  }
  if (json_file) json_file->write(exporter::check_json(report));
  if (diff_file) diff_file->commit();
  if (json_file) json_file->commit();
  run.finish(scene);

  std::cout << "hlr check: " << scene.input.faces << " faces, view " << view->name << ", " << reference.stats.lines
            << " lines, " << number(reference.visible_length() + reference.hidden_length())
            << " drawn length; exact in " << number(report.reference_seconds) << " s\n";
  const exporter::CheckedMethod* worst = nullptr;
  for (const exporter::CheckedMethod& m : report.methods) {
    const auto& a = m.agreement;
    std::cout << "  " << m.name() << ": ";
    if (!m.failure.empty()) {
      std::cout << "failed: " << m.failure << '\n';
    } else if (!a.invalid.empty()) {
      std::cout << "invalid result: " << a.invalid << '\n';
    } else {
      using exporter::Difference;
      std::cout << percent(a.fraction()) << " of " << number(a.total_length) << " line length alike in "
                << number(m.seconds) << " s; " << a.pieces.size() << " pieces differ: "
                << a.count(Difference::hidden_in_candidate) << " hidden that are visible ("
                << number(a.length(Difference::hidden_in_candidate)) << "), "
                << a.count(Difference::visible_in_candidate) << " visible that are hidden ("
                << number(a.length(Difference::visible_in_candidate)) << "), "
                << a.count(Difference::missing_in_candidate) << " missing ("
                << number(a.length(Difference::missing_in_candidate)) << ")\n";
    }
    auto score = [](const exporter::CheckedMethod& c) {
      return c.failure.empty() && c.agreement.invalid.empty() ? c.agreement.fraction() : -1.0;
    };
    if (!worst || score(m) < score(*worst)) worst = &m;
  }
  if (diff_file) std::cout << "wrote " << options.diff << '\n';
  if (json_file) std::cout << "wrote " << options.json << '\n';
  // The summary: the method that agrees least.
  std::cout << "check: ";
  if (!worst->failure.empty())
    std::cout << worst->name() << " failed";
  else if (!worst->agreement.invalid.empty())
    std::cout << worst->name() << " gave an invalid result";
  else
    std::cout << worst->name() << " classifies " << percent(worst->agreement.fraction())
              << " of the line length as the exact path does (" << worst->agreement.pieces.size()
              << " pieces differ, length " << number(worst->agreement.total_length - worst->agreement.agreeing_length)
              << ")";
  if (report.methods.size() > 1) std::cout << "; the least of " << report.methods.size() << " methods";
  std::cout << std::endl;
  return kExitOk;
}

}  // namespace

Subcommand add_check_command(CLI::App& parent) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "check", "Compare the exact drawing with the raster path (or an inexact kernel) on the same lines.");
  add_scene_options(*cmd, options->scene, /*kernel=*/false);
  cmd->add_option("--sun", options->suns,
                  "check shadows instead of lines: a directional light whose rays travel along DX,DY,DZ, "
                  "the exact lit areas against a raster shadow map; may be given several times")
      ->type_name("DX,DY,DZ");
  cmd->add_option("--point-light", options->point_lights,
                  "check the shadows of a point light at X,Y,Z likewise (outside the scene, as for hlr shadows)")
      ->type_name("X,Y,Z");
  cmd->add_option("--raster", options->rasters,
                  "raster resolutions to check, in pixels (default 1024): of the drawing, or of the shadow map")
      ->delimiter(',')
      ->check(CLI::Range(16, 8192))
      ->type_name("N,...");
  cmd->add_option("--kernels", options->kernels, "inexact kernels to check as well: epick, double")
      ->delimiter(',')
      ->check(CLI::IsMember({"epick", "double"}))
      ->type_name("K,...");
  cmd->add_option("--diff", options->diff,
                  "PNG of the exact drawing with the differences over it: red where the method hides a "
                  "visible line, blue where it shows a hidden one, orange where it has none")
      ->type_name("OUT.png");
  cmd->add_option("--json", options->json, "the report as hlr-check/1 JSON (docs/FORMATS.md)")->type_name("OUT.json");
  add_line_options(*cmd, options->lines);
  cmd->footer(
      "Example:\n"
      "  hlr check fixtures/parts/anchor.off --view iso --raster 2048 --diff out/anchor_check.png\n"
      "  hlr check fixtures/shadows/box_on_ground.off --sun 1,2,-4 --raster 64,512 --json out/box_check.json\n"
      "\n"
      "The last line is the summary. The exit status is 0 whatever the agreement; it is not 0 only on an\n"
      "error (a bad mesh, an unwritable output, a bad option).");
  return {cmd, [options, cmd] {
            options->view_given = cmd->count("--view") + cmd->count("--dir") + cmd->count("--eye") > 0;
            return run(*options);
          }};
}

}  // namespace hlr::app
