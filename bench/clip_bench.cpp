// clip_bench: hlr's clipper against CGAL's Boolean set operations (Epeck) and Clipper1.
//
// Two families, registered so that one run compares every method on the same inputs:
//
//   BM_Pair/<method>/<n>/holes:<0|1>
//       A subject and a clip polygon, each a random star of n vertices (same radius, centres
//       slightly offset, so intersection and difference are both non-trivial); with holes:1 each
//       also gets 4 star-shaped holes of max(3, n/8) vertices. One iteration = one pair clipped
//       into both lists, subject ∩ clip and subject − clip.
//   BM_Triangles/<method>/64/holes:<0|1>
//       One 64-vertex star clip polygon against 1,000 small random triangles spread over its
//       bounding box. One iteration = all 1,000 triangles clipped into both lists.
//
// Methods:
//   hlr_exact, hlr_epick, hlr_double   hlr::clip on ExactKernel / EpickKernel / DoubleKernel;
//                                      ClipRegion built inside the timed loop.
//   hlr_exact_prebuilt                 ExactKernel, subject and ClipRegion built once outside the
//                                      loop: only clip_polygon is timed (the area sort's case).
//   cgal                               CGAL::intersection + CGAL::difference of
//                                      Polygon_with_holes_2<Epeck>, polygons built per iteration.
//   cgal_prebuilt                      the same with the CGAL polygons built once, outside.
//   clipper1                           ClipperLib::Clipper, ctIntersection + ctDifference into
//                                      PolyTrees, coordinates scaled by 1e6 and rounded.
//
// Input policy (see docs/BENCHMARKS.md): every method starts from the same oriented double
// coordinates and converts them into its own input type inside the timed loop. This matters for
// Epeck: a lazy-exact point caches its exact value once a filtered predicate has failed on it, so
// reusing one set of points across iterations would let later iterations skip that work. Fresh
// points per iteration treat hlr_exact and cgal alike; the *_prebuilt variants show the other
// policy. Each benchmark cycles over a deterministic pool of input pairs.
//
// Counters (per pair, or per triangle list): verts = input vertices (subject + clip),
// in_polys / out_polys = output polygons, area_in / area_out / out_verts = result areas and output
// vertex count of pool pair 0 (to check that the methods agree), fail = fraction of iterations that threw ClipError (inexact
// kernels only), fail_other = fraction that threw any other exception.
//
// The process exits non-zero when no benchmark matched the filter or when the exact kernel threw,
// so the CTest smoke run catches a broken benchmark.

#include <hlr/clipper/clipper.hpp>
#include <polygon_generators.hpp>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <benchmark/benchmark.h>
#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

using hlr::testing::RawContour;
using hlr::testing::RawPoint;
using hlr::testing::RawPolygon;
using hlr::testing::Rng;

constexpr double kRadius = 100.0;         // star radius, in drawing units
constexpr double kClipperScale = 1e6;     // coordinates up to ~1.2e8 < Clipper1's loRange (2^30)
constexpr int kPoolSize = 8;              // input pairs per benchmark, cycled over iterations
constexpr int kTriangles = 1000;
constexpr int kTriangleClipVertices = 64;
constexpr double kTriangleSize = 4.0;     // triangle "radius": 2% of the clip's bounding box

std::atomic<int> g_unexpected_errors{0};

// ---------------------------------------------------------------------------------------------
// Inputs (doubles), generated once per configuration.

// Outer counter-clockwise, holes clockwise, as hlr, CGAL and Clipper (fill rule aside) expect.
// The generators' contours are far from degenerate, so the double shoelace sign is reliable.
RawPolygon oriented(RawPolygon p) {
  if (hlr::testing::twice_signed_area(p.outer) < 0) std::reverse(p.outer.begin(), p.outer.end());
  for (RawContour& h : p.holes)
    if (hlr::testing::twice_signed_area(h) > 0) std::reverse(h.begin(), h.end());
  return p;
}

