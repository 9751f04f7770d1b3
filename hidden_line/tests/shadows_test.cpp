// cast_shadows against hand-computed areas (fixtures/shadows/, exact fractions compared exactly)
// and the independent oracle (shadow_oracle.hpp) on those fixtures, fixtures/scenes, the shared
// scenes and random grid-snapped boxes and triangle soups under random rational suns.
#include "shadow_oracle.hpp"
#include "soup_generator.hpp"

#include <hlr/hidden_line/raster_shadows.hpp>
#include <hlr/hidden_line/shadows.hpp>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

namespace hlr::hltest {
namespace {

using hidden_line::cast_shadows;
using hidden_line::Facing;
using hidden_line::Light;
using hidden_line::ShadowResult;

std::vector<Mesh> load(const std::string& path) {
  ImportReport report;
  return {load_mesh(path, report)};
}

Light sun(double x, double y, double z) { return {Light::directional, {x, y, z}}; }
Light bulb(double x, double y, double z) { return {Light::point, {x, y, z}}; }

std::string joined(const std::vector<std::string>& errors) {
  std::ostringstream out;
  for (const auto& e : errors) out << "  " << e << "\n";
  return out.str();
}

// ---------------------------------------------------------------------------------------------
// Hand-computed lit areas (README.md of fixtures/shadows says how).

struct Expected {
  std::uint32_t face;
  int num, den;  // lit area = num / den
};
struct AnalyticCase {
  const char* file;
  Light light;
  std::vector<Expected> lit;
  const char* why;
};

const std::vector<AnalyticCase>& analytic_cases() {
  static const std::vector<AnalyticCase> cases = {
      // Ground shadow = hull of the 2 x 2 footprint and its translate by 2 (1, 2) / 4 = (1/2, 1):
      // 4 + 3 = 7 (the footprint itself is covered by the box); the sides facing the sun are lit.
      {"box_on_ground.off", sun(1, 2, -4), {{0, 393, 1}, {1, 0, 1}, {2, 4, 1}, {3, 4, 1}, {4, 0, 1}, {5, 0, 1}, {6, 4, 1}},
       "box on a ground plane, oblique sun"},
      {"box_on_ground.off", sun(0, 0, -1), {{0, 396, 1}, {2, 4, 1}, {3, 0, 1}, {4, 0, 1}}, "sun overhead: sides edge-on"},
      // d = (1, -1, -3): translate 2 (1, -1) / 3; hull area 4 + 2 (2/3 + 2/3) = 20/3.
      {"box_on_ground.off", sun(1, -1, -3), {{0, 1180, 3}, {2, 4, 1}, {3, 0, 1}, {5, 4, 1}, {6, 4, 1}}, "rational shadow area"},
      // Grazing: the ground edge-on (attached shadow), the top edge-on; the face x = 0 lit.
      {"box_on_ground.off", sun(1, 0, 0), {{0, 0, 1}, {2, 0, 1}, {6, 4, 1}}, "sun grazing the ground exactly"},
      // Nearly grazing: the shadow, 128 long, leaves the ground at x = 10: 10 x 2 of it.
      {"box_on_ground.off", sun(1, 0, -1.0 / 64), {{0, 380, 1}, {2, 4, 1}, {6, 4, 1}}, "sun 0.9 degrees above the horizon"},
      // Overhang 1 deep at z = 3 over the wall y = 0: a band z in [2, 3] in shadow.
      {"overhang.off", sun(0, 1, -1), {{2, 12, 1}, {6, 4, 1}, {1, 16, 1}, {3, 0, 1}, {5, 0, 1}}, "overhang over a wall"},
      // Oblique: the band's left end slides: shadow area int_2^3 (1 + z) dz = 7/2.
      {"overhang.off", sun(1, 1, -1), {{2, 25, 2}, {6, 4, 1}, {5, 16, 1}}, "overhang, oblique sun"},
      // Ground shadows [-2, 2] x [0, 2] (A) and [-1, 4] x [0, 2] (B) overlap: union 12. B shades
      // A's east face entirely and its top for x > 1.
      {"two_boxes.off", sun(-1, 0, -1), {{0, 388, 1}, {4, 0, 1}, {2, 2, 1}, {10, 8, 1}, {8, 2, 1}}, "two boxes, shadows overlap"},
      // Found by the property test: the ground is the first front in the rough order and wins the
      // coplanar tie with the triangle, though the box is nearer to the light over both. Ground
      // shadow: 1 + 1 (1 + 1) = 3.
      {"coplanar_under_box.off", sun(-1, -1, -1), {{0, 397, 1}, {7, 0, 1}, {2, 1, 1}}, "coplanar tie under a box"},
      // Point lights over the box [0, 2]^3: the ground shadow is the top face scaled from the light
      // onto z = 0 by h / (h - 2) (h the light's height; it contains the footprint). Over the centre at
      // h = 4: [-1, 3]^2, 16, ground lit 384; the sides face away.
      {"box_on_ground.off", bulb(1, 1, 4), {{0, 384, 1}, {1, 0, 1}, {2, 4, 1}, {3, 0, 1}, {4, 0, 1}, {5, 0, 1}, {6, 0, 1}},
       "point light over the box's centre"},
      // h = 5: scale 5/3, the scaled top (10/3)^2 = 100/9, ground lit 400 - 100/9 = 3500/9.
      {"box_on_ground.off", bulb(1, 1, 5), {{0, 3500, 9}, {2, 4, 1}}, "point light, rational shadow area"},
      // From (1, -4, 4) the top projects to p -> 2 p - L: hull of the footprint and the top's image
      // (0,0) (2,0) (3,4) (3,8) (-1,8) (-1,4), area 28 (the footprint included): ground lit 372;
      // -y lit.
      {"box_on_ground.off", bulb(1, -4, 4), {{0, 372, 1}, {2, 4, 1}, {3, 4, 1}, {4, 0, 1}, {5, 0, 1}, {6, 0, 1}},
       "point light in front of the -y face"},
      // From (2, -4, 4), in the plane of the +x face: that face is edge-on (attached shadow); hull
      // (0,0) (2,0) (2,8) (-2,8) (-2,4), area 28: ground lit 372.
      {"box_on_ground.off", bulb(2, -4, 4), {{0, 372, 1}, {2, 4, 1}, {3, 4, 1}, {4, 0, 1}, {6, 0, 1}},
       "point light in the plane of a face"},
      // Point lights among the geometry (the cube of six views; README.md of fixtures/shadows).
      // From (0, 0, 1) between two boxes: A [-3,-1]x[-1,2]x[0,2] shades the ground where a ray
      // crosses x = -1 with -1 <= y/(-x) <= 2: int_-10^-5 (10 - x) + int_-5^-1 (-3 x) = 247/2; B
      // [1,3]x[-1,1]x[0,2] the wedge |y| <= x, x >= 1: 99. Ground lit 400 - 247/2 - 99 = 355/2. The
      // panel at x = -1/2 (lit, 1) throws y in [0,2], z in [0,2] onto A's +x face: 6 - 4 = 2.
      {"light_between_boxes.off", bulb(0, 0, 1),
       {{0, 355, 2}, {1, 0, 1}, {2, 0, 1}, {3, 0, 1}, {4, 2, 1}, {5, 0, 1}, {6, 0, 1}, {7, 0, 1}, {8, 0, 1},
        {9, 0, 1}, {10, 0, 1}, {11, 0, 1}, {12, 4, 1}, {13, 1, 1}},
       "point light between two boxes, a panel in front of one"},
      // From (6, 6, 3) in a room without ceiling: the box [2,4]^2x[0,2] throws its top (scaled 3
      // from the light) and its footprint onto the floor: the hull's part in x, y >= 0 is
      // (0,0) (3,0) (4,2) (4,4) (2,4) (0,3), area 14: floor lit 50; onto the walls x = 0 and y = 0
      // the rectangle [0,3]x[0,3/2]: 32 - 9/2 = 55/2; the far walls and the box's top, +x, +y lit.
      {"open_room.off", bulb(6, 6, 3),
       {{0, 50, 1}, {1, 55, 2}, {2, 32, 1}, {3, 55, 2}, {4, 32, 1}, {5, 0, 1}, {6, 4, 1}, {7, 0, 1}, {8, 4, 1},
        {9, 4, 1}, {10, 0, 1}},
       "point light in an open room with a box"},
  };
  return cases;
}

std::string fixture(const char* name) { return std::string(HLR_SHADOW_FIXTURES_DIR) + "/" + name; }

TEST(ShadowFixtures, LitAreasAreTheHandComputedFractions) {
  for (const auto& c : analytic_cases()) {
    SCOPED_TRACE(std::string(c.file) + ": " + c.why);
    const auto meshes = load(fixture(c.file));
    const std::vector<Light> lights{c.light};
    const ShadowResult r = cast_shadows(meshes, lights);
    for (const auto& e : c.lit) {
      // Every face of these fixtures is axis-aligned: twice its projected area is twice its area.
      EXPECT_EQ(r.face_lit_area2[0][0][e.face], hidden_line::ShadowFT(2 * e.num) / hidden_line::ShadowFT(e.den))
          << "face " << e.face << ": lit " << CGAL::to_double(r.face_lit_area2[0][0][e.face]) / 2 << ", expected "
          << double(e.num) / e.den;
      EXPECT_DOUBLE_EQ(r.face_lit_area[0][0][e.face], double(e.num) / e.den);
    }
    const auto errors = check_shadows(meshes, lights, r);
    EXPECT_TRUE(errors.empty()) << joined(errors);
  }
}

TEST(ShadowFixtures, FacingAndCastersOfTheBoxOnTheGround) {
  const auto meshes = load(fixture("box_on_ground.off"));
  const ShadowResult r = cast_shadows(meshes, {sun(1, 2, -4)});
  ASSERT_EQ(r.sources.size(), 7u);  // the ground and six box faces, none merged
  const auto& ground = r.sources[r.face_source[0][0]];
  EXPECT_EQ(ground.lights[0].facing, Facing::toward);
  ASSERT_FALSE(ground.lights[0].shadow.empty());
  for (const auto& s : ground.lights[0].shadow)
    for (const auto& [mesh, face] : s.by) EXPECT_TRUE(face >= 1 && face <= 6) << face;  // cast by the box
  EXPECT_EQ(r.sources[r.face_source[0][1]].lights[0].facing, Facing::away);  // the bottom
  EXPECT_EQ(r.sources[r.face_source[0][4]].lights[0].facing, Facing::away);  // +x
  // The ground: lit 393 of 400, exactly, and in shadow the rest.
  EXPECT_EQ(ground.lights[0].lit_area2, hidden_line::ShadowFT(786));
  EXPECT_EQ(ground.area2, hidden_line::ShadowFT(800));
}

TEST(ShadowFixtures, ShadowsOfBothBoxesAreNamed) {
  const auto meshes = load(fixture("two_boxes.off"));
  const ShadowResult r = cast_shadows(meshes, {sun(-1, 0, -1)});
  std::set<std::uint32_t> casters;
  for (const auto& s : r.sources[r.face_source[0][0]].lights[0].shadow)
    for (const auto& [mesh, face] : s.by) casters.insert(face);
  EXPECT_TRUE(std::any_of(casters.begin(), casters.end(), [](auto f) { return f >= 1 && f <= 6; }));
  EXPECT_TRUE(std::any_of(casters.begin(), casters.end(), [](auto f) { return f >= 7 && f <= 12; }));
}

TEST(ShadowFixtures, SeveralLightsAreSolvedEachOnItsOwn) {
  const auto meshes = load(fixture("box_on_ground.off"));
  const std::vector<Light> lights{sun(1, 2, -4), sun(0, 0, -1), sun(1, 0, 0)};
  const ShadowResult r = cast_shadows(meshes, lights);
  EXPECT_EQ(r.face_lit_area2[0][0][0], hidden_line::ShadowFT(786));
  EXPECT_EQ(r.face_lit_area2[1][0][0], hidden_line::ShadowFT(792));
  EXPECT_EQ(r.face_lit_area2[2][0][0], hidden_line::ShadowFT(0));
  EXPECT_EQ(r.views.size(), 3u);
  const auto errors = check_shadows(meshes, lights, r);
  EXPECT_TRUE(errors.empty()) << joined(errors);
}

TEST(ShadowFixtures, PointLightFacingAndCasters) {
  const auto meshes = load(fixture("box_on_ground.off"));
  const ShadowResult r = cast_shadows(meshes, {bulb(2, -4, 4)});
  auto facing = [&](std::uint32_t face) { return r.sources[r.face_source[0][face]].lights[0].facing; };
  EXPECT_EQ(facing(0), Facing::toward);
  EXPECT_EQ(facing(2), Facing::toward);    // the top
  EXPECT_EQ(facing(3), Facing::toward);    // -y
  EXPECT_EQ(facing(4), Facing::edge_on);   // +x, in whose plane the light is
  EXPECT_EQ(facing(5), Facing::away);      // +y
  EXPECT_EQ(facing(1), Facing::away);      // the bottom
  const auto& ground = r.sources[r.face_source[0][0]].lights[0];
  ASSERT_FALSE(ground.shadow.empty());
  for (const auto& s : ground.shadow)
    for (const auto& [mesh, face] : s.by) EXPECT_TRUE(face == 2 || face == 3) << face;  // the top, -y
  // The light view is the perspective view from the light, looking down (-Z: the box's centre
  // direction has ground corners behind it).
  ASSERT_EQ(r.views.size(), 1u);
  ASSERT_TRUE(r.views[0].view.eye.has_value());
  EXPECT_EQ(r.views[0].view.direction, (Vec3{0, 0, -1}));
}

// A light outside the tetrahedron's slanted face, where only a slanted plane through the light
// has every vertex on one side (none of the box-centre and axis planes): found by the hull search.
// The slanted face is wholly lit (twice its area along z: 100), the others face away.
TEST(ShadowFixtures, PointLightBesideASlantedFace) {
  Mesh tetra;
  tetra.file = "tetra";
  tetra.vertices = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}};
  tetra.faces = {{1, 2, 3}, {0, 2, 1}, {0, 1, 3}, {0, 3, 2}};
  tetra.face_index = {0, 1, 2, 3};
  const std::vector<Mesh> meshes{tetra};
  const Light light = bulb(4, 4, 4);
  const auto view = hidden_line::point_light_view(meshes, light);
  ASSERT_TRUE(view.has_value());
  EXPECT_NE(view->direction[0], 0.0);  // not an axis
  const ShadowResult r = cast_shadows(meshes, {light});
  EXPECT_EQ(r.face_lit_area2[0][0][0], hidden_line::ShadowFT(100));
  for (std::uint32_t f = 1; f < 4; ++f) EXPECT_EQ(r.face_lit_area2[0][0][f], hidden_line::ShadowFT(0)) << f;
  const auto errors = check_shadows(meshes, {light}, r);
  EXPECT_TRUE(errors.empty()) << joined(errors);
  // In the slanted face's plane (x + y + z = 10, beside the face): edge-on, and still outside.
  EXPECT_TRUE(hidden_line::point_light_view(meshes, bulb(6, 6, -2)).has_value());
  // Inside it, or on its face: refused.
  EXPECT_FALSE(hidden_line::point_light_view(meshes, bulb(1, 1, 1)).has_value());
  EXPECT_FALSE(hidden_line::point_light_view(meshes, bulb(2, 3, 5)).has_value());
}

