// Exposure: the scale from linear radiance to display values (scene.h's Exposure). Automatic
// exposure is the photographic key of Reinhard et al. (2002): the log-average luminance of
// the lit pixels is brought to middle grey.
#pragma once

#include <string>

#include "render/prepare/image.h"
#include "scene/scene.h"

namespace geodesic {

constexpr double kMiddleGrey = 0.18;

// The stops that bring the log-average Rec. 709 luminance of the pixels brighter than 1e-6
// (black background, a void between objects, does not count) to kMiddleGrey, within
// +-kMaxExposureStops; 0 for an image with no such pixel.
double automatic_stops(const Image& image);

// The stops an exposure applies to this image.
double exposure_stops(const Exposure& exposure, const Image& image);

// An exposure written as text (the CLI's --exposure): stops in [-20, 20] or "auto". Throws
// std::invalid_argument saying what is expected.
Exposure parse_exposure(const std::string& text);

// The factor 2^stops.
float exposure_scale(double stops);

}  // namespace geodesic
