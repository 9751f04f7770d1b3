// Tests of the kernel-independent line writers (export/src/lines_writers.cpp) on small hand-made
// LineDrawings: sheets and scales, chaining, and the JSON, SVG and DXF documents. The SVG is read
// back with expat, the DXF with dxflib's reader.
//
// `export_tests --write-samples DIR` writes sample drawings instead of running the tests; CTest's
// export_samples_check runs tests/tools/check_drawing.py (ezdxf, rsvg-convert) on them.
#include <hlr/export/lines.hpp>

#include "svg_reader.hpp"

#include <dl_creationadapter.h>
#include <dl_dxf.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <random>
#include <set>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace {

using namespace hlr;
using namespace hlr::exporter;
using nlohmann::json;

DrawingSegment seg(Point2 a, Point2 b, bool visible = true, std::uint32_t mesh = 0) { return {a, b, visible, mesh}; }

// A drawing made of `segments` only (pieces follow them, at z = 0, as creases).
LineDrawing drawing_of(std::vector<DrawingSegment> segments) {
  LineDrawing d;
  d.input.files = {"fixtures/part.off"};
  d.input.faces = 12;
  d.input.vertices = 8;
  d.view.name = "front";
  d.view.direction = {0, 1, 0};
  d.view.up = {0, 0, 1};
  d.view.world_to_view = {{{1, 0, 0, 0}, {0, 0, 1, 0}, {0, -1, 0, 0}, {0, 0, 0, 1}}};
  std::uint32_t v = 0;
  for (const auto& s : segments) {
    DrawingPiece p;
    p.a = {s.a[0], s.a[1], 0};
    p.b = {s.b[0], s.b[1], 0};
    p.visible = s.visible;
    p.kind = FeatureKind::crease;
    p.has_edge = true;
    p.edge = {v, v + 1};
    v += 2;
    d.pieces.push_back(p);
  }
  d.segments = std::move(segments);
  return d;
}

// A closed polygon as segments.
std::vector<DrawingSegment> loop(const std::vector<Point2>& points, bool visible = true) {
  std::vector<DrawingSegment> out;
  for (std::size_t i = 0; i < points.size(); ++i) out.push_back(seg(points[i], points[(i + 1) % points.size()], visible));
  return out;
}

DrawingStyle a4() { return DrawingStyle{*sheet_by_name("A4"), std::nullopt, true}; }

// --------------------------------------------------------------------------------------------
// Sheets and scales.

TEST(Sheets, IsoA0ToA4LandscapeInAnyCase) {
  ASSERT_TRUE(sheet_by_name("A4"));
  EXPECT_EQ(sheet_by_name("a4")->name, "A4");
  EXPECT_EQ(sheet_by_name("a4")->width_mm, 297);
  EXPECT_EQ(sheet_by_name("a4")->height_mm, 210);
  EXPECT_EQ(sheet_by_name("A3")->width_mm, 420);
  EXPECT_EQ(sheet_by_name("A3")->height_mm, 297);
  EXPECT_EQ(sheet_by_name("a2")->width_mm, 594);
  EXPECT_EQ(sheet_by_name("A1")->width_mm, 841);
  EXPECT_EQ(sheet_by_name("A0")->width_mm, 1189);
  EXPECT_EQ(sheet_by_name("A0")->height_mm, 841);
  EXPECT_FALSE(sheet_by_name("A5"));
  EXPECT_FALSE(sheet_by_name("letter"));
  EXPECT_FALSE(sheet_by_name(""));
}

// A4's drawing area is 257 mm x 160 mm (frame 20/10/10/10, a 20 mm title strip, 5 mm clearance).
TEST(DrawingScale, PicksTheLargestIsoScaleThatFits) {
  auto box = [](double w, double h) { return drawing_of(loop({{0, 0}, {w, 0}, {w, h}, {0, h}})); };
  EXPECT_EQ(drawing_scale(box(1000, 100), a4()), 0.2);    // 1:2 gives 500 mm; 1:5 gives 200 mm
  EXPECT_EQ(drawing_scale(box(100, 50), a4()), 2.0);      // 2:1 gives 200 x 100
  EXPECT_EQ(drawing_scale(box(200, 100), a4()), 1.0);
  EXPECT_EQ(drawing_scale(box(100, 100), a4()), 1.0);     // height decides: 2:1 would be 200 > 160
  EXPECT_EQ(drawing_scale(box(10, 5), a4()), 20.0);
  EXPECT_EQ(drawing_scale(box(0.5, 0.1), a4()), 500.0);
  EXPECT_EQ(drawing_scale(box(3000, 10), a4()), 0.05);    // 1:20
  EXPECT_EQ(drawing_scale(box(1285, 10), a4()), 0.2);     // exactly 257 mm at 1:5
  EXPECT_EQ(drawing_scale(box(1285.001, 10), a4()), 0.1);
  EXPECT_EQ(drawing_scale(box(2e6, 10), a4()), 1e-4);     // 1:10000
  EXPECT_EQ(drawing_scale(box(1000, 100), DrawingStyle{*sheet_by_name("A0"), std::nullopt, true}), 1.0);
}

TEST(DrawingScale, GivenScaleEmptyDrawingAndHiddenLinesLeftOut) {
  auto d = drawing_of(loop({{0, 0}, {100, 0}, {100, 50}, {0, 50}}));
  DrawingStyle style = a4();
  style.scale = 0.5;
  EXPECT_EQ(drawing_scale(d, style), 0.5);
  EXPECT_EQ(drawing_scale(LineDrawing{}, a4()), 1.0);
  // One segment along x: its height is zero, the width decides.
  EXPECT_EQ(drawing_scale(drawing_of({seg({0, 0}, {100, 0})}), a4()), 2.0);
  // A hidden line far out counts only when hidden lines are drawn.
  d.segments.push_back(seg({0, 0}, {1000, 0}, false));
  EXPECT_EQ(drawing_scale(d, a4()), 0.2);
  style = a4();
  style.hidden = false;
  EXPECT_EQ(drawing_scale(d, style), 2.0);
}

// --------------------------------------------------------------------------------------------
// Chaining.

TEST(Chaining, OpenChainThroughDegreeTwoPoints) {
  // Out of order and in mixed directions.
  const auto chains = chain_segments({seg({1, 0}, {2, 0}), seg({0, 0}, {1, 0}), seg({2, 1}, {2, 0})});
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_FALSE(chains[0].closed);
  EXPECT_TRUE(chains[0].visible);
  EXPECT_EQ(chains[0].points, (std::vector<Point2>{{0, 0}, {1, 0}, {2, 0}, {2, 1}}));
}