TEST(ShadowFixtures, SunsAndPointLightsTogether) {
  const auto meshes = load(fixture("box_on_ground.off"));
  const std::vector<Light> lights{sun(1, 2, -4), bulb(1, 1, 4), sun(0, 0, -1), bulb(1, -4, 4)};
  const ShadowResult r = cast_shadows(meshes, lights);
  EXPECT_EQ(r.face_lit_area2[0][0][0], hidden_line::ShadowFT(786));
  EXPECT_EQ(r.face_lit_area2[1][0][0], hidden_line::ShadowFT(768));
  EXPECT_EQ(r.face_lit_area2[2][0][0], hidden_line::ShadowFT(792));
  EXPECT_EQ(r.face_lit_area2[3][0][0], hidden_line::ShadowFT(744));
  const auto errors = check_shadows(meshes, lights, r);
  EXPECT_TRUE(errors.empty()) << joined(errors);
}

TEST(ShadowFixtures, UnionOfShadowsOverTheLights) {
  const auto meshes = load(fixture("box_on_ground.off"));
  // Shadows [0, 4] x [0, 2] and [0, 2] x [0, 4] on the ground: union 8 + 8 - 4 = 12.
  hidden_line::ShadowOptions options;
  options.union_shadows = true;
  const ShadowResult r = cast_shadows(meshes, {sun(1, 0, -1), sun(0, 1, -1)}, options);
  EXPECT_EQ(r.face_union_shadow_area2[0][0], hidden_line::ShadowFT(24));
  EXPECT_EQ(r.face_union_shadow_area2[0][2], hidden_line::ShadowFT(0));   // the top: lit under both
  EXPECT_EQ(r.face_union_shadow_area2[0][4], hidden_line::ShadowFT(8));   // +x: away from the first
}

