// Numbers as the line writers print them (lines_writers.cpp, lines_json.cpp): the one formatter of
// every number in an SVG, DXF or hlr-lines/1 document, appended to the document's text without a
// stream or a string per number. All of it is std::to_chars or nlohmann's own number printer,
// independent of the C locale.
//
//   append_fixed        fixed notation with at most `decimals` decimals, trailing zeros and a
//                       trailing point dropped, no "-0" (SVG millimetres: 4 decimals).
//   append_round_trip   the shortest fixed notation that reads back as the same double, with ".0"
//                       where it would have no point (DXF readers differ on exponents).
//   append_json_number  what nlohmann::json's dump() prints for a double: its Grisu2 digits
//                       (which round-trip but are not always the shortest: std::to_chars would
//                       differ in about one number in a thousand), "null" for NaN and infinity.
//   json_number_text    the same digits of a finite double, in a caller's buffer.
//   JsonNumbers         append_json_number with the texts of recent numbers kept.
//   append_unsigned     a decimal integer.
#pragma once

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace hlr::exporter::detail {

// Room for any double in fixed notation: 309 integer digits or 324 decimals, and sign and point.
inline constexpr std::size_t number_chars = 400;

inline void append_fixed(std::string& out, double v, int decimals) {
  char buf[number_chars];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (ec != std::errc()) return;
  std::string_view s(buf, std::size_t(end - buf));
  if (s.find('.') != std::string_view::npos) {
    while (s.back() == '0') s.remove_suffix(1);
    if (s.back() == '.') s.remove_suffix(1);
  }
  out += s == "-0" ? std::string_view("0") : s;
}

inline std::string fixed(double v, int decimals) {
  std::string s;
  append_fixed(s, v, decimals);
  return s;
}

inline void append_round_trip(std::string& out, double v) {
  char buf[number_chars];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  const std::string_view s(buf, ec == std::errc() ? std::size_t(end - buf) : 0);
  out += s;
  if (s.find('.') == std::string_view::npos) out += ".0";
}

// nlohmann's text of a finite double, in `buf` (its serializer uses a buffer of 64 too).
inline std::string_view json_number_text(char (&buf)[64], double v) {
  return {buf, std::size_t(nlohmann::detail::to_chars(buf, buf + sizeof buf, v) - buf)};
}

inline void append_json_number(std::string& out, double v) {
  char buf[64];
  out += std::isfinite(v) ? json_number_text(buf, v) : std::string_view("null");
}

// append_json_number for documents where numbers repeat: a polygon map writes each corner in every
// piece around it (five times on average), and Grisu2 is most of what a number costs. The texts of
// recent numbers are kept in a small direct-mapped table, by their bits; one table per thread.
class JsonNumbers {
 public:
  void append(std::string& out, double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    Slot& slot = slots_[(bits * 0x9E3779B97F4A7C15ull) >> (64 - kSlotBits)];
    if (slot.length == 0 || slot.bits != bits) {
      if (!std::isfinite(v)) return append_json_number(out, v);
      char buf[64];
      const std::string_view text = json_number_text(buf, v);
      slot.bits = bits;
      slot.length = std::uint8_t(text.size());
      std::memcpy(slot.text, text.data(), text.size());
    }
    out.append(slot.text, slot.length);
  }

 private:
  static constexpr int kSlotBits = 12;
  struct Slot {
    std::uint64_t bits = 0;
    std::uint8_t length = 0;  // 0: empty
    char text[31];            // a double's text: "-1.7976931348623157e+308" is 24
  };
  std::vector<Slot> slots_ = std::vector<Slot>(std::size_t(1) << kSlotBits);
};

inline void append_unsigned(std::string& out, std::uint64_t v) {
  char buf[24];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, std::size_t(end - buf));
}

}  // namespace hlr::exporter::detail
