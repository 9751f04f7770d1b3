// Invariant checks of a hidden-surface solution against the independent oracle (surface_checks.hpp).
#include "surface_checks.hpp"

#include <oracle.hpp>  // tests/support: ExactRegion (CGAL Polygon_set_2 on Epeck)

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace hlr::hltest {

std::size_t CheckReport::failure_count() const {
  std::size_t n = 0;
  for (const auto& [kind, count] : failures) n += count;
  return n;
}

std::string CheckReport::summary() const {
  std::ostringstream out;
  out << visible_checked << " visible and " << hidden_checked << " hidden fragments checked";
  append_outcome(out, notes, failures, messages);
  return out.str();
}

namespace {

std::string exact(const FT& v) { return exact_rational_string(v); }
std::string point_text(const P2& p) { return "(" + exact(p.x()) + ", " + exact(p.y()) + ")"; }

std::string contour_text(const std::vector<P2>& c) {
  std::string s = "[";
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (i == 12 && c.size() > 14) {
      s += ", ... " + std::to_string(c.size() - 12) + " more";
      break;
    }
    s += (i ? ", " : "") + point_text(c[i]);
  }
  return s + "]";
}

double relative(const FT& got, const FT& want) {
  const double d = std::abs(CGAL::to_double(got - want));
  const double scale = std::max(std::abs(CGAL::to_double(want)), 1e-300);
  return d / scale;
}

class Checker {
 public:
  Checker(const SceneOracle& oracle, const XMap& map, const CheckOptions& options, CheckReport& report)
      : oracle_(oracle), map_(map), options_(options), report_(report) {}

  void run() {
    if (!indices()) return;
    sources();
    fragments();
    if (options_.region_checks) regions();
    points();
  }

 private:
  void fail(const std::string& kind, const std::string& message) {
    ++report_.failures[kind];
    if (report_.messages.size() < options_.max_messages) report_.messages.push_back(kind + ": " + message);
  }
  void note(const std::string& kind, std::size_t n = 1) { report_.notes[kind] += n; }

  // An area identity: exact on the exact kernel; on inexact kernels a relative error up to 1e-9 is
  // rounding, noted, not a failure.
  // `scale` (when given) is the area the error is relative to, for identities whose wanted value is
  // zero (the area of a symmetric difference).
  void area_identity(const std::string& kind, const FT& got, const FT& want, const std::string& what,
                     const FT* scale = nullptr) {
    if (got == want) return;
    const double rel = scale ? relative(got - want + *scale, *scale) : relative(got, want);
    if (!options_.exact && rel <= 1e-9) {
      note("rounding: " + kind);
      return;
    }
    std::ostringstream m;
    m << what << ": " << exact(got) << " != " << exact(want) << " (relative error " << rel << ")";
    fail(kind, m.str());
  }

  bool indices() {
    const std::size_t n = map_.sources.size();
    bool ok = true;
    for (std::size_t i = 0; i < map_.visible.size(); ++i) {
      const auto& f = map_.visible[i];
      if (f.source >= n || f.occluder != -1) {
        fail("fragment indices", "visible " + std::to_string(i) + " source " + std::to_string(f.source) +
                                     " occluder " + std::to_string(f.occluder));
        ok = false;
      }
    }
    for (std::size_t i = 0; i < map_.hidden.size(); ++i) {
      const auto& f = map_.hidden[i];
      if (f.source >= n || f.occluder < 0 || static_cast<std::size_t>(f.occluder) >= n ||
          static_cast<std::uint32_t>(f.occluder) == f.source) {
        fail("fragment indices", "hidden " + std::to_string(i) + " source " + std::to_string(f.source) +
                                     " occluder " + std::to_string(f.occluder));
        ok = false;
      }
    }
    for (std::size_t s = 0; s < n; ++s) {
      const auto& src = map_.sources[s];
      bool bad = src.mesh >= oracle_.mesh_count() || src.faces.empty();
      for (std::uint32_t f : src.faces) bad = bad || src.mesh >= oracle_.mesh_count() || f >= oracle_.face_count(src.mesh);
      if (bad) {
        fail("source indices", "source " + std::to_string(s));
        ok = false;
      }
    }
    return ok;
  }

  void sources() {
    // Group sources by face list: a consolidated group may come out as several polygons.
    std::map<std::pair<std::uint32_t, std::vector<std::uint32_t>>, std::uint32_t> group_of_list;
    group_.resize(map_.sources.size());
    face_group_.assign(oracle_.mesh_count(), {});
    for (std::uint32_t m = 0; m < oracle_.mesh_count(); ++m) face_group_[m].assign(oracle_.face_count(m), -1);
    std::vector<FT> group_area, group_face_area;
    std::set<FaceRef> listed;
    for (std::uint32_t s = 0; s < map_.sources.size(); ++s) {
      const XSource& src = map_.sources[s];
      auto [it, fresh] = group_of_list.try_emplace({src.mesh, src.faces}, static_cast<std::uint32_t>(group_area.size()));
      const std::uint32_t g = it->second;
      group_[s] = g;
      if (fresh) {
        group_area.push_back(0);
        FT faces_area = 0;
        for (std::uint32_t f : src.faces) {
          if (face_group_[src.mesh][f] != -1)
            fail("sources: a face in two groups", "mesh " + std::to_string(src.mesh) + " face " + std::to_string(f));
          face_group_[src.mesh][f] = static_cast<std::int32_t>(g);
          listed.insert({src.mesh, f});
          faces_area += CGAL::abs(oracle_.face({src.mesh, f}).twice_projected_area);
        }
        group_face_area.push_back(faces_area);
      }
      group_area[g] = group_area[g] + testing::twice_area(src.polygon);
      if (auto defect = testing::polygon_defect(src.polygon, true)) {
        fail("sources: invalid polygon", "source " + std::to_string(s) + " " + *defect);
        sources_valid_ = false;
      }
      // The plane of the source is the plane of each of its faces.
      const auto& first = oracle_.face({src.mesh, src.faces.front()});
      source_plane_.push_back(first.plane);
      if (options_.exact) {
        for (std::uint32_t f : src.faces) {
          const auto& face = oracle_.face({src.mesh, f});
          if (face.facing == 0) continue;  // reported as a kept-faces mismatch below
          if (!same_plane(face.plane, src.plane)) {
            fail("sources: plane", "source " + std::to_string(s) + " mesh " + std::to_string(src.mesh) + " face " +
                                       std::to_string(f) + " lies in z = " + exact(face.plane.a) + " x + " +
                                       exact(face.plane.b) + " y + " + exact(face.plane.c) + ", the source says z = " +
                                       exact(src.plane.a) + " x + " + exact(src.plane.b) + " y + " + exact(src.plane.c));
            break;
          }
        }
      }
    }
    for (const auto& [key, g] : group_of_list)
      area_identity("sources: area", group_area[g], group_face_area[g],
                    "faces of mesh " + std::to_string(key.first) + " starting at face " + std::to_string(key.second.front()) +
                        ": source area vs sum of projected face areas");
    // Kept faces: exactly those the oracle expects.
    std::size_t missing = 0, extra = 0;
    std::string first_missing, first_extra;
    for (std::uint32_t m = 0; m < oracle_.mesh_count(); ++m)
      for (std::uint32_t f = 0; f < oracle_.face_count(m); ++f) {
        const bool want = oracle_.kept({m, f}, options_.remove_back_faces);
        const bool have = listed.count({m, f}) > 0;
        if (want && !have && missing++ == 0) first_missing = "mesh " + std::to_string(m) + " face " + std::to_string(f);
        if (!want && have && extra++ == 0) first_extra = "mesh " + std::to_string(m) + " face " + std::to_string(f);
      }
    if (missing) fail("sources: kept faces", std::to_string(missing) + " faces missing, first " + first_missing);
    if (extra) fail("sources: kept faces", std::to_string(extra) + " faces that must be dropped, first " + first_extra);
  }

  void fragments() {
    const std::size_t n = map_.sources.size();
    valid_visible_.assign(map_.visible.size(), true);
    valid_hidden_.assign(map_.hidden.size(), true);
    std::vector<FT> sum(n, FT(0));
    auto visit = [&](const std::vector<XFragment>& list, std::vector<bool>& valid, const char* what) {
      for (std::size_t i = 0; i < list.size(); ++i) {
        const XFragment& f = list[i];
        if (auto defect = testing::polygon_defect(f.polygon, true)) {
          valid[i] = false;
          fail("fragment: invalid polygon", std::string(what) + " " + std::to_string(i) + " of source " +
                                                std::to_string(f.source) + ": " + *defect + " " + describe(f.polygon));
        }
        sum[f.source] = FT(CGAL::exact(sum[f.source]) + CGAL::exact(testing::twice_area(f.polygon)));
      }
    };
    visit(map_.visible, valid_visible_, "visible");
    visit(map_.hidden, valid_hidden_, "hidden");
    for (std::size_t s = 0; s < n; ++s)
      area_identity("(a) fragment areas", sum[s], testing::twice_area(map_.sources[s].polygon),
                    "source " + std::to_string(s) + ": visible + hidden fragments vs source");
  }

  void regions() {
    const std::size_t n = map_.sources.size();
    bool all_valid = std::all_of(valid_visible_.begin(), valid_visible_.end(), [](bool b) { return b; }) &&
                     std::all_of(valid_hidden_.begin(), valid_hidden_.end(), [](bool b) { return b; });
    if (!all_valid || !sources_valid_) {
      note("region checks skipped: invalid polygons");
      return;
    }
    // (a) in region form: each source is exactly the union of its fragments.
    std::vector<std::vector<EPolygon>> pieces(n);
    for (const auto& f : map_.visible) pieces[f.source].push_back(f.polygon);
    for (const auto& f : map_.hidden) pieces[f.source].push_back(f.polygon);
    // Each face group's polygons are exactly the union of its faces' projections.
    std::map<std::pair<std::uint32_t, std::vector<std::uint32_t>>, std::vector<EPolygon>> groups;
    for (const auto& src : map_.sources) groups[{src.mesh, src.faces}].push_back(src.polygon);
    for (const auto& [key, polygons] : groups) {
      std::vector<EPolygon> faces;
      for (std::uint32_t f : key.second) {
        const auto& face = oracle_.face({key.first, f});
        if (face.facing != 0) faces.push_back({face.points, {}});
      }
      const auto diff = testing::ExactRegion::from(polygons).symmetric_difference(testing::ExactRegion::from(faces));
      if (!diff.empty()) {
        const FT scale = testing::twice_area(polygons);
        area_identity("sources: region", diff.twice_area(), FT(0),
                      "mesh " + std::to_string(key.first) + " faces from " + std::to_string(key.second.front()) +
                          ": symmetric difference of the source polygon(s) and the union of the faces",
                      &scale);
      }
    }
    for (std::size_t s = 0; s < n; ++s) {
      const auto whole = testing::ExactRegion::from(map_.sources[s].polygon);
      const auto parts = testing::ExactRegion::from(pieces[s]);
      const auto diff = whole.symmetric_difference(parts);
      if (!diff.empty()) {
        const FT scale = testing::twice_area(map_.sources[s].polygon);
        area_identity("(a) fragments cover the source", diff.twice_area(), FT(0),
                      "source " + std::to_string(s) + ": symmetric difference of the fragments' union and the source",
                      &scale);
      }
    }
    // (b) visible fragments do not overlap, and cover the union of the sources.
    std::vector<EPolygon> visible, all;
    FT sum = 0;
    for (const auto& f : map_.visible) {
      visible.push_back(f.polygon);
      sum = FT(CGAL::exact(sum) + CGAL::exact(testing::twice_area(f.polygon)));
    }
    for (const auto& s : map_.sources) all.push_back(s.polygon);
    const auto visible_union = testing::ExactRegion::from(visible);
    const FT union_area = visible_union.twice_area();
    area_identity("(b) visible fragments overlap", sum, union_area, "sum of visible areas vs area of their union");
    const auto sources_union = testing::ExactRegion::from(all);
    const auto diff = visible_union.symmetric_difference(sources_union);
    if (!diff.empty()) {
      const auto uncovered = sources_union.difference(visible_union);
      std::string where;
      if (!uncovered.empty()) where = " uncovered part, e.g. " + describe(uncovered.polygons().front());
      area_identity("(b) visible union != sources union", diff.twice_area(), FT(0),
                    "area of the symmetric difference" + where, &union_area);
    }
  }

  bool in_group(const std::vector<FaceRef>& faces, std::uint32_t source) const {
    const XSource& src = map_.sources[source];
    for (const FaceRef& f : faces)
      if (f.mesh == src.mesh && face_group_[f.mesh][f.face] == static_cast<std::int32_t>(group_[source])) return true;
    return false;
  }

  std::string fragment_text(const char* what, std::size_t i, const XFragment& f, const P2& q) const {
    std::string s = std::string(what) + " fragment " + std::to_string(i) + " of source " + std::to_string(f.source);
    const XSource& src = map_.sources[f.source];
    s += " (mesh " + std::to_string(src.mesh) + ", faces";
    for (std::size_t k = 0; k < src.faces.size() && k < 6; ++k) s += " " + std::to_string(src.faces[k]);
    if (src.faces.size() > 6) s += " ...";
    s += ")";
    if (f.occluder >= 0) s += ", occluder " + std::to_string(f.occluder);
    return s + ", at q = " + point_text(q) + ", polygon " + describe(f.polygon);
  }

  void points() {
    auto visit = [&](const std::vector<XFragment>& list, const std::vector<bool>& valid, bool visible) {
      const char* what = visible ? "visible" : "hidden";
      for (std::size_t i = 0; i < list.size(); ++i) {
        const XFragment& f = list[i];
        auto q = interior_point(f.polygon.outer, f.polygon.holes);
        if (!q || !strictly_inside(f.polygon.outer, f.polygon.holes, *q)) {
          fail("interior point", std::string(what) + " " + std::to_string(i) + (valid[i] ? "" : " (invalid polygon)") +
                                     ": none found " + describe(f.polygon));
          continue;
        }
        ++(visible ? report_.visible_checked : report_.hidden_checked);
        const auto probe = oracle_.probe(*q);
        const FT zs = source_plane_[f.source].at(*q);
        if (!in_group(probe.faces, f.source)) {
          fail(visible ? "(c) point outside its source" : "(d) point outside its source", fragment_text(what, i, f, *q));
          continue;
        }
        if (visible) {
          if (*probe.max_z != zs)
            fail("(c) a face is strictly nearer", fragment_text(what, i, f, *q) + ": source depth " + exact(zs) +
                                                     ", nearest face depth " + exact(*probe.max_z));
          continue;
        }
        const auto o = static_cast<std::uint32_t>(f.occluder);
        if (!in_group(probe.faces, o)) {
          fail("(d) point outside the occluder", fragment_text(what, i, f, *q));
          continue;
        }
        const FT zo = source_plane_[o].at(*q);
        if (zo > zs) continue;
        if (zo == zs && o < f.source && same_plane(source_plane_[o], source_plane_[f.source])) {
          note("hidden by a coplanar tie");
          continue;
        }
        fail("(d) occluder not strictly nearer", fragment_text(what, i, f, *q) + ": source depth " + exact(zs) +
                                                   ", occluder depth " + exact(zo));
      }
    };
    visit(map_.visible, valid_visible_, true);
    visit(map_.hidden, valid_hidden_, false);
  }

  const SceneOracle& oracle_;
  const XMap& map_;
  const CheckOptions& options_;
  CheckReport& report_;
  std::vector<std::uint32_t> group_;                  // per source: its face group
  std::vector<std::vector<std::int32_t>> face_group_;  // per mesh, per face: group or -1
  std::vector<Plane> source_plane_;                   // per source: the oracle's plane of its first face
  std::vector<bool> valid_visible_, valid_hidden_;
  bool sources_valid_ = true;
};

}  // namespace

std::string describe(const EPolygon& p) {
  std::string s = "outer " + contour_text(p.outer);
  for (const auto& h : p.holes) s += " hole " + contour_text(h);
  return s;
}

CheckReport check_map(const SceneOracle& oracle, const XMap& map, const CheckOptions& options) {
  CheckReport report;
  Checker(oracle, map, options, report).run();
  return report;
}

void append_outcome(std::ostream& out, const std::map<std::string, std::size_t>& notes,
                    const std::map<std::string, std::size_t>& failures, const std::vector<std::string>& messages) {
  for (const auto& [kind, count] : notes) out << "; " << kind << ": " << count;
  if (failures.empty()) {
    out << "; no failure";
    return;
  }
  out << "\nFAILURES:";
  for (const auto& [kind, count] : failures) out << "\n  " << kind << ": " << count;
  for (const auto& m : messages) out << "\n  - " << m;
}

}  // namespace hlr::hltest