TEST(ShadowFixtures, BadLightsAreRefused) {
  const auto meshes = load(fixture("box_on_ground.off"));
  EXPECT_THROW(cast_shadows(meshes, {sun(0, 0, 0)}), std::invalid_argument);
  EXPECT_THROW(cast_shadows(meshes, {sun(std::nan(""), 0, -1)}), std::invalid_argument);
  EXPECT_THROW(cast_shadows(meshes, {bulb(0, std::numeric_limits<double>::infinity(), 10)}), std::invalid_argument);
  // Point lights that nothing serves: inside the box, on its top face, on the ground (in its
  // plane, among its vertices), on an edge of the box (the scene's box centre); as well in both
  // ways of solving a point light.
  for (const Light& l : {bulb(1, 1, 1), bulb(1, 1, 2), bulb(5, 5, 0), bulb(0, 0, 1)}) {
    SCOPED_TRACE(std::to_string(l.vector[0]) + "," + std::to_string(l.vector[1]) + "," + std::to_string(l.vector[2]));
    EXPECT_TRUE(hidden_line::point_light_defect(meshes, l).has_value());
    EXPECT_THROW(cast_shadows(meshes, {l}), std::invalid_argument);
    hidden_line::ShadowOptions cube;
    cube.point_light_views = hidden_line::PointLightViews::cube;
    EXPECT_THROW(cast_shadows(meshes, {l}, cube), std::invalid_argument);
  }
  EXPECT_NE(hidden_line::point_light_defect(meshes, bulb(1, 1, 1)).value_or("").find("inside a closed solid"), std::string::npos);
  EXPECT_NE(hidden_line::point_light_defect(meshes, bulb(1, 1, 2)).value_or("").find("on face 2 of"), std::string::npos);
  EXPECT_NE(hidden_line::point_light_defect(meshes, bulb(5, 5, 0)).value_or("").find("on face 0 of"), std::string::npos);
  // Outside: above everything, and beside it; among the geometry (the cube): over the ground
  // beside the box, below the box's top.
  EXPECT_FALSE(hidden_line::point_light_defect(meshes, bulb(0, 0, 10)).has_value());
  EXPECT_FALSE(hidden_line::point_light_defect(meshes, bulb(30, 1, 1)).has_value());
  EXPECT_FALSE(hidden_line::point_light_view(meshes, bulb(4, 1, 1)).has_value());
  EXPECT_FALSE(hidden_line::point_light_defect(meshes, bulb(4, 1, 1)).has_value());
  // Between the two boxes and the panel: served; inside box A, on the panel, on B's -x face: not.
  const auto between = load(fixture("light_between_boxes.off"));
  EXPECT_FALSE(hidden_line::point_light_defect(between, bulb(0, 0, 1)).has_value());
  EXPECT_NE(hidden_line::point_light_defect(between, bulb(-2, 0, 1)).value_or("").find("inside a closed solid"), std::string::npos);
  EXPECT_NE(hidden_line::point_light_defect(between, bulb(-0.5, 0.5, 1)).value_or("").find("on face 13 of"), std::string::npos);
  EXPECT_NE(hidden_line::point_light_defect(between, bulb(1, 0, 1)).value_or("").find("on face 12 of"), std::string::npos);
}

