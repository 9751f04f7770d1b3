// hlrdraw._hlrdraw: the library's jobs (export/jobs.hpp, export/polygons.hpp) for Python. The
// public API, its defaults and its documentation are python/hlrdraw/__init__.py's; this file only
// carries values across and keeps the library's promises in Python's terms:
//   - the same checks and one-line messages as the hlr program: hlr::UserError and
//     hlr::ImportError become hlrdraw.Error (a ValueError) with what() as the message, and the
//     options the program checks with CLI11 (view, kernel, crease, sheet, scale...) are checked
//     here with the same limits;
//   - the GIL is released while a job runs (other Python threads go on), and Ctrl-C stops a job
//     with KeyboardInterrupt (InterruptScope, PythonProgress);
//   - documents are made by the program's own writers, so that a file written from Python is the
//     file `hlr draw` writes for the same input and options.
#include "arrays.hpp"

#include <hlr/export/jobs.hpp>
#include <hlr/export/polygons.hpp>
#include <hlr/export/shadows.hpp>
#include <hlr/hidden_line/shadows.hpp>
#include <hlr/kernel/errors.hpp>
#include <hlr/kernel/features.hpp>
#include <hlr/kernel/scene.hpp>
#include <hlr/kernel/view.hpp>

#include <pybind11/stl.h>

