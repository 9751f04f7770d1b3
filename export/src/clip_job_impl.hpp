// The template behind clip_polygons (polygons.hpp), once per kernel in clip_job_<kernel>.cpp.
//
// Every geometric decision (validity, orientation, clipping, areas) is the clipper's, made in the
// kernel's arithmetic; the outcome is rounded once at the end.
#pragma once

#include <hlr/clipper/clipper.hpp>
#include <hlr/export/polygons.hpp>
#include <hlr/kernel/errors.hpp>
#include <hlr/kernel/kernel.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace hlr::exporter::clip_detail {

// A piece of the result and where it came from.
template <class K>
struct Piece {
  clip::Polygon<K> polygon;
  std::uint32_t subject = 0;  // index of the subject polygon it is part of
  std::int64_t clip = -1;     // inside pieces: index of the clip polygon it is inside of
};

template <class K>
class ClipRun {
 public:
  using G = Geometry<K>;
  using FT = typename G::FT;
  using Point = typename G::Point;

  ClipRun(const std::vector<RawPolygon>& subjects, const std::vector<RawPolygon>& clips, const ClipOptions& options)
      : raw_subjects_(subjects), raw_clips_(clips), options_(options), kernel_(kernel_name(options.kernel)) {}

  ClipOutcome run() {
    // Every input edge becomes a line of one shared table; the table is complete before the clip
    // regions are built (they keep a reference to it).
    for (std::size_t p = 0; p < raw_subjects_.size(); ++p)
      subjects_.push_back(build_polygon(raw_subjects_[p], "subject", p, options_.subject_name));
    for (std::size_t p = 0; p < raw_clips_.size(); ++p)
      clips_.push_back(build_polygon(raw_clips_[p], "clip", p, options_.clip_name));

    auto start = std::chrono::steady_clock::now();
    clip_all();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    check_areas();
    return outcome(seconds);
  }

 private:
  clip::Polygon<K> build_polygon(const RawPolygon& raw, const char* role, std::size_t index, const std::string& path) {
    clip::Polygon<K> polygon;
    polygon.outer = build_contour(raw.outer, role, index, 0);
    for (std::size_t h = 0; h < raw.holes.size(); ++h)
      polygon.holes.push_back(build_contour(raw.holes[h], role, index, h + 1));
    std::optional<std::string> defect;
    try {
      defect = clip::normalize_polygon<K>(polygon);
    } catch (const std::exception& e) {  // inexact kernels may trip over their own rounding
      defect = std::string("cannot be checked with kernel ") + kernel_ + " (" + e.what() + "; try --kernel exact)";
    }
    // The clipper's defects begin with the contour ("outer contour ...", "hole 1 ...") and number
    // vertices and edges as the input does.
    if (defect) throw UserError(path, "polygon " + std::to_string(index) + " " + *defect);
    return polygon;
  }

  clip::Contour<K> build_contour(const RawContour& raw, const char* role, std::size_t polygon, std::size_t contour) {
    std::vector<Point> points;
    points.reserve(raw.size());
    for (const auto& p : raw) points.push_back(G::point(p[0], p[1]));
    std::size_t first = lines_.size();
    clip::Contour<K> result = clip::make_contour<K>(points, lines_);
    // Edge i of the input runs from vertex i to vertex i + 1. Match every new line to its input
    // edge by its end points (exact equality of the very same doubles), so the provenance is right
    // whatever make_contour does with repeated points.
    std::vector<bool> used(raw.size(), false);
    for (std::size_t id = first; id < lines_.size(); ++id) {
      std::size_t n = raw.size();
      std::size_t guess = id - first;
      auto matches = [&](std::size_t i) {
        return !used[i] && G::equal(lines_[id].a, points[i]) && G::equal(lines_[id].b, points[(i + 1) % n]);
      };
      std::size_t edge = n;
      if (guess < n && matches(guess)) edge = guess;
      else
        for (std::size_t i = 0; i < n && edge == n; ++i)
          if (matches(i)) edge = i;
      if (edge == n) continue;  // not an input edge: stays without provenance
      used[edge] = true;
      if (sources_.size() <= id) sources_.resize(id + 1);
      sources_[id] = {role, static_cast<std::uint32_t>(polygon), static_cast<std::uint32_t>(contour),
                      static_cast<std::uint32_t>(edge)};
    }
    return result;
  }

