// Tests of drawing sheets (hlr/export/sheet.hpp) on a hand-made part drawn in every view: a box
// 100 x 60 x 40 with a vertical hole of radius 10 at (30, 30), its edges projected by each view's
// frame (visibility does not matter to the layout). The SVG is read back with expat, the DXF with
// dxflib: views where ISO 5456-2 puts them, aligned in model coordinates within 0.01 mm, at a
// scale of ISO 5455, with the right projection symbol, and the same layout in every format.
#include <hlr/export/sheet.hpp>
#include <hlr/kernel/view.hpp>

#include "svg_reader.hpp"

#include <dl_creationadapter.h>
#include <dl_dxf.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

namespace {

using namespace hlr;
using namespace hlr::exporter;
using hlr::test::parse_svg;
using hlr::test::SvgDocument;

constexpr double pi = 3.14159265358979323846;
using V3 = std::array<double, 3>;

V3 cross(const V3& a, const V3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
V3 unit(const V3& a) {
  const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return {a[0] / l, a[1] / l, a[2] / l};
}
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The part's edges in model space: the box, the hole's two rims (32-gons), and the hole's
// silhouettes as a viewer looking across it sees them (at the radius, on both sides).
std::vector<std::array<V3, 2>> part_edges(const V3& direction) {
  std::vector<std::array<V3, 2>> e;
  const double X = 100, Y = 60, Z = 40;
  const V3 c[8] = {{0, 0, 0}, {X, 0, 0}, {X, Y, 0}, {0, Y, 0}, {0, 0, Z}, {X, 0, Z}, {X, Y, Z}, {0, Y, Z}};
  const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const auto& k : edges) e.push_back({c[k[0]], c[k[1]]});
  for (double z : {0.0, Z})
    for (int k = 0; k < 32; ++k) {
      const double a0 = 2 * pi * k / 32, a1 = 2 * pi * ((k + 1) % 32) / 32;  // the loop closes exactly
      e.push_back({V3{30 + 10 * std::cos(a0), 30 + 10 * std::sin(a0), z}, V3{30 + 10 * std::cos(a1), 30 + 10 * std::sin(a1), z}});
    }
  const V3 side = unit(cross(direction, {0, 0, 1}));
  if (std::abs(direction[2]) < 1)
    for (double s : {-10.0, 10.0})
      e.push_back({V3{30 + s * side[0], 30 + s * side[1], 0}, V3{30 + s * side[0], 30 + s * side[1], Z}});
  return e;
}

LineDrawing drawing_in(const std::string& name) {
  View view;
  EXPECT_TRUE(named_view(name, view));
  const V3 d = unit(view.direction), x = unit(cross(view.direction, view.up)), y = unit(cross(x, view.direction));
  LineDrawing out;
  out.input.files = {"part.off"};
  out.view.name = name;
  out.view.direction = view.direction;
  out.view.up = view.up;
  out.view.world_to_view = {{{x[0], x[1], x[2], 0}, {y[0], y[1], y[2], 0}, {-d[0], -d[1], -d[2], 0}, {0, 0, 0, 1}}};
  for (const auto& [a, b] : part_edges(view.direction)) {
    const Point2 pa{dot(x, a), dot(y, a)}, pb{dot(x, b), dot(y, b)};
    if (pa != pb) out.segments.push_back({pa, pb, true, 0});
  }
  return out;
}

struct Part {
  std::map<std::string, LineDrawing> views;
  Part() {
    for (const char* v : {"front", "top", "right", "left", "bottom", "back", "iso"}) views[v] = drawing_in(v);
  }
  std::vector<SheetViewInput> inputs(const std::vector<std::string>& names) const {
    std::vector<SheetViewInput> in;
    for (const auto& n : names) in.push_back({n, &views.at(n)});
    return in;
  }
};

SheetSpec spec(Projection projection, const std::string& sheet = "A3") {
  SheetSpec s;
  s.style.sheet = *sheet_by_name(sheet);
  s.projection = projection;
  s.fields = {"Box with a hole", "HLR-7", "A. Drafter", "2025-01-01", "B"};
  return s;
}

// Every number pair of a path's d (M, L and A end points; H and V with the current point).
struct Box2 {
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  void add(double x, double y) { x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y); }
};
void add_path(Box2& box, const std::string& d) {
  std::istringstream in(d);
  char op = 0;
  double x = 0, y = 0;
  while (in >> std::ws && in.peek() != EOF) {
    if (std::isalpha(in.peek())) in >> op;
    if (op == 'Z') continue;
    if (op == 'M' || op == 'L') in >> x >> y;
    else if (op == 'H') in >> x;
    else if (op == 'V') in >> y;
    else if (op == 'A') {
      double rx, ry, rotation, large, sweep;
      in >> rx >> ry >> rotation >> large >> sweep >> x >> y;
    }
    box.add(x, y);
  }
}
// The extent on the sheet of a view group's lines (paths and circles), centre lines left out.
Box2 view_box(const SvgDocument& doc, const std::string& view) {
  Box2 box;
  for (const std::string cls : {"-visible", "-hidden"}) {
    for (const auto* p : doc.in_group("path", "view-" + view + cls)) add_path(box, p->attributes.at("d"));
    for (const auto* c : doc.in_group("circle", "view-" + view + cls)) {
      const double cx = std::stod(c->attributes.at("cx")), cy = std::stod(c->attributes.at("cy")), r = std::stod(c->attributes.at("r"));
      box.add(cx - r, cy - r), box.add(cx + r, cy + r);
    }
  }
  return box;
}

