// Tests of the fuzzy culling (fuzzy_cull.hpp), checked exactly: every culled face has no visible
// polygon in the exact solution without culling (faces unconsolidated, so that each source is one
// face), from every eye of the group and from random eyes inside the group's box; and the exact
// visible area of each view is the same with the culled sources left out. Boxes peeking past a
// wall by a sliver, seen from one eye only, test the culler where an unsafe rounding would show.
#include <hlr/hidden_line/fuzzy_cull.hpp>
#include <hlr/hidden_line/jobs.hpp>
#include <hlr/kernel/near_plane.hpp>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace hlr;
using hidden_line::fuzzy_cull;
using K = ExactKernel;

struct Box3 {
  double x0, y0, z0, x1, y1, z1;
};

// Closed boxes with outward quads (corner c has bits x, y, z), one mesh.
Mesh boxes_mesh(const std::vector<Box3>& boxes, bool inward = false) {
  Mesh mesh;
  mesh.file = "boxes";
  for (const Box3& b : boxes) {
    const std::uint32_t o = std::uint32_t(mesh.vertices.size());
    for (int c = 0; c < 8; ++c) mesh.vertices.push_back({c & 1 ? b.x1 : b.x0, c & 2 ? b.y1 : b.y0, c & 4 ? b.z1 : b.z0});
    const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
      std::vector<std::uint32_t> face{o + q[0], o + q[1], o + q[2], o + q[3]};
      if (inward) std::reverse(face.begin(), face.end());
      mesh.face_index.push_back(std::uint32_t(mesh.faces.size()));
      mesh.faces.push_back(face);
    }
  }
  return mesh;
}

View eye_view(const Vec3& eye, const Vec3& target) {
  View v;
  v.name = "custom";
  v.eye = eye;
  v.direction = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
  v.up = {0, 0, 1};
  return v;
}

// The faces that have a visible polygon in the exact solution of `view` without culling.
std::vector<std::vector<bool>> seen_faces(const Scene& scene, const View& view) {
  hidden_line::SolveOptions options;
  options.sources.consolidate = false;
  options.sort.keep_hidden = false;
  const auto solution = hidden_line::solve_view<K>(scene, view, options);
  std::vector<std::vector<bool>> seen(scene.meshes.size());
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) seen[m].assign(scene.meshes[m].faces.size(), false);
  for (const auto& frag : solution.map.visible) {
    const auto& source = solution.sources.polygons[frag.source];
    for (std::uint32_t f : source.faces) seen[source.mesh][f] = true;
  }
  return seen;
}

// The exact visible area of a view, with or without the culled sources.
K::FT visible_area(const Scene& scene, const View& view, const std::vector<std::vector<bool>>* culled) {
  const ViewFrame<K> frame(view, scene.meshes);
  hidden_line::SourceOptions options;
  options.culled = culled;
  auto sources = hidden_line::build_sources<K>(scene.meshes, frame, options);
  const auto map = hidden_line::area_sort<K>(sources, {.keep_hidden = false});
  K::FT area = 0;
  for (const auto& frag : map.visible) {
    area += clip::twice_signed_area<K>(frag.polygon.outer);
    for (const auto& h : frag.polygon.holes) area += clip::twice_signed_area<K>(h);
  }
  return area;
}

Scene scene_of(std::vector<Mesh> meshes) {
  Scene scene;
  scene.meshes = std::move(meshes);
  for (const Mesh& m : scene.meshes) {
    scene.input.faces += m.faces.size();
    scene.input.vertices += m.vertices.size();
  }
  return scene;
}