  [[noreturn]] void clip_failed(std::size_t subject, std::size_t clip, const std::exception& e) const {
    std::string problem = "polygon " + std::to_string(subject) + ": clipping by " + options_.clip_name + " polygon " +
                          std::to_string(clip) + " failed with kernel " + kernel_ + ": " + e.what();
    if (G::exact_constructions) problem += " (the exact kernel should never fail on valid input: a clipper bug)";
    else problem += " (try --kernel exact)";
    throw UserError(options_.subject_name, problem);
  }

  // Each subject is clipped on its own. The clip region is the union of the clip polygons, taken
  // one at a time: what lies inside clip polygon j is inside; what lies outside it goes on to
  // clip polygon j + 1; what is outside all of them is outside.
  void clip_all() {
    std::vector<clip::Polygon<K>> remaining = subjects_;
    std::vector<std::uint32_t> owner(subjects_.size());
    for (std::size_t p = 0; p < owner.size(); ++p) owner[p] = static_cast<std::uint32_t>(p);

    for (std::size_t j = 0; j < clips_.size() && !remaining.empty(); ++j) {
      options_.stop.check();
      std::vector<clip::ClipResult<K>> results;
      try {
        clip::ClipRegion<K> region(clips_[j], lines_);
        try {
          results = clip::clip_list<K>(std::span<const clip::Polygon<K>>(remaining), region);
        } catch (const std::exception& batch_error) {
          // Find the piece that fails, to name its subject polygon.
          for (std::size_t i = 0; i < remaining.size(); ++i) {
            try {
              (void)clip::clip_polygon<K>(remaining[i], region);
            } catch (const std::exception& e) {
              clip_failed(owner[i], j, e);
            }
          }
          clip_failed(owner.empty() ? 0 : owner[0], j, batch_error);
        }
      } catch (const UserError&) {
        throw;
      } catch (const std::exception& e) {  // the clip region itself could not be prepared
        clip_failed(owner.empty() ? 0 : owner[0], j, e);
      }
      if (results.size() != remaining.size())
        throw std::logic_error("clip_list returned " + std::to_string(results.size()) + " results for " +
                               std::to_string(remaining.size()) + " subjects");

      std::vector<clip::Polygon<K>> next;
      std::vector<std::uint32_t> next_owner;
      for (std::size_t i = 0; i < results.size(); ++i) {
        for (auto& piece : results[i].inside) inside_.push_back({std::move(piece), owner[i], static_cast<std::int64_t>(j)});
        for (auto& piece : results[i].outside) {
          next.push_back(std::move(piece));
          next_owner.push_back(owner[i]);
        }
      }
      remaining = std::move(next);
      owner = std::move(next_owner);
    }
    for (std::size_t i = 0; i < remaining.size(); ++i) outside_.push_back({std::move(remaining[i]), owner[i], -1});

    // Order by subject (then clip polygon), keeping the clipper's order within.
    std::stable_sort(inside_.begin(), inside_.end(),
                     [](const Piece<K>& a, const Piece<K>& b) { return a.subject < b.subject; });
    std::stable_sort(outside_.begin(), outside_.end(),
                     [](const Piece<K>& a, const Piece<K>& b) { return a.subject < b.subject; });
  }

  // A sum of many FT values, in G::Exact (see there).
  struct Sum {
    typename G::Exact value = 0;
    void add(const FT& v) { value += G::exact(v); }
    FT get() const { return FT(value); }
    bool operator==(const Sum& other) const { return value == other.value; }
  };

  // area(subject) = area(inside) + area(outside), per subject polygon, in the kernel's arithmetic.
  void check_areas() {
    std::vector<Sum> twice_in(subjects_.size()), twice_out(subjects_.size());
    for (const auto& piece : inside_) twice_in[piece.subject].add(clip::twice_area<K>(piece.polygon));
    for (const auto& piece : outside_) twice_out[piece.subject].add(clip::twice_area<K>(piece.polygon));
    Sum sub, in, out;
    identity_holds_ = true;
    for (std::size_t p = 0; p < subjects_.size(); ++p) {
      Sum twice_subject, pieces;
      twice_subject.add(clip::twice_area<K>(subjects_[p]));
      pieces.add(twice_in[p].get());
      pieces.add(twice_out[p].get());
      if (identity_holds_ && !(twice_subject == pieces)) {
        identity_holds_ = false;
        identity_failure_ = p;
      }
      sub.add(twice_subject.get());
      in.add(twice_in[p].get());
      out.add(twice_out[p].get());
    }
    subject_area_ = sub.get() / FT(2);
    inside_area_ = in.get() / FT(2);
    outside_area_ = out.get() / FT(2);
    discrepancy_ = G::to_double((in.get() + out.get() - sub.get()) / FT(2));
  }