TEST(Chaining, ClosedLoop) {
  const auto chains =
      chain_segments({seg({0, 0}, {1, 0}), seg({1, 1}, {1, 0}), seg({0, 1}, {1, 1}), seg({0, 1}, {0, 0})});
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_TRUE(chains[0].closed);
  EXPECT_EQ(chains[0].points, (std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
}

TEST(Chaining, TJunctionStaysSplit) {
  const auto chains = chain_segments({seg({0, 0}, {1, 0}), seg({1, 0}, {2, 0}), seg({1, 0}, {1, 1})});
  ASSERT_EQ(chains.size(), 3u);
  for (const auto& c : chains) {
    EXPECT_EQ(c.points.size(), 2u);
    EXPECT_FALSE(c.closed);
  }
  EXPECT_EQ(chains[0].points, (std::vector<Point2>{{0, 0}, {1, 0}}));  // in input order
  EXPECT_EQ(chains[2].points, (std::vector<Point2>{{1, 0}, {1, 1}}));
}

TEST(Chaining, ClassesAreNeverJoined) {
  const auto chains = chain_segments({seg({1, 0}, {2, 0}, false), seg({0, 0}, {1, 0}, true), seg({2, 0}, {3, 0}, false)});
  ASSERT_EQ(chains.size(), 2u);
  EXPECT_TRUE(chains[0].visible);  // visible chains first
  EXPECT_EQ(chains[0].points, (std::vector<Point2>{{0, 0}, {1, 0}}));
  EXPECT_FALSE(chains[1].visible);
  EXPECT_EQ(chains[1].points, (std::vector<Point2>{{1, 0}, {2, 0}, {3, 0}}));
}

TEST(Chaining, EqualDoublesOnlyNoTolerance) {
  const double almost_one = std::nextafter(1.0, 2.0);
  const auto chains = chain_segments({seg({0, 0}, {1, 0}), seg({almost_one, 0}, {2, 0})});
  EXPECT_EQ(chains.size(), 2u);
  // -0.0 and 0.0 are equal doubles: joined.
  EXPECT_EQ(chain_segments({seg({-1, 0}, {-0.0, 0}), seg({0.0, 0}, {1, 0})}).size(), 1u);
}

TEST(Chaining, LoopWithATailIsNotClosedAndPointsAreSkipped) {
  // A triangle whose corner (0,0) also has a tail: (0,0) has three segments, so no join there.
  const auto chains = chain_segments(
      {seg({0, 0}, {1, 0}), seg({1, 0}, {0, 1}), seg({0, 1}, {0, 0}), seg({0, 0}, {-1, 0}), seg({5, 5}, {5, 5})});
  ASSERT_EQ(chains.size(), 2u);
  EXPECT_FALSE(chains[0].closed);
  EXPECT_EQ(chains[0].points, (std::vector<Point2>{{0, 0}, {1, 0}, {0, 1}, {0, 0}}));
  EXPECT_EQ(chains[1].points, (std::vector<Point2>{{0, 0}, {-1, 0}}));
}

TEST(Chaining, Deterministic) {
  auto segments = loop({{0, 0}, {4, 0}, {4, 3}, {0, 3}});
  const auto more = loop({{1, 1}, {2, 1}, {2, 2}}, false);
  segments.insert(segments.end(), more.begin(), more.end());
  segments.push_back(seg({4, 0}, {6, 0}));
  const auto first = chain_segments(segments);
  for (int i = 0; i < 3; ++i) {
    const auto again = chain_segments(segments);
    ASSERT_EQ(again.size(), first.size());
    for (std::size_t c = 0; c < first.size(); ++c) {
      EXPECT_EQ(again[c].points, first[c].points);
      EXPECT_EQ(again[c].closed, first[c].closed);
    }
  }
}

// chain_segments as it was written first (lines_writers.cpp at 68e0aa3: a std::map from each
// mesh and point to the segments ending there), kept here as the reference of its output.
std::vector<DrawingPolyline> reference_chain_class(const std::vector<DrawingSegment>& segments, bool visible) {
  std::vector<const DrawingSegment*> mine;
  for (const auto& s : segments)
    if (s.visible == visible && s.a != s.b) mine.push_back(&s);
  using End = std::pair<std::uint32_t, Point2>;
  std::map<End, std::vector<std::size_t>> ending_at;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    ending_at[{mine[i]->mesh, mine[i]->a}].push_back(i);
    ending_at[{mine[i]->mesh, mine[i]->b}].push_back(i);
  }
  std::vector<bool> used(mine.size(), false);
  auto other_end = [&](std::size_t i, const Point2& p) { return mine[i]->a == p ? mine[i]->b : mine[i]->a; };
  auto walk = [&](Point2 end, std::size_t via, std::vector<Point2>& points) {
    for (;;) {
      const auto& incident = ending_at.find({mine[via]->mesh, end})->second;
      if (incident.size() != 2) return;
      const std::size_t next = incident[0] == via ? incident[1] : incident[0];
      if (used[next]) return;
      used[next] = true;
      end = other_end(next, end);
      points.push_back(end);
      via = next;
    }
  };
  std::vector<DrawingPolyline> chains;
  for (std::size_t seed = 0; seed < mine.size(); ++seed) {
    if (used[seed]) continue;
    used[seed] = true;
    DrawingPolyline chain;
    chain.visible = visible;
    chain.mesh = mine[seed]->mesh;
    chain.points = {mine[seed]->a, mine[seed]->b};
    walk(mine[seed]->b, seed, chain.points);
    const Point2 start = chain.points.front();
    if (chain.points.size() > 2 && chain.points.back() == start &&
        ending_at.find({chain.mesh, start})->second.size() == 2) {
      chain.points.pop_back();
      chain.closed = true;
    } else {
      std::vector<Point2> before;
      walk(start, seed, before);
      chain.points.insert(chain.points.begin(), before.rbegin(), before.rend());
    }
    chains.push_back(std::move(chain));
  }
  return chains;
}

TEST(Chaining, AsTheMapOfEndsDidOnRandomNetworks) {
  // Segments between points of a small grid (so that points of degree 1 to 6 and loops abound),
  // both directions, some of zero length, -0.0 beside 0.0, three meshes, both classes.
  std::mt19937 random(5);
  for (int round = 0; round < 40; ++round) {
    const int side = 3 + round % 6;
    std::uniform_int_distribution<int> coordinate(0, side - 1);
    auto point = [&]() -> Point2 {
      const int x = coordinate(random), y = coordinate(random);
      return {x == 0 && random() % 2 ? -0.0 : double(x), double(y) / 3};
    };
    std::vector<DrawingSegment> segments;
    const int n = 5 + int(random() % 200);
    for (int i = 0; i < n; ++i) {
      const Point2 a = point();
      Point2 b = point();
      if (random() % 3) b = {a[0] + (random() % 2 ? 1 : 0), a[1] + (random() % 2 ? 1.0 / 3 : 0)};  // neighbours
      segments.push_back(seg(a, b, random() % 4 != 0, std::uint32_t(random() % 3)));
    }
    auto want = reference_chain_class(segments, true);
    const auto hidden = reference_chain_class(segments, false);
    want.insert(want.end(), hidden.begin(), hidden.end());
    const auto got = chain_segments(segments);
    ASSERT_EQ(got.size(), want.size()) << "round " << round;
    for (std::size_t c = 0; c < got.size(); ++c) {
      EXPECT_EQ(got[c].visible, want[c].visible);
      EXPECT_EQ(got[c].mesh, want[c].mesh);
      EXPECT_EQ(got[c].closed, want[c].closed) << "round " << round << ", chain " << c;
      ASSERT_EQ(got[c].points.size(), want[c].points.size()) << "round " << round << ", chain " << c;
      for (std::size_t k = 0; k < got[c].points.size(); ++k)  // the same doubles, signed zeros and all
        EXPECT_EQ(std::memcmp(&got[c].points[k], &want[c].points[k], sizeof(Point2)), 0)
            << "round " << round << ", chain " << c << ", point " << k;
    }
  }
}

// --------------------------------------------------------------------------------------------
// JSON.

TEST(LinesJson, FieldByField) {
  LineDrawing d = drawing_of({seg({0.1, 0.2}, {1.0 / 3, 2})});
  d.kernel = KernelKind::exact;
  d.crease_degrees = 45;
  d.times.read = 0.5;
  d.times.sources = 0.25;
  d.times.sort = 0.125;
  d.times.lines = 0.375;
  d.times.total = 1.5;
  d.pieces[0].a = {0.1, 0.2, -0.3};
  d.pieces[0].b = {1.0 / 3, 2, 1e-300};
  d.pieces[0].edge = {3, 7};
  DrawingPiece cut;  // an intersection line: no mesh edge
  cut.a = {0, 0, 0};
  cut.b = {1, 0, 0};
  cut.visible = false;
  cut.kind = FeatureKind::intersection;
  cut.mesh = 1;
  cut.has_edge = true;  // even so, "edge" is null
  d.pieces.push_back(cut);
  d.stats.lines = 2;
  d.stats.by_kind[static_cast<int>(FeatureKind::crease)] = 1;
  d.stats.by_kind[static_cast<int>(FeatureKind::intersection)] = 1;
  d.stats.point_in_view = 3;
  d.stats.visible_pieces = 1;
  d.stats.hidden_pieces = 1;

  const json j = json::parse(lines_json(d));
  EXPECT_EQ(j["format"], "hlr-lines/1");
  EXPECT_EQ(j["input"], json({{"files", {"fixtures/part.off"}}, {"faces", 12}, {"vertices", 8}}));
  EXPECT_EQ(j["view"]["projection"], "orthographic");
  EXPECT_EQ(j["view"]["name"], "front");
  EXPECT_EQ(j["view"]["direction"], json({0, 1, 0}));
  EXPECT_EQ(j["view"]["up"], json({0, 0, 1}));
  EXPECT_EQ(j["view"]["world_to_view"], json({{1, 0, 0, 0}, {0, 0, 1, 0}, {0, -1, 0, 0}, {0, 0, 0, 1}}));
  EXPECT_EQ(j["view"].size(), 5u);

  ASSERT_EQ(j["lines"].size(), 2u);
  const json& crease = j["lines"][0];
  EXPECT_EQ(crease.size(), 6u);
  EXPECT_EQ(crease["a"].get<std::vector<double>>(), (std::vector<double>{0.1, 0.2, -0.3}));  // round trip
  EXPECT_EQ(crease["b"].get<std::vector<double>>(), (std::vector<double>{1.0 / 3, 2, 1e-300}));
  EXPECT_EQ(crease["visible"], true);
  EXPECT_EQ(crease["kind"], "crease");
  EXPECT_EQ(crease["mesh"], 0);
  EXPECT_EQ(crease["edge"], json({3, 7}));
  const json& intersection = j["lines"][1];
  EXPECT_EQ(intersection["kind"], "intersection");
  EXPECT_EQ(intersection["visible"], false);
  EXPECT_EQ(intersection["mesh"], 1);
  ASSERT_TRUE(intersection.contains("edge"));
  EXPECT_TRUE(intersection["edge"].is_null());

  const json& s = j["stats"];
  EXPECT_EQ(s["seconds"], 1.5);
  EXPECT_EQ(s["stage_seconds"], json({{"read", 0.5}, {"sources", 0.25}, {"sort", 0.125}, {"intersections", 0.0},
                                      {"lines", 0.375}, {"precedence", 0.0}, {"write", 0.0}}));
  EXPECT_EQ(s["lines"], 2);
  EXPECT_EQ(s["lines_by_kind"],
            json({{"silhouette", 0}, {"crease", 1}, {"boundary", 0}, {"intersection", 1}, {"group", 0}, {"smooth", 0}}));
  EXPECT_EQ(s["lines_seen_end_on"], 3);
  EXPECT_EQ(s["visible_pieces"], 1);
  EXPECT_EQ(s["hidden_pieces"], 1);
  EXPECT_EQ(j["kernel"], "exact");
  EXPECT_EQ(s["crease_degrees"], 45);
}

TEST(LinesJson, WriteStageCountsTheDocumentUpToItsStats) {
  LineDrawing d = drawing_of({seg({0, 0}, {1, 0})});
  d.times.read = 0.25;
  d.times.sort = 1;
  d.times.total = 1.25;
  d.times.write = 0.5;  // rounding, say
  json j = json::parse(lines_json(d));
  EXPECT_EQ(j["stats"]["stage_seconds"]["write"], 0.5);
  EXPECT_EQ(j["stats"]["seconds"], 1.75);
  int calls = 0;
  j = json::parse(lines_json(d, [&] { return ++calls, 2.0; }));
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(j["stats"]["stage_seconds"]["write"], 2.0);
  EXPECT_EQ(j["stats"]["seconds"], 3.25);
  d.raster = RasterInfo{64, 64, 32, 0.5};
  j = json::parse(lines_json(d));
  EXPECT_EQ(j["stats"]["stage_seconds"],
            json({{"read", 0.25}, {"intersections", 0.0}, {"zbuffer", 0.0}, {"lines", 0.0}, {"write", 0.5}}));
}

// Without a sheet, hlr draw merges beside the JSON's pieces (write_lines_json_merging): the same
// document and counts as merging first, on a drawing large enough to merge on a second thread.
TEST(LinesJson, MergingBesideThePiecesWritesWhatMergingFirstWrites) {
  std::mt19937_64 random(20261205);
  std::uniform_real_distribution<double> coordinate(0, 100);
  std::vector<DrawingSegment> segments;
  for (int i = 0; i < 15000; ++i) {
    const Point2 a{coordinate(random), coordinate(random)}, b{coordinate(random), coordinate(random)};
    segments.push_back(seg(a, b, i % 3 != 0));
    segments.push_back(seg({a[0], a[1] + 1e-7}, {b[0], b[1] + 1e-7}, i % 2 == 0));  // merged with it
  }
  const DrawingStyle style;
  LineDrawing first = drawing_of(segments), beside = first;
  const MergedSegments want = sheet_segments(first, style);
  record_sheet_counts(first, want, style);
  ASSERT_GT(want.merged, 10000u);
  const tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
  std::string document;
  const MergedSegments got =
      write_lines_json_merging(beside, style, [&](std::string_view text) { document += text; });
  EXPECT_EQ(got.merged, want.merged);
  EXPECT_EQ(got.segments.size(), want.segments.size());
  EXPECT_EQ(document, lines_json(first));
}

TEST(LinesJson, CustomViewHasNoNameAndEmptyDrawingHasEmptyLines) {
  LineDrawing d;
  d.view.name = "custom";
  d.view.direction = {1, 2, -3};
  d.kernel = KernelKind::epick;
  const json j = json::parse(lines_json(d));
  EXPECT_FALSE(j["view"].contains("name"));
  EXPECT_EQ(j["view"]["direction"], json({1, 2, -3}));
  EXPECT_TRUE(j["lines"].is_array());
  EXPECT_TRUE(j["lines"].empty());
  EXPECT_EQ(j["kernel"], "epick");
}

// The document as one nlohmann::json tree, dumped: how lines_json made it before it wrote the
// pieces itself (lines_writers.cpp at 68e0aa3, since then with the write stage in the stats),
// kept here as the reference for its bytes.
std::string lines_json_as_one_tree(const LineDrawing& drawing) {
  json out;
  out["format"] = "hlr-lines/1";
  out["input"] = {{"files", drawing.input.files}, {"faces", drawing.input.faces}, {"vertices", drawing.input.vertices}};
  const ViewInfo& v = drawing.view;
  json view;
  view["projection"] = "orthographic";
  if (v.name != "custom") view["name"] = v.name;
  view["direction"] = {v.direction[0], v.direction[1], v.direction[2]};
  view["up"] = {v.up[0], v.up[1], v.up[2]};
  json matrix = json::array();
  for (const auto& row : v.world_to_view) matrix.push_back({row[0], row[1], row[2], row[3]});
  view["world_to_view"] = std::move(matrix);
  out["view"] = std::move(view);
  out["kernel"] = drawing.raster ? "raster" : kernel_name(drawing.kernel);
  if (const auto& r = drawing.raster)
    out["raster"] = {{"resolution", r->resolution}, {"width", r->width}, {"height", r->height}, {"pixel", r->pixel}};
  json lines = json::array();
  for (const auto& p : drawing.pieces) {
    json line;
    line["a"] = {p.a[0], p.a[1], p.a[2]};
    line["b"] = {p.b[0], p.b[1], p.b[2]};
    line["visible"] = p.visible;
    line["kind"] = feature_kind_name(p.kind);
    line["mesh"] = p.mesh;
    if (p.has_edge && p.kind != FeatureKind::intersection)
      line["edge"] = {p.edge[0], p.edge[1]};
    else
      line["edge"] = nullptr;
    lines.push_back(std::move(line));
  }
  out["lines"] = std::move(lines);
  const auto& s = drawing.stats;
  json by_kind = json::object();
  for (auto kind : {FeatureKind::silhouette, FeatureKind::crease, FeatureKind::boundary, FeatureKind::intersection,
                    FeatureKind::group, FeatureKind::smooth})
    by_kind[feature_kind_name(kind)] = s.by_kind[static_cast<std::size_t>(kind)];
  const StageTimes& t = drawing.times;
  const json stages =
      drawing.raster ? json{{"read", t.read}, {"intersections", t.intersections}, {"zbuffer", drawing.zbuffer_seconds},
                            {"lines", t.lines}, {"write", t.write}}
                     : json{{"read", t.read}, {"sources", t.sources}, {"sort", t.sort}, {"intersections", t.intersections},
                            {"lines", t.lines}, {"precedence", t.precedence}, {"write", t.write}};
  out["stats"] = {
      {"seconds", t.total + t.write},
      {"stage_seconds", stages},
      {"lines", s.lines},
      {"lines_by_kind", std::move(by_kind)},
      {"lines_seen_end_on", s.point_in_view},
      {"visible_pieces", s.visible_pieces},
      {"hidden_pieces", s.hidden_pieces},
      {"drawn_visible_length", drawing.visible_length()},
      {"drawn_hidden_length", drawing.hidden_length()},
      {"crease_degrees", drawing.crease_degrees},
      {"welded_vertices", drawing.input.welded_vertices},
  };
  if (drawing.merged_segments) {
    out["stats"]["merged_segments"] = *drawing.merged_segments;
    out["stats"]["merge_distance_mm"] = drawing.merge_distance_mm;
    out["stats"]["contact_segments"] = drawing.contact_segments;
    out["stats"]["contact_degrees"] = drawing.contact_degrees;
  }
  if (drawing.curves) {
    out["stats"]["circles"] = drawing.curves->circles;
    out["stats"]["arcs"] = drawing.curves->arcs;
  }
  return out.dump(1) + "\n";
}

// Pieces of every kind with coordinates of every magnitude and bit pattern (signed zeros,
// subnormals, NaN and infinities, which JSON writes as null), edges up to the largest index.
LineDrawing random_drawing(std::uint32_t seed, std::size_t pieces) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(-500, 500);
  auto number = [&]() -> double {
    switch (rng() % 8) {
      case 0: return std::bit_cast<double>(rng());  // any double at all, NaN and infinity included
      case 1: return double(std::int64_t(rng() % 2001) - 1000);
      case 2: return (rng() % 2) ? 0.0 : -0.0;
      case 3: return std::ldexp(double(rng() % 1000), -int(rng() % 1100));  // down to subnormals
      default: return coordinate(rng);
    }
  };
  LineDrawing d = drawing_of({});
  d.input.files = {"fixtures/part.off", "dir/\"quoted\" na\\me\twith\ttabs.off", "dir/pièce — ∅.off"};
  d.input.faces = rng() % 100000;
  d.input.vertices = rng() % 100000;
  d.input.welded_vertices = rng() % 10;
  for (auto& row : d.view.world_to_view)
    for (double& x : row) x = number();
  for (std::size_t i = 0; i < pieces; ++i) {
    DrawingPiece p;
    p.a = {number(), number(), number()};
    p.b = {number(), number(), number()};
    p.visible = rng() % 2;
    p.kind = static_cast<FeatureKind>(rng() % kFeatureKinds);
    p.mesh = std::uint32_t(rng() % 3);
    p.has_edge = rng() % 4 != 0;
    p.edge = {std::uint32_t(rng()), i % 7 ? std::uint32_t(rng() % 100) : 0xffffffffu};
    d.pieces.push_back(p);
    if (i % 3 == 0) d.segments.push_back(seg({p.a[0], p.a[1]}, {p.b[0], p.b[1]}, p.visible, p.mesh));
  }
  d.stats.lines = pieces / 2;
  for (auto& k : d.stats.by_kind) k = rng() % 1000;
  d.stats.visible_pieces = rng() % 1000;
  d.stats.hidden_pieces = rng() % 1000;
  d.times.read = number();
  d.times.sort = 1.0 / 3;
  d.times.total = 2.5;
  d.times.write = 0.1;
  d.crease_degrees = 30;
  return d;
}

