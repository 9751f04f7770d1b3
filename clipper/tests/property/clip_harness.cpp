// Kernel-independent, exact judging of clipper output against CGAL's Boolean operations.
#include "clip_harness.hpp"

#include <cell_oracle.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hlr::testing {

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::pass: return "pass";
    case Verdict::input_rejected: return "input rejected";
    case Verdict::clip_error: return "ClipError";
    case Verdict::exception: return "exception";
    case Verdict::invalid_output: return "invalid output";
    case Verdict::bad_provenance: return "bad provenance";
    case Verdict::wrong_result: return "wrong result";
    case Verdict::bad_area: return "bad area";
  }
  return "?";
}

namespace {

constexpr double kUlp = 0x1.0p-53;

std::vector<EPolygon> polygons_of(const std::vector<ExactOutputPolygon>& ps) {
  std::vector<EPolygon> out;
  out.reserve(ps.size());
  for (const auto& p : ps) out.push_back(p.polygon);
  return out;
}

double to_d(const EFT& v) { return CGAL::to_double(v); }

// Distance from p to the segment ab, in double (a measurement, not a decision).
double distance_to_segment(const EPoint& pe, const EPoint& ae, const EPoint& be) {
  const double px = to_d(pe.x()), py = to_d(pe.y()), ax = to_d(ae.x()), ay = to_d(ae.y()), bx = to_d(be.x()),
               by = to_d(be.y());
  const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(ax + t * dx - px, ay + t * dy - py);
}

const std::vector<const EContour*> contours_of(const EPolygon& p) {
  std::vector<const EContour*> v{&p.outer};
  for (const auto& h : p.holes) v.push_back(&h);
  return v;
}

std::string contour_name(std::size_t c) { return c == 0 ? "outer contour" : "hole " + std::to_string(c - 1); }

}  // namespace

Evaluation judge(const RawPolygon& subject, const RawPolygon& clip, const ExactOutput& out, const JudgeOptions& options) {
  Evaluation e;
  e.inside_pieces = out.inside.size();
  e.outside_pieces = out.outside.size();
  auto fail = [&](Verdict v, std::string message) {
    e.verdict = v;
    e.message = std::move(message);
    return e;
  };
  const double scale = std::max({1.0, max_abs_coordinate(subject), max_abs_coordinate(clip)});

  // 1. structure and validity of every piece.
  for (int list = 0; list < 2; ++list) {
    const auto& pieces = list == 0 ? out.inside : out.outside;
    const std::string list_name = list == 0 ? "inside" : "outside";
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const auto& piece = pieces[k];
      const std::string name = list_name + " piece " + std::to_string(k);
      if (piece.point_counts_mismatch) return fail(Verdict::invalid_output, name + ": a contour has lines.size() != points.size()");
      if (piece.lines.size() != 1 + piece.polygon.holes.size()) return fail(Verdict::invalid_output, name + ": contour count mismatch");
      for (std::size_t c = 0; c < piece.lines.size(); ++c)
        for (clip::LineId l : piece.lines[c])
          if (l >= out.lines.size())
            return fail(Verdict::invalid_output, name + " " + contour_name(c) + " names line " + std::to_string(l) +
                                                     ", the table has " + std::to_string(out.lines.size()));
      if (auto d = polygon_defect(piece.polygon, true)) return fail(Verdict::invalid_output, name + ": " + *d);
    }
  }

  // 2. provenance: every edge lies on the input edge it names.
  for (int list = 0; list < 2; ++list) {
    const auto& pieces = list == 0 ? out.inside : out.outside;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const auto contours = contours_of(pieces[k].polygon);
      for (std::size_t c = 0; c < contours.size(); ++c) {
        const EContour& pts = *contours[c];
        const auto& ids = pieces[k].lines[c];
        for (std::size_t i = 0, n = pts.size(); i < n; ++i) {
          const EPoint& p = pts[i];
          const EPoint& q = pts[i + 1 == n ? 0 : i + 1];
          const auto& [a, b] = out.lines[ids[i]];
          if (segment_within(a, b, p, q)) continue;
          const std::string where = std::string(list == 0 ? "inside" : "outside") + " piece " + std::to_string(k) + " " +
                                    contour_name(c) + " edge " + std::to_string(i) + " does not lie on input edge " +
                                    std::to_string(ids[i]);
          if (options.exact_kernel) return fail(Verdict::bad_provenance, where);
          const double tol = 1e3 * kUlp * scale;
          const double dp = distance_to_segment(p, a, b), dq = distance_to_segment(q, a, b);
          if (dp <= tol && dq <= tol) {
            e.provenance_rounded = true;
          } else {
            std::ostringstream m;
            m << where << " (not even up to rounding: its ends are " << dp << " and " << dq
              << " away from the input edge, tolerance " << tol << ")";
            return fail(Verdict::bad_provenance, m.str());
          }
        }
      }
    }
  }

  // 3. the oracles: CGAL's Boolean operations, and the cell oracle, which decides when they
  // disagree (CGAL 5.5.1 gets some touching-hole configurations wrong; see cell_oracle.hpp).
  const std::vector<EPolygon> inside = polygons_of(out.inside), outside = polygons_of(out.outside);
  const EPolygon subject_e = to_exact(subject), clip_e = to_exact(clip);
  const CellCheck cells = check_cells(subject_e, clip_e, inside, outside);
  const ExactRegion s = ExactRegion::from(subject), c = ExactRegion::from(clip);
  const ExactRegion want_in = s.intersection(c), want_out = s.difference(c);
  const ExactRegion got_in = ExactRegion::from(inside), got_out = ExactRegion::from(outside);
  const ExactRegion xor_in = want_in.symmetric_difference(got_in), xor_out = want_out.symmetric_difference(got_out);
  const EFT subject_area = twice_area(subject_e);
  const EFT in_area = twice_area(inside), out_area = twice_area(outside);
  // CGAL can be wrong twice in the same way (its S − C and its union of the pieces): compare the
  // areas of its sets with the pieces' areas too.
  const bool cgal_agrees = xor_in.empty() && xor_out.empty() && in_area == want_in.twice_area() &&
                           out_area == want_out.twice_area();
  auto cgal_summary = [&]() {
    std::ostringstream m;
    m << "CGAL's Boolean operations " << (cgal_agrees ? "agree with the output" : "differ from the output")
      << ": inside xor has " << xor_in.polygon_count() << " pieces (twice area " << to_d(xor_in.twice_area())
      << "), outside xor has " << xor_out.polygon_count() << " pieces (twice area " << to_d(xor_out.twice_area())
      << "); CGAL inside has " << want_in.polygon_count() << " pieces, twice area " << to_d(want_in.twice_area())
      << "; CGAL outside has " << want_out.polygon_count() << " pieces, twice area " << to_d(want_out.twice_area())
      << "; twice area of the subject " << to_d(subject_area) << "; of the inside pieces " << to_d(in_area)
      << ", of the outside pieces " << to_d(out_area);
    if (!xor_in.empty()) m << "; inside xor: " << to_exact_json(xor_in.polygons());
    if (!xor_out.empty()) m << "; outside xor: " << to_exact_json(xor_out.polygons());
    return m.str();
  };
  if (!cells.ok) {
    const EFT wrong = cells.wrong_inside_twice_area + cells.wrong_outside_twice_area;
    e.xor_relative_area = to_d(wrong) / to_d(subject_area);
    const double rounding = 2 * 1e3 * kUlp * scale * (perimeter(subject) + perimeter(clip));
    e.xor_rounding_level = !cells.overlap && to_d(wrong) <= rounding;
    std::ostringstream m;
    m << (cells.overlap ? "pieces of one list overlap " : "differs from S∩C / S−C ") << cells.message
      << "; twice the wrong area: inside " << to_d(cells.wrong_inside_twice_area) << ", outside "
      << to_d(cells.wrong_outside_twice_area) << "; " << cgal_summary();
    return fail(cells.overlap ? Verdict::bad_area : Verdict::wrong_result, m.str());
  }
  if (!cgal_agrees) {
    // The cell oracle found every cell right: CGAL is wrong here. Not a clipper failure.
    e.oracle_disagreement = true;
    e.message = "cell oracle: output right; " + cgal_summary();
  }

  // 4. areas add up to the subject, exactly, and the clipper's own twice_area agrees.
  if (in_area + out_area != subject_area)
    return fail(Verdict::bad_area, "twice_area(inside) + twice_area(outside) != twice_area(subject)");
  for (int list = 0; list < 2; ++list) {
    const auto& pieces = list == 0 ? out.inside : out.outside;
    for (std::size_t k = 0; k < pieces.size(); ++k)
      if (pieces[k].kernel_twice_area && *pieces[k].kernel_twice_area != twice_area(pieces[k].polygon))
        return fail(Verdict::bad_area, std::string("clip::twice_area disagrees with the exact area of ") +
                                           (list == 0 ? "inside" : "outside") + " piece " + std::to_string(k));
  }
  return e;
}

