// The template behind run_clip_<kernel> (clip_run.hpp). Included only by clip_run_<kernel>.cpp.
//
// The app only converts and reports: every geometric decision (validity, orientation, clipping,
// areas) is the clipper's, made in the kernel's arithmetic.
#pragma once

#include "atomic_file.hpp"
#include "clip_run.hpp"
#include "errors.hpp"

#include <hlr/clipper/clipper.hpp>
#include <hlr/kernel/kernel.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace hlr::app::clip_detail {

// Where an input edge came from: edge `edge` (input vertex edge -> edge + 1, in the input's own
// order and numbering) of contour `contour` (0 = outer, h + 1 = hole h) of polygon `polygon` of the
// subject or the clip file.
struct EdgeSource {
  const char* role = nullptr;  // "subject" | "clip"; nullptr: the line is not an input edge
  std::uint32_t polygon = 0, contour = 0, edge = 0;
};

// A piece of the result and where it came from.
template <class K>
struct Piece {
  clip::Polygon<K> polygon;
  std::uint32_t subject = 0;  // index of the subject polygon it is part of
  std::int64_t clip = -1;     // inside pieces: index of the clip polygon it is inside of
};

inline std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The shortest text that reads back as the same double; plain decimals for everyday magnitudes
// ("100000", not "1e+05").
inline std::string number_text(double v) {
  char buffer[512];
  const double a = std::fabs(v);
  auto result = (a == 0 || (a >= 1e-6 && a < 1e16))
                    ? std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed)
                    : std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

// FT's exact number type when it is a lazy number, else FT itself.
template <class FT, bool lazy>
struct ExactTypeOf {
  using type = FT;
};
template <class FT>
struct ExactTypeOf<FT, true> {
  using type = typename FT::Exact_type;
};

template <class K>
class ClipRun {
 public:
  using G = Geometry<K>;
  using FT = typename G::FT;
  using Point = typename G::Point;

  ClipRun(const ClipJob& job, const char* kernel) : job_(job), kernel_(kernel) {}

  int run() {
    // Every input edge becomes a line of one shared table; the table is complete before the clip
    // regions are built (they keep a reference to it).
    for (std::size_t p = 0; p < job_.subjects.size(); ++p)
      subjects_.push_back(build_polygon(job_.subjects[p], "subject", p, job_.subject_path));
    for (std::size_t p = 0; p < job_.clips.size(); ++p)
      clips_.push_back(build_polygon(job_.clips[p], "clip", p, job_.clip_path));

    // Fail early on an output that cannot be written, before the clipping work.
    AtomicFile output(job_.output_path);

    auto start = std::chrono::steady_clock::now();
    clip_all();
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    check_areas();
    output.write(document());
    output.commit();

    std::ostream& out = *job_.summary;
    out << "hlr clip: " << plural(subjects_.size(), "subject polygon", "subject polygons") << ", "
        << plural(clips_.size(), "clip polygon", "clip polygons") << ", kernel " << kernel_ << "\n";
    out << "inside: " << plural(inside_.size(), "polygon", "polygons") << ", area " << area_text(inside_area_)
        << "; outside: " << plural(outside_.size(), "polygon", "polygons") << ", area "
        << area_text(outside_area_) << "; subject area " << area_text(subject_area_) << " (" << identity_text()
        << ")\n";
    out << "wrote " << job_.output_path << "\n";
    out.flush();

    if (!identity_holds_ && G::exact_constructions) {
      std::cerr << "hlr: " << job_.subject_path << ": internal error: area(inside) + area(outside) != area(subject) for polygon "
                << identity_failure_ << " with the exact kernel (a clipper bug; the result was written for inspection)\n";
      return kExitContract;
    }
    return kExitOk;
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
    std::string problem = "polygon " + std::to_string(subject) + ": clipping by " + job_.clip_path + " polygon " +
                          std::to_string(clip) + " failed with kernel " + kernel_ + ": " + e.what();
    if (G::exact_constructions) problem += " (the exact kernel should never fail on valid input: a clipper bug)";
    else problem += " (try --kernel exact)";
    throw UserError(job_.subject_path, problem);
  }

