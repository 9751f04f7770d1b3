#include <hlr/export/polygons.hpp>
#include <hlr/kernel/errors.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hlr::exporter {
namespace {

using nlohmann::json;

std::string errno_text(int error) { return std::strerror(error); }

// nlohmann refuses numbers that overflow a double (1e400) without saying where they are. The
// parse is retried with each such number replaced by a marker string of the same length (so that
// byte positions in later messages stay right): a backspace escape, then tildes. The reader then
// names the polygon and vertex that holds it.
std::string non_finite_marker_literal(std::size_t length) {  // length >= 4; numbers that overflow have >= 5
  return "\"\\b" + std::string(length - 4, '~') + "\"";
}

bool is_non_finite_marker(const nlohmann::json& value) {
  if (!value.is_string()) return false;
  const auto& s = value.get_ref<const std::string&>();
  return !s.empty() && s[0] == '\b' && s.find_first_not_of('~', 1) == std::string::npos;
}

// A DOM builder that records where the parse failed instead of throwing.
struct RecordingParser : nlohmann::detail::json_sax_dom_parser<nlohmann::json> {
  using Base = nlohmann::detail::json_sax_dom_parser<nlohmann::json>;
  explicit RecordingParser(nlohmann::json& root) : Base(root, false) {}

  std::size_t error_position = 0;
  std::string error_token;
  int error_id = 0;
  bool overflow = false;

  template <class Exception>
  bool parse_error(std::size_t position, const std::string& last_token, const Exception& ex) {
    error_position = position;
    error_token = last_token;
    error_id = ex.id;
    overflow = std::is_same_v<Exception, nlohmann::json::out_of_range> && ex.id == 406;
    return Base::parse_error(position, last_token, ex);
  }
};

// "a string", "an array", "null", ...
std::string a_type(const json& value) {
  if (is_non_finite_marker(value)) return "a number too large for a double";
  switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::binary: return "binary data";
    case json::value_t::discarded: return "nothing";
    default: return "a number";
  }
}

// nlohmann's message is "[json.exception.parse_error.101] parse error at line L, column C: syntax
// error while parsing VALUE - REASON; last read: 'TEXT'". Keep the position and the reason.
std::string describe_parse_error(const json::parse_error& e) {
  std::string what = e.what();
  std::string position, reason;
  if (auto at = what.find(" at line "); at != std::string::npos) {
    auto colon = what.find(": ", at);
    if (colon != std::string::npos) position = what.substr(at + 4, colon - at - 4);  // "line L, column C"
  }
  if (auto dash = what.find(" - "); dash != std::string::npos) {
    reason = what.substr(dash + 3);
    if (auto last = reason.find("; last read"); last != std::string::npos) reason.erase(last);
  }
  std::string message = "not valid JSON at byte " + std::to_string(e.byte);
  if (!position.empty()) message += " (" + position + ")";
  if (!reason.empty()) message += ": " + reason;
  return message;
}