TEST(LinesJson, BytesAsOneTreeDumpsThem) {
  LineDrawing empty;
  EXPECT_EQ(lines_json(empty), lines_json_as_one_tree(empty));
  empty.view.name = "custom";
  EXPECT_EQ(lines_json(empty), lines_json_as_one_tree(empty));
  for (std::uint32_t seed : {1u, 2u, 3u, 4u}) {
    LineDrawing d = random_drawing(seed, seed == 1 ? 1 : seed == 2 ? 15000 : 3000);  // seed 2: about 4 MB
    if (seed % 2 == 0) {
      d.merged_segments = seed;
      d.merge_distance_mm = 0.01;
      d.contact_segments = 2;
      d.contact_degrees = 10;
      d.curves = LineDrawing::CurveCounts{3, 5};
    }
    if (seed == 3) {
      d.raster = RasterInfo{512, 512, 300, 0.125};
      d.zbuffer_seconds = 0.75;
    }
    if (seed == 4) d.view.name = "custom";
    const std::string got = lines_json(d), want = lines_json_as_one_tree(d);
    // Written out as it is made: blocks of about a megabyte, in order, that make the same text.
    std::vector<std::string> blocks;
    write_lines_json(d, [&](std::string_view text) { blocks.emplace_back(text); });
    std::string joined;
    for (const auto& b : blocks) {
      joined += b;
      EXPECT_LE(b.size(), std::size_t(1) << 21);
    }
    EXPECT_EQ(joined, got) << "seed " << seed;
    if (got.size() > (std::size_t(3) << 20)) {
      EXPECT_GE(blocks.size(), 3u) << "seed " << seed;
    }
    EXPECT_EQ(got.size(), want.size()) << "seed " << seed;
    const auto mismatch = std::mismatch(got.begin(), got.end(), want.begin(), want.end());
    EXPECT_TRUE(mismatch.first == got.end() && mismatch.second == want.end())
        << "seed " << seed << ": first difference at byte " << (mismatch.first - got.begin()) << ":\n"
        << got.substr(std::size_t(std::max<std::ptrdiff_t>(0, mismatch.first - got.begin() - 80)), 160) << "\nagainst\n"
        << want.substr(std::size_t(std::max<std::ptrdiff_t>(0, mismatch.second - want.begin() - 80)), 160);
  }
}

