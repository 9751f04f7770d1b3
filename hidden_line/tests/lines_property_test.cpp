// Property tests of hidden-line classification, the engine on the exact kernel against the line
// oracle (coverage, visibility over every piece, the feature set, intersection lines sound and
// complete), with a random crease threshold and back faces removed or kept:
//   - random triangle soups (soup_generator.hpp), split at random into one or two meshes, with
//     face groups or not;
//   - random polygon faces: simple grid polygons (tests/support, often non-convex, numbered from a
//     random corner) mapped into 3D by small integer affine maps, as open sheets or extruded into
//     closed prisms (polygon top and bottom, quad sides), one to three per scene, together with a
//     few triangles of a soup.
// A failure prints the meshes as OFF files, the view and the options.
//
// Cases per run come from RC_PARAMS (hidden_line/tests/CMakeLists.txt: a few hundred by default,
// many more under the `soak` label).
#include "line_runs.hpp"
#include "soup_generator.hpp"

#include <polygon_generators.hpp>  // tests/support: random grid polygons

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <sstream>

namespace hlr::hltest {
namespace {

// The faces with part[f] == k, as a mesh of their own (vertices renumbered in order of use).
Mesh part_of(const Mesh& mesh, const std::vector<int>& part, int k) {
  Mesh out;
  out.file = mesh.file + "." + std::to_string(k);
  std::vector<std::int64_t> index(mesh.vertices.size(), -1);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (part[f] != k) continue;
    std::vector<std::uint32_t> face;
    for (std::uint32_t v : mesh.faces[f]) {
      if (index[v] < 0) {
        index[v] = static_cast<std::int64_t>(out.vertices.size());
        out.vertices.push_back(mesh.vertices[v]);
      }
      face.push_back(static_cast<std::uint32_t>(index[v]));
    }
    out.face_index.push_back(static_cast<std::uint32_t>(out.faces.size()));
    out.faces.push_back(face);
    if (!mesh.face_group.empty()) out.face_group.push_back(mesh.face_group[f]);
  }
  out.group_names = mesh.group_names;
  return out;
}

// Runs the engine on the meshes with a random crease threshold and back-face option, checks the
// result with the oracle, and classifies the case.
LineReport run_and_check_random_options(const std::vector<Mesh>& meshes, const View& view) {
  hidden_line::LineOptions options;
  options.features.crease_degrees = *rc::gen::element(30.0, 30.0, 0.0, 45.0, 90.0, 135.0, 180.0);
  const bool remove_back_faces = *rc::gen::arbitrary<bool>();
  // Screen subdivision: none, the default (which these scenes are too small for), or strips of one
  // to three sources, so that nearly every scene is cut.
  hidden_line::AreaSortOptions sort;
  sort.sources_per_strip = *rc::gen::element<std::size_t>(0, 4096, 1, 2, 3);
  // Without hidden pieces (as hlr draw sorts), pieces a convex front covers are dropped unclipped.
  sort.keep_hidden = *rc::gen::arbitrary<bool>();

  std::ostringstream context;
  context << "view " << view_text(view) << ", crease " << options.features.crease_degrees << " degrees, back faces "
          << (remove_back_faces ? "removed" : "kept") << ", " << sort.sources_per_strip << " sources per strip, hidden pieces "
          << (sort.keep_hidden ? "kept" : "dropped") << "\n";
  for (std::size_t m = 0; m < meshes.size(); ++m) context << "mesh " << m << ":\n" << off_text(meshes[m]);

  LineRun run;
  try {
    run = run_lines(meshes, view, options, remove_back_faces, sort);
  } catch (const std::exception& e) {
    RC_FAIL(std::string("exception: ") + e.what() + "\n" + context.str());
  }
  const LineOracle oracle(meshes, view);
  LineReport report = check_lines(oracle, run.set, check_options_for(options));
  if (!report.ok()) RC_FAIL(report.summary() + "\n" + context.str());
  const auto& by_kind = run.set.stats.by_kind;
  RC_CLASSIFY(by_kind[static_cast<int>(FeatureKind::intersection)] > 0, "intersection lines");
  RC_CLASSIFY(by_kind[static_cast<int>(FeatureKind::silhouette)] > 0, "silhouettes");
  RC_CLASSIFY(run.set.stats.hidden_pieces > 0, "hidden pieces");
  return report;
}

RC_GTEST_PROP(LinesProperty, TriangleSoupsSatisfyTheContract, ()) {
  const Soup soup = random_soup();
  Mesh mesh = to_mesh(soup);
  if (*rc::gen::inRange(0, 3) == 0) {
    mesh.group_names = {"a", "b"};
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) mesh.face_group.push_back(*rc::gen::inRange(0, 2));
  }
  std::vector<Mesh> meshes;
  if (*rc::gen::arbitrary<bool>()) {
    meshes.push_back(mesh);
  } else {
    std::vector<int> part;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) part.push_back(*rc::gen::inRange(0, 2));
    for (int k = 0; k < 2; ++k) {
      Mesh m = part_of(mesh, part, k);
      if (!m.faces.empty()) meshes.push_back(std::move(m));
    }
  }
  const LineReport report = run_and_check_random_options(meshes, soup.view);
  RC_CLASSIFY(report.notes.count("(b) isolated hidden point in a visible piece") > 0, "isolated hidden point");
}

