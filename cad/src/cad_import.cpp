// load_cad (hlr/cad/cad.hpp): OCC reads and tessellates the model; the triangles, welded along
// the B-rep's shared edges and vertices, go through kernel's make_mesh like any mesh.
#include "file_names.hpp"
#include "occ_module.hpp"
#include "planar_mesh.hpp"

#include <hlr/cad/cad.hpp>
#include <hlr/kernel/mesh_edges.hpp>  // UnionFind: its root is the lowest node

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <BRepMesh_Context.hxx>
#include <BRepMesh_FaceDiscret.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_AsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <streambuf>
#include <map>
#include <numbers>
#include <numeric>
#include <type_traits>
#include <unordered_map>

namespace hlr::cad {
namespace {

using detail::extension_of;
using detail::lower;

std::string stem_of(const std::string& path) {
  std::string s = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  const std::size_t dot = s.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? s : s.substr(0, dot);
}

// OCC reports through Message::DefaultMessenger, whose default printer writes to stdout: hlr's
// only message is its one line, so that printer goes.
void silence_occ() {
  static const bool silenced = [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    return true;
  }();
  (void)silenced;
}

// Some of OCC writes to std::cout and std::cerr itself (BRepTools' reader on a bad file): those
// streams write nowhere while OCC works.
class MuteStreams {
 public:
  MuteStreams() : out_(std::cout.rdbuf(&null_)), err_(std::cerr.rdbuf(&null_)) {}
  ~MuteStreams() {
    std::cout.rdbuf(out_);
    std::cerr.rdbuf(err_);
  }
  MuteStreams(const MuteStreams&) = delete;
  MuteStreams& operator=(const MuteStreams&) = delete;

