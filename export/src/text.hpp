// Small text helpers of the sheet writers: XML escaping, shortening to a cell, file base names.
#pragma once

#include <string>

namespace hlr::exporter::detail {

inline std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

inline std::string base_name(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// At most `chars` characters (UTF-8 aware: never cuts inside a character), "…" when cut.
inline std::string shorten(const std::string& s, std::size_t chars) {
  std::size_t count = 0, i = 0;
  for (; i < s.size(); ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) continue;  // continuation byte
    if (count == chars) return s.substr(0, i) + "\u2026";
    ++count;
  }
  return s;
}

}  // namespace hlr::exporter::detail