std::size_t vertex_count(const RawPolygon& p) {
  std::size_t n = p.outer.size();
  for (const RawContour& h : p.holes) n += h.size();
  return n;
}

int hole_vertices(int n) { return std::max(3, n / 8); }

struct PairInput {
  RawPolygon subject, clip;
};

// Pool entry i of size n: the outer contours depend on (n, i) only, so holes:1 is holes:0 plus
// holes. The clip is centred at (0.15 R, 0.10 R): the centres lie inside each other's kernel disk
// (radius 0.2 R), so ∩ is a large connected piece and − is many slivers between the spikes.
const std::vector<PairInput>& pair_pool(int n, bool holes) {
  static std::map<std::pair<int, bool>, std::vector<PairInput>> cache;
  std::vector<PairInput>& pool = cache[{n, holes}];
  if (pool.empty()) {
    for (int i = 0; i < kPoolSize; ++i) {
      Rng rng(0x9e3779b97f4a7c15ULL ^ (static_cast<std::uint64_t>(n) << 20) ^ static_cast<std::uint64_t>(i));
      RawPolygon s = hlr::testing::random_star(rng, n, kRadius, 0, 0);
      RawPolygon c = hlr::testing::random_star(rng, n, kRadius, 0.15 * kRadius, 0.10 * kRadius);
      if (holes) {
        Rng hole_rng(0xc2b2ae3d27d4eb4fULL ^ (static_cast<std::uint64_t>(n) << 20) ^ static_cast<std::uint64_t>(i));
        s = hlr::testing::with_random_holes(hole_rng, std::move(s), 4, hole_vertices(n));
        c = hlr::testing::with_random_holes(hole_rng, std::move(c), 4, hole_vertices(n));
      }
      pool.push_back({oriented(std::move(s)), oriented(std::move(c))});
    }
  }
  return pool;
}

struct TriangleInput {
  RawPolygon clip;
  std::vector<RawPolygon> triangles;
};

const TriangleInput& triangle_input(bool holes) {
  static std::map<bool, TriangleInput> cache;
  auto it = cache.find(holes);
  if (it != cache.end()) return it->second;
  TriangleInput in;
  Rng rng(0x7269616e676c6573ULL);  // same clip outer and triangles for holes:0 and holes:1
  in.clip = hlr::testing::random_star(rng, kTriangleClipVertices, kRadius, 0, 0);
  double x0 = in.clip.outer[0][0], x1 = x0, y0 = in.clip.outer[0][1], y1 = y0;
  for (const RawPoint& p : in.clip.outer) {
    x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
  }
  std::uniform_real_distribution<double> ux(x0, x1), uy(y0, y1);
  for (int i = 0; i < kTriangles; ++i) {
    double cx = ux(rng), cy = uy(rng);
    in.triangles.push_back(oriented(hlr::testing::random_star(rng, 3, kTriangleSize, cx, cy)));
  }
  if (holes) {
    Rng hole_rng(0x686f6c6573ULL);
    in.clip = hlr::testing::with_random_holes(hole_rng, std::move(in.clip), 4, hole_vertices(kTriangleClipVertices));
  }
  in.clip = oriented(std::move(in.clip));
  return cache.emplace(holes, std::move(in)).first->second;
}

// ---------------------------------------------------------------------------------------------
// Conversions, each timed as part of its method's iteration.

template <class K>
hlr::clip::Contour<K> to_hlr(const RawContour& raw, hlr::clip::LineTable<K>& lines) {
  std::vector<typename hlr::Geometry<K>::Point> points;
  points.reserve(raw.size());
  for (const RawPoint& p : raw) points.push_back(hlr::Geometry<K>::point(p[0], p[1]));
  return hlr::clip::make_contour<K>(std::move(points), lines);
}