#include <tbb/global_control.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <charconv>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace hlrdraw {
namespace {

using namespace hlr;

// A mesh with what importing it reported (its warnings, the vertices welded), as a Scene takes it.
struct ImportedMesh {
  Mesh mesh;
  ImportReport report;
};

// Messages are one line, as the program prints them.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

[[noreturn]] void bad_option(const std::string& option, const std::string& problem) {
  throw UserError(option, problem);
}

KernelKind kernel_kind(const std::string& name) {
  KernelKind kind = KernelKind::exact;
  if (!parse_kernel_kind(name, kind)) bad_option("kernel", "unknown kernel \"" + name + "\" (use exact, epick or double)");
  return kind;
}

Vec3 vector3(const std::vector<double>& v, const char* what) {
  if (v.size() != 3) bad_option(what, "expected 3 numbers (x, y, z), got " + std::to_string(v.size()));
  return {v[0], v[1], v[2]};
}

// Lights as `--sun DX,DY,DZ` and `--point-light X,Y,Z` take them (app/src/light_options.cpp): suns
// first, then point lights; a defect is an error naming the argument and the light. Point lights
// are checked against the scene once it is read (checked_point_lights).
std::vector<hidden_line::Light> resolve_lights(const std::vector<std::vector<double>>& suns,
                                               const std::vector<std::vector<double>>& point_lights) {
  std::vector<hidden_line::Light> out;
  auto add = [&](const std::vector<double>& v, hidden_line::Light::Kind kind, const char* what) {
    const hidden_line::Light light{kind, vector3(v, what)};
    if (auto defect = hidden_line::light_defect(light))
      bad_option(std::string(what) + " (" + exporter::number_text(v[0]) + ", " + exporter::number_text(v[1]) + ", " +
                     exporter::number_text(v[2]) + ")",
                 *defect);
    out.push_back(light);
  };
  for (const auto& v : suns) add(v, hidden_line::Light::directional, "sun");
  for (const auto& v : point_lights) add(v, hidden_line::Light::point, "point_light");
  return out;
}

void check_point_lights(const std::vector<Mesh>& meshes, const std::vector<hidden_line::Light>& lights) {
  for (const auto& light : lights) {
    if (light.kind != hidden_line::Light::point) continue;
    if (auto defect = hidden_line::point_light_defect(meshes, light)) {
      const Vec3& v = light.vector;
      bad_option("point_light (" + exporter::number_text(v[0]) + ", " + exporter::number_text(v[1]) + ", " +
                     exporter::number_text(v[2]) + ")",
                 *defect);
    }
  }
}

// The view as `hlr draw --view NAME | --dir X,Y,Z [--up X,Y,Z]` resolves it (app/src/scene_options.cpp).
View resolve_view(const std::string& name, const std::optional<std::vector<double>>& direction,
                  const std::optional<std::vector<double>>& up) {
  View view;
  if (direction) {
    view.name = "custom";
    view.direction = vector3(*direction, "direction");
    view.up = up ? vector3(*up, "up") : Vec3{0, 0, 1};
    // The default up is +Z (CAD convention); looking straight along Z, take +Y instead.
    if (!up && view.direction[0] == 0 && view.direction[1] == 0) view.up = {0, 1, 0};
  } else {
    if (up) bad_option("up", "needs a direction (up=... goes with direction=...)");
    if (!named_view(name, view))
      bad_option("view", "unknown view \"" + name + "\" (use " + named_view_list + ", or direction=(x, y, z))");
  }
  if (auto defect = view_defect(view)) bad_option(direction ? "direction/up" : "view", *defect);
  return view;
}

// --threads N: oneTBB limited to N threads while the job runs (0: every core). The limit is the
// process's: jobs run side by side in Python threads share the smallest one.
std::unique_ptr<tbb::global_control> thread_limit(int threads) {
  if (threads < 0 || threads > 1024) bad_option("threads", std::to_string(threads) + " is outside [0, 1024]");
  if (threads == 0) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
}

Scene make_scene(const std::vector<std::shared_ptr<ImportedMesh>>& meshes) {
  if (meshes.empty()) bad_option("meshes", "no mesh given");
  Scene scene;
  for (const auto& m : meshes) scene.add(m->mesh, m->report);
  return scene;
}

// Ctrl-C within a stage. Python's own SIGINT handler only trips a flag that the interpreter looks
// at between bytecodes, which it does not run while a job holds the main thread. So while a job
// runs in the main thread, and Python's default handler is in place, a C handler sets the flag
// the job's stages poll (hlr::StopToken): the job stops within a fraction of a second, and Python
// gets its KeyboardInterrupt. Python's handler is put back when the job ends.
std::atomic<bool> g_interrupted = false;

extern "C" void interrupt_job(int) { g_interrupted.store(true); }

class InterruptScope {
 public:
  InterruptScope() {  // with the GIL held
    const py::module_ threading = py::module_::import("threading");
    const py::module_ signal = py::module_::import("signal");
    if (!threading.attr("current_thread")().is(threading.attr("main_thread")())) return;
    if (!signal.attr("getsignal")(signal.attr("SIGINT")).is(signal.attr("default_int_handler"))) return;
    g_interrupted = false;
    struct sigaction action {};
    action.sa_handler = interrupt_job;
    sigemptyset(&action.sa_mask);
    active_ = ::sigaction(SIGINT, &action, &previous_) == 0;
  }
  ~InterruptScope() {
    if (!active_) return;
    ::sigaction(SIGINT, &previous_, nullptr);
    // A Ctrl-C after the job's last check: Python's KeyboardInterrupt comes at its next bytecode.
    if (g_interrupted) PyErr_SetInterrupt();
  }
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  StopToken token() const { return active_ ? StopToken(&g_interrupted) : StopToken(); }
  bool interrupted() const { return active_ && g_interrupted; }

 private:
  bool active_ = false;
  struct sigaction previous_ {};
};

// Progress for a job run from Python: stage lines to a Python callable, and Ctrl-C (or an
// exception in that callable) asked about between stages and, in the main thread, within them.
// Stages may be reported from several threads at once; each call takes the GIL.
class PythonProgress {
 public:
  explicit PythonProgress(py::object callback) : callback_(std::move(callback)) {}

  exporter::Progress progress() {
    exporter::Progress p;
    p.stop = interrupt_.token();
    if (!callback_.is_none())
      p.stage = [this](std::string_view what) {
        py::gil_scoped_acquire locked;
        if (stop_) return;
        try {
          callback_(std::string(what));
        } catch (py::error_already_set&) {
          std::lock_guard<std::mutex> guard(mutex_);
          if (!error_) error_ = std::current_exception();
          stop_ = true;
        }
      };
    p.cancelled = [this] {
      if (stop_) return true;
      py::gil_scoped_acquire locked;
      if (PyErr_CheckSignals() != 0) {  // only the main thread sees signals; elsewhere it is 0
        std::lock_guard<std::mutex> guard(mutex_);
        if (!error_) error_ = std::make_exception_ptr(py::error_already_set());
        stop_ = true;
      }
      return bool(stop_);
    };
    return p;
  }

