// Near-coincident drawing segments drawn once (hlr/export/lines.hpp, merge_segments), and the
// names of a drawing's parts.
//
// Why a tolerance here and nowhere else: two parts whose edges are 1e-7 apart in the input (CAD
// coordinates rounded to a few decimals) give two lines that the exact engine rightly keeps apart,
// and a sheet would show a dashed line under a solid one, or two solid lines drawn twice, where a
// drafter draws one. On the sheet, after the one rounding of the result, lines closer than the
// drawing's resolution are one line, and ISO 128 precedence (visible over hidden over thin) picks which.
//
// Each segment S is compared with the already kept segments K near it (a uniform grid over the
// drawing, cells about one mean segment length wide, each segment listed in the cells its
// distance-widened outline touches). Where S runs nearly parallel to K, the part of S that is
// within `distance` of K's line and whose foot lies on K is covered; the covered parts are cut out
// of S. Only nearly parallel pairs cover, so a line crossing another or ending on it is never cut.
#include <hlr/export/lines.hpp>
#include <hlr/hidden_line/parallel.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <set>

namespace hlr::exporter {
namespace {

// Directions closer than this (the sine of about 0.57 degrees) count as "along". Two lines at this
// angle stay within a resolution of 0.01 mm over 2 mm of the sheet, which the 0.5 mm line width
// covers; steeper meetings are crossings and T-junctions, which must stay whole.
constexpr double max_sine = 0.01;

double cross(const Point2& u, const Point2& v) { return u[0] * v[1] - u[1] * v[0]; }
double dot(const Point2& u, const Point2& v) { return u[0] * v[0] + u[1] * v[1]; }
Point2 minus(const Point2& a, const Point2& b) { return {a[0] - b[0], a[1] - b[1]}; }

double squared_distance_to_segment(const Point2& x, const Point2& a, const Point2& b) {
  const Point2 ab = minus(b, a), ax = minus(x, a);
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(ax, ab) / len2, 0.0, 1.0) : 0.0;
  const Point2 off{ax[0] - t * ab[0], ax[1] - t * ab[1]};
  return dot(off, off);
}

// A segment's length and unit direction, worked out once per segment rather than per candidate
// pair (a dense drawing compares each segment with dozens of neighbours).
struct Direction {
  double length;
  Point2 unit;
};

Direction direction_of(const DrawingSegment& s) {
  const Point2 ab = minus(s.b, s.a);
  const double len = std::hypot(ab[0], ab[1]);
  return {len, {ab[0] / len, ab[1] / len}};
}

// The drawing's extent and mean segment length, which size the grids.
struct Extent {
  double x0 = 0, y0 = 0, w = 1, h = 1, mean_length = 1;
};

Extent extent_of(const std::vector<DrawingSegment>& segments, double widen) {
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL, total = 0;
  for (const auto& s : segments) {
    for (const Point2& p : {s.a, s.b})
      x0 = std::min(x0, p[0]), y0 = std::min(y0, p[1]), x1 = std::max(x1, p[0]), y1 = std::max(y1, p[1]);
    total += std::hypot(s.b[0] - s.a[0], s.b[1] - s.a[1]);
  }
  if (!(x0 <= x1 && y0 <= y1)) x0 = y0 = 0, x1 = y1 = 1;
  const double n = double(segments.size());
  return {x0 - widen, y0 - widen, x1 - x0 + 2 * widen, y1 - y0 + 2 * widen, n > 0 ? total / n : 1.0};
}

// A uniform grid of square cells sized for about n segments: the cells within `widen` of a
// segment. A filter only: the cover test below decides.
class GridCells {
 public:
  GridCells(const Extent& extent, std::size_t n, double widen) : widen_(widen), x0_(extent.x0), y0_(extent.y0) {
    const double w = extent.w, h = extent.h;
    // About one mean segment length per cell, at most 2048 cells a side and about 4 cells a segment.
    double cell = std::max({extent.mean_length, 2 * widen, std::max(w, h) / 2048});
    cell = std::max(cell, std::sqrt(w * h / (4.0 * double(n) + 16)));
    if (!(cell > 0) || !std::isfinite(cell)) cell = std::max({w, h, 1.0});
    cell_ = cell;
    nx_ = std::clamp<long>(long(w / cell) + 1, 1, 4096);
    ny_ = std::clamp<long>(long(h / cell) + 1, 1, 4096);
  }

  std::size_t size() const { return std::size_t(nx_ * ny_); }
  Point2 centre(std::size_t cell) const {
    return {x0_ + (double(long(cell) % nx_) + 0.5) * cell_, y0_ + (double(long(cell) / nx_) + 0.5) * cell_};
  }