template <class K>
hlr::clip::Polygon<K> to_hlr(const RawPolygon& raw, hlr::clip::LineTable<K>& lines) {
  hlr::clip::Polygon<K> polygon;
  polygon.outer = to_hlr<K>(raw.outer, lines);
  polygon.holes.reserve(raw.holes.size());
  for (const RawContour& h : raw.holes) polygon.holes.push_back(to_hlr<K>(h, lines));
  return polygon;
}

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using CgalPolygon = CGAL::Polygon_2<Epeck>;
using CgalPwh = CGAL::Polygon_with_holes_2<Epeck>;

CgalPolygon to_cgal(const RawContour& raw) {
  CgalPolygon polygon;
  polygon.container().reserve(raw.size());
  for (const RawPoint& p : raw) polygon.push_back(Epeck::Point_2(p[0], p[1]));
  return polygon;
}

CgalPwh to_cgal(const RawPolygon& raw) {
  CgalPwh pwh(to_cgal(raw.outer));
  for (const RawContour& h : raw.holes) pwh.add_hole(to_cgal(h));
  return pwh;
}

ClipperLib::Paths to_clipper(const RawPolygon& raw) {
  ClipperLib::Paths paths;
  paths.reserve(1 + raw.holes.size());
  auto add = [&](const RawContour& c) {
    ClipperLib::Path path;
    path.reserve(c.size());
    for (const RawPoint& p : c)
      path.emplace_back(static_cast<ClipperLib::cInt>(std::llround(p[0] * kClipperScale)),
                        static_cast<ClipperLib::cInt>(std::llround(p[1] * kClipperScale)));
    paths.push_back(std::move(path));
  };
  add(raw.outer);
  for (const RawContour& h : raw.holes) add(h);
  return paths;
}

// ---------------------------------------------------------------------------------------------
// Result measures (outside the timed region except for the cheap polygon counts).

template <class K>
double area(const std::vector<hlr::clip::Polygon<K>>& polygons) {
  double a = 0;
  for (const auto& p : polygons) a += hlr::Geometry<K>::to_double(hlr::clip::twice_area<K>(p)) / 2;
  return a;
}

double area(const std::vector<CgalPwh>& polygons) {
  double a = 0;
  for (const CgalPwh& p : polygons) {
    a += CGAL::to_double(p.outer_boundary().area());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) a += CGAL::to_double(h->area());  // negative
  }
  return a;
}

template <class K>
double vertices(const std::vector<hlr::clip::Polygon<K>>& polygons) {
  double v = 0;
  for (const auto& p : polygons) {
    v += static_cast<double>(p.outer.size());
    for (const auto& h : p.holes) v += static_cast<double>(h.size());
  }
  return v;
}

double vertices(const std::vector<CgalPwh>& polygons) {
  double v = 0;
  for (const CgalPwh& p : polygons) {
    v += static_cast<double>(p.outer_boundary().size());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) v += static_cast<double>(h->size());
  }
  return v;
}

double vertices(const ClipperLib::PolyNode& node) {
  double v = 0;
  for (const ClipperLib::PolyNode* child : node.Childs) v += static_cast<double>(child->Contour.size()) + vertices(*child);
  return v;
}

double area(const ClipperLib::PolyNode& node) {
  double a = 0;
  for (const ClipperLib::PolyNode* child : node.Childs)
    a += ClipperLib::Area(child->Contour) / (kClipperScale * kClipperScale) + area(*child);
  return a;
}

int outer_count(const ClipperLib::PolyNode& node) {
  int n = 0;
  for (const ClipperLib::PolyNode* child : node.Childs) n += (child->IsHole() ? 0 : 1) + outer_count(*child);
  return n;
}

struct Tally {
  double in_polys = 0, out_polys = 0, fail = 0, fail_other = 0;
  double area_in = 0, area_out = 0, out_verts = 0;  // of pool pair 0, both lists
  bool have_area = false;
};

void report(benchmark::State& state, const Tally& t, double verts) {
  const double it = std::max<double>(1, static_cast<double>(state.iterations()));
  state.counters["verts"] = verts;
  state.counters["in_polys"] = t.in_polys / it;
  state.counters["out_polys"] = t.out_polys / it;
  state.counters["fail"] = t.fail / it;
  state.counters["fail_other"] = t.fail_other / it;
  if (t.have_area) {
    state.counters["area_in"] = t.area_in;
    state.counters["area_out"] = t.area_out;
    state.counters["out_verts"] = t.out_verts;
  }
  state.SetItemsProcessed(state.iterations());
}

