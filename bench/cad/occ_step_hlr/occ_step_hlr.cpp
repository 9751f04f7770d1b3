// occ_step_hlr: OpenCASCADE's hidden-line removal on a STEP part, for bench/cad/run.sh.
//
//   occ_step_hlr PART.step VIEW --algo exact|poly [--deflection D] [--json OUT.json]
//
// exact: HLRBRep_Algo on the B-rep itself (no tessellation). poly: HLRBRep_PolyAlgo on the
// B-rep tessellated by BRepMesh at D (default: hlr's, 0.001 of the bounding box's diagonal,
// angular 20 degrees), the tessellation timed with it. The projector, the result classes and the
// lengths are those of ../shared/peers/occ_hlr/occ_hlr.cpp (which does the same on OFF meshes):
// visible = sharp + outline lines (OCC's VCompound and OutLineVCompound), hidden likewise; the
// smooth (Rg1: tangent edges) and sewn (RgN) classes are reported apart, as hlr leaves tangent
// edges out by default. Lengths are those of OCC's projected curves, model units.
#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <HLRAlgo_Projector.hxx>
#include <HLRBRep_Algo.hxx>
#include <HLRBRep_HLRToShape.hxx>
#include <HLRBRep_PolyAlgo.hxx>
#include <HLRBRep_PolyHLRToShape.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The views of hlr (DESIGN.md "Views"): OCC's Z toward the viewer, X = direction x up.
gp_Ax2 view_axes(const std::string& name) {
  gp_Dir look, up;
  if (name == "front") look = gp_Dir(0, 1, 0), up = gp_Dir(0, 0, 1);
  else if (name == "top") look = gp_Dir(0, 0, -1), up = gp_Dir(0, 1, 0);
  else if (name == "right") look = gp_Dir(-1, 0, 0), up = gp_Dir(0, 0, 1);
  else if (name == "iso") look = gp_Dir(-1, 1, -1), up = gp_Dir(0, 0, 1);
  else throw std::runtime_error("unknown view '" + name + "' (front top right iso)");
  return gp_Ax2(gp_Pnt(0, 0, 0), look.Reversed(), look.Crossed(up));
}

double length_of(const TopoDS_Shape& compound, int& edges) {
  double sum = 0;
  if (compound.IsNull()) return 0;
  for (TopExp_Explorer ex(compound, TopAbs_EDGE); ex.More(); ex.Next()) {
    const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
    if (BRep_Tool::Degenerated(e)) continue;
    BRepAdaptor_Curve c(e);
    sum += GCPnts_AbscissaPoint::Length(c);
    ++edges;
  }
  return sum;
}

struct Lengths {
  double sharp = 0, outline = 0, smooth = 0, sewn = 0;
  int edges = 0;
};

template <class Extractor>
void extract(Extractor& x, Lengths& visible, Lengths& hidden) {
  visible.sharp = length_of(x.VCompound(), visible.edges);
  visible.outline = length_of(x.OutLineVCompound(), visible.edges);
  visible.smooth = length_of(x.Rg1LineVCompound(), visible.edges);
  visible.sewn = length_of(x.RgNLineVCompound(), visible.edges);
  hidden.sharp = length_of(x.HCompound(), hidden.edges);
  hidden.outline = length_of(x.OutLineHCompound(), hidden.edges);
  hidden.smooth = length_of(x.Rg1LineHCompound(), hidden.edges);
  hidden.sewn = length_of(x.RgNLineHCompound(), hidden.edges);
}

std::string json_lengths(const Lengths& l) {
  char text[256];
  std::snprintf(text, sizeof text,
                "{\"length\": %.9g, \"sharp\": %.9g, \"outline\": %.9g, \"smooth\": %.9g, \"sewn\": %.9g, \"edges\": %d}",
                l.sharp + l.outline, l.sharp, l.outline, l.smooth, l.sewn, l.edges);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: occ_step_hlr PART.step VIEW --algo exact|poly [--deflection D] [--json OUT.json]\n");
    return 2;
  }
  const std::string path = argv[1], view = argv[2];
  std::string algo = "exact", json_path;
  double deflection = 0;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--algo") algo = argv[i + 1];
    else if (a == "--deflection") deflection = std::atof(argv[i + 1]);
    else if (a == "--json") json_path = argv[i + 1];
  }
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  try {
    const gp_Ax2 axes = view_axes(view);
    auto t0 = Clock::now();
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw std::runtime_error(path + ": not a STEP file");
    reader.TransferRoots();
    const TopoDS_Shape shape = reader.OneShape();
    if (shape.IsNull()) throw std::runtime_error(path + ": no shape");
    const double read_s = seconds_since(t0);
    int faces = 0;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) ++faces;

    Lengths visible, hidden;
    double mesh_s = 0, hlr_s = 0, extract_s = 0;
    HLRAlgo_Projector projector(axes);
    if (algo == "exact") {
      t0 = Clock::now();
      Handle(HLRBRep_Algo) hlr = new HLRBRep_Algo();
      hlr->Add(shape);
      hlr->Projector(projector);
      hlr->Update();
      hlr->Hide();
      hlr_s = seconds_since(t0);
      t0 = Clock::now();
      HLRBRep_HLRToShape x(hlr);
      extract(x, visible, hidden);
      extract_s = seconds_since(t0);
    } else if (algo == "poly") {
      t0 = Clock::now();
      if (!(deflection > 0)) {
        Bnd_Box box;
        BRepBndLib::Add(shape, box);
        deflection = 0.001 * std::sqrt(box.SquareExtent());
      }
      BRepTools::Clean(shape);
      BRepMesh_IncrementalMesh mesher(shape, deflection, Standard_False, 20 * M_PI / 180, Standard_False);
      mesh_s = seconds_since(t0);
      t0 = Clock::now();
      Handle(HLRBRep_PolyAlgo) hlr = new HLRBRep_PolyAlgo(shape);
      hlr->Projector(projector);
      hlr->Update();
      hlr_s = seconds_since(t0);
      t0 = Clock::now();
      HLRBRep_PolyHLRToShape x;
      x.Update(hlr);
      extract(x, visible, hidden);
      extract_s = seconds_since(t0);
    } else {
      throw std::runtime_error("--algo must be exact or poly");
    }
    if (!json_path.empty()) {
      std::ofstream out(json_path);
      out << "{\"file\": \"" << path << "\", \"view\": \"" << view << "\", \"algo\": \"" << algo << "\", \"faces\": " << faces
          << ",\n \"read_s\": " << read_s << ", \"mesh_s\": " << mesh_s << ", \"hlr_s\": " << hlr_s
          << ", \"extract_s\": " << extract_s << ",\n \"visible\": " << json_lengths(visible)
          << ",\n \"hidden\": " << json_lengths(hidden) << "}\n";
    }
  } catch (const Standard_Failure& e) {
    std::fprintf(stderr, "occ_step_hlr: OpenCASCADE failed: %s\n", e.GetMessageString() ? e.GetMessageString() : "?");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "occ_step_hlr: %s\n", e.what());
    return 1;
  }
  return 0;
}
