// clip_polygons by kernel, and the hlr-clip/1 document of its outcome (polygons.hpp).
#include "clip_job_impl.hpp"

#include <nlohmann/json.hpp>

#include <charconv>

namespace hlr::exporter {
namespace {

using nlohmann::json;

json points_json(const RawContour& contour) {
  json a = json::array();
  for (const auto& p : contour) a.push_back({p[0], p[1]});
  return a;
}

json exact_json(const std::vector<ExactPoint2Text>& contour) {
  json a = json::array();
  for (const auto& p : contour) a.push_back({p[0], p[1]});
  return a;
}

json edges_json(const std::vector<EdgeSource>& edges) {
  json a = json::array();
  for (const auto& s : edges) a.push_back({s.role, s.polygon, s.contour, s.edge});
  return a;
}

template <class T, class F>
json list_json(const std::vector<T>& items, F&& item_json) {
  json a = json::array();
  for (const auto& item : items) a.push_back(item_json(item));
  return a;
}

void write_piece(std::string& out, const ClipPiece& piece, bool exact) {
  out += "    {\"subject\": " + std::to_string(piece.subject);
  if (piece.clip >= 0) out += ", \"clip\": " + std::to_string(piece.clip);
  out += ",\n     \"outer\": " + points_json(piece.polygon.outer).dump();
  out += ",\n     \"holes\": " + list_json(piece.polygon.holes, points_json).dump();
  out += ",\n     \"outer_edges\": " + edges_json(piece.outer_edges).dump();
  out += ",\n     \"holes_edges\": " + list_json(piece.hole_edges, edges_json).dump();
  if (exact) {
    out += ",\n     \"outer_exact\": " + exact_json(piece.outer_exact).dump();
    out += ",\n     \"holes_exact\": " + list_json(piece.holes_exact, exact_json).dump();
  }
  out += "}";
}

void write_list(std::string& out, const char* name, const std::vector<ClipPiece>& pieces, bool exact) {
  out += std::string("  \"") + name + "\": [";
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    out += i == 0 ? "\n" : ",\n";
    write_piece(out, pieces[i], exact);
  }
  out += pieces.empty() ? "],\n" : "\n  ],\n";
}

}  // namespace

ClipOutcome clip_polygons(const std::vector<RawPolygon>& subjects, const std::vector<RawPolygon>& clips,
                          const ClipOptions& options) {
  switch (options.kernel) {
    case KernelKind::epick: return clip_polygons_epick(subjects, clips, options);
    case KernelKind::floating: return clip_polygons_double(subjects, clips, options);
    case KernelKind::exact: break;
  }
  return clip_polygons_exact(subjects, clips, options);
}

std::string clip_json(const ClipOutcome& outcome) {
  const bool exact = outcome.exact_values;
  std::string out;
  out += "{\n  \"format\": \"hlr-clip/1\",\n";
  out += std::string("  \"kernel\": \"") + kernel_name(outcome.kernel) + "\",\n";
  write_list(out, "inside", outcome.inside, exact);
  write_list(out, "outside", outcome.outside, exact);
  nlohmann::ordered_json stats;
  stats["subject_polygons"] = outcome.subjects;
  stats["clip_polygons"] = outcome.clips;
  stats["inside_polygons"] = outcome.inside.size();
  stats["outside_polygons"] = outcome.outside.size();
  stats["subject_area"] = outcome.subject_area;
  stats["inside_area"] = outcome.inside_area;
  stats["outside_area"] = outcome.outside_area;
  if (exact) {
    stats["subject_area_exact"] = outcome.subject_area_exact;
    stats["inside_area_exact"] = outcome.inside_area_exact;
    stats["outside_area_exact"] = outcome.outside_area_exact;
  }
  stats["area_identity"] = outcome.identity_holds;
  stats["seconds"] = outcome.seconds;
  out += "  \"stats\": " + stats.dump() + "\n}\n";
  return out;
}

std::string number_text(double v) {
  char buffer[512];
  const double a = std::fabs(v);
  auto result = (a == 0 || (a >= 1e-6 && a < 1e16))
                    ? std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed)
                    : std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

}  // namespace hlr::exporter