double mean_verts(const std::vector<PairInput>& pool) {
  double v = 0;
  for (const PairInput& p : pool) v += static_cast<double>(vertex_count(p.subject) + vertex_count(p.clip));
  return v / static_cast<double>(pool.size());
}

// Exceptions: on the exact kernel any throw is a bug (the benchmark stops with an error and the
// process exits non-zero); on the inexact kernels ClipError is the documented failure mode and
// is counted, like any other exception, as a failed iteration.
template <class K>
constexpr bool kExact = std::is_same_v<K, hlr::ExactKernel>;

// An exception from a clip: on the exact kernel a bug, which stops the benchmark with an error; on
// the inexact kernels a failure to count. Returns false when the benchmark must stop.
template <class K, class TallyType>
bool count_failure(benchmark::State& state, TallyType& t, const std::exception& e) {
  if (kExact<K>) {
    ++g_unexpected_errors;
    state.SkipWithError(e.what());
    return false;
  }
  (dynamic_cast<const hlr::clip::ClipError*>(&e) ? t.fail : t.fail_other) += 1;
  return true;
}

// ---------------------------------------------------------------------------------------------
// BM_Pair

template <class K>
void pair_hlr(benchmark::State& state, int n, bool holes) {
  const std::vector<PairInput>& pool = pair_pool(n, holes);
  Tally t;
  std::size_t i = 0;
  for (auto _ : state) {
    const PairInput& in = pool[i % pool.size()];
    try {
      hlr::clip::LineTable<K> lines;
      lines.reserve(vertex_count(in.subject) + vertex_count(in.clip));
      hlr::clip::Polygon<K> subject = to_hlr<K>(in.subject, lines);
      hlr::clip::ClipRegion<K> region(to_hlr<K>(in.clip, lines), lines);
      hlr::clip::ClipResult<K> r = hlr::clip::clip_polygon<K>(subject, region);
      t.in_polys += static_cast<double>(r.inside.size());
      t.out_polys += static_cast<double>(r.outside.size());
      if (i == 0) {
        state.PauseTiming();
        t.area_in = area<K>(r.inside), t.area_out = area<K>(r.outside), t.have_area = true;
        t.out_verts = vertices<K>(r.inside) + vertices<K>(r.outside);
        state.ResumeTiming();
      }
      benchmark::DoNotOptimize(r);
    } catch (const std::exception& e) {
      if (!count_failure<K>(state, t, e)) break;
    }
    ++i;
  }
  report(state, t, mean_verts(pool));
}

// Subject and ClipRegion built once; only clip_polygon is timed. The points are reused, so any
// exact values cached in them by an earlier iteration stay cached. No area counters here: exact
// areas would force exact values into the reused inputs (hlr_exact reports them).
void pair_hlr_exact_prebuilt(benchmark::State& state, int n, bool holes) {
  using K = hlr::ExactKernel;
  const std::vector<PairInput>& pool = pair_pool(n, holes);
  struct Prepared {
    hlr::clip::LineTable<K> lines;
    hlr::clip::Polygon<K> subject;
    std::optional<hlr::clip::ClipRegion<K>> region;
  };
  std::vector<std::unique_ptr<Prepared>> prepared;  // stable addresses: regions keep &lines
  for (const PairInput& in : pool) {
    auto p = std::make_unique<Prepared>();
    p->subject = to_hlr<K>(in.subject, p->lines);
    hlr::clip::Polygon<K> clip = to_hlr<K>(in.clip, p->lines);
    p->region.emplace(std::move(clip), p->lines);
    prepared.push_back(std::move(p));
  }
  Tally t;
  std::size_t i = 0;
  for (auto _ : state) {
    const Prepared& p = *prepared[i % prepared.size()];
    try {
      hlr::clip::ClipResult<K> r = hlr::clip::clip_polygon<K>(p.subject, *p.region);
      t.in_polys += static_cast<double>(r.inside.size());
      t.out_polys += static_cast<double>(r.outside.size());
      benchmark::DoNotOptimize(r);
    } catch (const std::exception& e) {
      ++g_unexpected_errors;
      state.SkipWithError(e.what());
      break;
    }
    ++i;
  }
  report(state, t, mean_verts(pool));
}

