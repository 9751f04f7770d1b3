// The parts of hlr's DXF documents (lines_writers.cpp: one view; sheet_writers.cpp: a sheet),
// written with Debian's dxflib (libdxflib-dev).
//
// dxflib writes only to a named file and hard-codes $HANDSEED FFFF, so DxfText collects the text
// in memory instead (with round-trip numbers), and the HEADER section is written once the last
// handle is known (dxf_header). Evaluated against ezdxf 0.18's audit (recover.readfile, then
// doc.audit()): no errors; ezdxf repairs the owner handles (330) dxflib leaves out of the OBJECTS
// section and of blocks, reported as fixes, not errors, and its strict ezdxf.readfile takes the
// file as it is.
#pragma once

#include "canvas.hpp"

#include <hlr/export/lines.hpp>

#include <dl_dxf.h>
#include <dl_writer_ascii.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hlr::exporter::detail {

// dxflib's writer, collecting the text in memory. DL_WriterA only writes to a named file; every
// group goes through these virtual functions, so the file it was given ("") is never opened.
class DxfText : public DL_WriterA {
 public:
  DxfText() : DL_WriterA("", DL_Codes::AC1015) {}
  std::string& text() { return out_; }

  void dxfReal(int gc, double value) const override;
  void dxfInt(int gc, int value) const override;
  void dxfHex(int gc, int value) const override;
  void dxfString(int gc, const char* value) const override { group(gc, value); }
  void dxfString(int gc, const std::string& value) const override { group(gc, value); }

 private:
  void code(int gc) const;
  void group(int gc, std::string_view value) const;
  mutable std::string out_;
};

// The linetypes every document defines: BYBLOCK, BYLAYER, CONTINUOUS, and HIDDEN and CENTER with
// the dashes of `widths` (mm on paper; $LTSCALE or an entity's scale makes them so).
void dxf_linetypes(DL_Dxf& dxf, DxfText& out, const LineWidths& widths);

struct DxfLayer {
  std::string name;
  int colour = 7;
  double width_mm = 0.25;
  std::string linetype = "CONTINUOUS";
};
// The LAYER table: layer 0 and `layers`.
void dxf_layers(DL_Dxf& dxf, DxfText& out, const std::vector<DxfLayer>& layers);

// The tables after LAYER (text style, view, UCS, application id, dimension style, block records
// with the user blocks named), ending the TABLES section.
void dxf_other_tables(DL_Dxf& dxf, DxfText& out, const std::vector<std::string>& blocks);

// The entities of a view's curves, hidden ones first (if `hidden`), then thin ones, so that
// viewers drawing in file order put the visible lines on top: the straight runs of each path as
// LWPOLYLINE (closed when the whole path is), arcs as ARC, circles as CIRCLE. `layer` names the
// layer of a class (precedence_rank: 0 visible, 1 hidden, 2 thin) and part; every entity has the
// linetype BYLAYER and the linetype scale `ltscale`.
void dxf_curves(DL_Dxf& dxf, DxfText& out, const DrawingCurves& curves, bool hidden,
                const std::function<std::string(int rank, std::uint32_t mesh)>& layer, double ltscale);
void dxf_centre_lines(DL_Dxf& dxf, DxfText& out, const std::vector<CentreLine>& lines, const std::string& layer,
                      double ltscale);
// Filled areas (shadows) as solid HATCH entities on `layer`, one boundary loop of lines per contour.
void dxf_hatches(DL_Dxf& dxf, DxfText& out, const std::vector<DrawingArea>& areas, const std::string& layer);

// The HEADER section: version, $HANDSEED, units ($INSUNITS: 4 mm, 5 cm, 6 m, 1 in), metric or
// not, $LTSCALE, lineweights shown, and the extents.
std::string dxf_header(unsigned long handseed, int insunits, double ltscale, const Bounds& extents);
int dxf_insunits(const std::string& units);

// A canvas (canvas.hpp) that draws the sheet's furniture on layer `layer`: paths as LWPOLYLINE and
// ARC, rectangles as closed LWPOLYLINE, circles as CIRCLE, text as TEXT. The sheet's y runs down,
// the DXF's up: y becomes sheet_height - y.
std::unique_ptr<Canvas> dxf_canvas(DL_Dxf& dxf, DxfText& out, double sheet_height, const std::string& layer);

}  // namespace hlr::exporter::detail