// The oracle itself: planted errors are found.
// The result with the ground's last shadow polygon (face 0 of the box fixture) called lit.
ShadowResult ground_shadow_called_lit(ShadowResult r) {
  auto& sl = r.sources[r.face_source[0][0]].lights[0];
  EXPECT_FALSE(sl.shadow.empty());
  if (sl.shadow.empty()) return r;
  sl.lit.push_back(sl.shadow.back().polygon);
  sl.shadow.pop_back();
  return r;
}

// ---------------------------------------------------------------------------------------------
// The raster shadow map (raster_shadows.hpp) against the exact shadows: it converges.

// sum(area |raster fraction - exact fraction|) / sum(area), over the faces with area.
double raster_error(const std::vector<Mesh>& meshes, const ShadowResult& exact,
                    const hidden_line::RasterShadows& raster) {
  double error = 0, area = 0;
  for (std::uint32_t m = 0; m < meshes.size(); ++m)
    for (std::uint32_t f = 0; f < meshes[m].faces.size(); ++f) {
      const double a = exact.face_area[m][f];
      if (!(a > 0)) continue;
      error += a * std::abs(raster.sunlit_fraction[m][f] - exact.face_lit_area[0][m][f] / a);
      area += a;
    }
  return error / area;
}

TEST(RasterShadowMap, ConvergesToTheExactLitAreas) {
  for (const char* file : {"box_on_ground.off", "overhang.off", "two_boxes.off"})
    for (const Light& light : {sun(1, 2, -4), sun(-1, 0.5, -1), bulb(1, -4, 4)}) {
      const auto meshes = load(fixture(file));
      if (hidden_line::point_light_defect(meshes, light)) continue;
      SCOPED_TRACE(std::string(file) + (light.kind == Light::point ? " point light" : " sun"));
      const ShadowResult exact = cast_shadows(meshes, {light});
      const auto coarse = hidden_line::raster_shadows(meshes, light, 64);
      const auto fine = hidden_line::raster_shadows(meshes, light, 512);
      const double e64 = raster_error(meshes, exact, coarse), e512 = raster_error(meshes, exact, fine);
      // The error lies along shadow edges, one pixel wide: 8 times finer pixels, about 8 times less.
      EXPECT_LT(e512, e64 / 3) << e64 << " " << e512;
      EXPECT_LT(e512, 0.004) << e512;
      EXPECT_GT(fine.total_samples, 30 * coarse.total_samples);  // spacing 1/8: 64 times the samples
    }
}