// --------------------------------------------------------------------------------------------
// SVG, read back with expat.

using hlr::test::parse_svg;
using hlr::test::SvgDocument;
using hlr::test::SvgElement;

LineDrawing box_with_hidden_hole() {
  auto segments = loop({{0, 0}, {100, 0}, {100, 50}, {0, 50}});
  segments.push_back(seg({40, 0}, {40, 50}, false));
  segments.push_back(seg({60, 0}, {60, 50}, false));
  return drawing_of(segments);
}

TEST(LinesSvg, SheetGroupsAndIsoLineTypes) {
  const std::string svg = lines_svg(box_with_hidden_hole(), a4());
  const SvgDocument doc = parse_svg(svg);
  ASSERT_TRUE(doc.well_formed) << doc.error << "\n" << svg;
  const SvgElement& root = doc.elements.at(0);
  EXPECT_EQ(root.name, "svg");
  EXPECT_EQ(root.attributes.at("xmlns"), "http://www.w3.org/2000/svg");
  EXPECT_EQ(root.attributes.at("version"), "1.1");
  EXPECT_EQ(root.attributes.at("width"), "297mm");
  EXPECT_EQ(root.attributes.at("height"), "210mm");
  EXPECT_EQ(root.attributes.at("viewBox"), "0 0 297 210");

  const SvgElement* visible = doc.find("g", "visible");
  const SvgElement* hidden = doc.find("g", "hidden");
  ASSERT_TRUE(visible && hidden);
  EXPECT_EQ(visible->attributes.at("stroke-width"), "0.5");
  EXPECT_EQ(visible->attributes.count("stroke-dasharray"), 0u);
  EXPECT_EQ(hidden->attributes.at("stroke-width"), "0.25");
  EXPECT_EQ(hidden->attributes.at("stroke-dasharray"), "3 0.75");
  for (const SvgElement* g : {visible, hidden}) {
    EXPECT_EQ(g->attributes.at("stroke-linecap"), "butt");
    EXPECT_EQ(g->attributes.at("stroke-linejoin"), "round");
    EXPECT_EQ(g->attributes.at("fill"), "none");
  }
  EXPECT_LT(doc.position("g", "hidden"), doc.position("g", "visible"));  // hidden lines below
  EXPECT_EQ(doc.in_group("path", "visible").size(), 1u);  // the outline, one closed path
  EXPECT_EQ(doc.in_group("path", "hidden").size(), 2u);
  EXPECT_TRUE(doc.find("g", "frame"));
  EXPECT_TRUE(doc.find("g", "title-block"));
}

TEST(LinesSvg, CentredAtScaleWithViewYUp) {
  // 100 x 50 at 2:1 on A4, centred in the drawing area x 25..282, y 15..175 (centre 153.5, 95).
  const SvgDocument doc = parse_svg(lines_svg(box_with_hidden_hole(), a4()));
  const auto outline = doc.in_group("path", "visible");
  ASSERT_EQ(outline.size(), 1u);
  EXPECT_EQ(outline[0]->attributes.at("d"), "M53.5 145L253.5 145L253.5 45L53.5 45Z");
  EXPECT_EQ(doc.in_group("path", "hidden")[0]->attributes.at("d"), "M133.5 145L133.5 45");
}