 private:
  struct NullBuffer : std::streambuf {
    int overflow(int c) override { return traits_type::not_eof(c); }
  } null_;
  std::streambuf* out_;
  std::streambuf* err_;
};

struct Body {
  TopoDS_Shape shape;  // located
  std::string name;    // from the file, or ""
};

std::string label_name(const TDF_Label& label) {
  Handle(TDataStd_Name) name;
  if (!label.FindAttribute(TDataStd_Name::GetID(), name)) return "";
  std::string text = TCollection_AsciiString(name->Get()).ToCString();  // UTF-8
  // OCC's STEP writer puts its own name on a product that has none: that names no part.
  if (text.rfind("Open CASCADE STEP translator", 0) == 0) return "";
  return text;
}

// The shapes of an XCAF label, depth first through assemblies, with their placements and the
// names of their products.
void collect(const TDF_Label& label, const TopLoc_Location& placement, const std::string& name, std::vector<Body>& out) {
  if (XCAFDoc_ShapeTool::IsAssembly(label)) {
    TDF_LabelSequence components;
    XCAFDoc_ShapeTool::GetComponents(label, components, false);
    for (Standard_Integer i = 1; i <= components.Length(); ++i) {
      TDF_Label referred;
      if (!XCAFDoc_ShapeTool::GetReferredShape(components(i), referred)) continue;
      // The product's name, else the instance's, unless that is only the file's entity number
      // (OCC's writer numbers NEXT_ASSEMBLY_USAGE_OCCURRENCEs '1', '2', ...).
      std::string part = label_name(referred);
      if (part.empty()) {
        part = label_name(components(i));
        if (std::all_of(part.begin(), part.end(), [](unsigned char c) { return std::isdigit(c); })) part.clear();
      }
      collect(referred, placement * XCAFDoc_ShapeTool::GetLocation(components(i)), part, out);
    }
    return;
  }
  const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(label);
  if (shape.IsNull()) return;
  out.push_back({placement.IsIdentity() ? shape : shape.Moved(placement), name.empty() ? label_name(label) : name});
}

std::vector<Body> read_step(const std::string& path) {
  Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
  Handle(TDocStd_Document) doc;
  app->NewDocument("MDTV-XCAF", doc);
  STEPCAFControl_Reader reader;
  reader.SetNameMode(true);
  reader.SetColorMode(false);
  reader.SetLayerMode(false);
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
    app->Close(doc);
    throw ImportError(path + ": not a STEP file (OpenCASCADE cannot read it)");
  }
  const bool transferred = reader.Transfer(doc);
  std::vector<Body> bodies;
  if (transferred) {
    const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    TDF_LabelSequence free;
    tool->GetFreeShapes(free);
    for (Standard_Integer i = 1; i <= free.Length(); ++i) collect(free(i), TopLoc_Location(), "", bodies);
  }
  app->Close(doc);
  return bodies;
}

// The start of a file, for the signatures OCC's readers do not check.
std::string head_of(const std::string& path, std::size_t bytes) {
  std::string head(bytes, '\0');
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return "";
  head.resize(std::fread(head.data(), 1, bytes, file));
  std::fclose(file);
  return head;
}

std::vector<Body> read_iges(const std::string& path) {
  // IGES is 80-column records, the section letter (Start, Global, ..., or C: compressed) in
  // column 73; IGESControl_Reader takes other text for an empty model.
  const std::string head = head_of(path, 200);
  const std::size_t eol = head.find_first_of("\r\n");
  if (eol == std::string::npos || eol < 73 || std::string("SGC").find(head[72]) == std::string::npos)
    throw ImportError(path + ": not an IGES file (no IGES start record)");
  IGESControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw ImportError(path + ": not an IGES file (OpenCASCADE cannot read it)");
  reader.TransferRoots();
  TopoDS_Shape shape = reader.OneShape();
  if (shape.IsNull()) return {};
  // IGES usually gives faces with edges of their own (its "faces" mode): they are sewn into
  // shells, or the faces would share no edge. Input classification, as the B-rep's own topology is
  // for STEP, at the larger of the vertices' own tolerances (what the reader made of the file's
  // precision) and 1e-5 of the model's size (1e-6 model units left OCC's own faces-mode IGES of the
  // test plate unsewn; 1e-5 sewed it).
  if (TopExp_Explorer(shape, TopAbs_FACE, TopAbs_SHELL).More()) {
    Bnd_Box box;
    BRepBndLib::Add(shape, box);
    double tolerance = box.IsVoid() ? 1e-6 : 1e-5 * std::sqrt(box.SquareExtent());
    for (TopExp_Explorer e(shape, TopAbs_VERTEX); e.More(); e.Next())
      tolerance = std::max(tolerance, BRep_Tool::Tolerance(TopoDS::Vertex(e.Current())));
    BRepBuilderAPI_Sewing sewing(tolerance);
    sewing.Add(shape);
    sewing.Perform();
    if (!sewing.SewedShape().IsNull()) shape = sewing.SewedShape();
  }
  return {{shape, ""}};
}

std::vector<Body> read_brep(const std::string& path) {
  if (head_of(path, 256).find("CASCADE Topology V") == std::string::npos)
    throw ImportError(path + ": not an OpenCASCADE .brep file");
  TopoDS_Shape shape;
  BRep_Builder builder;
  if (!BRepTools::Read(shape, path.c_str(), builder)) throw ImportError(path + ": not an OpenCASCADE .brep file");
  if (shape.IsNull()) return {};
  return {{shape, ""}};
}

// The solids of a shape, then its shells outside solids, then its faces outside shells (as one).
std::vector<TopoDS_Shape> split_bodies(const TopoDS_Shape& shape) {
  std::vector<TopoDS_Shape> out;
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) out.push_back(e.Current());
  for (TopExp_Explorer e(shape, TopAbs_SHELL, TopAbs_SOLID); e.More(); e.Next()) out.push_back(e.Current());
  TopoDS_Compound loose;
  BRep_Builder builder;
  builder.MakeCompound(loose);
  bool any = false;
  for (TopExp_Explorer e(shape, TopAbs_FACE, TopAbs_SHELL); e.More(); e.Next()) {
    builder.Add(loose, e.Current());
    any = true;
  }
  if (any) out.push_back(loose);
  return out;
}