  // Calls each(cell) for every cell within widen of s.
  template <class Each>
  void for_each(const DrawingSegment& s, Each&& each) const {
    auto index = [&](double v, double lo, long n) {
      const double q = std::floor((v - lo) / cell_);
      return q >= double(n - 1) ? n - 1 : q >= 0 ? long(q) : 0;  // NaN and below go to 0
    };
    const long cx0 = index(std::min(s.a[0], s.b[0]) - widen_, x0_, nx_);
    const long cx1 = index(std::max(s.a[0], s.b[0]) + widen_, x0_, nx_);
    const long cy0 = index(std::min(s.a[1], s.b[1]) - widen_, y0_, ny_);
    const long cy1 = index(std::max(s.a[1], s.b[1]) + widen_, y0_, ny_);
    const bool one_cell = cx0 == cx1 || cy0 == cy1;  // a row or column: every cell is near
    // A cell whose centre is farther than this holds no point within widen_ of s; the margin
    // keeps rounding on the safe side.
    const double reach = cell_ * M_SQRT1_2 + widen_ + cell_ * 1e-9, reach2 = reach * reach;
    for (long y = cy0; y <= cy1; ++y)
      for (long x = cx0; x <= cx1; ++x) {
        const Point2 centre{x0_ + (double(x) + 0.5) * cell_, y0_ + (double(y) + 0.5) * cell_};
        if (one_cell || squared_distance_to_segment(centre, s.a, s.b) <= reach2) each(std::size_t(y * nx_ + x));
      }
  }

 private:
  double widen_, x0_ = 0, y0_ = 0, cell_ = 1;
  long nx_ = 1, ny_ = 1;
};

// The input segments, filed once: each cell's segments packed in one array in input order, each
// with its line in single precision (its direction, and its offset from the cell's centre). A
// query reads the segments near it in order, and passes over those that are not nearly parallel or
// not near its line without looking them up: all but a few of those it meets. (Filing by direction
// as well, in a grid per range of angles, made a query visit three times the cells, and each
// cell's first entry is a cache miss in a large drawing: slower.)
class FiledSegments {
 public:
  FiledSegments(const std::vector<DrawingSegment>& segments, const std::vector<Direction>& directions,
                const Extent& extent, double widen)
      : cells_(extent, segments.size(), widen),
        magnitude_(std::max({std::abs(extent.x0), std::abs(extent.y0), std::abs(extent.x0 + extent.w),
                             std::abs(extent.y0 + extent.h)})) {
    start_.assign(cells_.size() + 1, 0);
    for (const auto& s : segments) cells_.for_each(s, [&](std::size_t c) { ++start_[c + 1]; });
    for (std::size_t c = 0; c < cells_.size(); ++c) start_[c + 1] += start_[c];
    entries_.resize(start_.back());
    std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
    for (std::uint32_t i = 0; i < segments.size(); ++i) {
      const Point2& v = directions[i].unit;
      cells_.for_each(segments[i], [&](std::size_t c) {
        const float offset = float(cross(v, minus(segments[i].a, cells_.centre(c))));
        entries_[next[c]++] = {i, float(v[0]), float(v[1]), offset};
      });
    }
  }

  // Calls visit(id) for the segments near s that may cover part of it (cover_of) within
  // `distance`; an id may come once per cell it shares with s.
  template <class Visit>
  void query(const DrawingSegment& s, const Direction& d, double distance, Visit&& visit) const {
    // A cover needs the directions' sine within max_sine, and so s's start within
    // distance + length * max_sine of the coverer's line. The single-precision directions and
    // offsets are within 1.2e-7 of theirs relative to what they multiply or are, and the rest is
    // rounding in double, within a few units in the last place of the drawing's coordinates.
    const double filter_sine = max_sine + 1e-6, reach = distance + d.length * max_sine + 1e-13 * magnitude_;
    cells_.for_each(s, [&](std::size_t c) {
      const Point2 p = minus(s.a, cells_.centre(c));
      const double p1 = std::abs(p[0]) + std::abs(p[1]);
      for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
        const Entry& e = entries_[k];
        if (std::abs(d.unit[0] * e.y - d.unit[1] * e.x) > filter_sine) continue;
        const double h = double(e.x) * p[1] - double(e.y) * p[0] - double(e.offset);
        if (std::abs(h) > reach + 2e-7 * (p1 + std::abs(double(e.offset)))) continue;
        visit(e.id);
      }
    });
  }