TEST(LinesSvg, TitleBlockNamesFilesViewScaleAndProgram) {
  LineDrawing d = box_with_hidden_hole();
  d.input.files = {"/some/dir/a&b.off", "c.stl"};
  const SvgDocument doc = parse_svg(lines_svg(d, a4()));
  ASSERT_TRUE(doc.well_formed) << doc.error;
  std::vector<std::string> texts;
  for (const auto* t : doc.in_group("text", "title-text")) texts.push_back(t->text);
  EXPECT_NE(std::find(texts.begin(), texts.end(), "a&b.off, c.stl"), texts.end());
  EXPECT_NE(std::find(texts.begin(), texts.end(), "front"), texts.end());
  EXPECT_NE(std::find(texts.begin(), texts.end(), "2:1"), texts.end());
  EXPECT_NE(std::find(texts.begin(), texts.end(), "hlr"), texts.end());

  // A reduction scale reads 1:n.
  const SvgDocument big = parse_svg(lines_svg(drawing_of(loop({{0, 0}, {1000, 0}, {1000, 100}, {0, 100}})), a4()));
  texts.clear();
  for (const auto* t : big.in_group("text", "title-text")) texts.push_back(t->text);
  EXPECT_NE(std::find(texts.begin(), texts.end(), "1:5"), texts.end());
}

TEST(LinesSvg, HiddenNoneLeavesHiddenLinesOut) {
  DrawingStyle style = a4();
  style.hidden = false;
  const SvgDocument doc = parse_svg(lines_svg(box_with_hidden_hole(), style));
  ASSERT_TRUE(doc.well_formed);
  EXPECT_FALSE(doc.find("g", "hidden"));
  EXPECT_EQ(doc.in_group("path", "visible").size(), 1u);
}

TEST(LinesSvg, EmptyDrawingIsAnEmptySheet) {
  const SvgDocument doc = parse_svg(lines_svg(LineDrawing{}, a4()));
  ASSERT_TRUE(doc.well_formed) << doc.error;
  EXPECT_TRUE(doc.in_group("path", "visible").empty());
}

// --------------------------------------------------------------------------------------------
// DXF, read back with dxflib.

struct DxfReadBack : DL_CreationAdapter {
  struct Polyline {
    std::string layer, linetype;
    int flags = 0;
    std::vector<Point2> points;
  };
  std::map<std::string, DL_LayerData> layers;
  std::map<std::string, std::string> layer_linetype;
  std::map<std::string, int> layer_color, layer_lineweight;
  std::map<std::string, std::vector<double>> linetype_dashes;
  std::vector<double> pending_dashes;
  std::vector<Polyline> polylines;
  std::map<std::string, double> doubles;
  std::map<std::string, int> ints;

  void addLayer(const DL_LayerData& data) override {
    layers.emplace(data.name, data);
    layer_linetype[data.name] = getAttributes().getLinetype();
    layer_color[data.name] = getAttributes().getColor();
    layer_lineweight[data.name] = getAttributes().getWidth();
  }
  // dxflib reports a linetype's dashes (group 49) as it reads them, the linetype at its end.
  void addLinetypeDash(double length) override { pending_dashes.push_back(length); }
  void addLinetype(const DL_LinetypeData& data) override {
    linetype_dashes[data.name] = pending_dashes;
    pending_dashes.clear();
  }
  void addPolyline(const DL_PolylineData& data) override {
    polylines.push_back({getAttributes().getLayer(), getAttributes().getLinetype(), data.flags, {}});
  }
  void addVertex(const DL_VertexData& data) override { polylines.back().points.push_back({data.x, data.y}); }
  void setVariableDouble(const std::string& key, double value, int) override { doubles[key] = value; }
  void setVariableInt(const std::string& key, int value, int) override { ints[key] = value; }
};

DxfReadBack read_dxf(const std::string& text) {
  DxfReadBack back;
  std::stringstream in(text);
  DL_Dxf dxf;
  EXPECT_TRUE(dxf.in(in, &back));
  return back;
}

TEST(LinesDxf, LayersLinetypeAndPolylines) {
  LineDrawing d = box_with_hidden_hole();
  d.segments.push_back(seg({0.1, 1.0 / 3}, {-7.25, 1e-9}, false));  // numbers that must round-trip
  const std::string text = lines_dxf(d, a4());
  EXPECT_NE(text.find("AC1015"), std::string::npos);
  const DxfReadBack back = read_dxf(text);

  ASSERT_TRUE(back.layers.count("VISIBLE") && back.layers.count("HIDDEN") && back.layers.count("0"));
  EXPECT_EQ(back.layer_linetype.at("VISIBLE"), "CONTINUOUS");
  EXPECT_EQ(back.layer_lineweight.at("VISIBLE"), 50);
  EXPECT_EQ(back.layer_linetype.at("HIDDEN"), "HIDDEN");
  EXPECT_EQ(back.layer_lineweight.at("HIDDEN"), 25);
  ASSERT_TRUE(back.linetype_dashes.count("HIDDEN"));
  EXPECT_EQ(back.linetype_dashes.at("HIDDEN"), (std::vector<double>{3.0, -0.75}));

  EXPECT_EQ(back.ints.at("$INSUNITS"), 4);
  EXPECT_EQ(back.ints.at("$MEASUREMENT"), 1);
  EXPECT_EQ(back.doubles.at("$LTSCALE"), 0.5);  // drawn at 2:1

  // The outline as one closed LWPOLYLINE on VISIBLE, in model units; hidden lines on HIDDEN,
  // written first.
  std::vector<const DxfReadBack::Polyline*> visible, hidden;
  for (const auto& p : back.polylines) (p.layer == "VISIBLE" ? visible : hidden).push_back(&p);
  ASSERT_EQ(visible.size(), 1u);
  EXPECT_EQ(visible[0]->flags & 1, 1);
  EXPECT_EQ(visible[0]->points, (std::vector<Point2>{{0, 0}, {100, 0}, {100, 50}, {0, 50}}));
  EXPECT_EQ(visible[0]->linetype, "BYLAYER");
  ASSERT_EQ(hidden.size(), 3u);
  for (const auto* p : hidden) {
    EXPECT_EQ(p->layer, "HIDDEN");
    EXPECT_EQ(p->flags & 1, 0);
  }
  EXPECT_EQ(hidden[2]->points, (std::vector<Point2>{{0.1, 1.0 / 3}, {-7.25, 1e-9}}));
  EXPECT_EQ(back.polylines[0].layer, "HIDDEN");
  EXPECT_NE(text.find("LWPOLYLINE"), std::string::npos);
}

TEST(LinesDxf, HiddenNoneKeepsTheLayerDropsTheEntities) {
  DrawingStyle style = a4();
  style.hidden = false;
  const DxfReadBack back = read_dxf(lines_dxf(box_with_hidden_hole(), style));
  EXPECT_TRUE(back.layers.count("HIDDEN"));
  ASSERT_EQ(back.polylines.size(), 1u);
  EXPECT_EQ(back.polylines[0].layer, "VISIBLE");
}

TEST(LinesDxf, LtscaleIsOneOverTheScaleAndHandseedIsFree) {
  // 1000 mm wide: 1:5 on A4, so the 3 mm dash is 15 model units long.
  const std::string text = lines_dxf(drawing_of(loop({{0, 0}, {1000, 0}, {1000, 100}, {0, 100}})), a4());
  const DxfReadBack back = read_dxf(text);
  EXPECT_EQ(back.doubles.at("$LTSCALE"), 5.0);

  // Every handle (group 5 outside the HEADER, 105 for DIMSTYLE) is unique and below $HANDSEED.
  std::istringstream in(text);
  std::string code, value;
  unsigned long seed = 0;
  std::map<unsigned long, int> seen;
  bool after_seed = false;
  while (std::getline(in, code) && std::getline(in, value)) {
    const int gc = std::stoi(code);
    if (gc == 9) after_seed = value == "$HANDSEED";
    else if (after_seed && gc == 5) seed = std::stoul(value, nullptr, 16), after_seed = false;
    else if (gc == 5 || gc == 105) ++seen[std::stoul(value, nullptr, 16)];
  }
  ASSERT_GT(seed, 0u);
  ASSERT_FALSE(seen.empty());
  for (const auto& [handle, count] : seen) {
    EXPECT_EQ(count, 1) << std::hex << handle;
    EXPECT_LT(handle, seed) << std::hex << handle;
  }
}


