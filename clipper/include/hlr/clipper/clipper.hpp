// hlr clipper: Weiler–Atherton general polygon clipping, exact on ExactKernel.
//
// Clips a subject polygon with holes against a clip polygon with holes and returns the inside
// list (subject ∩ clip) and the outside list (subject − clip) as regularized polygons with holes:
// outer contours counter-clockwise, holes clockwise, no zero-area pieces, no zero-length edges.
// Every output edge names the supporting line it lies on, and every constructed vertex is the
// intersection of two such lines, which come straight from the input (DESIGN.md, rule 3).
// Pure 2D: it knows nothing of depth.
#pragma once

#include <hlr/kernel/kernel.hpp>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace hlr::clip {

// Index of a supporting line in a LineTable: the provenance of an edge.
using LineId = std::uint32_t;

// A line given by two input points. Fragment edges lie on such lines, and new vertices are only
// ever constructed as the intersection of two of them, never of already-constructed segments.
template <GeometryKernel K>
struct SupportLine {
  typename Geometry<K>::Point a, b;
};
template <class K>
using LineTable = std::vector<SupportLine<K>>;

// A closed contour: points[i] -> points[i+1 mod n] lies on line lines[i]. The first point is not
// repeated at the end.
template <GeometryKernel K>
struct Contour {
  std::vector<typename Geometry<K>::Point> points;
  std::vector<LineId> lines;
  std::size_t size() const { return points.size(); }
};

// Whether corner i is known to lie on `line` without arithmetic: it does on the support lines of
// the two edges that meet there. On the exact kernel the orientation of that corner against any two
// points of the line is then 0, which the filters cannot certify and would leave to exact arithmetic.
template <class K>
bool corner_on_line(const Contour<K>& c, std::size_t i, LineId line) {
  return c.lines[i] == line || c.lines[i == 0 ? c.size() - 1 : i - 1] == line;
}

template <GeometryKernel K>
struct Polygon {
  Contour<K> outer;
  std::vector<Contour<K>> holes;
};

template <class K>
struct ClipResult {
  std::vector<Polygon<K>> inside;   // subject ∩ clip
  std::vector<Polygon<K>> outside;  // subject − clip
};

// Thrown when input breaks the clipper's preconditions, or when an inexact kernel has produced
// an inconsistent arrangement (the exact kernel never does on valid input).
struct ClipError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Builds a contour from raw points, registering each edge as a new line of `lines`.
template <class K>
Contour<K> make_contour(std::vector<typename Geometry<K>::Point> points, LineTable<K>& lines);

// Orients a polygon in place (outer counter-clockwise, holes clockwise) and drops repeated
// consecutive points. Returns a description of the first defect, or nothing if the polygon is a
// valid polygon with holes: contours with at least 3 points and non-zero area, every contour
// simple (no edge meets a non-adjacent edge), contours of one polygon do not cross or overlap
// along an edge, and every hole lies inside the outer contour and outside the other holes.
// Contours may touch at single points.
template <class K>
std::optional<std::string> normalize_polygon(Polygon<K>& polygon);

// The points where two support lines cross, constructed once per pair of lines (rule 3 makes the
// pair a point's identity): the same crossing found by different clips is then one shared point,
// equal to itself without arithmetic. For the exact kernel; one per sort, not shared by threads.
template <class K>
class CrossingCache {
 public:
  using Point = typename Geometry<K>::Point;
  // Throws std::runtime_error when the lines are parallel.
  Point crossing(LineId a, LineId b, const LineTable<K>& lines) {
    const LineId lo = std::min(a, b), hi = std::max(a, b);
    auto [it, added] = points_.try_emplace((std::uint64_t(lo) << 32) | hi);
    if (added) {
      try {
        it->second = Geometry<K>::line_intersection(lines[lo].a, lines[lo].b, lines[hi].a, lines[hi].b);
      } catch (...) {
        points_.erase(it);
        throw;
      }
    }
    return it->second;
  }

 private:
  std::unordered_map<std::uint64_t, Point> points_;
};