  // Runs `job` without the GIL; a stop asked for by Python is raised as Python's own exception.
  template <class Job>
  auto run(Job&& job) -> decltype(job()) {
    try {
      py::gil_scoped_release unlocked;
      return job();
    } catch (const Cancelled&) {
      if (error_) std::rethrow_exception(error_);
      if (interrupt_.interrupted()) {
        g_interrupted = false;  // raised here, not again when the scope ends
        PyErr_SetNone(PyExc_KeyboardInterrupt);
        throw py::error_already_set();
      }
      throw;
    }
  }

  // py::object members must be released with the GIL held: the progress lives in a function
  // that holds it.
 private:
  py::object callback_;
  InterruptScope interrupt_;
  std::atomic<bool> stop_ = false;
  std::mutex mutex_;
  std::exception_ptr error_;
};

py::dict view_dict(const exporter::ViewInfo& v) {
  // The hlr-lines/1 and hlr-surfaces/1 "view" object (export/src/lines_json.cpp, view_json).
  py::dict view;
  view["projection"] = "orthographic";
  if (v.name != "custom") view["name"] = v.name;
  view["direction"] = py::cast(std::vector<double>(v.direction.begin(), v.direction.end()));
  view["up"] = py::cast(std::vector<double>(v.up.begin(), v.up.end()));
  py::list matrix;
  for (const auto& row : v.world_to_view) matrix.append(py::cast(std::vector<double>(row.begin(), row.end())));
  view["world_to_view"] = matrix;
  return view;
}

py::dict input_dict(const InputInfo& input) {
  py::dict out;
  out["files"] = input.files;
  out["faces"] = input.faces;
  out["vertices"] = input.vertices;
  return out;
}

// The sheet options of `hlr draw` (app/src/style_options.cpp), checked with the same limits.
struct StyleArguments {
  std::string sheet = "A4";
  py::object scale;  // None, a factor (sheet : part) or "1:2"
  std::string units = "mm";
  double line_group = 0.5;
  bool hidden = true;
  bool centre_lines = true;
  double merge_distance = 0.01;
  double contact_angle = 10;
};

std::optional<double> positive_number(std::string_view s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !(v > 0) || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string scale_spelling(const py::object& scale) { return py::str(scale); }

double scale_ratio(const py::object& scale) {
  std::optional<double> ratio;
  if (py::isinstance<py::str>(scale)) {
    const std::string text = scale.cast<std::string>();
    const auto colon = text.find(':');
    if (colon == std::string::npos) {
      ratio = positive_number(text);
    } else {
      const auto sheet = positive_number(std::string_view(text).substr(0, colon));
      const auto part = positive_number(std::string_view(text).substr(colon + 1));
      if (sheet && part && *sheet / *part > 0 && std::isfinite(*sheet / *part)) ratio = *sheet / *part;
    }
  } else if (py::isinstance<py::int_>(scale) || py::isinstance<py::float_>(scale)) {
    const double v = scale.cast<double>();
    if (v > 0 && std::isfinite(v)) ratio = v;
  }
  if (!ratio)
    bad_option("scale", "\"" + scale_spelling(scale) + "\" is not a scale (write \"1:2\", \"5:1\" or a factor such as 0.5)");
  return *ratio;
}

exporter::DrawingStyle drawing_style(const StyleArguments& a) {
  exporter::DrawingStyle style;
  if (const auto sheet = exporter::sheet_by_name(a.sheet)) style.sheet = *sheet;
  else bad_option("sheet", "unknown sheet \"" + a.sheet + "\" (use A0, A1, A2, A3 or A4)");
  if (a.units == "mm") style.unit_mm = 1;
  else if (a.units == "cm") style.unit_mm = 10;
  else if (a.units == "m") style.unit_mm = 1000;
  else if (a.units == "in") style.unit_mm = 25.4;
  else bad_option("units", "unknown unit \"" + a.units + "\" (use mm, cm, m or in)");
  style.units = a.units;
  if (!a.scale.is_none()) style.scale = scale_ratio(a.scale) * style.unit_mm;  // sheet mm per model unit
  if (a.line_group != 0.35 && a.line_group != 0.5 && a.line_group != 0.7)
    bad_option("line_group", exporter::number_text(a.line_group) + " is not an ISO 128 line group (use 0.35, 0.5 or 0.7)");
  style.line_group = a.line_group;
  style.hidden = a.hidden;
  style.centre_lines = a.centre_lines;
  if (!(a.merge_distance >= 0 && a.merge_distance <= 1))
    bad_option("merge_distance", exporter::number_text(a.merge_distance) + " mm is outside [0, 1]");
  style.merge_distance = a.merge_distance;
  if (!(a.contact_angle >= 0 && a.contact_angle <= 90))
    bad_option("contact_angle", exporter::number_text(a.contact_angle) + " degrees is outside [0, 90]");
  style.contact_degrees = a.contact_angle;
  return style;
}

enum class SheetFormat { svg, pdf, dxf };

// A sheet document as `hlr draw -o OUT.svg|.pdf|.dxf` writes it (app/src/draw_command.cpp).
py::bytes sheet_document(const exporter::LineDrawing& drawing, const StyleArguments& arguments, SheetFormat format) {
  const exporter::DrawingStyle style = drawing_style(arguments);
  const std::string scale = arguments.scale.is_none() ? "" : scale_spelling(arguments.scale);
  std::string document;
  {
    py::gil_scoped_release unlocked;
    const exporter::SheetLines sheet = exporter::sheet_lines(drawing, style);
    if (style.scale)
      if (const auto overflow = exporter::sheet_overflow(sheet, style)) throw UserError("scale " + scale, *overflow);
    switch (format) {
      case SheetFormat::svg: document = exporter::lines_svg(drawing, style, sheet); break;
      case SheetFormat::pdf: document = exporter::lines_pdf(drawing, style, sheet); break;
      case SheetFormat::dxf: document = exporter::lines_dxf(drawing, style, sheet); break;
    }
  }
  return py::bytes(document);
}

std::shared_ptr<ImportedMesh> read_mesh(const std::string& path) {
  auto m = std::make_shared<ImportedMesh>();
  py::gil_scoped_release unlocked;
  m->mesh = load_mesh(path, m->report);
  return m;
}

std::shared_ptr<ImportedMesh> mesh_of_arrays(const std::string& name, const py::object& vertices, const py::object& faces) {
  auto m = std::make_shared<ImportedMesh>();
  m->mesh = mesh_from_arrays(name, vertices, faces, m->report);
  return m;
}

exporter::LineDrawing draw(const std::vector<std::shared_ptr<ImportedMesh>>& meshes, const std::string& view_name,
                           const std::optional<std::vector<double>>& direction,
                           const std::optional<std::vector<double>>& up, const std::string& kernel, double crease,
                           bool intersections, const std::vector<std::vector<double>>& suns,
                           const std::vector<std::vector<double>>& point_lights, int threads,
                           const py::object& progress) {
  const View view = resolve_view(view_name, direction, up);
  exporter::DrawOptions options;
  options.kernel = kernel_kind(kernel);
  if (!(crease >= 0 && crease <= 180)) bad_option("crease", exporter::number_text(crease) + " degrees is outside [0, 180]");
  options.crease = crease;
  options.intersections = intersections;
  options.shadow_lights = resolve_lights(suns, point_lights);
  if (!options.shadow_lights.empty() && options.kernel != KernelKind::exact)
    bad_option(suns.empty() ? "point_light" : "sun", "shadows are drawn by the exact path only (kernel=\"exact\")");
  PythonProgress python(progress);
  options.progress = python.progress();
  auto limit = thread_limit(threads);
  return python.run([&] {
    const Scene scene = make_scene(meshes);
    check_point_lights(scene.meshes, options.shadow_lights);
    return exporter::draw_lines(scene, view, options);
  });
}

// `hlr shadows MESH... --sun ... --point-light ... [--union] -o OUT.json`: the hlr-shadows/1 text.
std::string shadows(const std::vector<std::shared_ptr<ImportedMesh>>& meshes, const std::vector<std::vector<double>>& suns,
                    const std::vector<std::vector<double>>& point_lights, bool union_shadows, int threads,
                    const py::object& progress) {
  const std::vector<hidden_line::Light> lights = resolve_lights(suns, point_lights);
  if (lights.empty()) bad_option("sun", "no light: give sun=(dx, dy, dz) or point_light=(x, y, z)");
  std::vector<exporter::LightLabel> labels;
  for (std::size_t k = 0; k < lights.size(); ++k)
    labels.push_back({k < suns.size() ? "sun" + std::to_string(k + 1) : "point" + std::to_string(k + 1 - suns.size()),
                      std::nullopt, {}, 0, 0});
  hidden_line::ShadowOptions options;
  options.union_shadows = union_shadows;
  options.light_views = false;
  PythonProgress python(progress);
  options.progress = python.progress();
  auto limit = thread_limit(threads);
  return python.run([&] {
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = make_scene(meshes);
    check_point_lights(scene.meshes, lights);
    const double read = hidden_line::seconds_since(start);
    const hidden_line::ShadowResult result = hidden_line::cast_shadows(scene, lights, options);
    return exporter::shadows_json({scene.input, scene.meshes, lights, labels, result, read});
  });
}

std::string surfaces(const std::vector<std::shared_ptr<ImportedMesh>>& meshes, const std::string& view_name,
                     const std::optional<std::vector<double>>& direction, const std::optional<std::vector<double>>& up,
                     const std::string& kernel, bool exact, bool keep_back_faces, bool consolidation, int threads,
                     const py::object& progress) {
  const View view = resolve_view(view_name, direction, up);
  exporter::SurfacesOptions options;
  options.kernel = kernel_kind(kernel);
  options.sources.remove_back_faces = !keep_back_faces;
  options.sources.consolidate = consolidation;
  PythonProgress python(progress);
  options.progress = python.progress();
  auto limit = thread_limit(threads);
  return python.run([&] {
    const Scene scene = make_scene(meshes);
    return exporter::solve_surfaces(scene, view, options).json(exact);
  });
}

// Both polygon sets as hlr-polygons/1 text, read by the program's own reader, so that what it
// rejects (and how it says so) is the same.
std::string clip(const std::string& subject, const std::string& clip, const std::string& subject_name,
                 const std::string& clip_name, const std::string& kernel, bool exact) {
  exporter::ClipOptions options;
  options.kernel = kernel_kind(kernel);
  options.subject_name = subject_name;
  options.clip_name = clip_name;
  options.exact_values = exact;
  py::gil_scoped_release unlocked;
  const auto subjects = exporter::parse_polygons(subject, subject_name);
  const auto clips = exporter::parse_polygons(clip, clip_name);
  const exporter::ClipOutcome outcome = exporter::clip_polygons(subjects, clips, options);
  if (!outcome.identity_holds && options.kernel == KernelKind::exact)
    throw std::logic_error(subject_name + ": internal error: area(inside) + area(outside) != area(subject) for polygon " +
                           std::to_string(outcome.identity_failure) + " with the exact kernel (a clipper bug)");
  return exporter::clip_json(outcome);
}

}  // namespace
}  // namespace hlrdraw