// Every culled face unseen from each view and from `extra` random eyes in the views' eye box, and
// the same visible area with and without culling; returns the number of faces culled.
std::size_t check_conservative(const Scene& scene, const std::vector<View>& views, const Vec3& target, int extra,
                               std::uint32_t seed) {
  const auto cull = fuzzy_cull(scene.meshes, views);
  std::vector<View> checks = views;
  Vec3 lo = *views.front().eye, hi = lo;
  for (const View& v : views)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], (*v.eye)[k]), hi[k] = std::max(hi[k], (*v.eye)[k]);
  std::mt19937 rng(seed);
  for (int i = 0; i < extra; ++i) {
    Vec3 e;
    for (int k = 0; k < 3; ++k) e[k] = std::uniform_real_distribution<double>(lo[k], hi[k])(rng);
    checks.push_back(eye_view(e, target));
    if (perspective_defect(scene.meshes, checks.back())) checks.pop_back();
  }
  for (const View& view : checks) {
    const auto seen = seen_faces(scene, view);
    for (std::size_t m = 0; m < seen.size(); ++m)
      for (std::size_t f = 0; f < seen[m].size(); ++f)
        if (cull.culled[m][f] && seen[m][f]) {
          ADD_FAILURE() << "face " << f << " of mesh " << m << " culled but seen from " << (*view.eye)[0] << ","
                        << (*view.eye)[1] << "," << (*view.eye)[2];
          return cull.culled_faces;
        }
  }
  for (const View& view : views) EXPECT_EQ(visible_area(scene, view, &cull.culled), visible_area(scene, view, nullptr));
  return cull.culled_faces;
}

const Vec3 kTarget{0, 0, 2};

std::vector<View> eye_group(const Vec3& centre, double size, const Vec3& target = kTarget) {
  std::vector<View> views;
  const double offsets[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0.5}, {0.5, 0.5, 1}, {1, 1, -0.5}};
  for (const auto& o : offsets)
    views.push_back(eye_view({centre[0] + o[0] * size, centre[1] + o[1] * size, centre[2] + o[2] * size}, target));
  return views;
}

TEST(FuzzyCull, BoxesBehindAWallAreCulled) {
  // A wall, three boxes behind it, one beside it.
  const Scene scene = scene_of({boxes_mesh({{-5, 0, 0, 5, 0.2, 5}, {-1, 2, 0.5, 0, 3, 1.5}, {1, 2.5, 1, 2, 3.5, 2},
                                             {-3, 4, 0, -2, 5, 3}, {7, 1, 0, 8, 2, 1}})});
  const std::size_t culled = check_conservative(scene, eye_group({0, -10, 2}, 0.2), kTarget, 4, 1);
  // The three boxes behind: 18 faces.
  EXPECT_GE(culled, 18u);
  // The box beside the wall is seen: none of its faces towards the eyes is culled.
  const auto cull = fuzzy_cull(scene.meshes, eye_group({0, -10, 2}, 0.2));
  EXPECT_FALSE(cull.culled[0][26]);  // its y = 1 face
  // A larger box of eyes sees round the wall's ends less surely: it culls no more.
  const auto wide = fuzzy_cull(scene.meshes, eye_group({0, -10, 2}, 3));
  EXPECT_LE(wide.culled_faces, cull.culled_faces);
}

TEST(FuzzyCull, InsideARoomEveryWallTakesPart) {
  // A room without a ceiling (open: its faces face in, and every view keeps them) with a box in
  // it and a box outside, behind its far wall.
  Mesh room = boxes_mesh({{-6, -12, -1, 6, 6, 8}}, true);
  room.faces.erase(room.faces.begin() + 1);
  room.face_index.pop_back();
  Mesh stuff = boxes_mesh({{-1, -2, 0, 1, -1, 1}, {-1, 8, 0, 1, 9, 1}});
  const Scene scene = scene_of({room, stuff});
  const std::size_t culled = check_conservative(scene, eye_group({0, -10, 2}, 0.3), kTarget, 4, 2);
  EXPECT_GE(culled, 6u);  // the box outside the room
}

TEST(FuzzyCull, NothingIsCulledWithoutOccluders) {
  const Scene scene = scene_of({boxes_mesh({{-1, 2, 0.5, 0, 3, 1.5}, {1, 5, 1, 2, 6, 2}})});
  const auto cull = fuzzy_cull(scene.meshes, eye_group({0, -10, 2}, 0.2));
  // Back faces of the closed boxes are behind their front faces and may go; no front face does.
  for (std::size_t f : {2u, 8u}) EXPECT_FALSE(cull.culled[0][f]) << f;  // the y = y0 faces, towards the eyes
  check_conservative(scene, eye_group({0, -10, 2}, 0.2), kTarget, 2, 3);
}

