// area_sign against the sign of the exact area, on contours whose corners are doubles (the
// expansion stage) and on constructed corners (the interval and rational stages): random, on a
// small grid (zero areas and collinear corners in most draws) and of mixed magnitude.
#include <hlr/clipper/area_sign.hpp>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using K = hlr::ExactKernel;
using G = hlr::Geometry<K>;
using FT = G::FT;

int exact_sign(const hlr::clip::Contour<K>& c) {
  FT twice = 0;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const auto& p = c.points[i];
    const auto& q = c.points[(i + 1) % c.points.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return static_cast<int>(CGAL::sign(twice.exact()));
}

TEST(AreaSign, AgreesWithTheExactAreaOnDoublesAndConstructedCorners) {
  std::mt19937 random(11);
  const double scales[] = {1.0, 1e-9, 1e9};
  int zero = 0, doubles = 0;
  for (int draw = 0; draw < 3000; ++draw) {
    const int grid = draw % 3 == 0 ? 0 : 2 + draw % 3;  // 0: continuous
    const double scale = scales[draw % 3], far = draw % 5 == 0 ? 1e6 : 0;
    auto coordinate = [&](int axis) {
      const double s = draw % 7 == 0 && axis == 1 ? scales[(draw / 7) % 3] : scale;  // mixed magnitudes
      if (grid == 0) return far + s * std::uniform_real_distribution<double>(-1, 1)(random);
      return far + s * double(std::uniform_int_distribution<int>(0, grid)(random));
    };
    hlr::clip::Contour<K> c;
    const int n = 3 + draw % 5;
    for (int i = 0; i < n; ++i) {
      if (draw % 4 == 3) {  // a constructed corner: the midpoint of two, exact but not a double
        const double x0 = coordinate(0), x1 = coordinate(0), y0 = coordinate(1), y1 = coordinate(1);
        c.points.push_back(G::point((FT(x0) + FT(x1)) / 3, (FT(y0) + FT(y1)) / 3));
      } else {
        c.points.push_back(G::point(coordinate(0), coordinate(1)));
      }
    }
    const int expected = exact_sign(c);
    ASSERT_EQ(hlr::clip::area_sign(c), expected) << "draw " << draw;
    zero += expected == 0;
    doubles += draw % 4 != 3;
  }
  EXPECT_GT(zero, 150);  // the grid draws reach the degenerate cases
  EXPECT_GT(doubles, 2000);
}

}  // namespace