std::optional<std::string> compare_results(const ExactOutput& a, const ExactOutput& b) {
  if (a.inside.size() != b.inside.size() || a.outside.size() != b.outside.size())
    return "piece counts differ: inside " + std::to_string(a.inside.size()) + " vs " + std::to_string(b.inside.size()) +
           ", outside " + std::to_string(a.outside.size()) + " vs " + std::to_string(b.outside.size());
  for (const auto& p : a.inside)
    if (auto d = polygon_defect(p.polygon, true)) return "first result invalid: " + *d;
  for (const auto& p : a.outside)
    if (auto d = polygon_defect(p.polygon, true)) return "first result invalid: " + *d;
  for (const auto& p : b.inside)
    if (auto d = polygon_defect(p.polygon, true)) return "second result invalid: " + *d;
  for (const auto& p : b.outside)
    if (auto d = polygon_defect(p.polygon, true)) return "second result invalid: " + *d;
  if (auto d = coverage_difference(polygons_of(a.inside), polygons_of(b.inside))) return "inside lists differ " + *d;
  if (auto d = coverage_difference(polygons_of(a.outside), polygons_of(b.outside))) return "outside lists differ " + *d;
  return std::nullopt;
}

std::string describe_case(const RawPolygon& subject, const RawPolygon& clip) {
  return "subject and clip, hlr-polygons/1 (17 digits, exact):\n  subject: " + to_json({subject}) + "\n  clip:    " +
         to_json({clip}) + "\nas C++ (RawPolygon initializers, exact):\n  subject: " + to_cpp(subject) +
         "\n  clip:    " + to_cpp(clip) + "\nboth, as input for clipper_minimize:\n  " + to_json({subject, clip}) + "\n";
}

std::string describe_output(const ExactOutput& out) {
  return "output (exact): inside " + to_exact_json(polygons_of(out.inside)) + "\n  outside " +
         to_exact_json(polygons_of(out.outside)) + "\n";
}

}  // namespace hlr::testing
