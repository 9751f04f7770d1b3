#include "scene_options.hpp"

#include "interrupt.hpp"
#include "subcommand.hpp"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <cmath>
#include <limits>
#include <sstream>

#include <hlr/kernel/near_plane.hpp>

namespace hlr::app {

void add_scene_options(CLI::App& cmd, SceneOptions& options, bool kernel) {
  cmd.add_option("meshes", options.meshes, std::string(kInputKinds) + ", drawn together as one scene")
      ->required()
      ->type_name("MESH...");
  auto* view = cmd.add_option("--view", options.view, std::string("named view: ") + named_view_list)
                   ->capture_default_str()
                   ->type_name("NAME");
  auto* dir = cmd.add_option("--dir", options.direction, "look direction instead of a named view")
                  ->delimiter(',')
                  ->expected(3)
                  ->type_name("X,Y,Z");
  dir->excludes(view);
  auto* eye = cmd.add_option("--eye", options.eye, "perspective view from this point, looking at --target or along --dir")
                  ->delimiter(',')
                  ->expected(3)
                  ->type_name("X,Y,Z");
  eye->excludes(view);
  cmd.add_option("--target", options.target, "the point a perspective view (--eye) looks at")
      ->delimiter(',')
      ->expected(3)
      ->needs(eye)
      ->excludes(dir)
      ->type_name("X,Y,Z");
  cmd.add_option("--up", options.up, "up vector for --dir or --target (default +Z, or +Y when looking along Z)")
      ->delimiter(',')
      ->expected(3)
      ->type_name("X,Y,Z");
  cmd.add_option("--near", options.near,
                 "perspective: the near plane at this fraction of the deepest vertex's distance along the view "
                 "(default 0.001); what lies nearer is clipped away")
      ->check(CLI::Range(0.0, 1.0))
      ->needs(eye)
      ->type_name("F");
  add_threads_option(cmd, options.threads);
  if (kernel) add_kernel_option(cmd, options.kernel);
  add_limit_options(cmd, options.limits);
  add_cad_options(cmd, options.cad);
}

void add_cad_options(CLI::App& cmd, cad::CadOptions& cad) {
  // A deflection of 0, below 0 or NaN would leave BRepMesh nothing to stop at: refused here.
  cmd.add_option("--deflection", cad.deflection,
                 "CAD models: the tessellation's largest distance from the surfaces, in model units "
                 "(default: 0.001 x the model's bounding-box diagonal)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            double v = 0;
            if (!CLI::detail::lexical_cast(text, v) || !(v > 0) || !std::isfinite(v))
              return "must be a positive number of model units, not " + text;
            return "";
          },
          "D > 0"))
      ->type_name("D");
  cmd.add_option("--angular-deflection", cad.angular_degrees,
                 "CAD models: the tessellation's largest angle between neighbouring normals, in degrees")
      ->check(CLI::Range(0.01, 90.0))
      ->capture_default_str()
      ->type_name("DEG");
}

void add_limit_options(CLI::App& cmd, RunLimits& limits, bool faces) {
  cmd.add_option("--timeout", limits.timeout,
                 "stop the run after SECONDS of wall clock (exit 124, no file written; 0: no limit)")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str()
      ->type_name("SECONDS");
  if (faces)
    cmd.add_option("--max-faces", limits.max_faces, "refuse a scene of more than N faces, before solving it")
        ->check(CLI::Range(std::size_t(1), std::numeric_limits<std::size_t>::max()))
        ->capture_default_str()
        ->type_name("N");
  cmd.add_flag("--progress", limits.progress,
               "one line per stage on stderr even when it is not a terminal (a terminal shows one live line)");
}

void add_threads_option(CLI::App& cmd, int& threads) {
  cmd.add_option("--threads", threads, "threads to use (0: every core); the output is the same for any number")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str()
      ->type_name("N");
}

namespace {

bool finite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double c) { return std::isfinite(c); });
}

}  // namespace