// Random boxes and triangles in front of and behind random walls, seen from a random small box of
// eyes: whatever is culled is unseen from each of them.

// Orthographic views (a sun study's light views): the viewpoints are directions.
View direction_view(const Vec3& d) {
  View v;
  v.name = "custom";
  v.direction = d;
  v.up = d[0] == 0 && d[1] == 0 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  return v;
}

// As check_conservative, for a group of directions: every culled face unseen along each of them
// and along `extra` random directions between them (convex combinations, inside the group's box of
// ratios), and the same visible area with and without culling.
std::size_t check_conservative_directions(const Scene& scene, const std::vector<View>& views, int extra,
                                          std::uint32_t seed) {
  const auto cull = fuzzy_cull(scene.meshes, views);
  std::vector<View> checks = views;
  std::mt19937 rng(seed);
  for (int i = 0; i < extra; ++i) {
    Vec3 d{0, 0, 0};
    double total = 0;
    std::vector<double> w;
    for (std::size_t k = 0; k < views.size(); ++k) w.push_back(std::uniform_real_distribution<double>(0, 1)(rng)), total += w.back();
    for (std::size_t k = 0; k < views.size(); ++k)
      for (int c = 0; c < 3; ++c) d[c] += w[k] / total * views[k].direction[c] / std::abs(views[k].direction[2]);
    checks.push_back(direction_view(d));
  }
  for (const View& view : checks) {
    const auto seen = seen_faces(scene, view);
    for (std::size_t m = 0; m < seen.size(); ++m)
      for (std::size_t f = 0; f < seen[m].size(); ++f)
        if (cull.culled[m][f] && seen[m][f]) {
          ADD_FAILURE() << "face " << f << " of mesh " << m << " culled but seen along " << view.direction[0] << ","
                        << view.direction[1] << "," << view.direction[2];
          return cull.culled_faces;
        }
  }
  for (const View& view : views) EXPECT_EQ(visible_area(scene, view, &cull.culled), visible_area(scene, view, nullptr));
  return cull.culled_faces;
}

TEST(FuzzyCull, UnderARoofAlongAGroupOfDirections) {
  // A roof slab over two boxes, lit from above at a slant: the boxes are culled, the ground around
  // them and the roof are not.
  const Scene scene = scene_of({boxes_mesh({{-10, -10, -1, 10, 10, 0}, {-4, -4, 4, 4, 4, 4.5}, {-1, -1, 0, 0, 0, 1}, {1, 0, 0, 2, 1, 2}})});
  std::vector<View> views;
  for (const Vec3& d : {Vec3{0.2, 0.1, -1}, Vec3{0.25, 0.05, -1}, Vec3{0.3, 0, -1}}) views.push_back(direction_view(d));
  const std::size_t culled = check_conservative_directions(scene, views, 4, 3);
  const auto cull = fuzzy_cull(scene.meshes, views);
  for (int f = 0; f < 12; ++f) EXPECT_FALSE(cull.culled[0][f]) << f;  // the ground slab and the roof
  for (int f = 12; f < 24; ++f) EXPECT_TRUE(cull.culled[0][f]) << f;  // the boxes under it
  EXPECT_EQ(culled, 12u);
  // Directions that do not run one way along any axis share no cube face: nothing is culled.
  const auto none = fuzzy_cull(scene.meshes, {direction_view({1, 0, -1}), direction_view({-1, 0, 1})});
  EXPECT_EQ(none.culled_faces, 0u);
}

