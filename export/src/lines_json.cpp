// hlr-lines/1 (hlr/export/lines.hpp, lines_json) and the "input" and "view" objects every JSON
// document of hlr shares (document_json.hpp).
//
// The document is what nlohmann::json's dump(1) makes of it, byte for byte: members in the order
// of their keys, one space of indent per level, numbers as nlohmann prints them. Only the "lines"
// array, nearly all of a large drawing's bytes, is written here piece by piece, straight into the
// document's text (no JSON tree of a million pieces, no string per number); every other member
// is a small nlohmann::json dumped in its place. lines_writers_test checks the bytes against a
// dump of the whole document as one nlohmann::json tree. write_lines_json hands the text on in
// blocks as it goes, so that a drawing of a million pieces is never held whole (lines_json
// collects the blocks).
#include <algorithm>
#include <hlr/export/lines.hpp>

#include "document_json.hpp"
#include "numbers.hpp"

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/task_group.h>

#include <string_view>

namespace hlr::exporter {
namespace {

using nlohmann::json;
using detail::append_member;

// The document's text on its way to the sink, handed on in blocks of about a megabyte.
class Output {
 public:
  explicit Output(const std::function<void(std::string_view)>& sink) : sink_(sink) { text.reserve(block + 4096); }
  std::string text;
  void flush_if_full() {
    if (text.size() >= block) flush();
  }
  void flush() {
    if (!text.empty()) sink_(text);
    text.clear();
  }