// --------------------------------------------------------------------------------------------
// Near-coincident segments (merge_segments) and parts.

TEST(MergeSegments, HiddenUnderANearlyCoincidentVisibleLineIsDropped) {
  // Two parts whose edges are 1e-7 apart: the exact engine gives a visible and a hidden line.
  const auto r = merge_segments({seg({0, 1e-7}, {10, 1e-7}, false, 1), seg({0, 0}, {10, 0}, true, 0)}, 0.01);
  ASSERT_EQ(r.segments.size(), 1u);
  EXPECT_TRUE(r.segments[0].visible);
  EXPECT_EQ(r.segments[0].mesh, 0u);
  EXPECT_EQ(r.merged, 1u);
}

// Smooth lines (thin) give way to hidden lines as to visible ones (ISO 128-20's precedence).
DrawingSegment thin_seg(Point2 a, Point2 b, std::uint32_t mesh = 0) {
  DrawingSegment s = seg(a, b, true, mesh);
  s.thin = true;
  return s;
}

TEST(MergeSegments, ThinUnderANearlyCoincidentHiddenOrVisibleLineIsDropped) {
  for (const bool visible : {true, false}) {
    const auto r = merge_segments({thin_seg({0, 0}, {10, 0}), seg({0, 1e-7}, {10, 1e-7}, visible)}, 0.01);
    ASSERT_EQ(r.segments.size(), 1u) << visible;
    EXPECT_FALSE(r.segments[0].thin);
    EXPECT_EQ(r.segments[0].visible, visible);
  }
  // A thin line alone stays; two thin ones are one.
  EXPECT_EQ(merge_segments({thin_seg({0, 0}, {10, 0}), thin_seg({0, 1e-7}, {10, 1e-7})}, 0.01).segments.size(), 1u);
}

TEST(Chaining, ThinIsAClassOfItsOwnAfterHidden) {
  const auto chains = chain_segments({thin_seg({1, 0}, {2, 0}), seg({0, 0}, {1, 0}, true), seg({2, 0}, {3, 0}, false),
                                      thin_seg({2, 0}, {1.5, 1})});
  ASSERT_EQ(chains.size(), 3u);
  EXPECT_TRUE(chains[0].visible && !chains[0].thin);
  EXPECT_FALSE(chains[1].visible);
  EXPECT_TRUE(chains[2].visible && chains[2].thin);
  EXPECT_EQ(chains[2].points, (std::vector<Point2>{{1, 0}, {2, 0}, {1.5, 1}}));
}

// The thin group: continuous narrow (01.1), between the hidden and the visible group, only when
// the drawing has thin lines; the DXF's layer THIN likewise.
TEST(LinesSvg, ThinGroupAndDxfLayerOnlyWithThinLines) {
  LineDrawing d = box_with_hidden_hole();
  const std::string plain_svg = lines_svg(d, a4()), plain_dxf = lines_dxf(d, a4());
  EXPECT_EQ(plain_svg.find("thin"), std::string::npos);
  EXPECT_FALSE(read_dxf(plain_dxf).layers.count("THIN"));
  d.segments.push_back(thin_seg({10, 10}, {90, 10}));
  const SvgDocument doc = parse_svg(lines_svg(d, a4()));
  ASSERT_TRUE(doc.well_formed) << doc.error;
  const SvgElement* thin = doc.find("g", "thin");
  ASSERT_TRUE(thin);
  EXPECT_EQ(thin->attributes.at("class"), "thin");
  EXPECT_EQ(thin->attributes.at("stroke-width"), "0.25");
  EXPECT_EQ(thin->attributes.count("stroke-dasharray"), 0u);
  EXPECT_LT(doc.position("g", "hidden"), doc.position("g", "thin"));
  EXPECT_LT(doc.position("g", "thin"), doc.position("g", "visible"));
  EXPECT_EQ(doc.in_group("path", "thin").size(), 1u);
  EXPECT_EQ(doc.in_group("path", "visible").size(), 1u);  // the outline only
  EXPECT_TRUE(doc.find("g", "part-part-thin"));
  const DxfReadBack back = read_dxf(lines_dxf(d, a4()));
  ASSERT_TRUE(back.layers.count("THIN"));
  EXPECT_EQ(back.layer_linetype.at("THIN"), "CONTINUOUS");
  EXPECT_EQ(back.layer_lineweight.at("THIN"), 25);
  std::size_t on_thin = 0;
  for (const auto& p : back.polylines) on_thin += p.layer == "THIN";
  EXPECT_EQ(on_thin, 1u);
}

TEST(MergeSegments, DuplicateOfOneClassKeepsTheFirst) {
  const auto r = merge_segments({seg({0, 0}, {10, 0}, true, 0), seg({10, 1e-9}, {1e-9, 0}, true, 1)}, 0.01);
  ASSERT_EQ(r.segments.size(), 1u);
  EXPECT_EQ(r.segments[0].mesh, 0u);  // the lower mesh (the first kept)
  EXPECT_EQ(r.merged, 1u);
}

TEST(MergeSegments, CollinearOverlapIsTrimmedOntoTheKeptEnd) {
  // The hidden line runs from -5 to 5 along a visible one from 0 to 10, 1e-6 off it: what is left
  // is -5..0, ending exactly at the visible line's end.
  const auto r = merge_segments({seg({0, 0}, {10, 0}), seg({-5, 1e-6}, {5, 1e-6}, false)}, 0.01);
  ASSERT_EQ(r.segments.size(), 2u);
  EXPECT_EQ(r.segments[0].a, (Point2{0, 0}));
  EXPECT_FALSE(r.segments[1].visible);
  EXPECT_EQ(r.segments[1].a, (Point2{-5, 1e-6}));
  EXPECT_EQ(r.segments[1].b, (Point2{0, 0}));
  EXPECT_EQ(r.merged, 1u);
  // A hidden line longer at both ends keeps both ends, with a gap where the visible one is.
  const auto both = merge_segments({seg({0, 0}, {10, 0}), seg({20, 0}, {-10, 0}, false)}, 0.01);
  ASSERT_EQ(both.segments.size(), 3u);
  EXPECT_EQ(both.segments[1].a, (Point2{20, 0}));
  EXPECT_EQ(both.segments[1].b, (Point2{10, 0}));
  EXPECT_EQ(both.segments[2].a, (Point2{0, 0}));
  EXPECT_EQ(both.segments[2].b, (Point2{-10, 0}));
}

TEST(MergeSegments, CrossingsJunctionsAndDistantParallelsStayWhole) {
  const std::vector<DrawingSegment> in{
      seg({0, 0}, {10, 0}),
      seg({5, -5}, {5, 5}, false),      // crosses
      seg({3, 0}, {3, 4}),              // T-junction on it
      seg({10, 0}, {12, 0.2}),          // meets its end at about 5.7 degrees
      seg({0, 0.02}, {10, 0.02}, false),  // parallel, 0.02 away: farther than the distance
      seg({0, 0}, {0.005, 0}, false),   // shorter than the distance, but under the line: dropped
  };
  const auto r = merge_segments(in, 0.01);
  ASSERT_EQ(r.segments.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(r.segments[i].a, in[i].a) << i;
    EXPECT_EQ(r.segments[i].b, in[i].b) << i;
  }
  EXPECT_EQ(r.merged, 1u);
  // Zero distance merges nothing.
  const auto none = merge_segments(in, 0);
  EXPECT_EQ(none.segments.size(), in.size());
  EXPECT_EQ(none.merged, 0u);
}

TEST(MergeSegments, SliversAreDroppedAndTheRestKeepsInputOrder) {
  // The second visible line sticks out 0.004 past the first: the sliver goes.
  const auto r = merge_segments({seg({0, 0}, {10, 0}), seg({-0.004, 0}, {10, 0}), seg({0, 5}, {1, 5})}, 0.01);
  ASSERT_EQ(r.segments.size(), 2u);
  EXPECT_EQ(r.segments[1].a, (Point2{0, 5}));
  EXPECT_EQ(r.merged, 1u);
}