// A closed box wound inward: its front side is the outside, for the map as for cast_shadows.
TEST(RasterShadowMap, TakesTheFrontSideAsTheExactPathDoes) {
  const auto meshes = load(std::string(HLR_SCENE_FIXTURES_DIR) + "/inward_box.off");
  const Light light = sun(1, 2, -4);
  const ShadowResult exact = cast_shadows(meshes, {light});
  EXPECT_LT(raster_error(meshes, exact, hidden_line::raster_shadows(meshes, light, 256)), 1e-9);
}

TEST(RasterShadowMap, FacesTurnedAwayAreDarkAndUnshadowedFacesLit) {
  const auto meshes = load(fixture("box_on_ground.off"));
  for (int n : {16, 100, 1024}) {
    const auto r = hidden_line::raster_shadows(meshes, sun(1, 2, -4), n);
    const auto& f = r.sunlit_fraction[0];
    // bottom, +x, +y face away from the sun: no samples, dark
    for (int face : {1, 4, 5}) {
      EXPECT_EQ(f[face], 0.0) << n << " face " << face;
      EXPECT_EQ(r.samples[0][face], 0u);
    }
    // top, -y, -x: nothing between them and the sun, and the bias keeps them from shadowing
    // themselves (no acne)
    for (int face : {2, 3, 6}) EXPECT_EQ(f[face], 1.0) << n << " face " << face;
    // the ground: 7 of 400 in shadow, up to the pixels along the shadow's outline
    EXPECT_NEAR(f[0], 393.0 / 400, 16.0 * 20 / n / 400) << n;
  }
  EXPECT_THROW(hidden_line::raster_shadows(meshes, sun(1, 2, -4), 15), std::invalid_argument);
  EXPECT_THROW(hidden_line::raster_shadows(meshes, sun(0, 0, 0), 64), std::invalid_argument);
  EXPECT_THROW(hidden_line::raster_shadows(meshes, bulb(1, 1, 1), 64), std::invalid_argument);  // inside the box
}