TEST(Sheet, PrincipalCellsAfterIso5456) {
  using P = std::pair<int, int>;
  EXPECT_EQ(principal_cell("front", Projection::third_angle), P(0, 0));
  EXPECT_EQ(principal_cell("top", Projection::third_angle), P(-1, 0));
  EXPECT_EQ(principal_cell("bottom", Projection::third_angle), P(1, 0));
  EXPECT_EQ(principal_cell("right", Projection::third_angle), P(0, 1));
  EXPECT_EQ(principal_cell("left", Projection::third_angle), P(0, -1));
  EXPECT_EQ(principal_cell("top", Projection::first_angle), P(1, 0));
  EXPECT_EQ(principal_cell("bottom", Projection::first_angle), P(-1, 0));
  EXPECT_EQ(principal_cell("right", Projection::first_angle), P(0, -1));
  EXPECT_EQ(principal_cell("left", Projection::first_angle), P(0, 1));
  EXPECT_EQ(principal_cell("back", Projection::first_angle), P(0, 2));
  EXPECT_FALSE(principal_cell("iso", Projection::first_angle));
}

void check_layout(Projection projection) {
  const Part part;
  const SheetSpec s = spec(projection);
  const SheetLayout layout = lay_out_sheet(part.inputs({"front", "top", "right", "iso"}), s);
  EXPECT_TRUE(is_iso_scale(layout.ratio)) << layout.ratio;
  const SvgDocument doc = parse_svg(sheet_svg(layout, s));
  ASSERT_TRUE(doc.well_formed) << doc.error;
  for (const char* v : {"front", "top", "right", "iso"}) ASSERT_TRUE(doc.find("g", std::string("view-") + v)) << v;
  const Box2 front = view_box(doc, "front"), top = view_box(doc, "top"), right = view_box(doc, "right"), iso = view_box(doc, "iso");
  const bool third = projection == Projection::third_angle;
  // Where ISO 5456-2 puts them (sheet y grows downwards), with room between.
  if (third) {
    EXPECT_LT(top.y1 + view_gap_mm, front.y0 + 1e-9);
    EXPECT_GT(right.x0, front.x1 + view_gap_mm - 1e-9);
    EXPECT_GT(iso.x0, top.x1);  // the free corner above the right view
    EXPECT_LT(iso.y1, right.y0);
  } else {
    EXPECT_GT(top.y0, front.y1 + view_gap_mm - 1e-9);
    EXPECT_LT(right.x1 + view_gap_mm, front.x0 + 1e-9);
    EXPECT_LT(iso.x1, top.x0);  // the free corner below the right view
    EXPECT_GT(iso.y0, right.y1);
  }
  // Aligned: the box is 100 wide in front and top, 40 high in front and right.
  EXPECT_NEAR(front.x0, top.x0, 0.01);
  EXPECT_NEAR(front.x1, top.x1, 0.01);
  EXPECT_NEAR(front.y0, right.y0, 0.01);
  EXPECT_NEAR(front.y1, right.y1, 0.01);
  EXPECT_NEAR(front.x1 - front.x0, 100 * layout.scale, 0.01);
  // A model point, the hole's axis: the top view's circle centre is on the front view's centre line.
  const auto circles = doc.in_group("circle", "view-top-visible");
  ASSERT_EQ(circles.size(), 1u);
  const double axis_x = std::stod(circles[0]->attributes.at("cx"));
  bool on_axis = false;
  for (const auto* p : doc.in_group("path", "view-front-center")) {
    Box2 line;
    add_path(line, p->attributes.at("d"));
    on_axis |= std::abs(line.x0 - axis_x) <= 0.01 && std::abs(line.x1 - axis_x) <= 0.01 && line.y1 - line.y0 > 40 * layout.scale;
  }
  EXPECT_TRUE(on_axis) << "no vertical centre line through the hole in the front view";
  EXPECT_EQ(doc.in_group("path", "view-top-center").size(), 2u);  // the hole's centre marks
  EXPECT_EQ(layout.circles, 1u);

  // The projection symbol: the view from the left (two circles) right of the cone in first angle,
  // left of it in third angle.
  const auto* symbol = doc.find("g", "projection-symbol");
  ASSERT_TRUE(symbol);
  EXPECT_EQ(symbol->attributes.at("class"), third ? "third-angle" : "first-angle");
  const auto rings = doc.in_group("circle", "projection-symbol");
  ASSERT_EQ(rings.size(), 2u);
  Box2 cone;
  for (const auto* p : doc.in_group("path", "projection-symbol"))
    if (p->group == "projection-symbol") add_path(cone, p->attributes.at("d"));
  const double ring_x = std::stod(rings[0]->attributes.at("cx"));
  if (third) EXPECT_LT(ring_x, cone.x0);
  else EXPECT_GT(ring_x, cone.x1);
  // The title block's fields and the scale.
  std::vector<std::string> texts;
  for (const auto* t : doc.in_group("text", "title-text")) texts.push_back(t->text);
  for (const std::string& want : std::vector<std::string>{"Box with a hole", "HLR-7", "A. Drafter", "2025-01-01", "B", scale_label(layout.ratio),
                                 third ? "third angle" : "first angle"})
    EXPECT_NE(std::find(texts.begin(), texts.end(), want), texts.end()) << want;
}