PYBIND11_MODULE(_hlrdraw, m) {
  using namespace hlrdraw;
  m.doc() = "hlr's jobs on numpy arrays; use the hlrdraw package, which documents them.";

  static py::exception<hlr::UserError> error(m, "Error", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const hlr::UserError& e) {
      error(one_line(e.what()).c_str());
    } catch (const hlr::ImportError& e) {
      error(one_line(e.what()).c_str());
    }
  });

  py::list kinds;
  for (auto k : {hlr::FeatureKind::silhouette, hlr::FeatureKind::crease, hlr::FeatureKind::boundary,
                 hlr::FeatureKind::intersection, hlr::FeatureKind::group, hlr::FeatureKind::smooth}) {
    if (py::ssize_t(k) != py::len(kinds)) throw std::logic_error("FeatureKind codes are not 0, 1, 2, ...");
    kinds.append(hlr::feature_kind_name(k));
  }
  m.attr("KIND_NAMES") = py::tuple(kinds);

  py::class_<ImportedMesh, std::shared_ptr<ImportedMesh>>(m, "Mesh")
      .def_property_readonly("name", [](const ImportedMesh& x) { return x.mesh.file; })
      .def_property_readonly("vertices", [](const ImportedMesh& x) { return mesh_vertices(x.mesh); })
      .def_property_readonly("faces", [](const ImportedMesh& x) { return mesh_faces(x.mesh); })
      .def_property_readonly("face_index",
                             [](const ImportedMesh& x) { return py::array(py::cast(x.mesh.face_index)); })
      .def_property_readonly("warnings", [](const ImportedMesh& x) { return x.report.warnings; })
      // vertices, faces = mesh
      .def("__iter__",
           [](const ImportedMesh& x) { return py::iter(py::make_tuple(mesh_vertices(x.mesh), mesh_faces(x.mesh))); })
      .def("__repr__", [](const ImportedMesh& x) {
        return "<hlrdraw.Mesh '" + x.mesh.file + "': " + std::to_string(x.mesh.vertices.size()) + " vertices, " +
               std::to_string(x.mesh.faces.size()) + " faces>";
      });
  m.def("read_mesh", &hlrdraw::read_mesh, py::arg("path"));
  m.def("make_mesh", &hlrdraw::mesh_of_arrays, py::arg("name"), py::arg("vertices"), py::arg("faces"));

  py::class_<hlr::exporter::LineDrawing>(m, "LineDrawing")
      .def("arrays", &drawing_arrays)
      .def_property_readonly("view", [](const hlr::exporter::LineDrawing& d) { return view_dict(d.view); })
      .def_property_readonly("input", [](const hlr::exporter::LineDrawing& d) { return input_dict(d.input); })
      .def_property_readonly("kernel", [](const hlr::exporter::LineDrawing& d) { return hlr::kernel_name(d.kernel); })
      .def_property_readonly("crease", [](const hlr::exporter::LineDrawing& d) { return d.crease_degrees; })
      .def("json",
           [](const hlr::exporter::LineDrawing& d) {
             py::gil_scoped_release unlocked;
             return hlr::exporter::lines_json(d);
           })
      .def(
          "sheet",
          [](const hlr::exporter::LineDrawing& d, const std::string& format, const std::string& sheet,
             const py::object& scale, const std::string& units, double line_group, bool hidden, bool centre_lines,
             double merge_distance, double contact_angle) {
            const StyleArguments style{sheet, scale, units, line_group, hidden, centre_lines, merge_distance, contact_angle};
            const SheetFormat f = format == "svg" ? SheetFormat::svg : format == "pdf" ? SheetFormat::pdf : SheetFormat::dxf;
            if (format != "svg" && format != "pdf" && format != "dxf")
              throw hlr::UserError("format", "unknown sheet format \"" + format + "\" (use svg, pdf or dxf)");
            return sheet_document(d, style, f);
          },
          py::arg("format"), py::arg("sheet"), py::arg("scale"), py::arg("units"), py::arg("line_group"),
          py::arg("hidden"), py::arg("centre_lines"), py::arg("merge_distance"), py::arg("contact_angle"));

  m.def("draw", &hlrdraw::draw, py::arg("meshes"), py::arg("view"), py::arg("direction"), py::arg("up"), py::arg("kernel"),
        py::arg("crease"), py::arg("intersections"), py::arg("suns"), py::arg("point_lights"), py::arg("threads"),
        py::arg("progress"));
  m.def("shadows", &hlrdraw::shadows, py::arg("meshes"), py::arg("suns"), py::arg("point_lights"),
        py::arg("union_shadows"), py::arg("threads"), py::arg("progress"));
  m.def("surfaces", &hlrdraw::surfaces, py::arg("meshes"), py::arg("view"), py::arg("direction"), py::arg("up"),
        py::arg("kernel"), py::arg("exact"), py::arg("keep_back_faces"), py::arg("consolidation"), py::arg("threads"),
        py::arg("progress"));
  m.def("clip", &hlrdraw::clip, py::arg("subject"), py::arg("clip"), py::arg("subject_name"), py::arg("clip_name"),
        py::arg("kernel"), py::arg("exact"));
}