std::optional<View> resolve_view(const SceneOptions& options) {
  View view;
  if (!options.up.empty() && options.direction.empty() && options.target.empty()) {
    std::cerr << "hlr: --up needs --dir or --target" << std::endl;
    return std::nullopt;
  }
  if (!options.eye.empty()) {
    if (options.target.empty() && options.direction.empty()) {
      std::cerr << "hlr: --eye: give --target X,Y,Z or --dir X,Y,Z (where the perspective view looks)" << std::endl;
      return std::nullopt;
    }
    if (!finite(options.eye) || !finite(options.target)) {
      std::cerr << "hlr: --eye/--target: " << (finite(options.eye) ? "target" : "eye") << " is not finite" << std::endl;
      return std::nullopt;
    }
    view.eye = Vec3{options.eye[0], options.eye[1], options.eye[2]};
    if (options.near > 0) {
      if (!(options.near < 1)) {
        std::cerr << "hlr: --near: the fraction must lie strictly between 0 and 1" << std::endl;
        return std::nullopt;
      }
      view.near_fraction = options.near;
    }
  }
  // With --target, the direction is target - eye rounded to double, then taken as exact.
  std::vector<double> direction = options.direction;
  if (!options.target.empty()) {
    direction.resize(3);
    for (int k = 0; k < 3; ++k) direction[k] = options.target[k] - options.eye[k];
    if (direction == std::vector<double>{0, 0, 0}) {
      std::cerr << "hlr: --eye/--target: the eye is at the target" << std::endl;
      return std::nullopt;
    }
  }
  if (!direction.empty()) {
    view.name = "custom";
    view.direction = {direction[0], direction[1], direction[2]};
    view.up = options.up.empty() ? Vec3{0, 0, 1} : Vec3{options.up[0], options.up[1], options.up[2]};
    // The default up is +Z (CAD convention); looking straight along Z, take +Y instead.
    if (options.up.empty() && view.direction[0] == 0 && view.direction[1] == 0) view.up = {0, 1, 0};
  } else if (!named_view(options.view, view)) {
    std::cerr << "hlr: --view: unknown view \"" << options.view << "\" (use " << named_view_list << ", or --dir X,Y,Z)"
              << std::endl;
    return std::nullopt;
  }
  if (auto defect = view_defect(view)) {
    const char* which = !options.eye.empty() ? "--eye" : options.direction.empty() ? "--view" : "--dir/--up";
    std::cerr << "hlr: " << which << ": " << *defect << std::endl;
    return std::nullopt;
  }
  return view;
}

void check_view_of(const Scene& scene, const View& view) {
  if (const auto defect = perspective_defect(scene.meshes, view)) {
    const Vec3& e = *view.eye;
    std::ostringstream eye;
    eye << e[0] << ',' << e[1] << ',' << e[2];
    throw UsageError("--eye " + eye.str() + ": " + *defect);
  }
}

Scene read_scene(const std::vector<std::string>& paths, const RunLimits& limits, const cad::CadOptions& cad) {
  Scene scene;
  {
    const StopAtOnce reading;  // the readers do not poll the stop flag
    scene = hlr::cad::load_scene(paths, cad);
  }
  if (scene.input.faces > limits.max_faces)
    throw UserError(paths.size() == 1 ? paths.front() : paths.front() + " and " + std::to_string(paths.size() - 1) + " more",
                    std::to_string(scene.input.faces) + " faces, more than --max-faces " +
                        std::to_string(limits.max_faces) + " (give a larger --max-faces to solve it)");
  return scene;
}

void print_warnings(const Scene& scene) {
  for (const auto& w : scene.warnings) std::cerr << "hlr: warning: " << w << '\n';
}

bool has_extension(const std::string& path, const std::string& extension) {
  if (path.size() <= extension.size()) return false;
  return std::equal(extension.begin(), extension.end(), path.end() - extension.size(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
  });
}

}  // namespace hlr::app
