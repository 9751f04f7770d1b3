// White-box property tests of the candidate filters of hidden_line/src/box_index.hpp.
// - The loose grid (area sort, line classification, precedence): a query must visit every inserted
//   box that overlaps it and was not removed, each once, and no other.
// - overlapping_box_pairs (the penetration search, precedence's line keys): every overlapping
//   pair of a set once, and no other, on one thread and on two.
// Boxes on a coarse grid (touching and equal boxes in most draws), points and slivers, far from
// the origin, and for the grid boxes inserted after the domain was fixed (the area sort files the
// pieces of clips, which may stick out of it by rounding).
#include "box_index.hpp"

#include <CGAL/Bbox_3.h>
#include <CGAL/box_intersection_d.h>
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <numeric>
#include <random>
#include <utility>
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

  // Frozen, the same grid visits the same ids in the same order.
  LooseGrid frozen = grid;
  frozen.freeze();

  for (int q = 0; q < 20; ++q) {
    const CGAL::Bbox_2 query = random_box(origin, unit);
    std::vector<std::uint32_t> visited, visited_frozen, expected;
    grid.query(query, [&](std::uint32_t id) { visited.push_back(id); });
    frozen.query(query, [&](std::uint32_t id) { visited_frozen.push_back(id); });
    RC_ASSERT(visited_frozen == visited);
    for (std::uint32_t i = 0; i < n; ++i)
      if (!removed[i] && CGAL::do_overlap(boxes[i], query)) expected.push_back(i);
    std::sort(visited.begin(), visited.end());
    RC_ASSERT(visited == expected);
  }
  RC_ASSERT_THROWS_AS(frozen.insert(0, boxes[0]), std::logic_error);
}

// Filed at once (the line classification's covers), on one thread and on two, a grid visits the
// ids in the order the grid made by inserting them one by one and freezing does.
RC_GTEST_PROP(LooseGrid, FiledAtOnceIsTheGridInsertedInTurn, ()) {
  const double origin = *rc::gen::element(0.0, 1e9, -3.5e6, 1e-9);
  const double unit = *rc::gen::element(1.0, 1e-3, 0.1, 1e-9, 7.0);
  // Above parallel_chunks' grain at times, so that two threads file the boxes.
  const std::size_t n = *rc::gen::weightedOneOf<std::size_t>({{3, rc::gen::inRange<std::size_t>(0, 300)},
                                                              {1, rc::gen::inRange<std::size_t>(4000, 9000)}});
  std::vector<CGAL::Bbox_2> boxes;
  CGAL::Bbox_2 domain;
  for (std::size_t i = 0; i < n; ++i) domain += boxes.emplace_back(random_box(origin, unit));
  LooseGrid inserted(domain, n);
  for (std::uint32_t i = 0; i < n; ++i) inserted.insert(i, boxes[i]);
  inserted.freeze();
  const int threads = *rc::gen::inRange(1, 3);
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const LooseGrid filed(domain, boxes);
  for (int q = 0; q < 20; ++q) {
    const CGAL::Bbox_2 query = random_box(origin, unit);
    std::vector<std::uint32_t> visited, visited_filed;
    inserted.query(query, [&](std::uint32_t id) { visited.push_back(id); });
    filed.query(query, [&](std::uint32_t id) { visited_filed.push_back(id); });
    RC_ASSERT(visited_filed == visited);
  }
  for (std::uint32_t i = 0; i < n; ++i) RC_ASSERT(filed.box(i) == boxes[i]);
}

// A 3D box as the penetration search makes them: mostly small, some flat (faces square to an
// axis), points, and long slivers across much of the scene (which the pair search sweeps apart).
CGAL::Bbox_3 random_box_3(double origin, double unit) {
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    const int at = *rc::gen::inRange(-30, 31);
    const int extent = *rc::gen::weightedOneOf<int>({{8, rc::gen::inRange(0, 4)}, {1, rc::gen::inRange(0, 61)}});
    lo[k] = origin + at * unit, hi[k] = origin + (at + extent) * unit;
  }
  return CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
}

using Box3 = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t>;