void pair_cgal(benchmark::State& state, int n, bool holes, bool prebuilt) {
  const std::vector<PairInput>& pool = pair_pool(n, holes);
  std::vector<std::pair<CgalPwh, CgalPwh>> built;
  if (prebuilt)
    for (const PairInput& in : pool) built.emplace_back(to_cgal(in.subject), to_cgal(in.clip));
  Tally t;
  std::size_t i = 0;
  for (auto _ : state) {
    std::vector<CgalPwh> inside, outside;
    if (prebuilt) {
      const auto& [subject, clip] = built[i % built.size()];
      CGAL::intersection(subject, clip, std::back_inserter(inside));
      CGAL::difference(subject, clip, std::back_inserter(outside));
    } else {
      const PairInput& in = pool[i % pool.size()];
      CgalPwh subject = to_cgal(in.subject), clip = to_cgal(in.clip);
      CGAL::intersection(subject, clip, std::back_inserter(inside));
      CGAL::difference(subject, clip, std::back_inserter(outside));
    }
    t.in_polys += static_cast<double>(inside.size());
    t.out_polys += static_cast<double>(outside.size());
    // Exact areas would force (and cache) exact values in reused inputs: fresh inputs only.
    if (i == 0 && !prebuilt) {
      state.PauseTiming();
      t.area_in = area(inside), t.area_out = area(outside), t.have_area = true;
      t.out_verts = vertices(inside) + vertices(outside);
      state.ResumeTiming();
    }
    benchmark::DoNotOptimize(inside);
    benchmark::DoNotOptimize(outside);
    ++i;
  }
  report(state, t, mean_verts(pool));
}