 private:
  static constexpr std::size_t block = std::size_t(1) << 20;
  const std::function<void(std::string_view)>& sink_;
};

// The "lines" array as dump(1) writes it one level in: each piece an object with its keys in
// order (a, b, edge, kind, mesh, visible) at two levels in, its values at three and four.
void append_lines(Output& output, const std::vector<DrawingPiece>& pieces) {
  std::string& out = output.text;
  out += "\n \"lines\": ";
  if (pieces.empty()) {
    out += "[]";
    return;
  }
  std::string kinds[kFeatureKinds];  // each kind's name as a JSON string
  for (std::size_t k = 0; k < kFeatureKinds; ++k) kinds[k] = json(feature_kind_name(static_cast<FeatureKind>(k))).dump();
  auto point = [&](const Point3& p) {
    out += "[\n    ";
    detail::append_json_number(out, p[0]);
    out += ",\n    ";
    detail::append_json_number(out, p[1]);
    out += ",\n    ";
    detail::append_json_number(out, p[2]);
    out += "\n   ]";
  };
  out += '[';
  bool first = true;
  for (const auto& p : pieces) {
    out += first ? "\n  {\n   \"a\": " : ",\n  {\n   \"a\": ";
    first = false;
    point(p.a);
    out += ",\n   \"b\": ";
    point(p.b);
    out += ",\n   \"edge\": ";
    // Intersection lines lie on no mesh edge (DESIGN.md): null, whatever the piece says.
    if (p.has_edge && p.kind != FeatureKind::intersection) {
      out += "[\n    ";
      detail::append_unsigned(out, p.edge[0]);
      out += ",\n    ";
      detail::append_unsigned(out, p.edge[1]);
      out += "\n   ]";
    } else {
      out += "null";
    }
    out += ",\n   \"kind\": ";
    out += kinds[static_cast<std::size_t>(p.kind)];
    out += ",\n   \"mesh\": ";
    detail::append_unsigned(out, p.mesh);
    out += p.visible ? ",\n   \"visible\": true\n  }" : ",\n   \"visible\": false\n  }";
    output.flush_if_full();
  }
  out += "\n ]";
}

json stats_json(const LineDrawing& drawing, double write) {
  const auto& s = drawing.stats;
  json by_kind = json::object();
  for (std::size_t kind = 0; kind < kFeatureKinds; ++kind)
    by_kind[feature_kind_name(static_cast<FeatureKind>(kind))] = s.by_kind[kind];
  const StageTimes& t = drawing.times;
  const json stages =
      drawing.raster ? json{{"read", t.read}, {"intersections", t.intersections}, {"zbuffer", drawing.zbuffer_seconds},
                            {"lines", t.lines}, {"write", write}}
                     : json{{"read", t.read}, {"sources", t.sources}, {"sort", t.sort}, {"intersections", t.intersections},
                            {"lines", t.lines}, {"precedence", t.precedence}, {"write", write}};
  json stats = {
      {"seconds", t.total + write},
      {"stage_seconds", stages},
      {"lines", s.lines},
      {"lines_by_kind", std::move(by_kind)},
      {"lines_seen_end_on", s.point_in_view},
      {"visible_pieces", s.visible_pieces},
      {"hidden_pieces", s.hidden_pieces},
      {"drawn_visible_length", drawing.visible_length()},
      {"drawn_hidden_length", drawing.hidden_length()},
      {"crease_degrees", drawing.crease_degrees},
      {"welded_vertices", drawing.input.welded_vertices},
  };
  if (drawing.merged_segments) {
    stats["merged_segments"] = *drawing.merged_segments;
    stats["merge_distance_mm"] = drawing.merge_distance_mm;
    stats["contact_segments"] = drawing.contact_segments;
    stats["contact_degrees"] = drawing.contact_degrees;
  }
  if (drawing.curves) {
    stats["circles"] = drawing.curves->circles;
    stats["arcs"] = drawing.curves->arcs;
  }
  if (drawing.cull) {
    stats["cull"] = {{"group", drawing.cull->group},
                     {"part", drawing.cull->part},
                     {"parts", drawing.cull->parts},
                     {"patches", drawing.cull->patches},
                     {"culled", drawing.cull->culled},
                     {"fuzzy_seconds", drawing.cull->fuzzy_seconds}};
    if (drawing.cull->unculled_seconds) stats["cull"]["unculled_seconds"] = *drawing.cull->unculled_seconds;
    if (drawing.cull->group_saved_seconds) stats["cull"]["group_saved_seconds"] = *drawing.cull->group_saved_seconds;
  }
  return stats;
}

}  // namespace

namespace detail {

void append_member(std::string& out, std::string_view key, const json& value) {
  out += "\n \"";
  out += key;  // hlr's own keys: nothing to escape
  out += "\": ";
  const std::string text = value.dump(1);
  for (char c : text) {  // raw newlines only come from the layout: strings escape theirs
    out += c;
    if (c == '\n') out += ' ';
  }
}

json input_json(const InputInfo& input) {
  json out = {{"files", input.files}, {"faces", input.faces}, {"vertices", input.vertices}};
  // Part names from the source (a CAD model's products), only where a source gave one.
  if (std::any_of(input.parts.begin(), input.parts.end(), [](const std::string& p) { return !p.empty(); }))
    out["parts"] = input.parts;
  return out;
}

json view_json(const ViewInfo& v) {
  json view;
  view["projection"] = v.eye ? "perspective" : "orthographic";
  if (v.name != "custom") view["name"] = v.name;
  if (v.eye) view["eye"] = {(*v.eye)[0], (*v.eye)[1], (*v.eye)[2]};
  view["direction"] = {v.direction[0], v.direction[1], v.direction[2]};
  view["up"] = {v.up[0], v.up[1], v.up[2]};
  json matrix = json::array();
  for (const auto& row : v.world_to_view) matrix.push_back({row[0], row[1], row[2], row[3]});
  view["world_to_view"] = std::move(matrix);
  return view;
}

}  // namespace detail

namespace {
// The document; `before_stats`, when set, runs once every piece is written and before the stats are.
void write_document(const LineDrawing& drawing, const std::function<void(std::string_view)>& sink,
                    const std::function<double()>& write_seconds, const std::function<void()>& before_stats) {
  Output output(sink);
  std::string& out = output.text;
  // The top level's members in the order of their keys, as dump() writes them.
  out += '{';
  append_member(out, "format", "hlr-lines/1");
  out += ',';
  append_member(out, "input", detail::input_json(drawing.input));
  out += ',';
  // top level, as in hlr-clip/1 and hlr-surfaces/1
  append_member(out, "kernel", drawing.raster ? "raster" : kernel_name(drawing.kernel));
  out += ',';
  append_lines(output, drawing.pieces);
  out += ',';
  if (const auto& r = drawing.raster) {
    append_member(out, "raster",
                  {{"resolution", r->resolution}, {"width", r->width}, {"height", r->height}, {"pixel", r->pixel}});
    out += ',';
  }
  if (before_stats) before_stats();
  append_member(out, "stats", stats_json(drawing, write_seconds ? write_seconds() : drawing.times.write));
  out += ',';
  append_member(out, "view", detail::view_json(drawing.view));
  out += "\n}\n";
  output.flush();
}

}  // namespace

void write_lines_json(const LineDrawing& drawing, const std::function<void(std::string_view)>& sink,
                      const std::function<double()>& write_seconds) {
  write_document(drawing, sink, write_seconds, {});
}

MergedSegments write_lines_json_merging(LineDrawing& drawing, const DrawingStyle& style,
                                        const std::function<void(std::string_view)>& sink,
                                        const std::function<double()>& write_seconds) {
  MergedSegments merged;
  auto merge = [&] { merged = sheet_segments(drawing, style); };
  auto record = [&] { record_sheet_counts(drawing, merged, style); };
  // Below this, starting a task takes longer than the merge saves.
  constexpr std::size_t kSegmentsBeside = 20000;
  if (drawing.segments.size() < kSegmentsBeside ||
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) < 2) {
    write_document(drawing, sink, write_seconds, [&] {
      merge();
      record();
    });
    return merged;
  }
  tbb::task_group beside;
  beside.run(merge);
  try {
    write_document(drawing, sink, write_seconds, [&] {
      beside.wait();
      record();
    });
  } catch (...) {
    beside.wait();  // the group must not be destroyed while the merge runs
    throw;
  }
  return merged;
}

std::string lines_json(const LineDrawing& drawing, const std::function<double()>& write_seconds) {
  std::string out;
  out.reserve(4096 + 300 * drawing.pieces.size());  // a piece takes 250 to 300 bytes
  write_lines_json(drawing, [&](std::string_view text) { out += text; }, write_seconds);
  return out;
}

}  // namespace hlr::exporter