RC_GTEST_PROP(FuzzyCullProperty, CulledFacesAreNeverLitAlongTheGroup, ()) {
  // Roofs on the ground, boxes under and beside them, and a group of sun directions.
  std::vector<Box3> boxes{{-12, -12, -1, 12, 12, 0}};
  const int roofs = *rc::gen::inRange(1, 3), objects = *rc::gen::inRange(1, 6);
  for (int i = 0; i < roofs; ++i) {
    const double x = *rc::gen::inRange(-8, 4), y = *rc::gen::inRange(-8, 4), z = *rc::gen::inRange(2, 6);
    boxes.push_back({x, y, z, x + *rc::gen::inRange(2, 8), y + *rc::gen::inRange(2, 8), z + 0.25});
  }
  for (int i = 0; i < objects; ++i) {
    // Every other one under the first roof (which may or may not hide it).
    const Box3& roof = boxes[1];
    const double x = i % 2 ? *rc::gen::inRange(-8, 8) : roof.x0 + *rc::gen::inRange(0, 8) * (roof.x1 - roof.x0) / 8;
    const double y = i % 2 ? *rc::gen::inRange(-8, 8) : roof.y0 + *rc::gen::inRange(0, 8) * (roof.y1 - roof.y0) / 8;
    const double s = *rc::gen::inRange(1, 4) / 4.0;
    boxes.push_back({x, y, 0, x + s, y + s, *rc::gen::inRange(1, 4) / 2.0});
  }
  const Scene scene = scene_of({boxes_mesh(boxes)});
  const double a = *rc::gen::inRange(-8, 9) / 10.0, b = *rc::gen::inRange(-8, 9) / 10.0;
  const double spread = *rc::gen::element(0.0, 0.05, 0.2, 0.5);
  std::vector<View> views;
  for (const auto& o : {std::array<double, 2>{0, 0}, {1, 0}, {0, 1}, {0.5, 0.5}})
    views.push_back(direction_view({a + o[0] * spread, b + o[1] * spread, -1}));
  const std::size_t culled = check_conservative_directions(scene, views, 2, 5);
  RC_TAG(culled > 0 ? "culls" : "culls nothing");
  RC_ASSERT(!::testing::Test::HasFailure());
}

RC_GTEST_PROP(FuzzyCullProperty, CulledFacesAreNeverSeen, ()) {
  const int walls = *rc::gen::inRange(1, 3);
  const int objects = *rc::gen::inRange(1, 6);
  std::vector<Box3> boxes;
  for (int i = 0; i < walls; ++i) {
    const double y = *rc::gen::inRange(0, 6);
    const double x0 = -*rc::gen::inRange(1, 8), x1 = *rc::gen::inRange(1, 8);
    boxes.push_back({x0, y, 0, x1, y + 0.25, double(*rc::gen::inRange(2, 6))});
  }
  for (int i = 0; i < objects; ++i) {
    const double x = *rc::gen::inRange(-6, 6), y = *rc::gen::inRange(-3, 10), z = *rc::gen::inRange(0, 4);
    const double s = *rc::gen::inRange(1, 4) / 2.0;
    boxes.push_back({x, y, z, x + s, y + s, z + s});
  }
  Mesh mesh = boxes_mesh(boxes);
  // Some loose triangles, open, facing either way.
  Mesh soup;
  soup.file = "soup";
  const int triangles = *rc::gen::inRange(0, 4);
  for (int t = 0; t < triangles; ++t) {
    for (int c = 0; c < 3; ++c)
      soup.vertices.push_back({double(*rc::gen::inRange(-5, 6)), double(*rc::gen::inRange(-2, 10)), double(*rc::gen::inRange(0, 5))});
    const std::uint32_t o = std::uint32_t(soup.vertices.size() - 3);
    const auto& a = soup.vertices[o];
    const auto& b = soup.vertices[o + 1];
    const auto& c = soup.vertices[o + 2];
    const double nx = (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
    const double ny = (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]);
    const double nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if (nx == 0 && ny == 0 && nz == 0) {
      soup.vertices.resize(o);
      continue;
    }
    soup.face_index.push_back(std::uint32_t(soup.faces.size()));
    soup.faces.push_back({o, o + 1, o + 2});
  }
  std::vector<Mesh> meshes{mesh};
  if (!soup.faces.empty()) meshes.push_back(soup);
  const Scene scene = scene_of(meshes);
  const Vec3 centre{double(*rc::gen::inRange(-2, 3)), -12.0 + *rc::gen::inRange(0, 4), 1.0 + *rc::gen::inRange(0, 3)};
  const double size = *rc::gen::element(0.0, 0.1, 0.5, 1.0);
  auto views = eye_group(centre, size);
  for (const View& v : views) RC_PRE(!perspective_defect(scene.meshes, v));
  const std::size_t culled = check_conservative(scene, views, kTarget, 1, 7);
  RC_TAG(culled > 0 ? "culls" : "culls nothing");
  RC_ASSERT(!::testing::Test::HasFailure());
}