void pair_clipper1(benchmark::State& state, int n, bool holes) {
  const std::vector<PairInput>& pool = pair_pool(n, holes);
  Tally t;
  std::size_t i = 0;
  for (auto _ : state) {
    const PairInput& in = pool[i % pool.size()];
    ClipperLib::Clipper clipper;
    clipper.AddPaths(to_clipper(in.subject), ClipperLib::ptSubject, true);
    clipper.AddPaths(to_clipper(in.clip), ClipperLib::ptClip, true);
    ClipperLib::PolyTree inside, outside;
    clipper.Execute(ClipperLib::ctIntersection, inside, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
    clipper.Execute(ClipperLib::ctDifference, outside, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
    t.in_polys += outer_count(inside);
    t.out_polys += outer_count(outside);
    if (i == 0) {
      state.PauseTiming();
      t.area_in = area(inside), t.area_out = area(outside), t.have_area = true;
      t.out_verts = vertices(inside) + vertices(outside);
      state.ResumeTiming();
    }
    benchmark::DoNotOptimize(inside);
    benchmark::DoNotOptimize(outside);
    ++i;
  }
  report(state, t, mean_verts(pool));
}

// ---------------------------------------------------------------------------------------------
// BM_Triangles

struct TriangleTally {
  double in_polys = 0, out_polys = 0, fail = 0, fail_other = 0;
  // From the first iteration: how many triangles lie inside, cross, or lie outside the clip.
  double inside = -1, crossing = -1, outside = -1;
};

void report(benchmark::State& state, const TriangleTally& t, const TriangleInput& in) {
  const double it = std::max<double>(1, static_cast<double>(state.iterations()));
  state.counters["verts"] = static_cast<double>(vertex_count(in.clip) + 3 * in.triangles.size());
  state.counters["in_polys"] = t.in_polys / it;
  state.counters["out_polys"] = t.out_polys / it;
  state.counters["fail"] = t.fail / it;
  state.counters["fail_other"] = t.fail_other / it;
  if (t.inside >= 0) {
    state.counters["tri_in"] = t.inside;
    state.counters["tri_cross"] = t.crossing;
    state.counters["tri_out"] = t.outside;
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(in.triangles.size()));
}

template <class Result, class In, class Out>
void classify(TriangleTally& t, const std::vector<Result>& results, In in_count, Out out_count) {
  t.inside = t.crossing = t.outside = 0;
  for (const Result& r : results) {
    const bool any_in = in_count(r) > 0, any_out = out_count(r) > 0;
    (any_in && any_out ? t.crossing : any_in ? t.inside : t.outside) += 1;
  }
}

template <class K>
void triangles_hlr(benchmark::State& state, bool holes) {
  const TriangleInput& in = triangle_input(holes);
  TriangleTally t;
  bool first = true;
  for (auto _ : state) {
    try {
      hlr::clip::LineTable<K> lines;
      lines.reserve(vertex_count(in.clip) + 3 * in.triangles.size());
      std::vector<hlr::clip::Polygon<K>> subjects;
      subjects.reserve(in.triangles.size());
      for (const RawPolygon& tri : in.triangles) subjects.push_back(to_hlr<K>(tri, lines));
      hlr::clip::ClipRegion<K> region(to_hlr<K>(in.clip, lines), lines);
      std::vector<hlr::clip::ClipResult<K>> results =
          hlr::clip::clip_list<K>(std::span<const hlr::clip::Polygon<K>>(subjects), region);
      for (const auto& r : results) {
        t.in_polys += static_cast<double>(r.inside.size());
        t.out_polys += static_cast<double>(r.outside.size());
      }
      if (first) {
        state.PauseTiming();
        classify(t, results, [](const auto& r) { return r.inside.size(); },
                 [](const auto& r) { return r.outside.size(); });
        state.ResumeTiming();
      }
      benchmark::DoNotOptimize(results);
    } catch (const std::exception& e) {
      if (!count_failure<K>(state, t, e)) break;
    }
    first = false;
  }
  report(state, t, in);
}

void triangles_cgal(benchmark::State& state, bool holes) {
  const TriangleInput& in = triangle_input(holes);
  TriangleTally t;
  bool first = true;
  struct Counts {
    std::size_t in, out;
  };
  std::vector<Counts> counts(in.triangles.size());
  for (auto _ : state) {
    CgalPwh clip = to_cgal(in.clip);
    std::vector<CgalPwh> inside, outside;
    for (std::size_t k = 0; k < in.triangles.size(); ++k) {
      CgalPwh tri = to_cgal(in.triangles[k]);
      inside.clear(), outside.clear();
      CGAL::intersection(tri, clip, std::back_inserter(inside));
      CGAL::difference(tri, clip, std::back_inserter(outside));
      t.in_polys += static_cast<double>(inside.size());
      t.out_polys += static_cast<double>(outside.size());
      counts[k] = {inside.size(), outside.size()};
      benchmark::DoNotOptimize(inside);
      benchmark::DoNotOptimize(outside);
    }
    if (first) {
      state.PauseTiming();
      classify(t, counts, [](const Counts& c) { return c.in; }, [](const Counts& c) { return c.out; });
      state.ResumeTiming();
    }
    first = false;
  }
  report(state, t, in);
}

void triangles_clipper1(benchmark::State& state, bool holes) {
  const TriangleInput& in = triangle_input(holes);
  TriangleTally t;
  bool first = true;
  struct Counts {
    int in, out;
  };
  std::vector<Counts> counts(in.triangles.size());
  for (auto _ : state) {
    const ClipperLib::Paths clip = to_clipper(in.clip);
    ClipperLib::PolyTree inside, outside;
    for (std::size_t k = 0; k < in.triangles.size(); ++k) {
      ClipperLib::Clipper clipper;
      clipper.AddPaths(to_clipper(in.triangles[k]), ClipperLib::ptSubject, true);
      clipper.AddPaths(clip, ClipperLib::ptClip, true);
      clipper.Execute(ClipperLib::ctIntersection, inside, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
      clipper.Execute(ClipperLib::ctDifference, outside, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
      const int ni = outer_count(inside), no = outer_count(outside);
      t.in_polys += ni;
      t.out_polys += no;
      counts[k] = {ni, no};
      benchmark::DoNotOptimize(inside);
      benchmark::DoNotOptimize(outside);
    }
    if (first) {
      state.PauseTiming();
      classify(t, counts, [](const Counts& c) { return c.in; }, [](const Counts& c) { return c.out; });
      state.ResumeTiming();
    }
    first = false;
  }
  report(state, t, in);
}

// ---------------------------------------------------------------------------------------------
// Registration

void register_all() {
  const int sizes[] = {4, 16, 64, 256, 1024, 4096};
  for (bool holes : {false, true}) {
    for (int n : sizes) {
      const std::string suffix = "/" + std::to_string(n) + "/holes:" + (holes ? "1" : "0");
      auto reg = [&](const char* method, auto fn) {
        benchmark::internal::Benchmark* b =
            benchmark::RegisterBenchmark(("BM_Pair/" + std::string(method) + suffix).c_str(), fn);
        // No per-benchmark MinTime or Iterations: Google Benchmark would append "/min_time:..."
        // to the name. The default 0.5 s minimum already stops a slow case after 1-3 iterations.
        b->Unit(benchmark::kMicrosecond);
      };
      reg("hlr_exact", [=](benchmark::State& s) { pair_hlr<hlr::ExactKernel>(s, n, holes); });
      reg("hlr_exact_prebuilt", [=](benchmark::State& s) { pair_hlr_exact_prebuilt(s, n, holes); });
      reg("hlr_epick", [=](benchmark::State& s) { pair_hlr<hlr::EpickKernel>(s, n, holes); });
      reg("hlr_double", [=](benchmark::State& s) { pair_hlr<hlr::DoubleKernel>(s, n, holes); });
      reg("cgal", [=](benchmark::State& s) { pair_cgal(s, n, holes, false); });
      reg("cgal_prebuilt", [=](benchmark::State& s) { pair_cgal(s, n, holes, true); });
      reg("clipper1", [=](benchmark::State& s) { pair_clipper1(s, n, holes); });
    }
  }
  for (bool holes : {false, true}) {
    const std::string suffix = "/" + std::to_string(kTriangleClipVertices) + "/holes:" + (holes ? "1" : "0");
    auto reg = [&](const char* method, auto fn) {
      benchmark::RegisterBenchmark(("BM_Triangles/" + std::string(method) + suffix).c_str(), fn)
          ->Unit(benchmark::kMicrosecond);
    };
    reg("hlr_exact", [=](benchmark::State& s) { triangles_hlr<hlr::ExactKernel>(s, holes); });
    reg("hlr_epick", [=](benchmark::State& s) { triangles_hlr<hlr::EpickKernel>(s, holes); });
    reg("hlr_double", [=](benchmark::State& s) { triangles_hlr<hlr::DoubleKernel>(s, holes); });
    reg("cgal", [=](benchmark::State& s) { triangles_cgal(s, holes); });
    reg("clipper1", [=](benchmark::State& s) { triangles_clipper1(s, holes); });
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("hlr.input", "star pairs, radius 100, clip centre (15, 10); fresh inputs per iteration");
  benchmark::AddCustomContext("hlr.clipper1_scale", "1e6");
  register_all();
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (ran == 0) {
    std::fprintf(stderr, "clip_bench: no benchmark matched the filter\n");
    return 1;
  }
  if (g_unexpected_errors > 0) {
    std::fprintf(stderr, "clip_bench: the exact kernel threw in %d benchmark(s)\n", g_unexpected_errors.load());
    return 1;
  }
  return 0;
}
