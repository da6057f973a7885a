// A press (sensor/press.hpp): parsed from "x,y,r,F", its pressure F/(π r²), and checked against
// the sheet with one-line messages.
#include "emit/sensor/press.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

TEST(Press, ParsesFourNumbersAndGivesItsPressure) {
  const Press p = parse_press(" 12.5,40, 2.5 ,7");
  EXPECT_EQ(p.x_mm, 12.5);
  EXPECT_EQ(p.y_mm, 40.0);
  EXPECT_EQ(p.radius_mm, 2.5);
  EXPECT_EQ(p.force_N, 7.0);
  EXPECT_DOUBLE_EQ(p.pressure_N_per_mm2(), 7 / (std::numbers::pi * 6.25));
}

// Five values carry the centre's z (a cylinder's presses need it: sensor/press.hpp).
TEST(Press, ParsesAPressWithItsHeight) {
  const Press p = parse_press("-8,1.5,-14.9,4,10");
  EXPECT_EQ(p.x_mm, -8.0);
  EXPECT_EQ(p.y_mm, 1.5);
  EXPECT_EQ(p.z_mm, -14.9);
  EXPECT_EQ(p.radius_mm, 4.0);
  EXPECT_EQ(p.force_N, 10.0);
}

// On a cylinder the centre must be on the surface (within 1 mm, then moved onto it): a press
// given without its z is on the axis' plane, half a sleeve's radius or more away, and refused.
TEST(Press, OnACylinderMustBeOnItsSurface) {
  Sensor sensor = load_sensor(test::source_path("examples/sensors/sleeve.json"));
  Press under{8, 0, 4, 10};
  under.z_mm = -15.5;  // 0.5 mm off: taken
  EXPECT_NO_THROW(validate_press(sensor, under, "press 0"));
  EXPECT_EQ(test::error_of([&] {
              validate_press(sensor, Press{8, 0, 4, 10}, "press 0");
            }),
            "press 0: centre (8, 0, 0) mm is 15 mm off the cylinder's surface (give its z)");
}

TEST(Press, ParseErrorsNameTheText) {
  EXPECT_EQ(test::error_of([] { parse_press("1,2,3"); }),
            "press \"1,2,3\": expected 4 values x_mm,y_mm,radius_mm,force_N (or 5, with z_mm after y_mm), got 3");
  EXPECT_EQ(test::error_of([] { parse_press("1,2,3mm,4"); }),
            "press \"1,2,3mm,4\": \"3mm\" is not a number (expected x_mm,y_mm[,z_mm],radius_mm,force_N)");
  EXPECT_EQ(test::error_of([] { parse_press("1,,3,4"); }),
            "press \"1,,3,4\": \"\" is not a number (expected x_mm,y_mm[,z_mm],radius_mm,force_N)");
}

TEST(Press, ValidationNamesWhatIsWrong) {
  const Sensor sensor = default_sensor();  // 60 × 60 mm from the origin
  EXPECT_EQ(test::error_of([&] { validate_press(sensor, {30, 30, 5, 10}, "press 1"); }), "no error");
  EXPECT_EQ(test::error_of([&] {
              validate_press(sensor, {30, std::nan(""), 5, 10}, "press 1");
            }),
            "press 1: values must be finite numbers");
  EXPECT_EQ(test::error_of([&] {
              validate_press(sensor, {30, 30, 0, 10}, "press 2");
            }),
            "press 2: radius must be positive");
  EXPECT_EQ(test::error_of([&] {
              validate_press(sensor, {30, 30, 5, -1}, "press 3");
            }),
            "press 3: force must not be negative");
  EXPECT_EQ(test::error_of([&] {
              validate_press(sensor, {-1, 30, 5, 1}, "press 4");
            }),
            "press 4: centre (-1, 30) mm is off the sheet");
}

}  // namespace
}  // namespace emit
