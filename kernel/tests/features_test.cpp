// Feature edges (hlr/kernel/features.hpp): the smooth-edge rule of meshes on tessellated fillets,
// cylinders, spheres and bends, exactly as the header states it.
#include <hlr/kernel/features.hpp>
#include <hlr/kernel/mesh_edges.hpp>
#include <hlr/kernel/scene.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

using namespace hlr;
using Point = std::array<double, 3>;
using Faces = std::vector<std::vector<std::uint32_t>>;

View view(const char* name) {
  View v;
  EXPECT_TRUE(named_view(name, v));
  return v;
}

std::map<std::pair<std::uint32_t, std::uint32_t>, FeatureKind> features(const Mesh& mesh, SmoothEdges smooth,
                                                                        const char* view_name = "iso",
                                                                        double crease = 30) {
  FeatureOptions options;
  options.smooth_edges = smooth;
  options.crease_degrees = crease;
  std::map<std::pair<std::uint32_t, std::uint32_t>, FeatureKind> out;
  for (const FeatureEdge& e : feature_edges(mesh, view(view_name), options)) out[{e.v0, e.v1}] = e.kind;
  return out;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> smooth_edges(const Mesh& mesh, const char* view_name = "iso",
                                                                  double crease = 30) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const auto& [edge, kind] : features(mesh, SmoothEdges::thin, view_name, crease))
    if (kind == FeatureKind::smooth) out.push_back(edge);
  return out;
}

Mesh mesh_of(std::vector<Point> vertices, Faces faces) {
  ImportReport report;
  return make_mesh("test", std::move(vertices), std::move(faces), report);
}

// An extrusion along y (0 to `length`) of a closed profile in the x-z plane, counter-clockwise
// seen from -y, its sides as triangle pairs (or quads), its ends polygons.
Mesh extrusion(const std::vector<std::array<double, 2>>& profile, double length, bool quads = false) {
  const auto n = std::uint32_t(profile.size());
  std::vector<Point> v;
  for (double y : {0.0, length})
    for (const auto& p : profile) v.push_back({p[0], y, p[1]});
  Faces f;
  std::vector<std::uint32_t> front, back;
  for (std::uint32_t i = 0; i < n; ++i) front.push_back(i), back.push_back(2 * n - 1 - i);
  f.push_back(front);
  f.push_back(back);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    if (quads) {
      f.push_back({j, i, n + i, n + j});
    } else {
      f.push_back({j, i, n + i});
      f.push_back({j, n + i, n + j});
    }
  }
  return mesh_of(v, f);
}

// An arc of `segments` steps around (cx, cz) from angle a0 to a1 (degrees), the ends exact.
void arc(std::vector<std::array<double, 2>>& p, double cx, double cz, double r, double a0, double a1, int segments,
         std::array<double, 2> first, std::array<double, 2> last) {
  p.push_back(first);
  for (int k = 1; k < segments; ++k) {
    const double a = (a0 + (a1 - a0) * k / segments) * std::numbers::pi / 180;
    p.push_back({cx + r * std::cos(a), cz + r * std::sin(a)});
  }
  p.push_back(last);
}

// A plate 40 x 5 with its top left corner rounded, radius 4, in `segments` steps: one fillet
// between the top (z = 5) and the left side (x = 0).
std::vector<std::array<double, 2>> rounded_plate(int segments) {
  std::vector<std::array<double, 2>> p{{0, 0}, {40, 0}, {40, 5}};
  arc(p, 4, 1, 4, 90, 180, segments, {4, 5}, {0, 1});
  return p;
}

// The edges whose two ends have the profile point (x, z).
bool is_ruling_at(const Mesh& mesh, std::pair<std::uint32_t, std::uint32_t> e, double x, double z) {
  const Point &a = mesh.vertices[e.first], &b = mesh.vertices[e.second];
  return a[0] == x && a[2] == z && b[0] == x && b[2] == z && a[1] != b[1];
}

TEST(SmoothEdges, AFilletsTwoTangentLinesAreSmooth) {
  for (const bool quads : {false, true})
    for (const int segments : {4, 6, 8}) {
      const Mesh mesh = extrusion(rounded_plate(segments), 10, quads);
      // Views in which neither tangent line is a silhouette (in the top view the one beside the
      // left side, seen edge-on, is: TheFilletedBracket).
      for (const char* v : {"iso", "front", "right", "bottom"}) {
        const auto smooth = smooth_edges(mesh, v);
        const std::string label = std::string(v) + (quads ? " quads " : " triangles ") + std::to_string(segments);
        ASSERT_EQ(smooth.size(), 2u) << label;
        EXPECT_TRUE(is_ruling_at(mesh, smooth[0], 4, 5) || is_ruling_at(mesh, smooth[1], 4, 5)) << label;
        EXPECT_TRUE(is_ruling_at(mesh, smooth[0], 0, 1) || is_ruling_at(mesh, smooth[1], 0, 1)) << label;
      }
    }
}

