// The sun's position (sun.hpp) against NOAA's solar calculator (its published equations, in a
// Python transcription run when this test was written: independent of libnova), and the time,
// sun-study and site parsers.
#include <hlr/kernel/sun.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace hlr {
namespace {

LocalTime time_of(const char* text) {
  std::string error;
  auto t = parse_local_time(text, error);
  EXPECT_TRUE(t) << text << ": " << error;
  return t.value_or(LocalTime{});
}

TEST(Sun, AgreesWithNoaaToAHundredthOfADegree) {
  struct Case {
    const char* time;
    Site site;
    double azimuth, altitude;  // NOAA, geometric (no refraction)
  };
  const Case cases[] = {
      {"2026-06-21T09:00+10:00", {-33.86, 151.21, 0}, 42.5649, 18.9316},
      {"2026-06-21T12:00+10:00", {-33.86, 151.21, 0}, 359.1533, 32.6973},
      {"2026-06-21T15:00+10:00", {-33.86, 151.21, 0}, 316.2553, 18.0491},
      {"2026-03-20T12:00Z", {51.4779, -0.0015, 0}, 177.6249, 38.4548},
      {"2026-12-02T10:30-05:00", {51.4779, -0.0015, 0}, 229.5669, 2.1101},
  };
  for (const auto& c : cases) {
    const SunPosition sun = sun_position(time_of(c.time), c.site);
    EXPECT_NEAR(sun.azimuth, c.azimuth, 0.01) << c.time;
    EXPECT_NEAR(sun.altitude, c.altitude, 0.01) << c.time;
  }
}

TEST(Sun, DirectionInModelAxes) {
  // Greenwich at the equinox near noon: the sun in the south, so light travels north (+Y) and down.
  const Site site{51.4779, -0.0015, 0};
  const SunPosition sun = sun_position(time_of("2026-03-20T12:07Z"), site);
  EXPECT_GT(sun.direction[1], 0.7);
  EXPECT_LT(sun.direction[2], -0.5);
  EXPECT_NEAR(std::hypot(sun.direction[0], sun.direction[1], sun.direction[2]), 1, 1e-12);
  // True north along +X (90 degrees clockwise from +Y): the light travels toward +X.
  const SunPosition turned = sun_position(time_of("2026-03-20T12:07Z"), {51.4779, -0.0015, 90});
  EXPECT_NEAR(turned.direction[0], sun.direction[1], 1e-12);
  EXPECT_NEAR(turned.direction[1], -sun.direction[0], 1e-12);
  EXPECT_EQ(turned.direction[2], sun.direction[2]);
}

TEST(Sun, SunStudies) {
  std::string error;
  auto times = parse_sun_times("2026-06-21T09:00+10:00/15:00/PT1H", error);
  ASSERT_TRUE(times) << error;
  ASSERT_EQ(times->size(), 7u);
  EXPECT_EQ(format_local_time(times->front()), "2026-06-21T09:00+10:00");
  EXPECT_EQ(format_local_time(times->back()), "2026-06-21T15:00+10:00");
  times = parse_sun_times("2026-12-31T23:30-03:30/2027-01-01T01:00-03:30/PT45M", error);
  ASSERT_TRUE(times) << error;
  ASSERT_EQ(times->size(), 3u);
  EXPECT_EQ(format_local_time((*times)[2]), "2027-01-01T01:00-03:30");
  times = parse_sun_times("2026-06-21T09:00Z/10:00/PT1H30M", error);
  ASSERT_TRUE(times) << error;
  EXPECT_EQ(times->size(), 1u);
  for (const char* bad : {"2026-06-21T09:00/08:00/PT1H", "2026-06-21T09:00/15:00", "2026-06-21T09:00/15:00/P1D",
                          "2026-06-21T09:00/15:00/PT0H", "2026-06-21", "2026-13-01T00:00", "2026-06-21T24:00",
                          "2026-06-21T09:00+15:00", "2027-02-29T12:00", "2026-06-21T09:00/15:00/PTH"})
    EXPECT_FALSE(parse_sun_times(bad, error)) << bad;
  EXPECT_TRUE(parse_sun_times("2028-02-29T12:00", error)) << error;
}

TEST(Sun, Sites) {
  std::string error;
  auto site = parse_site("-33.86,151.21,12.5", error);
  ASSERT_TRUE(site) << error;
  EXPECT_EQ(site->north, 12.5);
  for (const char* bad : {"90.5,0", "0,-181", "1", "1,2,3,4", "a,b", "1,,2", "nan,0"})
    EXPECT_FALSE(parse_site(bad, error)) << bad;
}

}  // namespace
}  // namespace hlr
