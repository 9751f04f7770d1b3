// Shadows as surface detail of a drawing (draw_lines with DrawOptions::shadow_lights): the drawn
// shadow areas against hand-computed ones on fixtures/shadows.
#include <hlr/export/jobs.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace hlr::exporter {
namespace {

double twice_area(const std::vector<std::array<double, 2>>& c) {
  double sum = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const auto& a = c[i];
    const auto& b = c[(i + 1) % c.size()];
    sum += a[0] * b[1] - b[0] * a[1];
  }
  return sum;
}

double shadow_area(const LineDrawing& d) {
  double sum = 0;
  for (const auto& area : d.shadows) {
    EXPECT_GT(twice_area(area.outer), 0);
    sum += twice_area(area.outer);
    for (const auto& h : area.holes) {
      EXPECT_LT(twice_area(h), 0);
      sum += twice_area(h);
    }
  }
  return sum / 2;
}

Scene box_on_ground() { return load_scene({std::string(HLR_SHADOW_FIXTURES_DIR) + "/box_on_ground.off"}); }

DrawOptions with_sun(Vec3 d) {
  DrawOptions o;
  o.shadow_lights = {{hidden_line::Light::directional, d}};
  return o;
}

TEST(ShadowAreas, TopViewShowsTheGroundShadowBesideTheBox) {
  // Ground shadow 7 (hull of the footprint and its translate (1/2, 1)), of which the box's top
  // hides the footprint (4) from above: 3 drawn; the top is lit, the sides edge-on.
  View top;
  ASSERT_TRUE(named_view("top", top));
  const LineDrawing d = draw_lines(box_on_ground(), top, with_sun({1, 2, -4}));
  EXPECT_NEAR(shadow_area(d), 3, 1e-12);
}

TEST(ShadowAreas, FrontViewShowsTheShadedSides) {
  // From the front (looking along +Y) the -y side (lit by (1, 2, -4)) and the ground edge-on:
  // nothing in shadow. Under (-1, -2, -4) the -y side faces away: its 2 x 2 is drawn shaded.
  View front;
  ASSERT_TRUE(named_view("front", front));
  EXPECT_NEAR(shadow_area(draw_lines(box_on_ground(), front, with_sun({1, 2, -4}))), 0, 1e-12);
  EXPECT_NEAR(shadow_area(draw_lines(box_on_ground(), front, with_sun({-1, 2, -4}))), 0, 1e-12);
  EXPECT_NEAR(shadow_area(draw_lines(box_on_ground(), front, with_sun({-1, -2, -4}))), 4, 1e-12);
}

TEST(ShadowAreas, NoLightNoShadowAndInexactKernelsRefused) {
  View iso;
  ASSERT_TRUE(named_view("iso", iso));
  EXPECT_TRUE(draw_lines(box_on_ground(), iso).shadows.empty());
  DrawOptions epick = with_sun({1, 2, -4});
  epick.kernel = KernelKind::epick;
  EXPECT_THROW(draw_lines(box_on_ground(), iso, epick), std::invalid_argument);
}

}  // namespace
}  // namespace hlr::exporter
