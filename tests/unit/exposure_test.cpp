// Exposure (render/prepare/exposure.h): the automatic exposure against its closed form, and the
// exposure's text and JSON forms with their refusals.
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "render/prepare/exposure.h"
#include "scene/render_settings_loader.h"

namespace geodesic {
namespace {

Image image_of(const std::vector<float>& luminances) {
  Image image{int(luminances.size()), 1, {}};
  for (float y : luminances) image.rgb.insert(image.rgb.end(), {y, y, y});  // grey: Y = value
  return image;
}

TEST(Exposure, AutomaticBringsTheLogAverageOfTheLitPixelsToMiddleGrey) {
  // Log-average of 0.01 and 0.25 is 0.05: 0.18 / 0.05 = 3.6 = 2^1.848.
  EXPECT_NEAR(automatic_stops(image_of({0.01f, 0.25f})), std::log2(3.6), 1e-6);
  // Black pixels (a void, the background) do not count; a bright light does, logarithmically.
  EXPECT_NEAR(automatic_stops(image_of({0.0f, 0.0f, 0.0f, 0.045f})), 2.0, 1e-6);
  EXPECT_NEAR(automatic_stops(image_of({0.045f * 100, 0.045f / 100})), 2.0, 1e-5);
  // Coloured: Rec. 709 luminance.
  Image red{1, 1, {0.18f / 0.2126f, 0, 0}};
  EXPECT_NEAR(automatic_stops(red), 0.0, 1e-6);
  // Nothing lit, or not finite: no change; far too dark or bright: the end of the range.
  EXPECT_EQ(automatic_stops(image_of({0, 0})), 0.0);
  EXPECT_EQ(automatic_stops(image_of({NAN, INFINITY, 0})), 0.0);
  EXPECT_NEAR(automatic_stops(image_of({1e-5f})), std::log2(18000.0), 1e-5);
  EXPECT_EQ(automatic_stops(image_of({1e9f})), -kMaxExposureStops);
  EXPECT_EQ(exposure_scale(3), 8.0f);
  EXPECT_EQ(exposure_stops({-2, false}, image_of({0.01f})), -2.0);
}

TEST(Exposure, TextAndJsonFormsAndTheirRefusals) {
  EXPECT_EQ(parse_exposure("auto"), (Exposure{0, true}));
  EXPECT_EQ(parse_exposure("-1.5"), (Exposure{-1.5, false}));
  EXPECT_EQ(parse_exposure("20"), (Exposure{20, false}));
  for (const char* bad : {"", "bright", "1.5x", "20.5", "-21", "nan", "inf", "AUTO"}) {
    try {
      parse_exposure(bad);
      ADD_FAILURE() << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()),
                std::string("must be a number of stops in [-20, 20] or \"auto\", not \"") + bad + "\"");
    }
  }
  using Json = nlohmann::ordered_json;
  EXPECT_EQ(exposure_from_json(Json("auto")), (Exposure{0, true}));
  EXPECT_EQ(exposure_from_json(Json(2.25)), (Exposure{2.25, false}));
  EXPECT_EQ(exposure_to_json({2.25, false}), Json(2.25));
  EXPECT_EQ(exposure_to_json({0, true}), Json("auto"));
  for (const Json& bad : {Json("dark"), Json(true), Json(25), Json::array({1}), Json(nullptr)})
    EXPECT_THROW(exposure_from_json(bad), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace geodesic