 private:
  struct Entry {
    std::uint32_t id;
    float x, y;    // its unit direction
    float offset;  // its line's offset from the cell's centre along the normal: cross(unit, a - centre)
  };
  GridCells cells_;
  double magnitude_;                  // of the drawing's coordinates
  std::vector<std::uint32_t> start_;  // cell c's entries are entries_[start_[c], start_[c + 1])
  std::vector<Entry> entries_;
};

// The pieces of segments cut by the merge, filed as they are made: each cell's list a chain
// through one array of entries, in the order of insertion. They are few (the segments cut are), so
// one coarse grid holds them all and stays in the cache.
class PieceGrid {
 public:
  PieceGrid(const Extent& extent, std::size_t n, double widen)
      : cells_(extent, n, widen), first_(cells_.size(), none), last_(cells_.size(), none) {}

  void insert(std::uint32_t id, const DrawingSegment& s) {
    cells_.for_each(s, [&](std::size_t cell) {
      const auto entry = std::uint32_t(entries_.size());
      entries_.push_back({id, none});
      if (last_[cell] == none) first_[cell] = entry;
      else entries_[last_[cell]].next = entry;
      last_[cell] = entry;
    });
    if (id >= stamp_.size()) stamp_.resize(id + 1, 0);
  }

  // Calls visit(id) once for every piece filed near s.
  template <class Visit>
  void query(const DrawingSegment& s, Visit&& visit) {
    if (entries_.empty()) return;
    ++round_;
    cells_.for_each(s, [&](std::size_t cell) {
      for (std::uint32_t e = first_[cell]; e != none; e = entries_[e].next) {
        const std::uint32_t id = entries_[e].id;
        if (stamp_[id] == round_) continue;
        stamp_[id] = round_;
        visit(id);
      }
    });
  }

 private:
  static constexpr std::uint32_t none = ~std::uint32_t(0);
  struct Entry {
    std::uint32_t id, next;
  };
  GridCells cells_;
  std::vector<std::uint32_t> first_, last_;  // per cell: its first and last entry, or none
  std::vector<Entry> entries_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t round_ = 0;
};

// A covered stretch [lo, hi] of S (arc length from S's start); an end that lies at an end of the
// covering segment carries that end, which the cut piece ends on.
struct Cover {
  double lo, hi;
  std::optional<Point2> at_lo, at_hi;
  std::uint32_t by = 0;  // the kept segment that covers: orders equal stretches whatever the visit order
};

// The part of s that runs along k within `distance`, if any.
std::optional<Cover> cover_of(const DrawingSegment& s, const Direction& ds, const DrawingSegment& k,
                              const Direction& dk, double distance) {
  const double len = ds.length, len_k = dk.length;
  if (!(len > 0) || !(len_k > 0)) return std::nullopt;
  const Point2 &u = ds.unit, &v = dk.unit;
  if (std::abs(cross(u, v)) > max_sine) return std::nullopt;
  // Foot on k: w(s) = w0 + s cos in [0, len_k]; |cos| is nearly 1 here.
  const Point2 pa = minus(s.a, k.a);
  const double cos = dot(u, v), w0 = dot(pa, v);
  double lo = -w0 / cos, hi = (len_k - w0) / cos;
  std::optional<Point2> at_lo = k.a, at_hi = k.b;
  if (lo > hi) std::swap(lo, hi), std::swap(at_lo, at_hi);
  // Distance from k's line: h(s) = h0 + s sin, |h| <= distance.
  const double sin = cross(v, u), h0 = cross(v, pa);
  if (sin == 0) {
    if (std::abs(h0) > distance) return std::nullopt;
  } else {
    double h_lo = (-distance - h0) / sin, h_hi = (distance - h0) / sin;
    if (h_lo > h_hi) std::swap(h_lo, h_hi);
    if (h_lo > lo) lo = h_lo, at_lo.reset();
    if (h_hi < hi) hi = h_hi, at_hi.reset();
  }
  if (lo < 0) lo = 0, at_lo.reset();
  if (hi > len) hi = len, at_hi.reset();
  if (!(lo < hi)) return std::nullopt;
  return Cover{lo, hi, at_lo, at_hi};
}

// A cover of the segment at `place` in precedence order by the input segment `segment`.
struct Found {
  std::uint32_t place, segment;
  Cover cover;
};
constexpr std::size_t kFoundChunk = 4096;