// The clip polygon, prepared once for clipping many subjects (the area sort's use).
// Must be normalized and valid. Keeps a reference to `lines`, which must outlive it, and takes
// its crossings from `crossings` when given.
template <class K>
class ClipRegion {
 public:
  ClipRegion(Polygon<K> polygon, const LineTable<K>& lines, CrossingCache<K>* crossings = nullptr);
  ~ClipRegion();
  ClipRegion(ClipRegion&&) noexcept;
  ClipRegion& operator=(ClipRegion&&) noexcept;

  const Polygon<K>& polygon() const;
  struct Prepared;
  const Prepared& prepared() const { return *prepared_; }

 private:
  std::unique_ptr<Prepared> prepared_;
};

// Clips one normalized, valid subject against the clip region.
template <class K>
ClipResult<K> clip_polygon(const Polygon<K>& subject, const ClipRegion<K>& clip);

// Clips each subject of a list against one clip region; result i belongs to subject i.
template <class K>
std::vector<ClipResult<K>> clip_list(std::span<const Polygon<K>> subjects, const ClipRegion<K>& clip);

// The union of counter-clockwise contours whose interiors do not overlap (a tessellation, such as
// the faces of one planar region), as polygons with holes; shared edges vanish. Throws ClipError
// when pieces overlap.
template <class K>
std::vector<Polygon<K>> merge_polygons(std::span<const Contour<K>> pieces, const LineTable<K>& lines);

// Where q lies with respect to a polygon with holes: +1 inside, 0 on its boundary, -1 outside.
template <class K>
int side_of_polygon(const Polygon<K>& polygon, const typename Geometry<K>::Point& q);

// side_of_polygon for a point q on a line, of the polygon bounded by `outer` and `holes` (all of
// a polygon's holes, or those that may hold or touch q), given the side of that line each corner
// lies on (`corner_sides`, -1, 0 or +1, contour after contour, the outer one first). An edge whose
// two corners lie on the line contains it, so q is collinear with that edge: known without the
// exact arithmetic a constructed q would need there. Only on the exact kernel, where a point
// constructed on the line lies on it; the other kernels, and empty `corner_sides`, decide every
// edge as side_of_polygon does.
template <class K>
int side_of_polygon_on_line(const Contour<K>& outer, std::span<const Contour<K>* const> holes,
                            std::span<const int> corner_sides, const typename Geometry<K>::Point& q);

// Exact signed area of a contour (twice the area, to stay in the ring of the coordinates) and of a
// polygon (outer minus holes). Positive for a counter-clockwise contour.
template <class K>
typename Geometry<K>::FT twice_signed_area(const Contour<K>& contour);
template <class K>
typename Geometry<K>::FT twice_area(const Polygon<K>& polygon);

// Explicit instantiations live in the clipper library; no translation unit outside it
// instantiates the algorithm.
#define HLR_CLIPPER_DECLARE(K, EXTERN)                                                               \
  EXTERN template Contour<K> make_contour<K>(std::vector<Geometry<K>::Point>, LineTable<K>&);        \
  EXTERN template std::optional<std::string> normalize_polygon<K>(Polygon<K>&);                      \
  EXTERN template class ClipRegion<K>;                                                               \
  EXTERN template ClipResult<K> clip_polygon<K>(const Polygon<K>&, const ClipRegion<K>&);            \
  EXTERN template std::vector<ClipResult<K>> clip_list<K>(std::span<const Polygon<K>>,               \
                                                          const ClipRegion<K>&);                     \
  EXTERN template std::vector<Polygon<K>> merge_polygons<K>(std::span<const Contour<K>>, const LineTable<K>&); \
  EXTERN template int side_of_polygon<K>(const Polygon<K>&, const Geometry<K>::Point&);               \
  EXTERN template int side_of_polygon_on_line<K>(const Contour<K>&, std::span<const Contour<K>* const>,     \
                                                std::span<const int>, const Geometry<K>::Point&);              \
  EXTERN template Geometry<K>::FT twice_signed_area<K>(const Contour<K>&);                           \
  EXTERN template Geometry<K>::FT twice_area<K>(const Polygon<K>&);

HLR_CLIPPER_DECLARE(ExactKernel, extern)
HLR_CLIPPER_DECLARE(EpickKernel, extern)
HLR_CLIPPER_DECLARE(DoubleKernel, extern)

}  // namespace hlr::clip