TEST(Sheet, ThirdAngleLayout) { check_layout(Projection::third_angle); }
TEST(Sheet, FirstAngleLayout) { check_layout(Projection::first_angle); }

TEST(Sheet, AllSixPrincipalViewsAndTheScaleThatFits) {
  const Part part;
  for (const auto projection : {Projection::first_angle, Projection::third_angle}) {
    const SheetSpec s = spec(projection, "A2");
    const SheetLayout layout = lay_out_sheet(part.inputs({"front", "top", "bottom", "left", "right", "back", "iso"}), s);
    const SvgDocument doc = parse_svg(sheet_svg(layout, s));
    const Box2 front = view_box(doc, "front"), back = view_box(doc, "back");
    for (const char* v : {"left", "right", "back"}) {
      EXPECT_NEAR(view_box(doc, v).y0, front.y0, 0.01) << v;
      EXPECT_NEAR(view_box(doc, v).y1, front.y1, 0.01) << v;
    }
    for (const char* v : {"top", "bottom"}) {
      EXPECT_NEAR(view_box(doc, v).x0, front.x0, 0.01) << v;
      EXPECT_NEAR(view_box(doc, v).x1, front.x1, 0.01) << v;
    }
    EXPECT_GT(back.x0, std::max(view_box(doc, "left").x1, view_box(doc, "right").x1));
    // The largest ISO scale: twice it does not fit.
    EXPECT_TRUE(is_iso_scale(layout.ratio));
    SheetSpec bigger = s;
    bigger.style.scale = is_iso_scale(2 * layout.ratio) ? 2 * layout.ratio : 2.5 * layout.ratio;  // the next one
    ASSERT_TRUE(is_iso_scale(*bigger.style.scale));
    EXPECT_THROW(lay_out_sheet(part.inputs({"front", "top", "bottom", "left", "right", "back", "iso"}), bigger), SheetError);
  }
}