std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}

// One tessellated body as hlr's mesh (cad.hpp says how it is welded and what it marks).
CadPart make_part(const TopoDS_Shape& body, const std::string& path, const std::string& name) {
  auto fail = [&](const std::string& problem) -> void { throw ImportError(path + ": " + problem); };
  TopTools_IndexedMapOfShape faces, edges, vertices;
  TopExp::MapShapes(body, TopAbs_FACE, faces);
  TopExp::MapShapes(body, TopAbs_EDGE, edges);
  TopExp::MapShapes(body, TopAbs_VERTEX, vertices);
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndUniqueAncestors(body, TopAbs_EDGE, TopAbs_FACE, edge_faces);

  // Every face's nodes, numbered one after the other; the polygons of its edges on them.
  std::vector<std::array<double, 3>> nodes;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::int32_t> triangle_face;
  struct Polygon {
    int edge;
    std::vector<std::uint32_t> nodes;  // along the edge's parameter
  };
  std::vector<Polygon> polygons;
  std::unordered_map<std::uint64_t, std::uint32_t> edge_node;  // (edge, k) -> first node seen
  std::unordered_map<int, std::uint32_t> vertex_node;          // vertex -> first node seen
  std::vector<std::pair<std::uint32_t, std::uint32_t>> joins;
  std::unordered_map<int, std::vector<double>> edge_params;    // of the first polygon seen

  for (int f = 1; f <= faces.Extent(); ++f) {
    const TopoDS_Face& face = TopoDS::Face(faces(f));
    TopLoc_Location loc;
    const Handle(Poly_Triangulation)& tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull() || tri->NbTriangles() == 0)
      fail("the tessellation failed (face " + std::to_string(f) + " of " + std::to_string(faces.Extent()) +
           " has no triangles)");
    const std::uint32_t base = static_cast<std::uint32_t>(nodes.size());
    const gp_Trsf& trsf = loc.Transformation();
    for (Standard_Integer i = 1; i <= tri->NbNodes(); ++i) {
      gp_Pnt p = tri->Node(i);
      if (!loc.IsIdentity()) p.Transform(trsf);
      nodes.push_back({p.X(), p.Y(), p.Z()});
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (Standard_Integer t = 1; t <= tri->NbTriangles(); ++t) {
      Standard_Integer a, b, c;
      tri->Triangle(t).Get(a, b, c);
      if (reversed) std::swap(b, c);
      triangles.push_back({base + std::uint32_t(a - 1), base + std::uint32_t(b - 1), base + std::uint32_t(c - 1)});
      triangle_face.push_back(f - 1);
    }
    // A seam appears twice in its face, forward and reversed, each with its own polygon.
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(ex.Current());
      const int e = edges.FindIndex(edge);
      const Handle(Poly_PolygonOnTriangulation)& poly = BRep_Tool::PolygonOnTriangulation(edge, tri, loc);
      if (poly.IsNull()) {
        if (BRep_Tool::Degenerated(edge)) continue;  // a pole: its nodes meet at one point anyway
        fail("the tessellation failed (edge " + std::to_string(e) + " has no polygon on face " + std::to_string(f) + ")");
      }
      const TColStd_Array1OfInteger& ids = poly->Nodes();
      Polygon polygon{e, {}};
      for (Standard_Integer k = ids.Lower(); k <= ids.Upper(); ++k) polygon.nodes.push_back(base + std::uint32_t(ids(k) - 1));
      const std::size_t n = polygon.nodes.size();
      // Both faces' polygons follow the edge's parameter (BRepMesh discretizes an edge once); the
      // parameters, where given, confirm it, or say that one runs backwards.
      bool backwards = false;
      if (poly->HasParameters() && poly->Parameters()->Length() == Standard_Integer(n)) {
        std::vector<double> params;
        for (Standard_Integer k = 1; k <= poly->Parameters()->Length(); ++k) params.push_back(poly->Parameter(k));
        auto [it, first] = edge_params.try_emplace(e, params);
        if (!first && it->second != params && it->second.size() == n &&
            std::equal(params.begin(), params.end(), it->second.rbegin()))
          backwards = true;
      }
      if (backwards) std::reverse(polygon.nodes.begin(), polygon.nodes.end());
      for (std::size_t k = 0; k < n; ++k) {
        auto [it, first] = edge_node.try_emplace((std::uint64_t(e) << 32) | k, polygon.nodes[k]);
        if (!first) joins.emplace_back(it->second, polygon.nodes[k]);
      }
      TopoDS_Vertex v0, v1;
      TopExp::Vertices(edge, v0, v1);  // of the edge as it runs along its parameter
      if (BRep_Tool::Degenerated(edge)) {
        for (std::uint32_t id : polygon.nodes) joins.emplace_back(polygon.nodes.front(), id);
      }
      const std::pair<const TopoDS_Vertex*, std::uint32_t> ends[] = {{&v0, polygon.nodes.front()}, {&v1, polygon.nodes.back()}};
      for (const auto& [v, id] : ends) {
        if (v->IsNull()) continue;
        auto [it, first] = vertex_node.try_emplace(vertices.FindIndex(*v), id);
        if (!first) joins.emplace_back(it->second, id);
      }
      polygons.push_back(std::move(polygon));
    }
  }
  if (triangles.empty()) fail("no faces (the model has no B-rep face)");

  // Topological welding, then equal coordinates (-0 == +0), as kernel welds mesh files: each
  // vertex is the first node of its class, numbered in order of first appearance.
  UnionFind classes(nodes.size());
  for (const auto& [a, b] : joins) classes.join(a, b);
  std::map<std::array<double, 3>, std::uint32_t> by_point;
  std::vector<std::uint32_t> vertex_of(nodes.size(), UINT32_MAX);
  std::vector<std::array<double, 3>> points;
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    const std::uint32_t r = classes.find(i);
    if (vertex_of[r] == UINT32_MAX) {
      std::array<double, 3> p = nodes[r];
      for (double& x : p) x = x == 0 ? 0.0 : x;
      auto [it, first] = by_point.try_emplace(p, std::uint32_t(points.size()));
      if (first) points.push_back(nodes[r]);
      vertex_of[r] = it->second;
    }
    vertex_of[i] = vertex_of[r];
  }

  // Triangle edges on B-rep edges: a feature between two distinct faces; tangent when OCC's
  // regularity says G1 or better (input classification; cad.hpp).
  BRepLib::EncodeRegularity(body, kTangentDegrees * std::numbers::pi / 180.0);
  std::vector<std::uint8_t> edge_kind(edges.Extent() + 1, 0);  // 1 feature, 3 tangent feature
  for (int e = 1; e <= edges.Extent(); ++e) {
    const TopoDS_Edge& edge = TopoDS::Edge(edges(e));
    const int i = edge_faces.FindIndex(edge);
    if (i == 0 || BRep_Tool::Degenerated(edge)) continue;
    const TopTools_ListOfShape& around = edge_faces(i);
    if (around.Extent() < 2) continue;  // a seam, or a free edge (a boundary by itself)
    edge_kind[e] = 1;
    if (around.Extent() == 2) {
      const TopoDS_Face& f1 = TopoDS::Face(around.First());
      const TopoDS_Face& f2 = TopoDS::Face(around.Last());
      if (BRep_Tool::HasContinuity(edge, f1, f2) && BRep_Tool::Continuity(edge, f1, f2) >= GeomAbs_G1) edge_kind[e] = 3;
    }
  }
  std::unordered_map<std::uint64_t, std::uint8_t> on_edge;
  for (const Polygon& polygon : polygons) {
    if (edge_kind[polygon.edge] == 0) continue;
    for (std::size_t k = 1; k < polygon.nodes.size(); ++k) {
      const std::uint32_t a = vertex_of[polygon.nodes[k - 1]], b = vertex_of[polygon.nodes[k]];
      if (a != b) on_edge[pair_key(a, b)] |= edge_kind[polygon.edge];
    }
  }

  // The circles among them: OCC's exact centre, normal and radius, and the edge's polyline
  // (the first face's; both faces' are one after welding).
  std::vector<SourceCurve> curves;
  std::vector<bool> curve_done(edges.Extent() + 1, false);
  for (const Polygon& polygon : polygons) {
    if (edge_kind[polygon.edge] == 0 || curve_done[polygon.edge]) continue;
    curve_done[polygon.edge] = true;
    const BRepAdaptor_Curve curve(TopoDS::Edge(edges(polygon.edge)));  // with the edge's location
    if (curve.GetType() != GeomAbs_Circle) continue;
    const gp_Circ circle = curve.Circle();
    const gp_Pnt& c = circle.Location();
    const gp_Dir& n = circle.Axis().Direction();
    SourceCurve out{{c.X(), c.Y(), c.Z()}, {n.X(), n.Y(), n.Z()}, circle.Radius(), {}};
    for (std::uint32_t node : polygon.nodes)
      if (out.vertices.empty() || out.vertices.back() != vertex_of[node]) out.vertices.push_back(vertex_of[node]);
    if (out.vertices.size() >= 2) curves.push_back(std::move(out));
  }

  std::vector<std::vector<std::uint32_t>> mesh_faces;
  std::vector<std::int32_t> mesh_face_group;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const std::uint32_t a = vertex_of[triangles[t][0]], b = vertex_of[triangles[t][1]], c = vertex_of[triangles[t][2]];
    if (a == b || b == c || c == a) continue;  // closed up by the welding (at a pole)
    mesh_faces.push_back({a, b, c});
    mesh_face_group.push_back(triangle_face[t]);
  }
  if (mesh_faces.empty()) fail("no faces left after the tessellation");

  CadPart part;
  part.mesh = make_mesh(path, std::move(points), std::move(mesh_faces), part.report);
  Mesh& mesh = part.mesh;
  mesh.name = name;
  mesh.face_group.resize(mesh.faces.size());
  mesh.source_edges.assign(mesh.faces.size(), 0);
  for (std::size_t k = 0; k < mesh.faces.size(); ++k) {
    mesh.face_group[k] = mesh_face_group[mesh.face_index[k]];
    const auto& face = mesh.faces[k];
    for (std::size_t i = 0; i < face.size() && i < 4; ++i) {
      const auto it = on_edge.find(pair_key(face[i], face[(i + 1) % face.size()]));
      if (it == on_edge.end()) continue;
      mesh.source_edges[k] |= std::uint8_t(1u << i);
      if (it->second & 2u) mesh.source_edges[k] |= std::uint8_t(1u << (i + 4));
    }
  }
  mesh.source_curves = std::move(curves);
  mesh.group_names.clear();
  for (int f = 1; f <= faces.Extent(); ++f) mesh.group_names.push_back("face " + std::to_string(f));
  return part;
}

