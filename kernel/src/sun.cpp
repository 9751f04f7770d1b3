// The sun's direction (sun.hpp) through libnova.
#include <hlr/kernel/sun.hpp>

#include <libnova/earth.h>
#include <libnova/julian_day.h>
#include <libnova/nutation.h>
#include <libnova/precession.h>
#include <libnova/transform.h>

#include <charconv>
#include <cmath>
#include <cstdio>

namespace hlr {
namespace {

// Days since 1970-01-01 of a proleptic Gregorian date, and back (H. Hinnant's algorithms).
long days_from_civil(long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long>(doe) - 719468;
}
void civil_from_days(long z, int& y, int& m, int& d) {
  z += 719468;
  const long era = (z >= 0 ? z : z - 146096) / 146097;
  const unsigned doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  d = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  m = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  y = static_cast<int>(yoe + era * 400 + (m <= 2));
}
int days_in_month(int y, int m) {
  static const int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
  return m == 2 && leap ? 29 : days[m - 1];
}

// Minutes since 1970-01-01T00:00 local time (the offset not applied).
long local_minutes(const LocalTime& t) {
  return days_from_civil(t.year, unsigned(t.month), unsigned(t.day)) * 1440 + t.hour * 60 + t.minute;
}
LocalTime from_local_minutes(long minutes, int offset) {
  LocalTime t;
  long days = minutes >= 0 ? minutes / 1440 : -((-minutes + 1439) / 1440);
  long rest = minutes - days * 1440;
  civil_from_days(days, t.year, t.month, t.day);
  t.hour = int(rest / 60);
  t.minute = int(rest % 60);
  t.offset_minutes = offset;
  return t;
}

bool digits(std::string_view s, std::size_t at, std::size_t n, int& out) {
  if (at + n > s.size()) return false;
  for (std::size_t i = at; i < at + n; ++i)
    if (s[i] < '0' || s[i] > '9') return false;
  std::from_chars(s.data() + at, s.data() + at + n, out);
  return true;
}

// "HH:MM" at `at`.
bool clock(std::string_view s, std::size_t at, int& h, int& m) {
  return digits(s, at, 2, h) && at + 2 < s.size() && s[at + 2] == ':' && digits(s, at + 3, 2, m);
}

bool parse_offset(std::string_view s, int& minutes, std::string& error) {
  if (s.empty() || s == "Z") {
    minutes = 0;
    return true;
  }
  int h = 0, m = 0;
  if ((s[0] != '+' && s[0] != '-') || s.size() != 6 || !clock(s, 1, h, m)) {
    error = "the UTC offset must be +HH:MM, -HH:MM or Z";
    return false;
  }
  if (h > 14 || m > 59 || (h == 14 && m > 0)) {
    error = "the UTC offset is out of range (at most 14:00)";
    return false;
  }
  minutes = (s[0] == '-' ? -1 : 1) * (h * 60 + m);
  return true;
}

bool parse_number(std::string_view s, double& out) {
  if (s.empty()) return false;
  std::string text(s);
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(out);
}

}  // namespace

std::optional<LocalTime> parse_local_time(std::string_view s, std::string& error) {
  LocalTime t;
  if (!(digits(s, 0, 4, t.year) && s.size() > 4 && s[4] == '-' && digits(s, 5, 2, t.month) && s.size() > 7 &&
        s[7] == '-' && digits(s, 8, 2, t.day) && s.size() > 10 && s[10] == 'T' && clock(s, 11, t.hour, t.minute))) {
    error = "the time must be YYYY-MM-DDTHH:MM with an optional UTC offset (+HH:MM, -HH:MM or Z)";
    return std::nullopt;
  }
  if (t.month < 1 || t.month > 12 || t.day < 1 || t.day > days_in_month(t.year, t.month)) {
    error = "no such date";
    return std::nullopt;
  }
  if (t.hour > 23 || t.minute > 59) {
    error = "no such time of day";
    return std::nullopt;
  }
  if (!parse_offset(s.substr(16), t.offset_minutes, error)) return std::nullopt;
  return t;
}

std::optional<std::vector<LocalTime>> parse_sun_times(std::string_view s, std::string& error) {
  const std::size_t a = s.find('/');
  if (a == std::string_view::npos) {
    auto t = parse_local_time(s, error);
    if (!t) return std::nullopt;
    return std::vector<LocalTime>{*t};
  }
  const std::size_t b = s.find('/', a + 1);
  if (b == std::string_view::npos) {
    error = "a sun study is START/END/STEP (for example 2026-06-21T09:00+10:00/15:00/PT1H)";
    return std::nullopt;
  }
  auto start = parse_local_time(s.substr(0, a), error);
  if (!start) return std::nullopt;
  const std::string_view end_text = s.substr(a + 1, b - a - 1), step_text = s.substr(b + 1);
  LocalTime end = *start;
  if (end_text.size() == 5) {
    if (!clock(end_text, 0, end.hour, end.minute) || end.hour > 23 || end.minute > 59) {
      error = "the end time must be HH:MM or a full time";
      return std::nullopt;
    }
  } else {
    auto e = parse_local_time(end_text, error);
    if (!e) return std::nullopt;
    end = *e;
  }
  // STEP: PT#H, PT#M, PT#H#M.
  long step = 0;
  bool ok = step_text.size() > 2 && step_text.substr(0, 2) == "PT";
  std::size_t i = 2;
  bool any = false, seen_minutes = false;
  while (ok && i < step_text.size()) {
    std::size_t j = i;
    while (j < step_text.size() && step_text[j] >= '0' && step_text[j] <= '9') ++j;
    if (j == i || j == step_text.size() || j - i > 5) {
      ok = false;
      break;
    }
    long n = 0;
    std::from_chars(step_text.data() + i, step_text.data() + j, n);
    if (step_text[j] == 'H' && !any) step += 60 * n;
    else if (step_text[j] == 'M' && !seen_minutes) step += n, seen_minutes = true;
    else ok = false;
    any = true;
    i = j + 1;
  }
  if (!ok || !any) {
    error = "the step must be PT#H, PT#M or PT#H#M (for example PT1H or PT30M)";
    return std::nullopt;
  }
  if (step <= 0) {
    error = "the step is zero";
    return std::nullopt;
  }
  // In UTC minutes, so that START and END may have different offsets.
  const long t0 = local_minutes(*start) - start->offset_minutes, t1 = local_minutes(end) - end.offset_minutes;
  if (t1 < t0) {
    error = "the end is before the start";
    return std::nullopt;
  }
  if ((t1 - t0) / step >= 10000) {
    error = "more than 10000 times";
    return std::nullopt;
  }
  std::vector<LocalTime> out;
  for (long t = t0; t <= t1; t += step) out.push_back(from_local_minutes(t + start->offset_minutes, start->offset_minutes));
  return out;
}

std::string format_local_time(const LocalTime& t) {
  char buf[40];
  const int off = std::abs(t.offset_minutes);
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d%c%02d:%02d", t.year, t.month, t.day, t.hour, t.minute,
                t.offset_minutes < 0 ? '-' : '+', off / 60, off % 60);
  return buf;
}

