// The line writers' number formatter (export/src/numbers.hpp) against the formatters it replaced:
// the SVG's and DXF's string-per-number functions as they were (copied here as the reference) and
// nlohmann::json's dump() for JSON numbers. Every output byte of the writers depends on these, so
// they are compared on special values and on a million random doubles of every magnitude.
#include "numbers.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace hlr::exporter::detail;

// The writers' formatters before numbers.hpp (lines_writers.cpp at 68e0aa3), verbatim.
std::string reference_fixed(double v, int decimals) {
  char buf[400];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  std::string s(buf, ec == std::errc() ? end : buf);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

std::string reference_round_trip(double v) {
  char buf[400];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  std::string s(buf, ec == std::errc() ? end : buf);
  if (s.find('.') == std::string::npos) s += ".0";
  return s;
}

std::vector<double> special_values() {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> v = {0.0, -0.0, 1.0, -1.0, 0.5, 0.1, 0.2, 0.3, 1e-5, -1e-5, 4.99995e-5, 5e-5, -5e-5,
                           0.00005, 0.00015, 2.5, 1e15, 1e16, 1e17, 1e21, 1e22, 1e23, 123456789012345678.0,
                           std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                           std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min(),
                           -std::numeric_limits<double>::denorm_min(), 1e-300, 1e300, 297.0, 210.0, 0.35,
                           2.1213203435596424, -1.2247448713915892, 3.8343192976162205e+241, inf, -inf,
                           std::numeric_limits<double>::quiet_NaN()};
  for (int e = -330; e <= 310; ++e) v.push_back(std::pow(10.0, e)), v.push_back(-3 * std::pow(10.0, e));
  return v;
}

// Random doubles: every bit pattern (all magnitudes), and values of drawing size with few digits.
std::vector<double> random_values(std::size_t n) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> drawing(-2000, 2000);
  std::vector<double> v;
  for (std::size_t i = 0; i < n; ++i) {
    switch (i % 3) {
      case 0: v.push_back(std::bit_cast<double>(rng())); break;
      case 1: v.push_back(drawing(rng)); break;
      default: v.push_back(std::round(drawing(rng) * 1e4) / 1e4); break;  // on or near a 4-decimal grid
    }
  }
  return v;
}

template <class Each>
void for_values(Each&& each) {
  for (double v : special_values()) each(v);
  for (double v : random_values(1000000)) each(v);
}

TEST(Numbers, FixedAsBefore) {
  std::size_t bad = 0;
  for_values([&](double v) {
    for (int decimals : {4, 6}) {
      std::string got = "<";
      append_fixed(got, v, decimals);
      if (got != "<" + reference_fixed(v, decimals) && bad++ < 10)
        ADD_FAILURE() << v << " at " << decimals << ": " << got << " against <" << reference_fixed(v, decimals);
      if (fixed(v, decimals) != reference_fixed(v, decimals) && bad++ < 10) ADD_FAILURE() << v;
    }
  });
  EXPECT_EQ(bad, 0u);
  EXPECT_EQ(fixed(-0.00001, 4), "0");
  EXPECT_EQ(fixed(12.5, 4), "12.5");
  EXPECT_EQ(fixed(210, 4), "210");
}

TEST(Numbers, RoundTripAsBefore) {
  std::size_t bad = 0;
  for_values([&](double v) {
    std::string got = "<";
    append_round_trip(got, v);
    if (got != "<" + reference_round_trip(v) && bad++ < 10)
      ADD_FAILURE() << v << ": " << got << " against <" << reference_round_trip(v);
  });
  EXPECT_EQ(bad, 0u);
  std::string s;
  append_round_trip(s, 2.0);
  append_round_trip(s, -0.25);
  EXPECT_EQ(s, "2.0-0.25");
}

TEST(Numbers, JsonNumbersAsNlohmannDumpsThem) {
  std::size_t bad = 0;
  for_values([&](double v) {
    std::string got = "<";
    append_json_number(got, v);
    const std::string want = "<" + nlohmann::json(v).dump();
    if (got != want && bad++ < 10) ADD_FAILURE() << v << ": " << got << " against " << want;
  });
  EXPECT_EQ(bad, 0u);
  for (std::uint64_t v : {std::uint64_t(0), std::uint64_t(7), std::uint64_t(4294967295u), ~std::uint64_t(0)}) {
    std::string got;
    append_unsigned(got, v);
    EXPECT_EQ(got, nlohmann::json(v).dump());
  }
}

}  // namespace