std::vector<CadPart> read_model(const std::string& path, const CadOptions& options) {
  const std::string ext = lower(extension_of(path));
  if (!(options.deflection >= 0) || !std::isfinite(options.deflection))
    throw ImportError(path + ": --deflection must be a positive number of model units");
  if (!(options.angular_degrees > 0 && options.angular_degrees < 180))
    throw ImportError(path + ": --angular-deflection must be between 0 and 180 degrees");
  {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) throw ImportError(path + ": cannot open (" + std::strerror(errno) + ")");
    const int c = std::fgetc(file);
    std::fclose(file);
    if (c == EOF) throw ImportError(path + ": empty file");
  }
  silence_occ();
  const MuteStreams mute;
  std::vector<Body> bodies = ext == ".step" || ext == ".stp"   ? read_step(path)
                             : ext == ".iges" || ext == ".igs" ? read_iges(path)
                                                                : read_brep(path);
  if (bodies.empty()) throw ImportError(path + ": empty model (no shape in the file)");

  Bnd_Box box;
  std::size_t face_count = 0;
  for (const Body& b : bodies) {
    BRepBndLib::Add(b.shape, box);
    for (TopExp_Explorer e(b.shape, TopAbs_FACE); e.More(); e.Next()) ++face_count;
  }
  if (face_count == 0 || box.IsVoid()) throw ImportError(path + ": no faces (the model has no B-rep face)");
  const double diagonal = std::sqrt(box.SquareExtent());
  const double deflection = options.deflection > 0 ? options.deflection : kDefaultRelativeDeflection * diagonal;
  if (!(deflection > 0)) throw ImportError(path + ": the model has no extent (its bounding box is a point)");

  // The parts: one per solid (shell, free faces), named from the file where it names them.
  std::vector<std::pair<TopoDS_Shape, std::string>> shapes;
  std::size_t unnamed = 0;
  for (const Body& b : bodies) {
    BRepTools::Clean(b.shape);  // a .brep's own triangulation would stand in for the deflection
    // Faces are meshed in parallel on oneTBB, within the run's --threads; each face's triangles
    // depend only on its own boundary, so the result is the same for any number of threads.
    // Planar faces are triangulated by planar_mesh.hpp.
    BRepMesh_IncrementalMesh mesher;
    mesher.SetShape(b.shape);
    IMeshTools_Parameters& parameters = mesher.ChangeParameters();
    parameters.Deflection = deflection;
    parameters.Angle = options.angular_degrees * std::numbers::pi / 180.0;
    parameters.InParallel = Standard_True;
    Handle(IMeshTools_Context) context = new BRepMesh_Context;
    context->SetFaceDiscret(new BRepMesh_FaceDiscret(new PlanarFirstMeshAlgoFactory));
    mesher.Perform(context);
    if (!mesher.IsDone()) throw ImportError(path + ": the tessellation failed (BRepMesh did not finish)");
    const std::vector<TopoDS_Shape> split = split_bodies(b.shape);
    for (std::size_t i = 0; i < split.size(); ++i) {
      std::string name = b.name;
      // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "#" + string.
      if (name.empty()) {
        name = stem_of(path);
        name.push_back('#');
        name += std::to_string(++unnamed);
      } else if (split.size() > 1) {
        name.push_back('#');
        name += std::to_string(i + 1);
      }
      shapes.emplace_back(split[i], name);
    }
  }
  // One part without a name of its own: named from the file, as a mesh file is.
  if (shapes.size() == 1 && unnamed == 1) shapes.front().second.clear();
  std::vector<CadPart> parts;
  for (const auto& [shape, name] : shapes) {
    if (!TopExp_Explorer(shape, TopAbs_FACE).More()) continue;
    parts.push_back(make_part(shape, path, name));
  }
  if (parts.empty()) throw ImportError(path + ": no faces (the model has no B-rep face)");
  return parts;
}

}  // namespace
}  // namespace hlr::cad

// hlr_cad_occ's entry point (occ_module.hpp); the module's other symbols are hidden.
extern "C" __attribute__((visibility("default"))) void hlr_cad_read_model(const std::string& path,
                                                                          const hlr::cad::CadOptions& options,
                                                                          std::vector<hlr::cad::CadPart>& parts) {
  try {
    parts = hlr::cad::read_model(path, options);
  } catch (const Standard_Failure& e) {
    throw hlr::ImportError(path + ": OpenCASCADE failed: " + (e.GetMessageString() ? e.GetMessageString() : "?"));
  }
}
static_assert(std::is_same_v<decltype(hlr_cad_read_model), hlr::cad::detail::ReadModelFunction>);