// A box behind a wall that one eye of the group sees by a sliver only: past the wall's end or over
// its top, by `peek` beyond the ray from that eye through the wall's outline. The culler must keep
// its faces that the eye sees; a culler that rounds one step the unsafe way (an extent from one eye
// only, a pixel too few) culls them. A second box wholly behind the wall gives it something to cull.
RC_GTEST_PROP(FuzzyCullProperty, BarelyVisibleFacesAreKept, ()) {
  // Eyes close to the wall and boxes far behind it: the parallax across the box of eyes is many
  // pixels of the fuzzy cube, so that an unsafe rounding shows.
  const double wall_y = *rc::gen::inRange(0, 3), height = *rc::gen::inRange(2, 5);
  const double x0 = -*rc::gen::inRange(2, 8), x1 = *rc::gen::inRange(2, 8);
  const Vec3 centre{double(*rc::gen::inRange(-1, 2)), -4.0 + *rc::gen::inRange(0, 3), 1.0 + *rc::gen::inRange(0, 2)};
  const double size = *rc::gen::element(0.1, 0.5, 1.0);
  // Looking along +Y, so that everything behind the wall is in front of every eye.
  const Vec3 target{centre[0], 40, centre[2]};
  const auto views = eye_group(centre, size, target);
  const Vec3 eye = *views[std::size_t(*rc::gen::inRange(0, 5))].eye;
  const double peek = *rc::gen::element(1e-4, 1e-3, 1e-2, 0.1);
  const int side = *rc::gen::inRange(0, 3);  // 0: past the right end, 1: past the left end, 2: over the top
  const double y0 = wall_y + 0.25 + *rc::gen::inRange(1, 40) / 4.0, depth = *rc::gen::inRange(1, 4) / 2.0;
  // Where the rays from the eye through the wall's outline edge (on its near or its far face) are
  // at depth y0: the outermost of the two bounds what the wall hides there.
  auto ray = [&](int k, double outline, double y) { return eye[k] + (outline - eye[k]) * (y0 - eye[1]) / (y - eye[1]); };
  auto outermost = [&](int k, double outline, int sign) {
    return sign * std::max(sign * ray(k, outline, wall_y), sign * ray(k, outline, wall_y + 0.25));
  };
  Box3 peeker{};
  if (side == 0) {
    const double x = outermost(0, x1, 1);
    peeker = {x - 1, y0, 0.5, x + peek, y0 + depth, height - 0.5};
  } else if (side == 1) {
    const double x = outermost(0, x0, -1);
    peeker = {x - peek, y0, 0.5, x + 1, y0 + depth, height - 0.5};
  } else {
    const double z = outermost(2, height, 1);
    peeker = {-1, y0, z - 1, 1, y0 + depth, z + peek};
  }
  const Box3 wall{x0, wall_y, 0, x1, wall_y + 0.25, height};
  const Box3 hidden{-0.5, y0 + depth + 1, 0.5, 0.5, y0 + depth + 2, 1.5};
  const Scene scene = scene_of({boxes_mesh({wall, peeker, hidden})});
  for (const View& v : views) RC_PRE(!perspective_defect(scene.meshes, v));
  // The construction is right: the chosen eye sees the peeking box (its faces 6 to 11).
  const auto seen = seen_faces(scene, eye_view(eye, target));
  RC_ASSERT(std::any_of(seen[0].begin() + 6, seen[0].begin() + 12, [](bool b) { return b; }));
  const std::size_t culled = check_conservative(scene, views, target, 0, 11);
  RC_TAG(culled > 0 ? "culls" : "culls nothing");
  RC_ASSERT(!::testing::Test::HasFailure());
}

}  // namespace