  // Each subject is clipped on its own. The clip region is the union of the clip polygons, taken
  // one at a time: what lies inside clip polygon j is inside; what lies outside it goes on to
  // clip polygon j + 1; what is outside all of them is outside.
  void clip_all() {
    std::vector<clip::Polygon<K>> remaining = subjects_;
    std::vector<std::uint32_t> owner(subjects_.size());
    for (std::size_t p = 0; p < owner.size(); ++p) owner[p] = static_cast<std::uint32_t>(p);

    for (std::size_t j = 0; j < clips_.size() && !remaining.empty(); ++j) {
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

  // A sum of many FT values. With the exact kernel it is kept in the exact number type: a sum of
  // lazy numbers is a chain as deep as it is long, and evaluating a chain of 10^5 lazy additions
  // exactly (which an equality test of equal values always does) recurses deep enough to overflow
  // the stack.
  struct Sum {
    static constexpr bool exact = G::exact_constructions;
    using Value = typename ExactTypeOf<FT, exact>::type;
    Value value = Value(0);
    void add(const FT& v) {
      if constexpr (exact) value += CGAL::exact(v);
      else value += v;
    }
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

  static std::string area_text(const FT& v) { return number_text(G::to_double(v)); }

  // ---- hlr-clip/1 -----------------------------------------------------------------------------

  double coordinate(const FT& v) const {
    double d = G::to_double(v);
    if (!std::isfinite(d))
      throw UserError(job_.subject_path, std::string("kernel ") + kernel_ +
                                             " produced a non-finite coordinate in the result (try --kernel exact)");
    return d;
  }

  nlohmann::json points_json(const clip::Contour<K>& contour) const {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& p : contour.points) a.push_back({coordinate(G::x(p)), coordinate(G::y(p))});
    return a;
  }

  nlohmann::json exact_json(const clip::Contour<K>& contour) const {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& p : contour.points) a.push_back({G::exact_string(G::x(p)), G::exact_string(G::y(p))});
    return a;
  }

  nlohmann::json edges_json(const clip::Contour<K>& contour) const {
    nlohmann::json a = nlohmann::json::array();
    for (clip::LineId id : contour.lines) {
      if (id >= sources_.size() || sources_[id].role == nullptr)
        throw std::logic_error("output edge lies on line " + std::to_string(id) + ", which is not an input edge");
      const EdgeSource& s = sources_[id];
      a.push_back({s.role, s.polygon, s.contour, s.edge});
    }
    return a;
  }

  template <class F>
  nlohmann::json holes_json(const clip::Polygon<K>& polygon, F&& contour_json) const {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& hole : polygon.holes) a.push_back(contour_json(hole));
    return a;
  }

  void write_piece(std::string& out, const Piece<K>& piece) const {
    const auto& poly = piece.polygon;
    out += "    {\"subject\": " + std::to_string(piece.subject);
    if (piece.clip >= 0) out += ", \"clip\": " + std::to_string(piece.clip);
    out += ",\n     \"outer\": " + points_json(poly.outer).dump();
    out += ",\n     \"holes\": " + holes_json(poly, [&](const auto& c) { return points_json(c); }).dump();
    out += ",\n     \"outer_edges\": " + edges_json(poly.outer).dump();
    out += ",\n     \"holes_edges\": " + holes_json(poly, [&](const auto& c) { return edges_json(c); }).dump();
    if (job_.exact_output) {
      out += ",\n     \"outer_exact\": " + exact_json(poly.outer).dump();
      out += ",\n     \"holes_exact\": " + holes_json(poly, [&](const auto& c) { return exact_json(c); }).dump();
    }
    out += "}";
  }

  void write_list(std::string& out, const char* name, const std::vector<Piece<K>>& pieces) const {
    out += std::string("  \"") + name + "\": [";
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      out += i == 0 ? "\n" : ",\n";
      write_piece(out, pieces[i]);
    }
    out += pieces.empty() ? "],\n" : "\n  ],\n";
  }

  std::string document() const {
    std::string out;
    out += "{\n  \"format\": \"hlr-clip/1\",\n";
    out += std::string("  \"kernel\": \"") + kernel_ + "\",\n";
    write_list(out, "inside", inside_);
    write_list(out, "outside", outside_);
    nlohmann::ordered_json stats;
    stats["subject_polygons"] = subjects_.size();
    stats["clip_polygons"] = clips_.size();
    stats["inside_polygons"] = inside_.size();
    stats["outside_polygons"] = outside_.size();
    stats["subject_area"] = G::to_double(subject_area_);
    stats["inside_area"] = G::to_double(inside_area_);
    stats["outside_area"] = G::to_double(outside_area_);
    if (job_.exact_output) {
      stats["subject_area_exact"] = G::exact_string(subject_area_);
      stats["inside_area_exact"] = G::exact_string(inside_area_);
      stats["outside_area_exact"] = G::exact_string(outside_area_);
    }
    stats["area_identity"] = identity_holds_;
    stats["seconds"] = seconds_;
    out += "  \"stats\": " + stats.dump() + "\n}\n";
    return out;
  }

  const ClipJob& job_;
  const char* kernel_;
  clip::LineTable<K> lines_;
  std::vector<EdgeSource> sources_;  // indexed by LineId
  std::vector<clip::Polygon<K>> subjects_, clips_;
  std::vector<Piece<K>> inside_, outside_;
  FT subject_area_ = FT(0), inside_area_ = FT(0), outside_area_ = FT(0);
  double discrepancy_ = 0;
  bool identity_holds_ = true;
  std::size_t identity_failure_ = 0;
  double seconds_ = 0;
};

}  // namespace hlr::app::clip_detail