class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path) {}

  [[noreturn]] void fail(const std::string& problem) const { throw UserError(path_, problem); }

  double coordinate(const json& value, const std::string& where, const char* axis) const {
    if (is_non_finite_marker(value)) fail(where + ": " + axis + " coordinate is not a finite number");
    if (!value.is_number())
      fail(where + ": " + axis + " is " + a_type(value) + ", expected a number");
    double v = value.get<double>();
    if (!std::isfinite(v)) fail(where + ": " + axis + " coordinate is not a finite number");
    if (std::fabs(v) > kMaxCoordinate) {
      char text[64];
      auto end = std::to_chars(text, text + sizeof text, v).ptr;
      fail(where + ": " + axis + " coordinate " + std::string(text, end) +
           " is out of range (at most 1e100 in magnitude)");
    }
    return v;
  }

  // `name` is "polygon 2 outer" or "polygon 2 hole 1".
  RawContour contour(const json& value, const std::string& name) const {
    if (!value.is_array())
      fail(name + " contour is " + a_type(value) + ", expected an array of [x, y] vertices");
    RawContour points;
    points.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) {
      const json& vertex = value[i];
      std::string where = name + " vertex " + std::to_string(i);
      if (!vertex.is_array() || vertex.size() != 2) {
        std::string got = vertex.is_array() ? "an array of " + std::to_string(vertex.size()) + " values" : a_type(vertex);
        fail(where + " is " + got + ", expected [x, y]");
      }
      points.push_back({coordinate(vertex[0], where, "x"), coordinate(vertex[1], where, "y")});
    }
    std::vector<RawPoint> distinct = points;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    if (distinct.size() < 3) {
      fail(name + " contour has " + std::to_string(distinct.size()) + " distinct " +
           (distinct.size() == 1 ? "vertex" : "vertices") + ", at least 3 are needed");
    }
    return points;
  }

  RawPolygon polygon(const json& value, std::size_t index) const {
    std::string name = "polygon " + std::to_string(index);
    if (!value.is_object()) fail(name + " is " + a_type(value) + ", expected an object with \"outer\"");
    auto outer = value.find("outer");
    if (outer == value.end()) fail(name + " has no \"outer\" contour");
    RawPolygon polygon;
    polygon.outer = contour(*outer, name + " outer");
    auto holes = value.find("holes");
    if (holes != value.end() && !holes->is_null()) {
      if (!holes->is_array()) fail(name + " \"holes\" is " + a_type(*holes) + ", expected an array of contours");
      for (std::size_t h = 0; h < holes->size(); ++h)
        polygon.holes.push_back(contour((*holes)[h], name + " hole " + std::to_string(h)));
    }
    return polygon;
  }

  std::vector<RawPolygon> document(const json& doc) const {
    if (!doc.is_object()) fail("top level is " + a_type(doc) + ", expected an object");
    auto format = doc.find("format");
    if (format == doc.end()) fail(std::string("\"format\" is missing, expected \"") + kPolygonsFormat + "\"");
    if (!format->is_string())
      fail("\"format\" is " + a_type(*format) + ", expected \"" + kPolygonsFormat + "\"");
    if (format->get<std::string>() != kPolygonsFormat)
      fail("format is " + format->dump() + ", expected \"" + kPolygonsFormat + "\"");
    auto polygons = doc.find("polygons");
    if (polygons == doc.end()) fail("\"polygons\" is missing");
    if (!polygons->is_array()) fail("\"polygons\" is " + a_type(*polygons) + ", expected an array");
    std::vector<RawPolygon> result;
    result.reserve(polygons->size());
    for (std::size_t i = 0; i < polygons->size(); ++i) result.push_back(polygon((*polygons)[i], i));
    return result;
  }

 private:
  const std::string& path_;
};

}  // namespace

std::string read_text_file(const std::string& path) {
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw UserError(path, "cannot open (" + errno_text(errno) + ")");
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) {
    ::close(fd);
    throw UserError(path, "cannot read (" + errno_text(EISDIR) + ")");
  }
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      int error = errno;
      ::close(fd);
      throw UserError(path, "cannot read (" + errno_text(error) + ")");
    }
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return text;
}

std::vector<RawPolygon> parse_polygons(const std::string& text, const std::string& path) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw UserError(path, text.empty() ? "file is empty, expected an hlr-polygons/1 JSON document"
                                       : "file holds only white space, expected an hlr-polygons/1 JSON document");
  json doc;
  std::string patched;  // `text` with overflowing numbers replaced by markers, once one is found
  const std::string* input = &text;
  for (int attempt = 0;; ++attempt) {
    doc = json();
    RecordingParser parser(doc);
    bool ok = false;
    try {
      ok = json::sax_parse(*input, &parser);
    } catch (const json::exception& e) {  // not expected with allow_exceptions off; be safe
      throw UserError(path, std::string("not valid JSON: ") + e.what());
    }
    if (ok && !parser.is_errored()) break;
    if (parser.overflow && attempt < 1000) {
      // The token ends at or just before the reported position; replace that occurrence.
      std::size_t end = std::min(parser.error_position, input->size());
      std::size_t at = input->rfind(parser.error_token, end);
      if (at != std::string::npos && parser.error_token.size() >= 4) {
        if (input != &patched) patched = text, input = &patched;
        patched.replace(at, parser.error_token.size(), non_finite_marker_literal(parser.error_token.size()));
        continue;
      }
    }
    if (parser.overflow)
      throw UserError(path, "number " + parser.error_token + " at byte " + std::to_string(parser.error_position) +
                                " is not a finite double");
    // Parse again with exceptions on, for nlohmann's description of the error.
    try {
      json again = json::parse(*input);
    } catch (const json::parse_error& e) {
      throw UserError(path, describe_parse_error(e));
    } catch (const json::exception& e) {
      throw UserError(path, std::string("not valid JSON: ") + e.what());
    }
    throw UserError(path, "not valid JSON at byte " + std::to_string(parser.error_position));
  }
  return Reader(path).document(doc);
}

}  // namespace hlr::exporter
