// `hlr frames MESH... (--eyes FILE | --orbit N [--elevation DEG] [--distance D]) [--target X,Y,Z]
//             [--up X,Y,Z] [--near F] [--cull fuzzy|none] [--cull-report] -o DIR/frame_%03d.svg [-o ...]`
//
// One perspective drawing per eye, each the drawing `hlr draw --eye E --target T` makes, written
// under names numbered from 0 and laid out at one scale about one centre, so that they play as an
// animation. The job is exporter::draw_frames (hlr/export/frames.hpp).
#include "atomic_file.hpp"
#include "errors.hpp"
#include "line_options.hpp"
#include "run_scope.hpp"
#include "style_options.hpp"
#include "subcommand.hpp"

#include <hlr/export/check.hpp>
#include <hlr/export/frames.hpp>
#include <hlr/kernel/near_plane.hpp>

#include <sys/resource.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace hlr::app {
namespace {

struct FramesCommandOptions {
  std::vector<std::string> meshes, patterns;
  std::string eyes_file;
  int orbit = 0;
  double elevation = 30;
  double distance = 0;  // 0: kOrbitDiagonals bounding-box diagonals
  std::vector<double> target, up;
  double near = 0;
  std::string cull = "fuzzy";
  bool cull_report = false;
  std::string kernel = "exact";
  int raster = 0;
  std::string dash = "arc";
  int threads = 0;
  RunLimits limits;
  cad::CadOptions cad;
  exporter::DrawOptions lines;
  StyleOptions style;
};

enum class Format { json, svg, pdf, dxf, png };

Format format_of(const std::string& pattern) {
  if (has_extension(pattern, ".json")) return Format::json;
  if (has_extension(pattern, ".svg")) return Format::svg;
  if (has_extension(pattern, ".pdf")) return Format::pdf;
  if (has_extension(pattern, ".dxf")) return Format::dxf;
  if (has_extension(pattern, ".png")) return Format::png;
  throw UsageError("-o " + pattern + ": unknown output format (the name must end in .svg, .pdf, .dxf, .json or .png)");
}

// A name pattern with one printf-style frame number: %d, %3d or %03d (and %% for a percent sign).
struct Pattern {
  std::string before, after;
  int width = 0;
  bool zeros = false;

  std::string name(std::size_t frame) const {
    std::string number = std::to_string(frame);
    if (number.size() < std::size_t(width)) number.insert(0, std::size_t(width) - number.size(), zeros ? '0' : ' ');
    return before + number + after;
  }
};

Pattern parse_pattern(const std::string& text) {
  Pattern p;
  bool found = false;
  std::string* part = &p.before;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      *part += text[i];
      continue;
    }
    if (i + 1 < text.size() && text[i + 1] == '%') {
      *part += '%';
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    const bool zeros = j < text.size() && text[j] == '0';
    if (zeros) ++j;
    int width = 0;
    while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])) && width < 100) width = width * 10 + (text[j++] - '0');
    if (j >= text.size() || text[j] != 'd' || found)
      throw UsageError("-o " + text + ": a pattern takes one frame number, %d or %03d (and %% for a percent sign)");
    found = true;
    p.zeros = zeros;
    p.width = width;
    part = &p.after;
    i = j;
  }
  if (!found) throw UsageError("-o " + text + ": the pattern has no frame number (such as out/frame_%03d.svg)");
  return p;
}

// The eyes file: one `x y z` per line; blank lines and lines starting with # are skipped.
std::vector<Vec3> read_eyes(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("--eyes " + path + ": cannot read the file");
  std::vector<Vec3> eyes;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const std::size_t start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#') continue;
    const std::string where = "--eyes " + path + ": line " + std::to_string(number);
    std::istringstream words(line);
    std::vector<std::string> fields;
    for (std::string w; words >> w;) fields.push_back(w);
    if (fields.size() != 3) throw UsageError(where + ": expected three numbers x y z, found " + std::to_string(fields.size()) + " fields");
    Vec3 eye{};
    for (int k = 0; k < 3; ++k) {
      const char* s = fields[k].c_str();
      char* end = nullptr;
      errno = 0;
      eye[k] = std::strtod(s, &end);
      if (end == s || *end != '\0') throw UsageError(where + ": \"" + fields[k] + "\" is not a number");
      if (!std::isfinite(eye[k]) || errno == ERANGE) throw UsageError(where + ": the eye is not finite");
    }
    eyes.push_back(eye);
  }
  if (eyes.empty()) throw UsageError("--eyes " + path + ": no eye in the file (one 'x y z' per line)");
  return eyes;
}

