// `hlr shadows MESH... (--sun DX,DY,DZ | --sun-at TIME --site LAT,LON[,NORTH] | --point-light X,Y,Z)...
//  [--union] [--cull fuzzy|none]
//  -o OUT.json|OUT.csv|OUT.svg`: the options, then hidden_line::cast_shadows, then the writers.
#include "atomic_file.hpp"
#include "errors.hpp"
#include "light_options.hpp"
#include "run_scope.hpp"
#include "scene_options.hpp"
#include "subcommand.hpp"

#include <hlr/export/shadows.hpp>
#include <hlr/hidden_line/shadows.hpp>
#include <hlr/kernel/sun.hpp>

#include <charconv>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace hlr::app {
namespace {

struct ShadowsOptions {
  std::vector<std::string> meshes;
  std::vector<std::string> suns, sun_at, point_lights;
  std::string site;
  bool union_shadows = false;
  std::string cull = "fuzzy";
  std::vector<std::string> outputs;
  int threads = 0;
  RunLimits limits;
  cad::CadOptions cad;
};

enum class Format { json, csv, svg };

Format format_of(const std::string& path) {
  if (has_extension(path, ".json")) return Format::json;
  if (has_extension(path, ".csv")) return Format::csv;
  if (has_extension(path, ".svg")) return Format::svg;
  throw UserError(path, "unknown output format (the name must end in .json, .csv or .svg)");
}

struct Lights {
  std::vector<hidden_line::Light> lights;
  std::vector<exporter::LightLabel> labels;
};

Lights resolve_lights(const ShadowsOptions& o) {
  Lights out;
  for (const auto& light : parse_suns(o.suns)) {
    out.lights.push_back(light);
    out.labels.push_back({"sun" + std::to_string(out.lights.size()), std::nullopt, {}, 0, 0});
  }
  if (!o.sun_at.empty() && o.site.empty()) throw UsageError("--sun-at " + o.sun_at.front() + ": needs --site LAT,LON");
  if (o.sun_at.empty() && !o.site.empty()) throw UsageError("--site " + o.site + ": needs --sun-at");
  if (!o.sun_at.empty()) {
    std::string error;
    const auto site = parse_site(o.site, error);
    if (!site) throw UsageError("--site " + o.site + ": " + error);
    for (const auto& text : o.sun_at) {
      const auto times = parse_sun_times(text, error);
      if (!times) throw UsageError("--sun-at " + text + ": " + error);
      for (const auto& t : *times) {
        const SunPosition sun = sun_position(t, *site);
        const std::string label = format_local_time(t);
        if (sun.altitude <= 0) {
          std::ostringstream e;
          e.precision(3);
          e << std::fixed << "the sun is below the horizon at " << label << " (altitude " << sun.altitude
            << " degrees)";
          throw UserError("--sun-at " + text, e.str());
        }
        out.lights.push_back({hidden_line::Light::directional, sun.direction});
        out.labels.push_back({label, label, {site->latitude, site->longitude, site->north}, sun.azimuth, sun.altitude});
      }
    }
  }
  std::size_t points = 0;
  for (const auto& light : parse_point_lights(o.point_lights)) {
    out.lights.push_back(light);
    out.labels.push_back({"point" + std::to_string(++points), std::nullopt, {}, 0, 0});
  }
  if (out.lights.empty())
    throw UsageError("no light: give --sun DX,DY,DZ, --sun-at TIME --site LAT,LON or --point-light X,Y,Z");
  return out;
}

int run(const ShadowsOptions& options) {
  // Before the clock: the thread pool's one-time set-up is the process starting (draw_command.cpp).
  RunScope run(options.limits, options.threads);
  const auto start = std::chrono::steady_clock::now();
  std::vector<Format> formats;
  for (const auto& out : options.outputs) formats.push_back(format_of(out));
  const Lights lights = resolve_lights(options);
  OutputFiles files(options.outputs);
  const Scene scene = run.read(options.meshes, options.cad);
  const auto& input = scene.input;
  const double read = seconds_since(start);
  check_point_lights(scene.meshes, options.point_lights);

  hidden_line::ShadowOptions shadow_options;
  shadow_options.union_shadows = options.union_shadows;
  shadow_options.light_views = std::find(formats.begin(), formats.end(), Format::svg) != formats.end();
  shadow_options.progress = run.progress();
  // The culled faces change no face's lit area, but the polygons of a .json or .svg (the area
  // sort's fragments) depend on every polygon sorted: culling only where the outputs are areas.
  const bool areas_only = std::all_of(formats.begin(), formats.end(), [](Format f) { return f == Format::csv; });
  shadow_options.cull = options.cull == "fuzzy" && areas_only;
  const hidden_line::ShadowResult result = hidden_line::cast_shadows(scene, lights.lights, shadow_options);

  exporter::ShadowsDocument doc{input, scene.meshes, lights.lights, lights.labels, result, read};
  doc.cull = shadow_options.cull;
  for (std::size_t i = 0; i < files.size(); ++i)
    files[i].write(formats[i] == Format::json  ? exporter::shadows_json(doc)
                   : formats[i] == Format::csv ? exporter::shadows_csv(doc)
                                               : exporter::shadows_svg(doc));
  files.commit();
  run.finish(scene);
  double area = 0, lit = 0;
  for (const auto& s : result.sources) {
    area += s.area * double(lights.lights.size());
    for (const auto& sl : s.lights) lit += sl.lit_area;
  }
  std::cout << "hlr shadows: " << input.faces << " faces, " << result.sources.size() << " sources, "
            << lights.lights.size() << " light(s); sunlit " << (area > 0 ? 100 * lit / area : 0.0)
            << "% of the surface in " << result.times.total << " s\n";
  std::cout << "  cull " << (shadow_options.cull ? "fuzzy" : "none");
  if (options.cull == "fuzzy" && !shadow_options.cull) std::cout << " (.json and .svg polygons depend on every face sorted)";
  std::cout << ", " << result.cull_groups.size() << (result.cull_groups.size() == 1 ? " group" : " groups")
            << " of directional lights\n";
  double fuzzy = 0, solve = 0;
  for (std::size_t g = 0; g < result.cull_groups.size(); ++g) {
    const auto& group = result.cull_groups[g];
    fuzzy += group.fuzzy_seconds, solve += group.solve_seconds;
    if (result.cull_groups.size() > 8 && (!shadow_options.cull || group.culled == 0)) continue;
    std::cout << "  group " << g << ": lights " << group.first << " to " << group.first + group.count - 1;
    if (shadow_options.cull) {
      std::cout << ", " << group.culled << " of " << group.patches << " faces culled";
      if (group.parts > 1) std::cout << " (the most of its " << group.parts << " parts)";
      std::cout << "; fuzzy pass" << (group.fuzzy_passes == 1 ? " " : "es ") << group.fuzzy_seconds << " s";
    }
    std::cout << ", lights " << group.solve_seconds << " s\n";
  }
  if (!result.cull_groups.empty())
    std::cout << "  directional lights solved in " << solve << " s (light views " << result.times.views << " s, sorts "
              << result.times.sort << " s, map back " << result.times.map_back << " s)" << (shadow_options.cull ? ", fuzzy passes " : "")
              << (shadow_options.cull ? std::to_string(fuzzy) + " s" : "") << '\n';
  for (const auto& out : options.outputs) std::cout << "wrote " << out << '\n';
  return kExitOk;
}

}  // namespace