TEST(SmoothEdges, ModesAddTheSmoothEdgesAsSmoothOrAsCreases) {
  const Mesh mesh = extrusion(rounded_plate(6), 10);
  const auto off = features(mesh, SmoothEdges::off), thin = features(mesh, SmoothEdges::thin),
             full = features(mesh, SmoothEdges::full);
  EXPECT_EQ(thin.size(), off.size() + 2);
  EXPECT_EQ(full.size(), off.size() + 2);
  for (const auto& [edge, kind] : thin) {
    const auto it = off.find(edge);
    if (it != off.end()) {
      EXPECT_EQ(kind, it->second);
      EXPECT_EQ(full.at(edge), it->second);
    } else {
      EXPECT_EQ(kind, FeatureKind::smooth);
      EXPECT_EQ(full.at(edge), FeatureKind::crease);
    }
  }
  // Off: none of the fillet's edges is drawn but where it turns from the viewer (iso: none).
  for (const auto& [edge, kind] : off) EXPECT_NE(kind, FeatureKind::smooth);
}

// Below the crease threshold only: at --crease 8 the fillet's inner edges (15 degrees apart) are
// creases, so its facets are no strips of soft edges and nothing is smooth. (At thresholds above
// 90 degrees a box's sides become strips between soft edges; the rule is meant for the usual
// thresholds, below the right angles of a part.)
TEST(SmoothEdges, OnlyBelowTheCreaseThreshold) {
  const Mesh mesh = extrusion(rounded_plate(6), 10);
  EXPECT_TRUE(smooth_edges(mesh, "iso", 8).empty());
  EXPECT_EQ(smooth_edges(mesh, "iso", 30).size(), 2u);
}

TEST(SmoothEdges, ACylinderOrASphereHasNone) {
  // A cylinder of 24 sides along y, its sides triangle pairs or quads, its ends 24-gons.
  for (const bool quads : {false, true}) {
    std::vector<std::array<double, 2>> circle;
    for (int k = 0; k < 24; ++k) circle.push_back({5 * std::cos(k * std::numbers::pi / 12), 5 * std::sin(k * std::numbers::pi / 12)});
    const Mesh cylinder = extrusion(circle, 20, quads);
    for (const char* v : {"iso", "front", "top"}) EXPECT_TRUE(smooth_edges(cylinder, v).empty()) << v;
    // Only its ends' rims are drawn, and its silhouettes.
    for (const auto& [edge, kind] : features(cylinder, SmoothEdges::thin, "top"))
      EXPECT_TRUE(kind == FeatureKind::crease || kind == FeatureKind::silhouette);
  }
  // A UV sphere: 16 meridians, 8 rings, planar quads (two triangles each) and triangle fans at the poles.
  std::vector<Point> v{{0, 0, 10}};
  for (int ring = 1; ring < 8; ++ring)
    for (int m = 0; m < 16; ++m) {
      const double theta = ring * std::numbers::pi / 8, phi = m * std::numbers::pi / 8;
      v.push_back({10 * std::sin(theta) * std::cos(phi), 10 * std::sin(theta) * std::sin(phi), 10 * std::cos(theta)});
    }
  v.push_back({0, 0, -10});
  const auto south = std::uint32_t(v.size() - 1);
  auto at = [](int ring, int m) { return std::uint32_t(1 + (ring - 1) * 16 + (m % 16)); };
  Faces f;
  for (int m = 0; m < 16; ++m) {
    f.push_back({0, at(1, m), at(1, m + 1)});
    f.push_back({south, at(7, m + 1), at(7, m)});
    for (int ring = 1; ring < 7; ++ring) {
      f.push_back({at(ring, m), at(ring + 1, m), at(ring + 1, m + 1)});
      f.push_back({at(ring, m), at(ring + 1, m + 1), at(ring, m + 1)});
    }
  }
  const Mesh sphere = mesh_of(v, f);
  for (const char* view_name : {"iso", "front", "top"}) EXPECT_TRUE(smooth_edges(sphere, view_name).empty()) << view_name;
}