// For each chunk of kFoundChunk places in precedence order (`order`), the covers of its segments
// by the segments before them in that order, by place: what the merge would find if every segment
// were kept whole. Each chunk on its own thread.
std::vector<std::vector<Found>> covers_by_earlier(const std::vector<DrawingSegment>& segments,
                                                  const std::vector<Direction>& directions,
                                                  const std::vector<std::uint32_t>& order, const FiledSegments& filed,
                                                  double distance) {
  const std::size_t n = order.size();
  std::vector<std::uint32_t> place_of(n);
  for (std::uint32_t place = 0; place < n; ++place) place_of[order[place]] = place;
  std::vector<std::vector<Found>> found((n + kFoundChunk - 1) / kFoundChunk);
  hidden_line::parallel_chunks(found.size(), 1, [&](const auto& range) {
    std::vector<std::uint32_t> near;
    for (std::size_t chunk = range.begin(); chunk != range.end(); ++chunk)
      for (std::size_t place = chunk * kFoundChunk; place < std::min(n, (chunk + 1) * kFoundChunk); ++place) {
        const std::uint32_t i = order[place];
        near.clear();
        filed.query(segments[i], directions[i], distance, [&](std::uint32_t k) {
          if (place_of[k] < place) near.push_back(k);
        });
        std::sort(near.begin(), near.end());  // a segment comes once per cell it shares with i
        near.erase(std::unique(near.begin(), near.end()), near.end());
        for (const std::uint32_t k : near)
          if (auto c = cover_of(segments[i], directions[i], segments[k], directions[k], distance))
            found[chunk].push_back({std::uint32_t(place), k, *c});
      }
  });
  return found;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// merge_segments, with the candidates from the grids or, for the tests' oracle, every kept
// segment and piece.
MergedSegments merge(const std::vector<DrawingSegment>& segments, double distance, bool all_pairs) {
  MergedSegments out;
  if (!(distance > 0) || !std::isfinite(distance)) {
    out.segments = segments;
    return out;
  }
  constexpr std::uint32_t none = ~std::uint32_t(0);
  const std::size_t n = segments.size();
  // Precedence: visible, hidden, then thin (precedence_rank), input order within a class.
  std::vector<std::uint32_t> order;
  order.reserve(n);
  for (int rank = 0; rank < 3; ++rank)
    for (std::uint32_t i = 0; i < n; ++i)
      if (precedence_rank(segments[i]) == rank) order.push_back(i);

  std::vector<Direction> directions(n);
  for (std::size_t i = 0; i < n; ++i) directions[i] = direction_of(segments[i]);
  const Extent extent = extent_of(segments, distance);
  // A kept segment covers those merged after it. Nearly all are kept whole: they are found among
  // the input segments, filed once; the pieces of the others are filed as they are cut.
  std::optional<FiledSegments> filed;
  if (!all_pairs) filed.emplace(segments, directions, extent, distance);
  PieceGrid piece_grid(extent, n / 64, distance);
  // Kept things are numbered in the order they are kept, which orders equal covers: kept_as[i]
  // is segment i's number if it is kept whole, else none (not merged yet, or cut).
  std::vector<std::uint32_t> kept_as(n, none);
  std::uint32_t kept_count = 0;
  std::vector<DrawingSegment> pieces;
  std::vector<Direction> piece_directions;
  std::vector<std::uint32_t> piece_kept_as;
  // The pieces of cut segment i are pieces[pieces_of[i].first, pieces_of[i].second).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pieces_of(n);
  // The covers of each segment by the input segments before it in precedence order, as though
  // every one of those were kept whole, found on every thread; the merge below keeps those by
  // segments that were. Most segments meet none, and the search is most of the merge's time.
  const std::vector<std::vector<Found>> found =
      all_pairs ? std::vector<std::vector<Found>>() : covers_by_earlier(segments, directions, order, *filed, distance);
  std::size_t next = 0;  // in found[place / kFoundChunk]
  std::vector<Cover> covers, runs;
  for (std::size_t place = 0; place < n; ++place) {
    const std::uint32_t i = order[place];
    const DrawingSegment& s = segments[i];
    const Direction& ds = directions[i];
    covers.clear();
    auto piece_candidate = [&](std::uint32_t p) {
      if (auto c = cover_of(s, ds, pieces[p], piece_directions[p], distance)) c->by = piece_kept_as[p], covers.push_back(*c);
    };
    if (all_pairs) {
      for (std::uint32_t k = 0; k < n; ++k)
        if (kept_as[k] != none)
          if (auto c = cover_of(s, ds, segments[k], directions[k], distance)) c->by = kept_as[k], covers.push_back(*c);
      for (std::uint32_t p = 0; p < pieces.size(); ++p) piece_candidate(p);
    } else {
      const std::vector<Found>& chunk = found[place / kFoundChunk];
      if (place % kFoundChunk == 0) next = 0;
      for (; next < chunk.size() && chunk[next].place == place; ++next)
        if (const std::uint32_t by = kept_as[chunk[next].segment]; by != none) {
          covers.push_back(chunk[next].cover);
          covers.back().by = by;
        }
      piece_grid.query(s, piece_candidate);
    }
    // Covers joined into runs where the gap between them is below the distance (such a gap is a
    // sliver of the same line). A run shorter than the distance is no overlap but two lines
    // meeting end to end (the neighbours along a tessellated curve), unless it is all of s.
    const double len = ds.length;
    std::sort(covers.begin(), covers.end(), [](const Cover& x, const Cover& y) {
      return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.by < y.by;
    });
    runs.clear();
    for (const Cover& c : covers) {
      if (!runs.empty() && c.lo <= runs.back().hi + distance) {
        if (c.hi > runs.back().hi) runs.back().hi = c.hi, runs.back().at_hi = c.at_hi;
      } else {
        runs.push_back(c);
      }
    }
    std::erase_if(runs, [&](const Cover& r) { return r.hi - r.lo < distance && !(r.lo <= 0 && r.hi >= len); });
    if (runs.empty()) {
      kept_as[i] = kept_count++;
      continue;
    }
    ++out.merged;
    pieces_of[i] = {std::uint32_t(pieces.size()), std::uint32_t(pieces.size())};
    auto at = [&](double t) -> Point2 {
      return {s.a[0] + (s.b[0] - s.a[0]) * (t / len), s.a[1] + (s.b[1] - s.a[1]) * (t / len)};
    };
    double from = 0;
    Point2 from_point = s.a;
    // Uncovered leftovers at the ends shorter than the distance are slivers: dropped.
    auto piece = [&](double t1, const Point2& end) {
      if (t1 - from < distance) return;
      DrawingSegment kept_piece = s;
      kept_piece.a = from_point, kept_piece.b = end;
      const Direction d = direction_of(kept_piece);
      piece_grid.insert(std::uint32_t(pieces.size()), kept_piece);
      pieces.push_back(kept_piece);
      piece_directions.push_back(d);
      piece_kept_as.push_back(kept_count++);
      pieces_of[i].second = std::uint32_t(pieces.size());
    };
    for (const Cover& r : runs) {
      if (r.lo > from) piece(r.lo, r.at_lo.value_or(at(r.lo)));
      from = r.hi;
      from_point = r.hi >= len ? s.b : r.at_hi.value_or(at(r.hi));
    }
    if (from < len) piece(len, s.b);
  }
  out.segments.reserve(kept_count);
  for (std::size_t i = 0; i < n; ++i) {
    if (kept_as[i] != none) out.segments.push_back(segments[i]);
    else out.segments.insert(out.segments.end(), pieces.begin() + pieces_of[i].first, pieces.begin() + pieces_of[i].second);
  }
  return out;
}

}  // namespace

