#include "arrays.hpp"

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace hlrdraw {
namespace {

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) text += (d ? ", " : "") + std::to_string(a.shape(d));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

bool is_integer(const py::array& a) { return a.dtype().kind() == 'i' || a.dtype().kind() == 'u'; }

// Vertex indices as make_mesh takes them (unsigned 32 bits); a negative index or one beyond that is
// out of range in the words the file readers use.
class FaceReader {
 public:
  FaceReader(const std::string& name, std::size_t vertices) : name_(name), vertices_(vertices) {}

  void append(const std::int64_t* p, std::size_t count, std::size_t face, std::vector<std::uint32_t>& out) const {
    out.reserve(out.size() + count);
    for (std::size_t i = 0; i < count; ++i) {
      if (p[i] < 0 || std::uint64_t(p[i]) >= vertices_)
        throw hlr::ImportError(name_ + ": face " + std::to_string(face) + ": vertex index " + std::to_string(p[i]) +
                               " is out of range (" + std::to_string(vertices_) + " vertices)");
      out.push_back(std::uint32_t(p[i]));
    }
  }

 private:
  const std::string& name_;
  std::size_t vertices_;
};

}  // namespace

hlr::Mesh mesh_from_arrays(const std::string& name, const py::handle& vertices, const py::handle& faces,
                           hlr::ImportReport& report) {
  auto fail = [&](const std::string& problem) { throw hlr::ImportError(name + ": " + problem); };

  py::array v = py::array::ensure(vertices);
  if (!v) fail("vertices are not an array of numbers");
  if (v.ndim() != 2 || v.shape(1) != 3) fail("vertices have shape " + shape_text(v) + ", expected (n, 3)");
  const char kind = v.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    fail("vertices are not numbers (dtype " + std::string(py::str(v.dtype())) + ")");
  const auto coordinates = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v);
  std::vector<std::array<double, 3>> points(std::size_t(v.shape(0)));
  const double* c = coordinates.data();
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = {c[3 * i], c[3 * i + 1], c[3 * i + 2]};

  const FaceReader reader(name, points.size());
  std::vector<std::vector<std::uint32_t>> polygons;
  const bool is_array = py::isinstance<py::array>(faces);
  const py::array table = is_array ? py::reinterpret_borrow<py::array>(faces) : py::array();
  if (is_array && table.ndim() == 2) {
    // An (m, k) table: m faces of k corners each, the fast path for triangle and quad meshes.
    if (table.size() > 0 && !is_integer(table))
      fail("faces are not vertex indices (dtype " + std::string(py::str(table.dtype())) + ", expected integers)");
    const auto indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(table);
    const auto m = std::size_t(table.shape(0)), k = std::size_t(table.shape(1));
    polygons.resize(m);
    for (std::size_t f = 0; f < m; ++f) reader.append(indices.data() + f * k, k, f, polygons[f]);
  } else if (is_array && table.dtype().kind() != 'O') {
    fail("faces have shape " + shape_text(table) + ", expected (m, k) vertex indices or a sequence of faces");
  } else {
    // Faces of any number of corners: a sequence (or an object array) of index sequences.
    if (!py::isinstance<py::sequence>(faces) || py::isinstance<py::str>(faces))
      fail("faces are not a sequence of faces");
    const auto sequence = py::reinterpret_borrow<py::sequence>(faces);
    polygons.resize(std::size_t(py::len(sequence)));
    for (std::size_t f = 0; f < polygons.size(); ++f) {
      const py::object item = sequence[f];
      const py::array face = py::array::ensure(item);
      if (!face || face.ndim() != 1 || (face.size() > 0 && !is_integer(face)))
        fail("face " + std::to_string(f) + " is not a sequence of vertex indices");
      const auto indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(face);
      reader.append(indices.data(), std::size_t(indices.size()), f, polygons[f]);
    }
  }

  // Preparing faces decides planarity and simplicity exactly: long on large meshes, and Python's
  // own threads may run meanwhile.
  py::gil_scoped_release unlocked;
  return hlr::make_mesh(name, std::move(points), std::move(polygons), report);
}

py::array_t<double> mesh_vertices(const hlr::Mesh& mesh) {
  py::array_t<double> out({py::ssize_t(mesh.vertices.size()), py::ssize_t(3)});
  double* p = out.mutable_data();
  for (const auto& v : mesh.vertices)
    for (double c : v) *p++ = c;
  return out;
}

py::object mesh_faces(const hlr::Mesh& mesh) {
  const std::size_t k = mesh.faces.empty() ? 0 : mesh.faces.front().size();
  bool uniform = true;
  for (const auto& f : mesh.faces) uniform &= f.size() == k;
  if (uniform) {
    py::array_t<std::int64_t> out({py::ssize_t(mesh.faces.size()), py::ssize_t(k)});
    std::int64_t* p = out.mutable_data();
    for (const auto& f : mesh.faces)
      for (std::uint32_t v : f) *p++ = v;
    return out;
  }
  py::list out;
  for (const auto& f : mesh.faces) {
    py::array_t<std::int64_t> face(py::ssize_t(f.size()));
    std::int64_t* p = face.mutable_data();
    for (std::uint32_t v : f) *p++ = v;
    out.append(std::move(face));
  }
  return out;
}

py::dict drawing_arrays(const hlr::exporter::LineDrawing& drawing) {
  const auto n = py::ssize_t(drawing.pieces.size());
  py::array_t<double> a({n, py::ssize_t(3)}), b({n, py::ssize_t(3)});
  py::array_t<bool> visible(n);
  py::array_t<std::uint8_t> kind(n);
  py::array_t<std::int64_t> mesh(n), edge({n, py::ssize_t(2)}), line(n);
  double *pa = a.mutable_data(), *pb = b.mutable_data();
  bool* pv = visible.mutable_data();
  std::uint8_t* pk = kind.mutable_data();
  std::int64_t *pm = mesh.mutable_data(), *pe = edge.mutable_data(), *pl = line.mutable_data();
  for (const auto& piece : drawing.pieces) {
    for (int i = 0; i < 3; ++i) *pa++ = piece.a[i], *pb++ = piece.b[i];
    *pv++ = piece.visible;
    *pk++ = std::uint8_t(piece.kind);
    *pm++ = piece.mesh;
    *pe++ = piece.has_edge ? std::int64_t(piece.edge[0]) : -1;
    *pe++ = piece.has_edge ? std::int64_t(piece.edge[1]) : -1;
    *pl++ = piece.line;
  }
  py::dict out;
  out["a"] = a;
  out["b"] = b;
  out["visible"] = visible;
  out["kind"] = kind;
  out["mesh"] = mesh;
  out["edge"] = edge;
  out["line"] = line;
  return out;
}

}  // namespace hlrdraw