std::string point_text(const Vec3& p) {
  std::ostringstream s;
  s << p[0] << ',' << p[1] << ',' << p[2];
  return s.str();
}

// Every output file of the run is open at once until all are committed together.
void allow_open_files(std::size_t count) {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0) return;
  const rlim_t wanted = rlim_t(count + 64);
  if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur < wanted) {
    limit.rlim_cur = limit.rlim_max == RLIM_INFINITY ? wanted : std::min(wanted, limit.rlim_max);
    setrlimit(RLIMIT_NOFILE, &limit);
    getrlimit(RLIMIT_NOFILE, &limit);
  }
  if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur < wanted)
    throw UsageError("-o: " + std::to_string(count) + " output files are more than this process may open at once (" +
                     std::to_string(limit.rlim_cur) + "); write fewer frames or formats per run");
}

int run(const FramesCommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (options.orbit == 0 && options.eyes_file.empty()) throw UsageError("--eyes FILE or --orbit N: give the eyes");
  const std::optional<exporter::DrawingStyle> style = resolve_style(options.style);
  if (!style) return kExitUsage;
  if (options.raster > 0 && options.kernel != "exact")
    throw UsageError("--raster and --kernel " + options.kernel + " exclude each other");
  KernelKind kind = KernelKind::exact;
  parse_kernel_kind(options.kernel, kind);
  std::vector<Pattern> patterns;
  std::vector<Format> formats;
  for (const auto& text : options.patterns) {
    formats.push_back(format_of(text));
    patterns.push_back(parse_pattern(text));
    if (formats.back() == Format::png && options.raster == 0)
      throw UsageError("-o " + text + ": a PNG is drawn by the raster path: add --raster N (pixels, such as 1024)");
  }
  for (const std::vector<double>* v : {&options.target, &options.up})
    for (double c : *v)
      if (!std::isfinite(c)) throw UsageError(std::string(v == &options.target ? "--target" : "--up") + ": not finite");
  std::vector<Vec3> eyes;
  if (!options.eyes_file.empty()) eyes = read_eyes(options.eyes_file);

  RunScope run(options.limits, options.threads);
  const Scene scene = run.read(options.meshes, options.cad);
  const Vec3 target = options.target.empty() ? exporter::scene_centre(scene)
                                             : Vec3{options.target[0], options.target[1], options.target[2]};
  if (options.orbit > 0) {
    const double distance = options.distance > 0 ? options.distance : exporter::kOrbitDiagonals * exporter::scene_diagonal(scene);
    if (!(distance > 0)) throw UsageError("--orbit: the scene is a point; give --distance");
    eyes = exporter::orbit_eyes(target, options.orbit, options.elevation, distance);
  }
  const std::optional<Vec3> up =
      options.up.empty() ? std::nullopt : std::optional<Vec3>(Vec3{options.up[0], options.up[1], options.up[2]});
  const std::vector<View> views =
      exporter::frame_views(eyes, target, up, options.near > 0 ? std::optional<double>(options.near) : std::nullopt);
  for (std::size_t i = 0; i < views.size(); ++i) {
    const std::string which = "--eye " + point_text(eyes[i]) + " (frame " + std::to_string(i) + ")";
    if (views[i].direction == Vec3{0, 0, 0}) throw UsageError(which + ": the eye is at the target");
    if (const auto defect = view_defect(views[i])) throw UsageError(which + ": " + *defect);
    if (const auto defect = perspective_defect(scene.meshes, views[i])) throw UsageError(which + ": " + *defect);
  }

  // Every output is checked and opened before the work starts, and all are committed together.
  std::vector<std::string> paths;
  for (std::size_t i = 0; i < views.size(); ++i)
    for (const Pattern& p : patterns) paths.push_back(p.name(i));
  allow_open_files(paths.size());
  OutputFiles files(paths);

  exporter::FramesOptions job;
  job.draw = options.lines;
  job.draw.kernel = kind;
  job.draw.progress = run.progress();
  job.cull = options.cull == "none" ? exporter::CullMode::none : exporter::CullMode::fuzzy;
  job.cull_report = options.cull_report;
  job.raster = options.raster;
  exporter::FrameSet set = exporter::draw_frames(scene, views, job);
  const double solved = seconds_since(start);

  run.stage("writing " + std::to_string(paths.size()) + " outputs");
  const auto write_start = std::chrono::steady_clock::now();
  const bool on_sheet = std::any_of(formats.begin(), formats.end(), [](Format f) {
    return f == Format::svg || f == Format::pdf || f == Format::dxf;
  });
  std::vector<exporter::SheetLines> sheets;
  try {
    if (on_sheet) sheets = exporter::frames_sheet(set.frames, *style);
  } catch (const std::invalid_argument& e) {
    throw UsageError("--scale " + options.style.scale + ": " + e.what());
  }
  const double scale = sheets.empty() ? 0 : sheets.front().scale;
  for (std::size_t i = 0; i < set.frames.size(); ++i) {
    exporter::LineDrawing& drawing = set.frames[i];
    // What the sheet merges, for the JSON's stats: at the frames' common scale.
    exporter::MergedSegments merged =
        on_sheet ? sheets[i].merged : exporter::sheet_segments(drawing, *style);
    if (on_sheet) drawing.curves = exporter::LineDrawing::CurveCounts{sheets[i].curves.circles.size(), sheets[i].curves.arcs};
    exporter::record_sheet_counts(drawing, merged, *style);
    for (std::size_t j = 0; j < patterns.size(); ++j) {
      AtomicFile& file = files[i * patterns.size() + j];
      switch (formats[j]) {
        case Format::json: exporter::write_lines_json(drawing, [&](std::string_view text) { file.write(text); }); break;
        case Format::svg: file.write(exporter::lines_svg(drawing, *style, sheets[i])); break;
        case Format::pdf: file.write(exporter::lines_pdf(drawing, *style, sheets[i])); break;
        case Format::dxf: file.write(exporter::lines_dxf(drawing, *style, sheets[i])); break;
        case Format::png:
          file.write(exporter::png_document(set.rasters[i]->pbuffer(
              options.dash == "paper" ? hidden_line::DashPattern::paper : hidden_line::DashPattern::arc_length)));
          break;
      }
    }
  }
  files.commit();
  const double written = seconds_since(write_start);
  run.finish(scene);

  std::cout << "hlr frames: " << scene.input.faces << " faces, " << views.size() << " frames in " << set.groups.size()
            << (set.groups.size() == 1 ? " group" : " groups") << ", "
            << (options.raster > 0 ? "raster " + std::to_string(options.raster) + " px" : "kernel " + std::string(kernel_name(kind)))
            << ", cull " << options.cull << '\n';
  std::size_t visible = 0, hidden = 0;
  for (const auto& f : set.frames) visible += f.stats.visible_pieces, hidden += f.stats.hidden_pieces;
  std::cout << "  " << visible << " visible and " << hidden << " hidden pieces in all frames\n";
  for (std::size_t g = 0; g < set.groups.size(); ++g) {
    const auto& group = set.groups[g];
    if (group.culled == 0 && set.groups.size() > 8) continue;
    std::cout << "  group " << g << ": frames " << group.first << " to " << group.first + group.count - 1 << ", "
              << group.culled << " of " << group.patches << " faces culled";
    if (group.parts > 1) std::cout << " (the most of its " << group.parts << " parts)";
    std::cout << "; fuzzy pass" << (group.fuzzy_passes == 1 ? " " : "es ") << group.fuzzy_seconds << " s, frames "
              << group.solve_seconds << " s";
    if (const auto saved = group.saved_seconds())
      std::cout << ", without culling " << *group.unculled_seconds << " s: saved " << *saved << " s";
    std::cout << '\n';
  }
  if (scale > 0) std::cout << "  sheets at one scale, " << exporter::scale_label(scale / style->unit_mm) << " of the image plane\n";
  std::cout << "  outputs written in " << written << " s (" << solved + written << " s in all)\n";
  std::cout << "wrote " << paths.size() << " files: " << paths.front() << " ... " << paths.back() << '\n';
  return kExitOk;
}

}  // namespace

