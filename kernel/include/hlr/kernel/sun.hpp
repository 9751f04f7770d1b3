// hlr kernel, sun: the direction of sunlight at a date, time and place, for `--sun-at` (DESIGN.md,
// "Shadows"). The sun's position comes from libnova (Debian's libnova-dev): the Earth by VSOP87,
// nutation, precession to the date and horizontal coordinates for the site (Meeus, "Astronomical
// Algorithms", ch. 25; sun.cpp says why not libnova's own ln_get_solar_equ_coords). Within about
// 0.003° of NOAA's solar calculator. It is geometric: no atmospheric refraction (which lifts the
// sun by about 0.5° at the horizon and under 0.03° above 30°).
//
// Times are ISO 8601 local times with a UTC offset, "YYYY-MM-DDTHH:MM[+HH:MM|-HH:MM|Z]" (no
// offset: UTC). A sun study is "START/END/STEP": END a full time or "HH:MM" on START's date and
// offset, STEP "PT#H", "PT#M" or "PT#H#M"; the times START, START + STEP, ... up to END.
// The model's +Z is up and true north is NORTH degrees clockwise from +Y seen from above (0: +Y).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hlr {

struct LocalTime {
  int year = 2000, month = 1, day = 1, hour = 0, minute = 0;
  int offset_minutes = 0;  // local time minus UTC
};

// The time, or nothing with `error` saying what is wrong.
std::optional<LocalTime> parse_local_time(std::string_view text, std::string& error);
// START or START/END/STEP; at most 10000 times.
std::optional<std::vector<LocalTime>> parse_sun_times(std::string_view text, std::string& error);
std::string format_local_time(const LocalTime& t);  // "2026-06-21T09:00+10:00"

struct Site {
  double latitude = 0, longitude = 0;  // degrees, north and east positive
  double north = 0;                    // degrees clockwise from the model's +Y to true north
};
// "LAT,LON[,NORTH]"; nothing with `error` for a malformed list or a site outside ±90°/±180°.
std::optional<Site> parse_site(std::string_view text, std::string& error);

struct SunPosition {
  double azimuth = 0;   // degrees clockwise from true north
  double altitude = 0;  // degrees above the horizon (geometric)
  std::array<double, 3> direction{};  // the direction sunlight travels, in model axes (unit, rounded)
};
SunPosition sun_position(const LocalTime& time, const Site& site);

}  // namespace hlr
