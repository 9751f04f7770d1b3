// The OCC fixtures of cad_fixtures.hpp.
#include "cad_fixtures.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepLib.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <utility>

namespace hlr::cad_test {
namespace {

TopoDS_Shape box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), gp_Pnt(x1, y1, z1)).Shape();
}

// A vertical cylinder (axis +Z) of radius r from z0 to z1 at (x, y).
TopoDS_Shape cylinder(double x, double y, double r, double z0, double z1) {
  return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, z0), gp_Dir(0, 0, 1)), r, z1 - z0).Shape();
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  BRepAlgoAPI_Cut op(a, b);
  if (!op.IsDone()) throw std::runtime_error("BRepAlgoAPI_Cut failed");
  return op.Shape();
}

TopoDS_Shape plate() {
  TopoDS_Shape s = box(0, 0, 0, 100, 60, 10);
  s = cut(s, cylinder(20, 30, 5, -1, 11));
  s = cut(s, cylinder(80, 30, 5, -1, 11));
  s = cut(s, cylinder(50, 30, 6, -1, 11));
  s = cut(s, cylinder(50, 30, 10, 6, 11));  // the counterbore, 4 deep
  return s;
}

TopoDS_Shape flange() {
  TopoDS_Shape s = cylinder(0, 0, 50, 0, 12);
  s = cut(s, cylinder(0, 0, 15, -1, 13));
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3;
    s = cut(s, cylinder(35 * std::cos(a), 35 * std::sin(a), 4, -1, 13));
  }
  return s;
}

// The edge parallel to Y through (x, ., z).
TopoDS_Edge edge_along_y(const TopoDS_Shape& s, double x, double z) {
  for (TopExp_Explorer e(s, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    const gp_Pnt a = BRep_Tool::Pnt(TopExp::FirstVertex(edge)), b = BRep_Tool::Pnt(TopExp::LastVertex(edge));
    if (std::abs(a.X() - x) < 1e-9 && std::abs(b.X() - x) < 1e-9 && std::abs(a.Z() - z) < 1e-9 &&
        std::abs(b.Z() - z) < 1e-9 && std::abs(a.Y() - b.Y()) > 1)
      return edge;
  }
  throw std::runtime_error("bracket: no edge along Y");
}

TopoDS_Shape bracket() {
  BRepBuilderAPI_MakePolygon profile;
  for (auto [x, z] : {std::pair{0.0, 0.0}, {60.0, 0.0}, {60.0, 8.0}, {8.0, 8.0}, {8.0, 50.0}, {0.0, 50.0}})
    profile.Add(gp_Pnt(x, 0, z));
  profile.Close();
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(profile.Wire(), Standard_True).Face();
  const TopoDS_Shape prism = BRepPrimAPI_MakePrism(face, gp_Vec(0, 40, 0)).Shape();
  BRepFilletAPI_MakeFillet fillet(prism);
  fillet.Add(6, edge_along_y(prism, 8, 8));
  fillet.Add(10, edge_along_y(prism, 0, 0));
  fillet.Build();
  if (!fillet.IsDone()) throw std::runtime_error("bracket: fillet failed");
  return fillet.Shape();
}

void write_step(const TopoDS_Shape& s, const std::string& path) {
  STEPControl_Writer writer;
  if (writer.Transfer(s, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(path.c_str()) != IFSelect_RetDone)
    throw std::runtime_error(path + ": STEP writer failed");
}

// `brep`: IGES's B-rep mode (shells and solids with shared edges), else its faces mode (each face
// with edges of its own, as most IGES files are).
void write_iges(const TopoDS_Shape& s, const std::string& path, bool brep = true) {
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", brep ? 1 : 0);
  writer.AddShape(s);
  writer.ComputeModel();
  if (!writer.Write(path.c_str())) throw std::runtime_error(path + ": IGES writer failed");
}

void write_assembly(const std::string& path) {
  Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
  Handle(TDocStd_Document) doc;
  app->NewDocument("MDTV-XCAF", doc);
  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const TDF_Label assembly = tool->NewShape();
  TDataStd_Name::Set(assembly, "assembly");
  const TDF_Label base = tool->AddShape(box(0, 0, 0, 80, 80, 10), Standard_False);
  TDataStd_Name::Set(base, "base");
  const TDF_Label peg = tool->AddShape(cylinder(0, 0, 10, 0, 30), Standard_False);
  TDataStd_Name::Set(peg, "peg");
  tool->AddComponent(assembly, base, TopLoc_Location());
  gp_Trsf on_top;
  on_top.SetTranslation(gp_Vec(40, 40, 10));
  tool->AddComponent(assembly, peg, TopLoc_Location(on_top));
  tool->UpdateAssemblies();
  STEPCAFControl_Writer writer;
  writer.SetNameMode(Standard_True);
  if (!writer.Transfer(doc, STEPControl_AsIs) || writer.Write(path.c_str()) != IFSelect_RetDone)
    throw std::runtime_error(path + ": STEP (XCAF) writer failed");
  app->Close(doc);
}

}  // namespace

void write_fixtures(const std::string& dir) {
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  const TopoDS_Shape p = plate();
  write_step(p, dir + "/plate.step");
  write_iges(p, dir + "/plate.iges");
  write_iges(p, dir + "/plate_faces.igs", false);
  if (!BRepTools::Write(p, (dir + "/plate.brep").c_str())) throw std::runtime_error("plate.brep: write failed");
  write_step(flange(), dir + "/flange.step");
  write_step(bracket(), dir + "/bracket.step");
  write_assembly(dir + "/assembly.step");
  TopoDS_Compound two;
  BRep_Builder builder;
  builder.MakeCompound(two);
  builder.Add(two, box(0, 0, 0, 10, 10, 10));
  builder.Add(two, box(20, 0, 0, 30, 10, 10));
  write_step(two, dir + "/two_solids.step");
  write_step(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0)).Edge(), dir + "/wire_only.step");
}