Subcommand add_frames_command(CLI::App& parent) {
  auto options = std::make_shared<FramesCommandOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "frames", "Draw a sequence of perspective views (an orbit, a walk-through) at one scale, as an animation.");
  cmd->add_option("meshes", options->meshes, std::string(kInputKinds) + ", drawn together as one scene")
      ->required()
      ->type_name("MESH...");
  cmd->add_option("-o,--output", options->patterns,
                  "file name pattern with the frame number as %d or %03d (from 0), by extension: .svg or .pdf (a "
                  "sheet, in mm), .dxf, .json (hlr-lines/1) or .png (with --raster); may be given several times")
      ->required()
      ->type_name("PATTERN");
  auto* eyes = cmd->add_option("--eyes", options->eyes_file, "the eyes, one 'x y z' per line (# starts a comment)")
                   ->type_name("FILE");
  auto* orbit = cmd->add_option("--orbit", options->orbit, "N eyes evenly around the target, Z up")
                    ->check(CLI::Range(1, 100000))
                    ->excludes(eyes)
                    ->type_name("N");
  cmd->add_option("--elevation", options->elevation, "the orbit's elevation above the target, degrees")
      ->check(CLI::Range(-89.0, 89.0))
      ->capture_default_str()
      ->needs(orbit)
      ->type_name("DEG");
  cmd->add_option("--distance", options->distance,
                  "the orbit's distance from the target (default: 2 bounding-box diagonals)")
      ->check(CLI::PositiveNumber)
      ->needs(orbit)
      ->type_name("D");
  cmd->add_option("--target", options->target, "the point every frame looks at (default: the bounding box's centre)")
      ->delimiter(',')
      ->expected(3)
      ->type_name("X,Y,Z");
  cmd->add_option("--up", options->up, "up vector (default +Z, or +Y when looking along Z)")
      ->delimiter(',')
      ->expected(3)
      ->type_name("X,Y,Z");
  cmd->add_option("--near", options->near,
                  "the near plane at this fraction of the deepest vertex's distance along each view (default 0.001)")
      ->check(CLI::Range(0.0, 1.0))
      ->type_name("F");
  cmd->add_option("--cull", options->cull,
                  "fuzzy: leave out of each frame's area sort the faces no eye of its group can see (Lim's fuzzy "
                  "culling; exact kernel, the same drawings); none: solve every face")
      ->check(CLI::IsMember({"fuzzy", "none"}))
      ->capture_default_str()
      ->type_name("MODE");
  cmd->add_flag("--cull-report", options->cull_report,
                "solve every frame a second time without culling and report the time the culling saved "
                "(stats.cull.unculled_seconds, group_saved_seconds; the run takes about twice as long)");
  add_line_options(*cmd, options->lines);
  add_style_options(*cmd, options->style);
  cmd->add_option("--raster", options->raster,
                  "draw each frame by the raster path instead (inexact, no culling): a Z-buffer N pixels along the "
                  "longer side; needed for .png output")
      ->check(CLI::Range(16, 8192))
      ->type_name("N");
  cmd->add_option("--dash", options->dash, "hidden-line dashes in the PNG: arc or paper (as hlr draw)")
      ->check(CLI::IsMember({"arc", "paper"}))
      ->capture_default_str()
      ->type_name("STYLE");
  add_kernel_option(*cmd, options->kernel);
  add_threads_option(*cmd, options->threads);
  add_limit_options(*cmd, options->limits);
  add_cad_options(*cmd, options->cad);
  cmd->footer(
      "Example:\n"
      "  hlr frames fixtures/scenes/l_bracket.off --orbit 36 --elevation 25 -o out/orbit/frame_%03d.svg\n"
      "  hlr frames room.off --eyes walk.txt --target 5,8,1.6 -o out/walk/f%04d.json -o out/walk/f%04d.svg\n"
      "\n"
      "Each frame is the drawing 'hlr draw --eye E --target T' makes. Formats: docs/FORMATS.md, \"hlr frames\".");
  return {cmd, [options] { return run(*options); }};
}

}  // namespace hlr::app