TEST(ShadowOracle, FindsPlantedErrors) {
  const auto meshes = load(fixture("box_on_ground.off"));
  const std::vector<Light> lights{sun(1, 2, -4)};
  const ShadowResult good = cast_shadows(meshes, lights);
  ASSERT_TRUE(check_shadows(meshes, lights, good).empty());
  EXPECT_FALSE(check_shadows(meshes, lights, ground_shadow_called_lit(good)).empty());
  {  // a lit polygon dropped
    ShadowResult bad = good;
    auto& sl = bad.sources[bad.face_source[0][0]].lights[0];
    sl.lit.pop_back();
    EXPECT_FALSE(check_shadows(meshes, lights, bad).empty());
  }
  {  // the wrong caster
    ShadowResult bad = good;
    for (auto& s : bad.sources[bad.face_source[0][0]].lights[0].shadow) s.by = {{0, 0}};
    EXPECT_FALSE(check_shadows(meshes, lights, bad).empty());
  }
  {  // a point light's shadow called lit, and the light taken for another
    const std::vector<Light> bulbs{bulb(1, -4, 4)};
    const ShadowResult r = cast_shadows(meshes, bulbs);
    ASSERT_TRUE(check_shadows(meshes, bulbs, r).empty());
    EXPECT_FALSE(check_shadows(meshes, {bulb(1, 1, 4)}, r).empty());
    EXPECT_FALSE(check_shadows(meshes, bulbs, ground_shadow_called_lit(r)).empty());
  }
}

// ---------------------------------------------------------------------------------------------
// Every fixture of fixtures/shadows and fixtures/scenes, several suns.

const std::vector<Light>& suns() {
  static const std::vector<Light> lights{sun(1, 2, -4), sun(-1, 0.5, -1), sun(0, 0, -1), sun(3, -1, -1),
                                         sun(-1, -1, -1), sun(0.25, 1, 0)};
  return lights;
}

// Point lights around a scene, all outside it: over its centre, over a corner, beside it at
// mid-height (on a 1/16 grid, so that the numbers stay small).
std::vector<Light> point_lights_around(const std::vector<Mesh>& meshes) {
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& m : meshes)
    for (const auto& p : m.vertices)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  auto grid = [](double v) { return std::round(v * 16) / 16; };
  auto mid = [&](int k) { return grid((lo[k] + hi[k]) / 2); };
  return {bulb(mid(0), mid(1), grid(hi[2] + size)),
          bulb(grid(lo[0] - size / 2), grid(hi[1] + size / 4), grid(hi[2] + size / 3)),
          bulb(grid(hi[0] + size / 2), mid(1) + 0.25, mid(2) + 0.125)};
}

TEST(ShadowFixtures, OracleOnEveryFixture) {
  std::vector<std::string> files;
  for (const char* dir : {HLR_SHADOW_FIXTURES_DIR, HLR_SCENE_FIXTURES_DIR})
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".off") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    SCOPED_TRACE(file);
    const auto meshes = load(file);
    const ShadowResult r = cast_shadows(meshes, suns());
    const auto errors = check_shadows(meshes, suns(), r);
    EXPECT_TRUE(errors.empty()) << joined(errors);
    const std::vector<Light> bulbs = point_lights_around(meshes);
    const ShadowResult rp = cast_shadows(meshes, bulbs);
    const auto point_errors = check_shadows(meshes, bulbs, rp);
    EXPECT_TRUE(point_errors.empty()) << "point lights\n" << joined(point_errors);
  }
}

// The cube of views gives a point light the single view's answer, exactly, where both can serve
// it (the lights around every fixture), and keeps the contract.
TEST(ShadowFixtures, PointLightCubeGivesTheSingleViewsAnswer) {
  std::vector<std::string> files;
  for (const char* dir : {HLR_SHADOW_FIXTURES_DIR, HLR_SCENE_FIXTURES_DIR})
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".off") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  hidden_line::ShadowOptions cube;
  cube.point_light_views = hidden_line::PointLightViews::cube;
  for (const auto& file : files) {
    SCOPED_TRACE(file);
    const auto meshes = load(file);
    std::vector<Light> bulbs = point_lights_around(meshes);
    if (file.ends_with("box_on_ground.off")) bulbs.insert(bulbs.end(), {bulb(1, 1, 4), bulb(1, -4, 4), bulb(2, -4, 4)});
    const ShadowResult single = cast_shadows(meshes, bulbs);
    const ShadowResult six = cast_shadows(meshes, bulbs, cube);
    for (std::size_t k = 0; k < bulbs.size(); ++k) {
      EXPECT_TRUE(single.views[k].pyramids.empty());
      EXPECT_FALSE(six.views[k].pyramids.empty());
      for (std::size_t m = 0; m < meshes.size(); ++m)
        for (std::size_t f = 0; f < meshes[m].faces.size(); ++f)
          EXPECT_EQ(six.face_lit_area2[k][m][f], single.face_lit_area2[k][m][f]) << "light " << k << " face " << f;
    }
    const auto errors = check_shadows(meshes, bulbs, six);
    EXPECT_TRUE(errors.empty()) << joined(errors);
  }
}