TEST(MergeSegments, ManySegmentsThroughTheGrid) {
  // A tessellated circle of 20000 segments, and the same circle moved by 1e-7 as a second part's
  // hidden lines, given first: every hidden one goes, every visible one stays.
  std::vector<DrawingSegment> in;
  const int n = 20000;
  auto at = [&](int i, double r, double dx) {
    return Point2{dx + r * std::cos(2 * M_PI * i / n), r * std::sin(2 * M_PI * i / n)};
  };
  for (int i = 0; i < n; ++i) in.push_back(seg(at(i, 100, 1e-7), at(i + 1, 100, 1e-7), false, 1));
  for (int i = 0; i < n; ++i) in.push_back(seg(at(i, 100, 0), at(i + 1, 100, 0), true, 0));
  // Random short segments elsewhere, none near the circle: untouched.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-50, 50), step(-1, 1);
  for (int i = 0; i < 2000; ++i) {
    const Point2 a{coordinate(random), coordinate(random)};
    in.push_back(seg(a, {a[0] + step(random), a[1] + step(random)}, i % 2 == 0, 2));
  }
  const auto r = merge_segments(in, 0.01);
  std::size_t visible = 0, hidden_of_circle = 0, random_kept = 0;
  for (const auto& s : r.segments) {
    visible += s.visible && s.mesh == 0;
    hidden_of_circle += !s.visible && s.mesh == 1;
    random_kept += s.mesh == 2;
  }
  EXPECT_EQ(visible, std::size_t(n));
  EXPECT_EQ(hidden_of_circle, 0u);
  EXPECT_GE(r.merged, std::size_t(n));
  // The random ones may cover each other now and then, but nearly all stay.
  EXPECT_GT(random_kept, 1950u);
}

// The grids only filter: the merge must keep what the merge with every kept segment and piece as
// a candidate keeps. Segments on a coarse grid, many repeated nearly on top of each other (moved,
// turned, cut short or reversed by about the distance, above and below it), near and far from the
// origin and at several scales, so that covers, cut pieces and pieces covering later segments are
// common. The last draws have thousands of segments: the covers are then found in several chunks,
// on every thread.
TEST(MergeSegments, SameAsTheMergeWithEveryPairACandidate) {
  std::mt19937_64 random(20261206);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  auto pick = [&](int n) { return int(random() % unsigned(n)); };
  std::size_t merged_total = 0;
  for (int draw = 0; draw < 303; ++draw) {
    const double scale = std::pow(10.0, pick(7) - 3), distance = 0.01 * scale;
    const Point2 origin{pick(3) == 0 ? 1e6 * scale : 0.0, pick(3) == 0 ? -3e5 * scale : 0.0};
    auto grid_point = [&] { return Point2{origin[0] + scale * pick(8), origin[1] + scale * pick(8)}; };
    auto near = [&](const Point2& p) {
      const double r = distance * std::array<double, 5>{0, 1e-5, 0.5, 1, 1.5}[pick(5)];
      return Point2{p[0] + uniform(-r, r), p[1] + uniform(-r, r)};
    };
    std::vector<DrawingSegment> in;
    const int n = draw < 300 ? 20 + pick(200) : 9000 + pick(1000);
    for (int i = 0; i < n; ++i) {
      DrawingSegment s;
      if (in.empty() || pick(3) == 0) {
        s = seg(grid_point(), grid_point());
      } else {
        s = in[std::size_t(pick(int(in.size())))];
        s.a = near(s.a), s.b = near(s.b);
        if (pick(4) == 0) {  // cut short
          const double t = uniform(0, 1);
          s.b = {s.a[0] + t * (s.b[0] - s.a[0]), s.a[1] + t * (s.b[1] - s.a[1])};
        }
        if (pick(2) == 0) std::swap(s.a, s.b);
      }
      s.visible = pick(3) != 0;
      s.thin = pick(6) == 0;
      s.mesh = std::uint32_t(pick(3));
      s.line = std::uint32_t(i);
      in.push_back(s);
    }
    const MergedSegments got = merge_segments(in, distance), want = detail::merge_segments_all_pairs(in, distance);
    ASSERT_EQ(got.merged, want.merged) << draw;
    ASSERT_EQ(got.segments.size(), want.segments.size()) << draw;
    for (std::size_t k = 0; k < got.segments.size(); ++k) {
      const DrawingSegment &g = got.segments[k], &w = want.segments[k];
      ASSERT_TRUE(g.a == w.a && g.b == w.b && g.visible == w.visible && g.thin == w.thin && g.mesh == w.mesh &&
                  g.line == w.line)
          << draw << " segment " << k;
    }
    merged_total += got.merged;
  }
  EXPECT_GT(merged_total, 3000u);  // the draws do merge
}

TEST(SheetSegments, DistanceIsMillimetresOnTheSheet) {
  // 100 x 50 at 2:1: 0.01 mm on the sheet is 0.005 in the model.
  LineDrawing d = box_with_hidden_hole();
  d.segments.push_back(seg({0, 0.004}, {100, 0.004}, false));  // within 0.005
  d.segments.push_back(seg({0, 49.994}, {100, 49.994}, false));  // 0.006 off the top: kept
  const auto r = sheet_segments(d, a4());
  EXPECT_EQ(r.merged, 1u);
  EXPECT_EQ(r.segments.size(), d.segments.size() - 1);
  DrawingStyle coarse = a4();
  coarse.merge_distance = 0.02;
  EXPECT_EQ(sheet_segments(d, coarse).merged, 2u);
  DrawingStyle visible_only = a4();
  visible_only.hidden = false;
  EXPECT_EQ(sheet_segments(d, visible_only).merged, 0u);
  // The SVG and the DXF draw the merged segments: one hidden path fewer.
  const SvgDocument doc = parse_svg(lines_svg(d, a4()));
  EXPECT_EQ(doc.in_group("path", "hidden").size(), 3u);
}

TEST(SheetLines, OnceForBothWriters) {
  LineDrawing d = box_with_hidden_hole();
  d.segments.push_back(seg({0, 0.004}, {100, 0.004}, false));  // merged at 2:1
  DrawingSegment contact = seg({10, 10}, {20, 10});
  contact.meeting_degrees = 5;  // a contact line: left out
  d.segments.push_back(contact);
  const SheetLines sheet = sheet_lines(d, a4());
  EXPECT_EQ(sheet.scale, drawing_scale(d, a4()));
  const MergedSegments merged = sheet_segments(d, a4());
  EXPECT_EQ(sheet.merged.merged, 1u);
  EXPECT_EQ(sheet.merged.contact, 1u);
  ASSERT_EQ(sheet.merged.segments.size(), merged.segments.size());
  const auto chains = chain_segments(merged.segments);
  ASSERT_EQ(sheet.chains.size(), chains.size());
  for (std::size_t c = 0; c < chains.size(); ++c) EXPECT_EQ(sheet.chains[c].points, chains[c].points);
  EXPECT_EQ(lines_svg(d, a4(), sheet), lines_svg(d, a4()));
  EXPECT_EQ(lines_dxf(d, a4(), sheet), lines_dxf(d, a4()));
  // The writers draw what they are given: a sheet without curves has no lines.
  SheetLines none = sheet;
  none.curves = {};
  EXPECT_TRUE(parse_svg(lines_svg(d, a4(), none)).in_group("path", "visible").empty());
  EXPECT_EQ(read_dxf(lines_dxf(d, a4(), none)).polylines.size(), 0u);
}

TEST(PartNames, StemsMadeIdSafeAndUnique) {
  LineDrawing d;
  d.input.files = {"a/bolt.off", "b/Bolt.stl", "nut v2.obj", "/x/.off", "ünï.ply", "bolt-2.off", "dir.d/plate"};
  d.segments.push_back(seg({0, 0}, {1, 0}, true, 8));
  EXPECT_EQ(part_names(d), (std::vector<std::string>{"bolt", "Bolt-2", "nut_v2", "_off", "_n_", "bolt-2-2", "plate",
                                                     "mesh-7", "mesh-8"}));
}