Subcommand add_shadows_command(CLI::App& parent) {
  auto options = std::make_shared<ShadowsOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "shadows", "Find which part of every face each light reaches, exactly, and the shadows on the rest.");
  cmd->add_option("meshes", options->meshes, std::string(kInputKinds) + ", lit together as one scene")
      ->required()
      ->type_name("MESH...");
  cmd->add_option("--sun", options->suns,
                  "a directional light whose rays travel along DX,DY,DZ (for example 1,2,-4); may be given "
                  "several times")
      ->type_name("DX,DY,DZ");
  cmd->add_option("--sun-at", options->sun_at,
                  "the sun at a local time, YYYY-MM-DDTHH:MM[+HH:MM], or a sun study START/END/STEP (for "
                  "example 2026-06-21T09:00+10:00/15:00/PT1H: one light per step); needs --site")
      ->type_name("TIME");
  cmd->add_option("--site", options->site,
                  "the site for --sun-at: latitude and longitude in degrees (north, east positive), and "
                  "optionally true north in degrees clockwise from the model's +Y (+Z is up)")
      ->type_name("LAT,LON[,NORTH]");
  cmd->add_option("--point-light", options->point_lights,
                  "a point light at X,Y,Z, outside the scene: every vertex strictly on one side of a plane "
                  "through it (one perspective view from the light); may be given several times")
      ->type_name("X,Y,Z");
  cmd->add_flag("--union", options->union_shadows,
                "also the union of every face's shadows over all lights (CSV columns, JSON union_shadow_area)");
  cmd->add_option("-o,--output", options->outputs,
                  "file to write: .json (hlr-shadows/1), .csv (per face lit areas) or .svg (the view from "
                  "each light); may be given several times")
      ->required()
      ->type_name("OUT");
  cmd->add_option("--cull", options->cull,
                  "fuzzy: leave out of the light views of each group of sun directions the faces none of them "
                  "can light (Lim's fuzzy culling; the same lit areas), where every output is .csv (the polygons "
                  "of .json and .svg depend on every face sorted: those runs solve every face); none: solve every "
                  "face")
      ->check(CLI::IsMember({"fuzzy", "none"}))
      ->capture_default_str()
      ->type_name("MODE");
  add_threads_option(*cmd, options->threads);
  add_limit_options(*cmd, options->limits);
  add_cad_options(*cmd, options->cad);
  cmd->footer(
      "Examples:\n"
      "  hlr shadows fixtures/shadows/box_on_ground.off --sun 1,2,-4 -o out/box.json -o out/box.csv\n"
      "  hlr shadows site.off --sun-at 2026-06-21T09:00+10:00/15:00/PT1H --site -33.86,151.21 --union -o out/day.csv\n"
      "  hlr shadows fixtures/shadows/box_on_ground.off --point-light 1,-4,4 -o out/lamp.json -o out/lamp.svg\n"
      "\n"
      "Each light is solved on its own: the scene seen from the light, its visible polygons the lit parts,\n"
      "taken back exactly onto their faces; lit + shadow = every face. Format: docs/FORMATS.md (hlr-shadows/1).");
  return {cmd, [options] { return run(*options); }};
}

}  // namespace hlr::app