// The shared scenes (one test per scene through the filter; skipped without ../shared/scenes).
class ShadowScenes : public ::testing::TestWithParam<std::string> {};
TEST_P(ShadowScenes, Oracle) {
  const std::string path = std::string(HLR_SHARED_SCENES) + "/" + GetParam();
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
  const auto meshes = load(path);
  std::vector<Light> lights{sun(1, 2, -4), sun(-3, 1, -2)};
  lights.push_back(point_lights_around(meshes)[1]);
  const ShadowResult r = cast_shadows(meshes, lights);
  ShadowCheckOptions options;
  options.max_polygons = 2;
  const auto errors = check_shadows(meshes, lights, r, options);
  EXPECT_TRUE(errors.empty()) << joined(errors);
}
std::vector<std::string> scene_names(const char* list_text) {
  std::vector<std::string> out;
  std::stringstream list(list_text);
  for (std::string s; std::getline(list, s, ',');) out.push_back(s);
  return out;
}
std::string scene_test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string n = info.param.substr(0, info.param.find('.'));
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}
INSTANTIATE_TEST_SUITE_P(Shared, ShadowScenes, ::testing::ValuesIn(scene_names(HLR_SHADOW_SCENES)), scene_test_name);
INSTANTIATE_TEST_SUITE_P(SharedSoak, ShadowScenes, ::testing::ValuesIn(scene_names(HLR_SHADOW_SOAK_SCENES)),
                         scene_test_name);

// A shared scene on a ground twice its size, the light beside it at mid-height: among the
// geometry (no plane through the light has the scene on one side), so solved in the cube.
class ShadowScenesAmong : public ::testing::TestWithParam<std::string> {};
TEST_P(ShadowScenesAmong, Oracle) {
  const std::string path = std::string(HLR_SHARED_SCENES) + "/" + GetParam();
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
  std::vector<Mesh> meshes = load(path);
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& p : meshes[0].vertices)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  auto grid = [](double v) { return std::round(v * 16) / 16; };
  Mesh ground;
  ground.file = "ground";
  const double g0 = grid(lo[0] - size), g1 = grid(hi[0] + size), h0 = grid(lo[1] - size), h1 = grid(hi[1] + size);
  ground.vertices = {{g0, h0, lo[2]}, {g1, h0, lo[2]}, {g1, h1, lo[2]}, {g0, h1, lo[2]}};
  ground.faces = {{0, 1, 2, 3}};
  ground.face_index = {0};
  meshes.push_back(ground);
  const Light light = bulb(grid(hi[0] + size / 8), grid((lo[1] + hi[1]) / 2) + 0.0625, grid((lo[2] + hi[2]) / 2) + 0.03125);
  ASSERT_FALSE(hidden_line::point_light_view(meshes, light).has_value());
  ASSERT_FALSE(hidden_line::point_light_defect(meshes, light).has_value());
  const ShadowResult r = cast_shadows(meshes, {light});
  EXPECT_FALSE(r.views[0].pyramids.empty());
  ShadowCheckOptions options;
  options.max_polygons = 2;
  const auto errors = check_shadows(meshes, {light}, r, options);
  EXPECT_TRUE(errors.empty()) << joined(errors);
}
INSTANTIATE_TEST_SUITE_P(Shared, ShadowScenesAmong, ::testing::ValuesIn(scene_names(HLR_SHADOW_SCENES)), scene_test_name);
INSTANTIATE_TEST_SUITE_P(SharedSoak, ShadowScenesAmong, ::testing::ValuesIn(scene_names(HLR_SHADOW_SOAK_SCENES)),
                         scene_test_name);

// ---------------------------------------------------------------------------------------------
// Random grid-snapped boxes on a ground, with a triangle soup, under random rational suns.

Mesh box_mesh(int x0, int y0, int z0, int x1, int y1, int z1) {
  Mesh m;
  m.file = "box";
  m.vertices = {{double(x0), double(y0), double(z0)}, {double(x1), double(y0), double(z0)},
                {double(x1), double(y1), double(z0)}, {double(x0), double(y1), double(z0)},
                {double(x0), double(y0), double(z1)}, {double(x1), double(y0), double(z1)},
                {double(x1), double(y1), double(z1)}, {double(x0), double(y1), double(z1)}};
  m.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (std::uint32_t f = 0; f < 6; ++f) m.face_index.push_back(f);
  return m;
}

std::string scene_text(const std::vector<Mesh>& meshes, const Light& l) {
  std::ostringstream out;
  out << (l.kind == Light::point ? "point light (" : "sun (") << l.vector[0] << ", " << l.vector[1] << ", "
      << l.vector[2] << ")\n";
  for (const auto& m : meshes) out << off_text(m);
  return out.str();
}