// Three parts, the first and the last with lines of both classes, the middle one entirely hidden.
LineDrawing three_parts() {
  std::vector<DrawingSegment> segments = loop({{0, 0}, {100, 0}, {100, 50}, {0, 50}});
  for (auto& s : loop({{40, 10}, {60, 10}, {60, 30}, {40, 30}}, false)) segments.push_back(s), segments.back().mesh = 1;
  for (auto& s : loop({{110, 0}, {130, 0}, {130, 50}, {110, 50}})) segments.push_back(s), segments.back().mesh = 2;
  segments.push_back(seg({10, 0}, {10, 50}, false, 0));
  segments.push_back(seg({120, 0}, {120, 50}, false, 2));
  LineDrawing d = drawing_of(segments);
  d.input.files = {"parts/bolt.off", "parts/bolt.stl", "nut.off"};
  return d;
}

TEST(LinesSvg, EachPartInAGroupInsideTheClassGroups) {
  const std::string svg = lines_svg(three_parts(), a4());
  const SvgDocument doc = parse_svg(svg);
  ASSERT_TRUE(doc.well_formed) << doc.error;
  std::set<std::string> ids;
  for (const auto& e : doc.elements)
    if (e.attributes.count("id")) {
      EXPECT_TRUE(ids.insert(e.attributes.at("id")).second) << "repeated id " << e.attributes.at("id");
    }
  struct Want {
    std::string id, klass, outer;
    std::size_t paths;
  };
  for (const Want& w : {Want{"part-bolt-visible", "part-bolt", "visible", 1}, Want{"part-bolt-hidden", "part-bolt", "hidden", 1},
                        Want{"part-bolt-2-hidden", "part-bolt-2", "hidden", 1},
                        Want{"part-nut-visible", "part-nut", "visible", 1}, Want{"part-nut-hidden", "part-nut", "hidden", 1}}) {
    SCOPED_TRACE(w.id);
    const SvgElement* g = doc.find("g", w.id);
    ASSERT_TRUE(g);
    EXPECT_EQ(g->group, w.outer);
    EXPECT_EQ(g->attributes.at("class"), w.klass);
    EXPECT_EQ(doc.in_group("path", w.id).size(), w.paths);
  }
  EXPECT_FALSE(doc.find("g", "part-bolt-2-visible"));  // nothing of it is visible: no empty group
  // Every path lies in a part group inside the visible or the hidden group.
  for (const auto* path : doc.in_group("path", "visible")) EXPECT_EQ(path->group.rfind("part-", 0), 0u);
  for (const auto* path : doc.in_group("path", "hidden")) EXPECT_EQ(path->group.rfind("part-", 0), 0u);
  EXPECT_EQ(doc.in_group("path", "visible").size() + doc.in_group("path", "hidden").size(), 5u);
}

TEST(LinesSvg, PartsAreNeverChainedTogether) {
  // Two parts' segments meet end to end at (10, 0): two paths, not one.
  LineDrawing d = drawing_of({seg({0, 0}, {10, 0}, true, 0), seg({10, 0}, {20, 0}, true, 1)});
  d.input.files = {"a.off", "b.off"};
  const SvgDocument doc = parse_svg(lines_svg(d, a4()));
  EXPECT_EQ(doc.in_group("path", "part-a-visible").size(), 1u);
  EXPECT_EQ(doc.in_group("path", "part-b-visible").size(), 1u);
}

TEST(LinesDxf, OneLayerPairPerPartWhenTheSceneHasSeveralMeshes) {
  const DxfReadBack back = read_dxf(lines_dxf(three_parts(), a4()));
  for (const char* name : {"BOLT-VISIBLE", "BOLT-HIDDEN", "BOLT-2-VISIBLE", "BOLT-2-HIDDEN", "NUT-VISIBLE", "NUT-HIDDEN"})
    EXPECT_TRUE(back.layers.count(name)) << name;
  EXPECT_FALSE(back.layers.count("VISIBLE"));
  EXPECT_FALSE(back.layers.count("HIDDEN"));
  EXPECT_EQ(back.layer_linetype.at("NUT-HIDDEN"), "HIDDEN");
  EXPECT_EQ(back.layer_linetype.at("BOLT-2-VISIBLE"), "CONTINUOUS");
  EXPECT_EQ(back.layer_lineweight.at("BOLT-VISIBLE"), 50);
  std::map<std::string, int> entities;
  for (const auto& p : back.polylines) ++entities[p.layer];
  EXPECT_EQ(entities, (std::map<std::string, int>{
                          {"BOLT-VISIBLE", 1}, {"BOLT-HIDDEN", 1}, {"BOLT-2-HIDDEN", 1}, {"NUT-VISIBLE", 1}, {"NUT-HIDDEN", 1}}));
  // One mesh: VISIBLE and HIDDEN as before.
  const DxfReadBack one = read_dxf(lines_dxf(box_with_hidden_hole(), a4()));
  EXPECT_TRUE(one.layers.count("VISIBLE") && one.layers.count("HIDDEN"));
  EXPECT_FALSE(one.layers.count("PART-VISIBLE"));
}

TEST(LinesJson, MergedSegmentsInStatsWhenKnown) {
  LineDrawing d = box_with_hidden_hole();
  EXPECT_FALSE(json::parse(lines_json(d))["stats"].contains("merged_segments"));
  d.merged_segments = 3;
  d.merge_distance_mm = 0.01;
  const json j = json::parse(lines_json(d));
  EXPECT_EQ(j["stats"]["merged_segments"], 3);
  EXPECT_EQ(j["stats"]["merge_distance_mm"], 0.01);
}

// --------------------------------------------------------------------------------------------
// Samples for tests/tools/check_drawing.py.

// An L-shaped part in a front view: visible outline and a visible hole, a hidden slot and a
// hidden through hole, and an intersection line.
LineDrawing sample_bracket() {
  auto segments = loop({{0, 0}, {80, 0}, {80, 10}, {10, 10}, {10, 60}, {0, 60}});
  std::vector<Point2> circle;
  for (int i = 0; i < 32; ++i)
    circle.push_back({5 + 3 * std::cos(i * M_PI / 16), 45 + 3 * std::sin(i * M_PI / 16)});
  const auto hole = loop(circle);
  segments.insert(segments.end(), hole.begin(), hole.end());
  for (double x : {35.0, 45.0}) segments.push_back(seg({x, 0}, {x, 10}, false));
  const auto slot = loop({{55, 2}, {70, 2}, {70, 8}, {55, 8}}, false);
  segments.insert(segments.end(), slot.begin(), slot.end());
  LineDrawing d = drawing_of(segments);
  d.input.files = {"fixtures/scenes/l_bracket.off"};
  d.pieces.back().kind = FeatureKind::intersection;
  d.pieces.back().has_edge = false;
  d.kernel = KernelKind::exact;
  return d;
}

int write_samples(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
  };
  const DrawingStyle a4_style = a4();
  DrawingStyle visible_only = a4_style;
  visible_only.hidden = false;
  const LineDrawing bracket = sample_bracket();
  write("bracket.svg", lines_svg(bracket, a4_style));
  write("bracket.pdf", lines_pdf(bracket, a4_style));
  write("bracket.dxf", lines_dxf(bracket, a4_style));
  write("bracket.json", lines_json(bracket));
  write("bracket_visible_only.svg", lines_svg(bracket, visible_only));
  write("bracket_visible_only.dxf", lines_dxf(bracket, visible_only));
  const LineDrawing big = drawing_of(loop({{0, 0}, {1000, 0}, {1000, 100}, {0, 100}}));
  write("big_a3.svg", lines_svg(big, DrawingStyle{*sheet_by_name("A3"), std::nullopt, true}));
  write("big_a3.dxf", lines_dxf(big, DrawingStyle{*sheet_by_name("A3"), std::nullopt, true}));
  const LineDrawing parts = three_parts();
  write("parts.svg", lines_svg(parts, a4_style));
  write("parts.dxf", lines_dxf(parts, a4_style));
  write("empty.svg", lines_svg(LineDrawing{}, a4_style));
  write("empty.dxf", lines_dxf(LineDrawing{}, a4_style));
  write("empty.json", lines_json(LineDrawing{}));
  std::cout << "wrote samples to " << dir << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--write-samples") == 0) return write_samples(argv[2]);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