  std::string identity_text() const {
    if (G::exact_constructions)
      return identity_holds_ ? "exact identity holds"
                             : "EXACT IDENTITY FAILS for polygon " + std::to_string(identity_failure_) +
                                   ": inside + outside - subject = " + number_text(discrepancy_);
    if (identity_holds_) return std::string("identity holds in ") + kernel_ + " arithmetic";
    return "identity off by " + number_text(discrepancy_) + " in " + kernel_ + " arithmetic";
  }

  // ---- the outcome, rounded once -------------------------------------------------------------

  double coordinate(const FT& v) const {
    double d = G::to_double(v);
    if (!std::isfinite(d))
      throw UserError(options_.subject_name, std::string("kernel ") + kernel_ +
                                                 " produced a non-finite coordinate in the result (try --kernel exact)");
    return d;
  }

  RawContour rounded(const clip::Contour<K>& contour) const {
    RawContour out;
    out.reserve(contour.points.size());
    for (const auto& p : contour.points) out.push_back({coordinate(G::x(p)), coordinate(G::y(p))});
    return out;
  }

  std::vector<ExactPoint2Text> exact_text(const clip::Contour<K>& contour) const {
    std::vector<ExactPoint2Text> out;
    for (const auto& p : contour.points) out.push_back({G::exact_string(G::x(p)), G::exact_string(G::y(p))});
    return out;
  }

  std::vector<EdgeSource> edges(const clip::Contour<K>& contour) const {
    std::vector<EdgeSource> out;
    for (clip::LineId id : contour.lines) {
      if (id >= sources_.size() || sources_[id].role == nullptr)
        throw std::logic_error("output edge lies on line " + std::to_string(id) + ", which is not an input edge");
      out.push_back(sources_[id]);
    }
    return out;
  }

  ClipPiece rounded(const Piece<K>& piece) const {
    ClipPiece out;
    out.subject = piece.subject;
    out.clip = piece.clip;
    out.polygon.outer = rounded(piece.polygon.outer);
    out.outer_edges = edges(piece.polygon.outer);
    if (options_.exact_values) out.outer_exact = exact_text(piece.polygon.outer);
    for (const auto& hole : piece.polygon.holes) {
      out.polygon.holes.push_back(rounded(hole));
      out.hole_edges.push_back(edges(hole));
      if (options_.exact_values) out.holes_exact.push_back(exact_text(hole));
    }
    return out;
  }

  ClipOutcome outcome(double seconds) const {
    ClipOutcome out;
    out.kernel = options_.kernel;
    out.exact_values = options_.exact_values;
    out.subjects = subjects_.size();
    out.clips = clips_.size();
    for (const auto& piece : inside_) out.inside.push_back(rounded(piece));
    for (const auto& piece : outside_) out.outside.push_back(rounded(piece));
    out.subject_area = G::to_double(subject_area_);
    out.inside_area = G::to_double(inside_area_);
    out.outside_area = G::to_double(outside_area_);
    if (options_.exact_values) {
      out.subject_area_exact = G::exact_string(subject_area_);
      out.inside_area_exact = G::exact_string(inside_area_);
      out.outside_area_exact = G::exact_string(outside_area_);
    }
    out.identity_holds = identity_holds_;
    out.identity_failure = identity_failure_;
    out.identity_text = identity_text();
    out.seconds = seconds;
    return out;
  }

  const std::vector<RawPolygon>& raw_subjects_;
  const std::vector<RawPolygon>& raw_clips_;
  const ClipOptions& options_;
  const char* kernel_;
  clip::LineTable<K> lines_;
  std::vector<EdgeSource> sources_;  // indexed by LineId
  std::vector<clip::Polygon<K>> subjects_, clips_;
  std::vector<Piece<K>> inside_, outside_;
  FT subject_area_ = FT(0), inside_area_ = FT(0), outside_area_ = FT(0);
  double discrepancy_ = 0;
  bool identity_holds_ = true;
  std::size_t identity_failure_ = 0;
};

}  // namespace hlr::exporter::clip_detail

namespace hlr::exporter {
ClipOutcome clip_polygons_exact(const std::vector<RawPolygon>&, const std::vector<RawPolygon>&, const ClipOptions&);
ClipOutcome clip_polygons_epick(const std::vector<RawPolygon>&, const std::vector<RawPolygon>&, const ClipOptions&);
ClipOutcome clip_polygons_double(const std::vector<RawPolygon>&, const std::vector<RawPolygon>&, const ClipOptions&);
}  // namespace hlr::exporter
