// Shared set-up for render tests: one Vulkan device per test binary, scenes from JSON text,
// and image statistics to assert on.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "render/device/renderer.h"
#include "scene/scene_loader.h"

namespace geodesic::test {

inline VulkanContext& device() {
  static VulkanContext ctx;  // default selection: lavapipe on CI machines
  return ctx;
}

inline std::filesystem::path source_path(const std::string& relative) {
  return std::filesystem::path(GEODESIC_SOURCE_DIR) / relative;
}

inline Scene scene_from_json(const std::string& text) {
  return parse_scene(nlohmann::ordered_json::parse(text), source_path("scenes"));
}

// A bundled scene file (relative to the source tree) at a small resolution.
inline Scene small_scene(const std::string& relative, int width, int height) {
  Scene scene = load_scene_file(source_path(relative));
  scene.render.width = width;
  scene.render.height = height;
  return scene;
}

// A bundled scene (scenes/<name>.json), size x size pixels.
inline Scene bundled_scene(const std::string& name, int size = 16) {
  return small_scene("scenes/" + name + ".json", size, size);
}

// The scene under the paper's lighting model with its defaults (no Russian roulette): the
// model the geometry tests were written against (eq. 2.2 is deterministic per hit).
inline Scene paper_model(Scene scene) {
  scene.render.lighting = LightingModel::Paper;
  scene.render.russian_roulette = false;
  return scene;
}

inline Image render(const Scene& scene, uint32_t spp, BackendKind backend = BackendKind::Auto) {
  Renderer renderer(device(), scene, backend);
  renderer.add_samples(spp);
  return renderer.image();
}

struct Rgb {
  double r = 0, g = 0, b = 0;
};

// Mean colour over the pixel rectangle [x0, x1) x [y0, y1).
inline Rgb mean(const Image& image, int x0, int y0, int x1, int y1) {
  Rgb m;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      m.r += image.at(x, y, 0);
      m.g += image.at(x, y, 1);
      m.b += image.at(x, y, 2);
    }
  const double n = double(x1 - x0) * (y1 - y0);
  return {m.r / n, m.g / n, m.b / n};
}

inline Rgb mean(const Image& image) { return mean(image, 0, 0, image.width, image.height); }

// Of two renders of one view: the pixels `lit` in `by` (channel sum above 0.1), and the pixels
// where a and b differ by more than 0.02 in some channel, among all and among the lit ones.
struct PixelAgreement {
  int lit = 0, differing = 0, differing_lit = 0;
};
inline PixelAgreement compare_pixels(const Image& a, const Image& b, const Image& by) {
  PixelAgreement agreement;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      double difference = 0, brightness = 0;
      for (int c = 0; c < 3; ++c) {
        difference = std::max(difference, double(std::abs(a.at(x, y, c) - b.at(x, y, c))));
        brightness += by.at(x, y, c);
      }
      const bool lit = brightness > 0.1, differs = difference > 0.02;
      agreement.lit += lit;
      agreement.differing += differs;
      agreement.differing_lit += lit && differs;
    }
  return agreement;
}

// Root-mean-square difference between two images of the same size.
inline double rms_difference(const Image& a, const Image& b) {
  double sum = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i) {
    const double d = double(a.rgb[i]) - b.rgb[i];
    sum += d * d;
  }
  return std::sqrt(sum / a.rgb.size());
}

inline double luminance_of(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// sqrt(sum (Y_a - Y_b)^2 / sum Y_b^2) over pixel luminances Y: the error measure of
// Renderer::estimated_error between two images.
inline double relative_rms_difference(const Image& a, const Image& b) {
  double difference = 0, signal = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const Rgb pa = mean(a, x, y, x + 1, y + 1), pb = mean(b, x, y, x + 1, y + 1);
      difference += std::pow(luminance_of(pa) - luminance_of(pb), 2);
      signal += std::pow(luminance_of(pb), 2);
    }
  return std::sqrt(difference / signal);
}

}  // namespace geodesic::test