BrepCounts brep_counts(const std::string& fixture) {
  const TopoDS_Shape s = fixture == "plate" ? plate() : fixture == "flange" ? flange() : bracket();
  BRepLib::EncodeRegularity(s, 0.5 * std::numbers::pi / 180);
  BrepCounts c;
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(s, TopAbs_FACE, faces);
  c.faces = faces.Extent();
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndUniqueAncestors(s, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  std::set<std::pair<int, int>> pairs, tangent;
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edge_faces.FindKey(i));
    if (BRep_Tool::Degenerated(e) || edge_faces(i).Extent() != 2) continue;
    const TopoDS_Face& f1 = TopoDS::Face(edge_faces(i).First());
    const TopoDS_Face& f2 = TopoDS::Face(edge_faces(i).Last());
    const std::pair<int, int> pair = std::minmax(faces.FindIndex(f1), faces.FindIndex(f2));
    pairs.insert(pair);
    if (BRep_Tool::HasContinuity(e, f1, f2) && BRep_Tool::Continuity(e, f1, f2) >= GeomAbs_G1) tangent.insert(pair);
  }
  c.face_pairs = int(pairs.size());
  c.tangent_pairs = int(tangent.size());
  return c;
}

std::vector<BrepCircle> brep_circles(const std::string& step_path) {
  STEPControl_Reader reader;
  if (reader.ReadFile(step_path.c_str()) != IFSelect_RetDone) throw std::runtime_error(step_path + ": cannot read");
  reader.TransferRoots();
  const TopoDS_Shape s = reader.OneShape();
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndUniqueAncestors(s, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  std::vector<BrepCircle> out;
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edge_faces.FindKey(i));
    if (BRep_Tool::Degenerated(e) || edge_faces(i).Extent() != 2) continue;
    const BRepAdaptor_Curve curve(e);
    if (curve.GetType() != GeomAbs_Circle) continue;
    const gp_Circ c = curve.Circle();
    out.push_back({{c.Location().X(), c.Location().Y(), c.Location().Z()},
                   {c.Axis().Direction().X(), c.Axis().Direction().Y(), c.Axis().Direction().Z()},
                   c.Radius()});
  }
  return out;
}

void write_bench_parts(const std::string& dir, const std::vector<int>& sizes) {
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  for (int n : sizes) {
    // All holes in one cut: a compound of tools, one boolean instead of n^2.
    TopoDS_Compound holes;
    BRep_Builder builder;
    builder.MakeCompound(holes);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) builder.Add(holes, cylinder(i + 1.0, j + 1.0, 0.25, -1, 2));
    const std::string name = "grid_" + std::to_string(n) + "x" + std::to_string(n) + ".step";
    write_step(cut(box(0, 0, 0, n + 1.0, n + 1.0, 1), holes), dir + "/" + name);
  }
}

}  // namespace hlr::cad_test