TEST(Sheet, AGivenScaleThatDoesNotFitIsRefusedWithOneLine) {
  const Part part;
  SheetSpec s = spec(Projection::third_angle, "A4");
  s.style.scale = 5;
  try {
    lay_out_sheet(part.inputs({"front", "top", "right"}), s);
    FAIL() << "5:1 fits";
  } catch (const SheetError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("--scale 5:1: ", 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
  s.style.scale = 0.5;  // fits: taken as given
  EXPECT_EQ(lay_out_sheet(part.inputs({"front", "top", "right"}), s).ratio, 0.5);
  // Units: in centimetres the part is ten times larger; 1:2 of the part is 5 mm on the sheet per unit.
  s.style.unit_mm = 10;
  s.style.units = "cm";
  s.style.scale = 0.5 * 10;
  EXPECT_THROW(lay_out_sheet(part.inputs({"front", "top", "right"}), s), SheetError);
  s.style.scale = 0.05 * 10;
  const SheetLayout cm = lay_out_sheet(part.inputs({"front", "top", "right"}), s);
  EXPECT_DOUBLE_EQ(cm.ratio, 0.05);
  EXPECT_DOUBLE_EQ(cm.scale, 0.5);
  s.style.scale.reset();
  EXPECT_TRUE(is_iso_scale(lay_out_sheet(part.inputs({"front", "top", "right"}), s).ratio));
}

TEST(Sheet, ViewsListedTwiceOrNoneAreErrors) {
  const Part part;
  EXPECT_THROW(lay_out_sheet(part.inputs({"front", "front"}), spec(Projection::first_angle)), SheetError);
  EXPECT_THROW(lay_out_sheet({}, spec(Projection::first_angle)), SheetError);
}

TEST(Sheet, NoCentreLinesWhenAskedSo) {
  const Part part;
  SheetSpec s = spec(Projection::third_angle);
  s.style.centre_lines = false;
  const SheetLayout layout = lay_out_sheet(part.inputs({"front", "top", "right"}), s);
  EXPECT_EQ(layout.centre_lines, 0u);
  const SvgDocument doc = parse_svg(sheet_svg(layout, s));
  EXPECT_FALSE(doc.find("g", "view-front-center"));
}

// The DXF read back: layers, blocks and what each holds, inserts.
struct DxfSheet : DL_CreationAdapter {
  std::map<std::string, std::string> layer_linetype;
  std::map<std::string, std::map<std::string, int>> block_entities;  // block -> "TYPE:LAYER" -> count
  std::vector<DL_InsertData> inserts;
  std::string block;
  int border = 0;
  void addLayer(const DL_LayerData& d) override { layer_linetype[d.name] = getAttributes().getLinetype(); }
  void addBlock(const DL_BlockData& d) override { block = d.name; }
  void endBlock() override { block.clear(); }
  void count(const char* type) {
    if (!block.empty()) ++block_entities[block][std::string(type) + ":" + getAttributes().getLayer()];
    else if (getAttributes().getLayer() == "BORDER") ++border;
  }
  void addPolyline(const DL_PolylineData&) override { count("LWPOLYLINE"); }
  void addCircle(const DL_CircleData&) override { count("CIRCLE"); }
  void addArc(const DL_ArcData&) override { count("ARC"); }
  void addLine(const DL_LineData&) override { count("LINE"); }
  void addText(const DL_TextData&) override { count("TEXT"); }
  void addInsert(const DL_InsertData& d) override { inserts.push_back(d); }
};

TEST(Sheet, DxfHasABlockPerViewInsertedWhereTheSvgPutsIt) {
  const Part part;
  const SheetSpec s = spec(Projection::first_angle);
  const SheetLayout layout = lay_out_sheet(part.inputs({"front", "top", "right", "iso"}), s);
  const std::string text = sheet_dxf(layout, s);
  DxfSheet back;
  std::stringstream in(text);
  DL_Dxf dxf;
  ASSERT_TRUE(dxf.in(in, &back));
  EXPECT_EQ(back.layer_linetype.at("VISIBLE"), "CONTINUOUS");
  EXPECT_EQ(back.layer_linetype.at("HIDDEN"), "HIDDEN");
  EXPECT_EQ(back.layer_linetype.at("CENTER"), "CENTER");
  EXPECT_TRUE(back.layer_linetype.count("BORDER"));
  ASSERT_EQ(back.inserts.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const PlacedView& v = layout.views[i];
    EXPECT_EQ(back.inserts[i].name, "VIEW_" + std::string(i == 0 ? "FRONT" : i == 1 ? "TOP" : i == 2 ? "RIGHT" : "ISO"));
    EXPECT_DOUBLE_EQ(back.inserts[i].ipx, v.ox);
    EXPECT_DOUBLE_EQ(back.inserts[i].ipy, s.style.sheet.height_mm - v.oy);
    EXPECT_DOUBLE_EQ(back.inserts[i].sx, layout.scale);
  }
  EXPECT_EQ(back.block_entities["VIEW_TOP"]["CIRCLE:VISIBLE"], 1);
  EXPECT_EQ(back.block_entities["VIEW_TOP"]["LINE:CENTER"], 2);
  EXPECT_EQ(back.block_entities["VIEW_FRONT"]["LINE:CENTER"], 1);
  EXPECT_GT(back.block_entities["VIEW_ISO"]["LWPOLYLINE:VISIBLE"], 0);
  EXPECT_GT(back.border, 10);  // frame, title block, its text, the symbol
}

TEST(Sheet, PdfIsOnePageOfTheSheetsSize) {
  const Part part;
  const SheetSpec s = spec(Projection::third_angle, "A3");
  const std::string pdf = sheet_pdf(lay_out_sheet(part.inputs({"front", "top"}), s), s);
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_NE(pdf.find("/MediaBox [ 0 0 1190.551181 841.889764 ]"), std::string::npos);  // A3 in points
  EXPECT_EQ(pdf, sheet_pdf(lay_out_sheet(part.inputs({"front", "top"}), s), s));  // no time stamp
}

}  // namespace
