// White-box property test of the loose grid (hidden_line/src/box_index.hpp), the candidate filter
// of the area sort, line classification and precedence: a query must visit every inserted box
// that overlaps it and was not removed, each once, and no other. Boxes on a coarse grid (touching and equal boxes in
// most draws), points and slivers, far from the origin, and boxes inserted after the domain was
// fixed (the area sort files the pieces of clips, which may stick out of it by rounding).
#include "box_index.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace {

using hlr::hidden_line::detail::LooseGrid;

CGAL::Bbox_2 random_box(double origin, double unit) {
  const int x = *rc::gen::inRange(-40, 41), y = *rc::gen::inRange(-40, 41);
  // Mostly small boxes, some points and slivers, a few as large as the domain.
  const int w = *rc::gen::weightedOneOf<int>({{6, rc::gen::inRange(0, 4)}, {1, rc::gen::inRange(0, 80)}});
  const int h = *rc::gen::weightedOneOf<int>({{6, rc::gen::inRange(0, 4)}, {1, rc::gen::inRange(0, 80)}});
  return CGAL::Bbox_2(origin + x * unit, origin + y * unit, origin + (x + w) * unit, origin + (y + h) * unit);
}

RC_GTEST_PROP(LooseGrid, VisitsExactlyTheOverlappingBoxesOnce, ()) {
  const double origin = *rc::gen::element(0.0, 1e9, -3.5e6, 1e-9);
  const double unit = *rc::gen::element(1.0, 1e-3, 0.1, 1e-9, 7.0);
  const std::size_t n = *rc::gen::inRange<std::size_t>(1, 400);
  std::vector<CGAL::Bbox_2> boxes;
  for (std::size_t i = 0; i < n; ++i) boxes.push_back(random_box(origin, unit));
  // The domain of the first boxes only: the rest are filed later, as the area sort's pieces are.
  const std::size_t first = *rc::gen::inRange<std::size_t>(1, n + 1);
  CGAL::Bbox_2 domain;
  for (std::size_t i = 0; i < first; ++i) domain += boxes[i];
  LooseGrid grid(domain, first);
  for (std::uint32_t i = 0; i < n; ++i) grid.insert(i, boxes[i]);
  // Some taken out again, as the area sort does with the pieces a clip replaces.
  std::vector<char> removed(n, 0);
  for (std::uint32_t i = 0; i < n; ++i)
    if (*rc::gen::inRange(0, 3) == 0) {
      grid.remove(i);
      removed[i] = 1;
    }

  for (int q = 0; q < 20; ++q) {
    const CGAL::Bbox_2 query = random_box(origin, unit);
    std::vector<std::uint32_t> visited, expected;
    grid.query(query, [&](std::uint32_t id) { visited.push_back(id); });
    for (std::uint32_t i = 0; i < n; ++i)
      if (!removed[i] && CGAL::do_overlap(boxes[i], query)) expected.push_back(i);
    std::sort(visited.begin(), visited.end());
    RC_ASSERT(visited == expected);
  }
}

}  // namespace