std::optional<Site> parse_site(std::string_view s, std::string& error) {
  std::vector<double> values;
  std::size_t at = 0;
  while (true) {
    const std::size_t comma = s.find(',', at);
    double v = 0;
    if (!parse_number(s.substr(at, comma == std::string_view::npos ? std::string_view::npos : comma - at), v)) {
      error = "the site must be LAT,LON or LAT,LON,NORTH in degrees";
      return std::nullopt;
    }
    values.push_back(v);
    if (comma == std::string_view::npos) break;
    at = comma + 1;
  }
  if (values.size() < 2 || values.size() > 3) {
    error = "the site must be LAT,LON or LAT,LON,NORTH in degrees";
    return std::nullopt;
  }
  if (std::abs(values[0]) > 90) {
    error = "the latitude is outside -90..90 degrees";
    return std::nullopt;
  }
  if (std::abs(values[1]) > 180) {
    error = "the longitude is outside -180..180 degrees";
    return std::nullopt;
  }
  return Site{values[0], values[1], values.size() == 3 ? values[2] : 0.0};
}

SunPosition sun_position(const LocalTime& time, const Site& site) {
  // UTC: the local time minus its offset.
  const LocalTime utc = from_local_minutes(local_minutes(time) - time.offset_minutes, 0);
  ln_date date{utc.year, utc.month, utc.day, utc.hour, utc.minute, 0.0};
  const double jd = ln_get_julian_day(&date);
  // libnova's VSOP87 Earth is referred to the ecliptic and equinox of J2000, and 0.16's
  // ln_get_solar_equ_coords takes it as of date (0.36° off in 2026: 50" a year of precession;
  // Meeus' example 25.b comes out 0.10° off in right ascension). So: the Sun's J2000 ecliptic
  // position from the Earth's, aberration (-20.4898" / R) and nutation in longitude, to J2000
  // equatorial coordinates (mean obliquity of J2000), then precessed to the date. Example 25.b
  // then agrees to 0.001°, and NOAA's solar calculator to about 0.003° (kernel/tests/sun_test.cpp).
  ln_helio_posn earth{};
  ln_get_earth_helio_coords(jd, &earth);
  ln_nutation nutation{};
  ln_get_nutation(jd, &nutation);
  const double rad = M_PI / 180;
  const double lambda = (earth.L + 180 - 20.4898 / 3600 / earth.R + nutation.longitude) * rad;
  const double beta = -earth.B * rad, eps = 23.4392911 * rad;
  ln_equ_posn j2000{};
  j2000.ra = std::fmod(std::atan2(std::sin(lambda) * std::cos(eps) - std::tan(beta) * std::sin(eps), std::cos(lambda)) / rad + 360, 360);
  j2000.dec = std::asin(std::sin(beta) * std::cos(eps) + std::cos(beta) * std::sin(eps) * std::sin(lambda)) / rad;
  ln_equ_posn equ{};
  ln_get_equ_prec2(&j2000, JD2000, jd, &equ);
  ln_lnlat_posn observer{site.longitude, site.latitude};
  ln_hrz_posn hrz{};
  ln_get_hrz_from_equ(&equ, &observer, jd, &hrz);
  SunPosition out;
  out.azimuth = std::fmod(hrz.az + 180.0, 360.0);  // libnova: 0 = south, 90 = west
  out.altitude = hrz.alt;
  const double deg = M_PI / 180;
  const double a = out.azimuth * deg, h = out.altitude * deg, north = site.north * deg;
  const double e = std::sin(a) * std::cos(h), n = std::cos(a) * std::cos(h), u = std::sin(h);
  // Toward the sun in model axes: north (sin N, cos N, 0), east (cos N, -sin N, 0), up +Z.
  const double toward[3] = {e * std::cos(north) + n * std::sin(north), -e * std::sin(north) + n * std::cos(north), u};
  for (int i = 0; i < 3; ++i) out.direction[i] = -toward[i] + 0.0;
  return out;
}

}  // namespace hlr