// The same in perspective: eyes near and inside the soup, faces cut by the near plane.
RC_GTEST_PROP(LinesProperty, PerspectiveSoupsSatisfyTheContract, ()) {
  Soup soup = random_soup();
  soup.view = *gen_perspective_view();
  const std::vector<Mesh> meshes{to_mesh(soup)};
  RC_PRE(!perspective_defect(meshes, soup.view));
  run_and_check_random_options(meshes, soup.view);
}

// The oracle catches errors planted in a correct LineSet of a random soup: a piece flipped, a
// split point moved halfway to a neighbouring one, an edge dropped, an edge given another kind.
RC_GTEST_PROP(LinesProperty, PlantedErrorsAreCaught, ()) {
  const Soup soup = random_soup();
  const std::vector<Mesh> meshes{to_mesh(soup)};
  const LineRun run = run_lines(meshes, soup.view);
  const LineOracle oracle(meshes, soup.view);
  RC_PRE(check_lines(oracle, run.set, {}).ok());  // a wrong LineSet is the other properties' business
  const auto& lines = run.set.lines;
  std::vector<std::size_t> with_pieces, split, edges;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (!lines[i].pieces.empty()) with_pieces.push_back(i);
    if (lines[i].pieces.size() > 1) split.push_back(i);
    if (lines[i].kind != FeatureKind::intersection) edges.push_back(i);
  }
  auto pick = [](const std::vector<std::size_t>& v) { return v[static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, v.size()))]; };
  hidden_line::LineSet<ExactKernel> bad = run.set;
  std::string what;
  const int mutation = *rc::gen::inRange(0, 4);
  if (mutation == 0) {
    RC_PRE(!with_pieces.empty());
    auto& l = bad.lines[pick(with_pieces)];
    auto& p = l.pieces[*rc::gen::inRange<std::size_t>(0, l.pieces.size())];
    p.visible = !p.visible;
    what = "a piece flipped";
  } else if (mutation == 1) {
    RC_PRE(!split.empty());
    auto& l = bad.lines[pick(split)];
    const std::size_t k = *rc::gen::inRange<std::size_t>(1, l.pieces.size());
    const FT old = l.pieces[k].t0;
    const FT t = *rc::gen::arbitrary<bool>() ? (old + l.pieces[k - 1].t0) / 2 : (old + l.pieces[k].t1) / 2;
    l.pieces[k - 1].t1 = t;
    l.pieces[k].t0 = t;
    what = "a split point moved";
  } else if (mutation == 2) {
    RC_PRE(!edges.empty());
    bad.lines.erase(bad.lines.begin() + static_cast<std::ptrdiff_t>(pick(edges)));
    what = "an edge dropped";
  } else {
    RC_PRE(!edges.empty());
    auto& l = bad.lines[pick(edges)];
    const FeatureKind kinds[] = {FeatureKind::silhouette, FeatureKind::crease, FeatureKind::boundary, FeatureKind::group};
    FeatureKind k = l.kind;
    while (k == l.kind) k = kinds[*rc::gen::inRange(0, 4)];
    l.kind = k;
    what = "a kind changed";
  }
  RC_TAG(what);
  const LineReport report = check_lines(oracle, bad, {});
  if (report.ok()) RC_FAIL(what + " went unnoticed\nview " + view_text(soup.view) + "\n" + off_text(meshes[0]));
}