// The overlapping pairs (i < j, sorted) by a plain sweep along x: each box against those that
// begin before it ends.
std::vector<std::pair<std::uint32_t, std::uint32_t>> overlapping_pairs(const std::vector<Box3>& boxes) {
  auto overlap = [](const Box3& x, const Box3& y) {
    for (int k = 0; k < 3; ++k)
      if (x.max_coord(k) < y.min_coord(k) || y.max_coord(k) < x.min_coord(k)) return false;
    return true;
  };
  const std::size_t n = boxes.size();
  std::vector<std::uint32_t> by_x(n);
  std::iota(by_x.begin(), by_x.end(), 0u);
  std::sort(by_x.begin(), by_x.end(), [&](std::uint32_t a, std::uint32_t b) { return boxes[a].min_coord(0) < boxes[b].min_coord(0); });
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t l = k + 1; l < n && boxes[by_x[l]].min_coord(0) <= boxes[by_x[k]].max_coord(0); ++l)
      if (overlap(boxes[by_x[k]], boxes[by_x[l]])) pairs.emplace_back(std::min(by_x[k], by_x[l]), std::max(by_x[k], by_x[l]));
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// The pairs overlapping_box_pairs visits (i < j, sorted), on `threads` threads.
std::vector<std::pair<std::uint32_t, std::uint32_t>> visited_pairs(const std::vector<Box3>& boxes, int axis, int threads) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> visited;
  std::mutex mutex;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    hlr::hidden_line::detail::overlapping_box_pairs(boxes, axis, [&](const Box3& x, const Box3& y) {
      const std::lock_guard lock(mutex);
      visited.emplace_back(std::min(x.info(), y.info()), std::max(x.info(), y.info()));
    });
  }
  std::sort(visited.begin(), visited.end());
  return visited;
}

RC_GTEST_PROP(OverlappingBoxPairs, VisitsEveryOverlappingPairOnce, ()) {
  using Box = Box3;
  const double origin = *rc::gen::element(0.0, 1e9, -3.5e6, 1e-9);
  const double unit = *rc::gen::element(1.0, 1e-3, 0.1, 1e-9, 7.0);
  // Past 4,096 boxes the columns are searched on several threads (past 16,384 the set-up too:
  // OverlappingBoxPairs.ManyBoxesOnOneAndTwoThreads).
  const std::size_t n = *rc::gen::weightedOneOf<std::size_t>({{6, rc::gen::inRange<std::size_t>(0, 300)},
                                                              {1, rc::gen::inRange<std::size_t>(4096, 5000)}});
  const int axis = *rc::gen::inRange(0, 3);
  const int threads = *rc::gen::inRange(1, 3);
  std::vector<Box> boxes;
  for (std::uint32_t i = 0; i < n; ++i) boxes.emplace_back(random_box_3(origin, unit), i);
  // All of them in one plane now and then: every extent along one axis 0.
  if (n > 0 && *rc::gen::inRange(0, 8) == 0)
    for (Box& b : boxes) {
      double lo[3] = {b.min_coord(0), b.min_coord(1), b.min_coord(2)}, hi[3] = {b.max_coord(0), b.max_coord(1), b.max_coord(2)};
      hi[axis] = lo[axis] = origin;
      b = Box(lo, hi, b.info());
    }

  RC_ASSERT(visited_pairs(boxes, axis, threads) == overlapping_pairs(boxes));
}

// Past 16,384 boxes the boxes are listed, sorted and put in columns on several threads too. Drawn
// with a plain generator (rapidcheck's cost per draw is too high for this many), as the property
// above draws them: small boxes on a grid, some flat, some long slivers.
TEST(OverlappingBoxPairs, ManyBoxesOnOneAndTwoThreads) {
  std::mt19937 random(27);
  for (const double origin : {0.0, -3.5e6}) {
    std::vector<Box3> boxes;
    for (std::uint32_t i = 0; i < 20000; ++i) {
      double lo[3], hi[3];
      for (int k = 0; k < 3; ++k) {
        const int at = int(random() % 61) - 30;
        const int extent = random() % 9 == 0 ? int(random() % 61) : int(random() % 4);
        lo[k] = origin + at * 0.1, hi[k] = origin + (at + extent) * 0.1;
      }
      boxes.emplace_back(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), i);
    }
    const auto expected = overlapping_pairs(boxes);
    for (const int threads : {1, 2})
      for (const int axis : {0, 2}) {
        EXPECT_TRUE(visited_pairs(boxes, axis, threads) == expected)
            << threads << " threads, axis " << axis << ", origin " << origin;
      }
  }
}

// resize_in_parallel (hlr/hidden_line/parallel.hpp) gives what resize gives: the elements kept,
// the new ones value-initialized (default member initializers too), on one thread or two, from
// empty and from a vector with elements, across the chunks it writes the new room in.
TEST(ResizeInParallel, SameAsResize) {
  struct Item {
    double x = 1.5;
    std::uint32_t id = 7;
    bool operator==(const Item&) const = default;
  };
  for (const int threads : {1, 2})
    for (const std::size_t from : {std::size_t(0), std::size_t(3), std::size_t(100000)})
      for (const std::size_t to : {std::size_t(0), std::size_t(2), std::size_t(70000), std::size_t(300001)}) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        std::vector<Item> items(from, Item{2.5, 9}), expected = items;
        std::vector<double> numbers(from, 4.0), expected_numbers = numbers;
        hlr::hidden_line::resize_in_parallel(items, to);
        hlr::hidden_line::resize_in_parallel(numbers, to);
        expected.resize(to);
        expected_numbers.resize(to);
        EXPECT_TRUE(items == expected) << threads << " threads, " << from << " to " << to;
        EXPECT_TRUE(numbers == expected_numbers) << threads << " threads, " << from << " to " << to;
      }
}

}  // namespace