// Two flat faces meeting at 10 degrees, without a fillet: soft, but no smooth edge (neither is a
// facet strip).
TEST(SmoothEdges, AShallowBendIsNone) {
  const double s = std::sin(10 * std::numbers::pi / 180), c = std::cos(10 * std::numbers::pi / 180);
  const Mesh bend = extrusion({{0, 0}, {20, 0}, {20 + 20 * c, 20 * s}, {20 + 20 * c, 20 * s + 2}, {20, 2}, {0, 2}}, 10);
  EXPECT_TRUE(smooth_edges(bend).empty());
  EXPECT_TRUE(smooth_edges(bend, "front").empty());
}

// The bundled fixture: its two fillets' four tangent lines, and nothing else. A tangent line that
// is also a silhouette (in the top view the inner fillet's upper line, beside the wall seen
// edge-on) stays a silhouette.
TEST(SmoothEdges, TheFilletedBracket) {
  const std::filesystem::path path = std::filesystem::path(HLR_PART_FIXTURES) / "filleted_bracket.off";
  ImportReport report;
  const Mesh mesh = load_mesh(path.string(), report);
  const std::set<std::pair<double, double>> tangents{{0, 6}, {6, 0}, {18, 8}, {8, 18}};
  for (const char* v : {"iso", "front", "top", "right"}) {
    std::set<std::pair<double, double>> smooth_at, tangent_drawn;
    for (const auto& [e, kind] : features(mesh, SmoothEdges::thin, v)) {
      const Point& a = mesh.vertices[e.first];
      const bool ruling = is_ruling_at(mesh, e, a[0], a[2]) && tangents.count({a[0], a[2]});
      if (kind == FeatureKind::smooth) {
        EXPECT_TRUE(ruling) << v;
        EXPECT_TRUE(smooth_at.insert({a[0], a[2]}).second) << v;
      }
      if (ruling && (kind == FeatureKind::smooth || kind == FeatureKind::silhouette)) tangent_drawn.insert({a[0], a[2]});
    }
    EXPECT_EQ(tangent_drawn, tangents) << v;
    EXPECT_GE(smooth_at.size(), 3u) << v;
  }
}

}  // namespace

// edge_uses files a large mesh's uses on every thread: the same as a stable sort by key of the
// uses made in face and corner order, including the uses of one edge by one face twice (a face
// that doubles back), vertices with hundreds of uses, and every fan and source bit.
TEST(MeshEdges, EdgeUsesAreTheStableSortByKey) {
  std::mt19937 random(7);
  Mesh mesh;
  const std::uint32_t vertices = 3000;
  mesh.vertices.resize(vertices);
  std::uniform_int_distribution<std::uint32_t> vertex(0, vertices - 1), hub(0, 3), corners(3, 7);
  for (int f = 0; f < 70000; ++f) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t k = corners(random); k-- > 0;) face.push_back(f % 5 == 0 ? hub(random) : vertex(random));
    if (f % 97 == 0) face = {face[0], face[1], face[0], face[2]};  // edge face[0]-face[1] twice
    mesh.faces.push_back(face);
    mesh.fan_edges.push_back(std::uint8_t(random()));
    mesh.source_edges.push_back(std::uint8_t(random()));
  }
  std::vector<EdgeUse> expected;
  for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& face = mesh.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i) {
      const std::uint32_t a = face[i], b = face[(i + 1) % face.size()];
      const bool fan = i < 8 && (mesh.fan_edges[f] >> i & 1u);
      const std::uint8_t bits = i < 4 ? std::uint8_t(mesh.source_edges[f] >> i) : 0;
      expected.push_back({edge_key(a, b), f, a < b, fan, std::uint8_t((bits & 1u) ? 1u | ((bits >> 4 & 1u) << 1) : 0u)});
    }
  }
  std::stable_sort(expected.begin(), expected.end(), [](const EdgeUse& x, const EdgeUse& y) { return x.key < y.key; });
  const std::vector<EdgeUse> uses = edge_uses(mesh);
  ASSERT_EQ(uses.size(), expected.size());
  for (std::size_t k = 0; k < uses.size(); ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(uses[k].key, expected[k].key);
    EXPECT_EQ(uses[k].face, expected[k].face);
    EXPECT_EQ(uses[k].forward, expected[k].forward);
    EXPECT_EQ(uses[k].fan, expected[k].fan);
    ASSERT_EQ(uses[k].source, expected[k].source);
  }
}