MergedSegments merge_segments(const std::vector<DrawingSegment>& segments, double distance) {
  return merge(segments, distance, false);
}

MergedSegments detail::merge_segments_all_pairs(const std::vector<DrawingSegment>& segments, double distance) {
  return merge(segments, distance, true);
}

std::vector<std::string> part_names(const LineDrawing& drawing) {
  std::uint32_t parts = std::uint32_t(drawing.input.files.size());
  for (const auto& s : drawing.segments) parts = std::max(parts, s.mesh + 1);
  std::vector<std::string> names;
  std::set<std::string> taken;  // lower case
  for (std::uint32_t m = 0; m < parts; ++m) {
    std::string name;
    if (m < drawing.input.files.size()) {
      std::string stem = drawing.input.files[m];
      if (m < drawing.input.parts.size() && !drawing.input.parts[m].empty()) {
        stem = drawing.input.parts[m];  // named by its source (a STEP product): no file stem
      } else {
        if (const auto slash = stem.find_last_of("/\\"); slash != std::string::npos) stem = stem.substr(slash + 1);
        if (const auto dot = stem.find_last_of('.'); dot != std::string::npos && dot > 0) stem = stem.substr(0, dot);
      }
      for (char c : stem) {
        const bool ok = std::isalnum(static_cast<unsigned char>(c)) && static_cast<unsigned char>(c) < 128;
        if (ok || c == '_' || c == '-') name += c;
        else if (name.empty() || name.back() != '_') name += '_';
      }
      if (name.empty()) name = "mesh";
    } else {
      name = "mesh-" + std::to_string(m);
    }
    std::string unique = name;
    for (int k = 2; taken.count(lower(unique)); ++k) unique = name + "-" + std::to_string(k);
    taken.insert(lower(unique));
    names.push_back(unique);
  }
  return names;
}

}  // namespace hlr::exporter