// A simple grid polygon mapped into 3D by p -> o + x u + y v, as a sheet (one face) or extruded
// along w into a closed, outward-oriented prism.
Mesh random_polygon_mesh(std::uint64_t seed, bool prism) {
  testing::Rng rng(seed);
  testing::RawContour c = testing::random_grid_polygon(rng, 4, 8, false).outer;
  if (testing::twice_signed_area(c) < 0) std::reverse(c.begin(), c.end());
  std::rotate(c.begin(), c.begin() + testing::uniform_int(rng, 0, static_cast<int>(c.size()) - 1), c.end());
  using V = std::array<long, 3>;
  auto small = [&] { return V{testing::uniform_int(rng, -1, 1), testing::uniform_int(rng, -1, 1), testing::uniform_int(rng, -1, 1)}; };
  auto axis = [&] {
    V a{0, 0, 0};
    a[static_cast<std::size_t>(testing::uniform_int(rng, 0, 2))] = testing::uniform_int(rng, 0, 1) ? 1 : -1;
    return a;
  };
  auto det = [](const V& a, const V& b, const V& c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  };
  V u, v, w;
  do {
    // Mostly axis-aligned (the degenerate views of CAD parts), sometimes skew.
    u = testing::uniform_int(rng, 0, 2) ? axis() : small();
    v = testing::uniform_int(rng, 0, 2) ? axis() : small();
    w = testing::uniform_int(rng, 0, 2) ? axis() : small();
  } while (det(u, v, w) == 0);
  const V o{testing::uniform_int(rng, -2, 2), testing::uniform_int(rng, -2, 2), testing::uniform_int(rng, -2, 2)};
  const long h = testing::uniform_int(rng, 1, 3);
  Mesh mesh;
  mesh.file = prism ? "prism" : "sheet";
  auto add = [&](double x, double y, long k) {
    std::array<double, 3> p;
    for (int i = 0; i < 3; ++i) p[i] = double(o[i]) + x * double(u[i]) + y * double(v[i]) + double(k * w[i]);
    mesh.vertices.push_back(p);
  };
  const auto n = static_cast<std::uint32_t>(c.size());
  for (const auto& p : c) add(p[0], p[1], 0);
  std::vector<std::uint32_t> bottom, top;
  for (std::uint32_t i = 0; i < n; ++i) bottom.push_back(i);
  mesh.faces.push_back(bottom);
  if (prism) {
    for (const auto& p : c) add(p[0], p[1], h);
    for (std::uint32_t i = 0; i < n; ++i) top.push_back(n + i);
    // Outward: with det(u, v, w) > 0 the top runs counter-clockwise seen from outside.
    std::reverse(mesh.faces[0].begin(), mesh.faces[0].end());
    mesh.faces.push_back(top);
    for (std::uint32_t i = 0; i < n; ++i) mesh.faces.push_back({i, (i + 1) % n, (i + 1) % n + n, i + n});
    if (det(u, v, w) < 0)
      for (auto& f : mesh.faces) std::reverse(f.begin(), f.end());
  }
  for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) mesh.face_index.push_back(f);
  return mesh;
}

RC_GTEST_PROP(LinesProperty, PolygonFacesAndPrismsSatisfyTheContract, ()) {
  std::vector<Mesh> meshes;
  const int count = *rc::gen::inRange(1, 4);
  for (int k = 0; k < count; ++k)
    meshes.push_back(random_polygon_mesh(*rc::gen::arbitrary<std::uint64_t>(), *rc::gen::inRange(0, 3) != 0));
  Soup soup = random_soup();
  soup.triangles.resize(static_cast<std::size_t>(*rc::gen::inRange(0, 4)));
  if (!soup.triangles.empty()) meshes.push_back(to_mesh(soup));
  run_and_check_random_options(meshes, soup.view);
}

}  // namespace
}  // namespace hlr::hltest