// A ground, a few boxes and a triangle soup, all in [-2, 6] x [-2, 6] x [0, 6].
std::vector<Mesh> random_scene() {
  std::vector<Mesh> meshes;
  if (*rc::gen::arbitrary<bool>()) {
    Mesh ground;
    ground.file = "ground";
    ground.vertices = {{-2, -2, 0}, {6, -2, 0}, {6, 6, 0}, {-2, 6, 0}};
    ground.faces = {{0, 1, 2, 3}};
    ground.face_index = {0};
    meshes.push_back(ground);
  }
  const int boxes = *rc::gen::inRange(0, 4);
  for (int b = 0; b < boxes; ++b) {
    const int x0 = *rc::gen::inRange(0, 4), y0 = *rc::gen::inRange(0, 4), z0 = *rc::gen::inRange(0, 2);
    const int x1 = x0 + *rc::gen::inRange(1, 3), y1 = y0 + *rc::gen::inRange(1, 3), z1 = z0 + *rc::gen::inRange(1, 4);
    meshes.push_back(box_mesh(x0, y0, z0, x1, y1, z1));
  }
  if (meshes.empty() || *rc::gen::arbitrary<bool>()) {
    Soup soup;
    const int n = *rc::gen::inRange(1, 7);
    soup.triangles = *rc::gen::container<std::vector<Triangle>>(static_cast<std::size_t>(n), gen_triangle());
    soup.share_vertices = *rc::gen::arbitrary<bool>();
    meshes.push_back(to_mesh(soup));
  }
  return meshes;
}

RC_GTEST_PROP(ShadowProperty, OracleAndAreaIdentity, ()) {
  const std::vector<Mesh> meshes = random_scene();
  const int scale = *rc::gen::element(1, 2, 4, 8);
  auto c = rc::gen::inRange(-6, 7);
  const auto d = *rc::gen::suchThat(rc::gen::tuple(c, c, c), [](const auto& t) {
    return std::get<0>(t) != 0 || std::get<1>(t) != 0 || std::get<2>(t) != 0;
  });
  const Light light = sun(double(std::get<0>(d)) / scale, double(std::get<1>(d)) / scale, double(std::get<2>(d)) / scale);
  RC_TAG(light.vector[2] < 0 ? "sun above" : "sun level or below");
  const ShadowResult r = cast_shadows(meshes, {light});
  const auto errors = check_shadows(meshes, {light}, r);
  if (!errors.empty()) RC_FAIL(joined(errors) + scene_text(meshes, light));
}

// Random rational point lights around the same scenes: those that a single perspective view
// serves (point_light_defect: nothing); the others are discarded.
RC_GTEST_PROP(ShadowProperty, PointLightOracleAndAreaIdentity, ()) {
  const std::vector<Mesh> meshes = random_scene();
  const int scale = *rc::gen::element(1, 2, 4);
  const double x = double(*rc::gen::inRange(-10 * scale, 18 * scale + 1)) / scale;
  const double y = double(*rc::gen::inRange(-10 * scale, 18 * scale + 1)) / scale;
  const double z = double(*rc::gen::inRange(-4 * scale, 16 * scale + 1)) / scale;
  const Light light = bulb(x, y, z);
  RC_PRE(!hidden_line::point_light_defect(meshes, light).has_value());
  RC_TAG(z > 6 ? "light above" : "light beside or below");
  const ShadowResult r = cast_shadows(meshes, {light});
  const auto errors = check_shadows(meshes, {light}, r);
  if (!errors.empty()) RC_FAIL(joined(errors) + scene_text(meshes, light));
}

// Random grid-snapped rational point lights among the boxes (inside the scene's box, where most
// need the cube): those not on a face nor inside a box; the area identity and the oracle hold,
// and where one view serves too, the cube's lit areas are that view's.
RC_GTEST_PROP(ShadowProperty, PointLightAmongTheGeometry, ()) {
  const std::vector<Mesh> meshes = random_scene();
  const int scale = *rc::gen::element(2, 4, 8);
  const double x = double(*rc::gen::inRange(-2 * scale, 6 * scale + 1)) / scale;
  const double y = double(*rc::gen::inRange(-2 * scale, 6 * scale + 1)) / scale;
  const double z = double(*rc::gen::inRange(1, 6 * scale)) / scale;
  const Light light = bulb(x, y, z);
  RC_PRE(!hidden_line::point_light_defect(meshes, light).has_value());
  const bool one_view = hidden_line::point_light_view(meshes, light).has_value();
  RC_TAG(one_view ? "one view serves" : "cube only");
  hidden_line::ShadowOptions cube;
  cube.point_light_views = hidden_line::PointLightViews::cube;
  const ShadowResult r = cast_shadows(meshes, {light}, cube);
  const auto errors = check_shadows(meshes, {light}, r);
  if (!errors.empty()) RC_FAIL(joined(errors) + scene_text(meshes, light));
  if (one_view) {
    const ShadowResult single = cast_shadows(meshes, {light});
    for (std::size_t m = 0; m < meshes.size(); ++m)
      for (std::size_t f = 0; f < meshes[m].faces.size(); ++f)
        RC_ASSERT(single.face_lit_area2[0][m][f] == r.face_lit_area2[0][m][f]);
  }
}

}  // namespace
}  // namespace hlr::hltest
