#include "scene/render_settings_loader.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace geodesic {
namespace {

template <typename Enum>
Enum read_choice(const JsonNode& node, std::initializer_list<std::pair<const char*, Enum>> choices) {
  const std::string value = read_string(node);
  std::string expected;
  for (const auto& [name, e] : choices) {
    if (value == name) return e;
    expected += std::string(expected.empty() ? "\"" : ", \"") + name + "\"";
  }
  node.fail("unknown value \"" + value + "\" (expected one of " + expected + ")");
}

}  // namespace

Exposure exposure_from_json(const nlohmann::ordered_json& value) {
  if (value.is_string() && value.get<std::string>() == "auto") return {0, true};
  const double stops = value.is_number() ? value.get<double>() : NAN;
  if (!(std::abs(stops) <= kMaxExposureStops))
    throw std::invalid_argument("must be a number of stops in [-20, 20] or \"auto\"");
  return {stops, false};
}

nlohmann::ordered_json exposure_to_json(const Exposure& exposure) {
  return exposure.automatic ? nlohmann::ordered_json("auto") : nlohmann::ordered_json(exposure.stops);
}

RenderSettings read_render(const JsonNode& node) {
  node.expect_object({"width", "height", "max_depth", "spp", "seed", "ambient", "lighting",
                      "light_sampling", "light_samples", "light_cutoff", "russian_roulette",
                      "clamp", "exposure"});
  RenderSettings render;
  if (const auto n = node.find("width")) render.width = read_int(*n, 1, 8192);
  if (const auto n = node.find("height")) render.height = read_int(*n, 1, 8192);
  if (const auto n = node.find("max_depth")) render.max_depth = read_int(*n, 0, 64);
  if (const auto n = node.find("spp")) render.spp = read_int(*n, 1, 1000000);
  if (const auto n = node.find("seed")) render.seed = read_uint64(*n);
  if (const auto n = node.find("ambient")) render.ambient_light = read_rgb(*n);
  if (const auto n = node.find("lighting"))
    render.lighting = read_choice<LightingModel>(
        *n, {{"physical", LightingModel::Physical}, {"paper", LightingModel::Paper}});
  if (const auto n = node.find("light_sampling"))
    render.light_sampling = read_choice<LightSampling>(
        *n, {{"mis", LightSampling::Mis}, {"bsdf", LightSampling::Bsdf}, {"light", LightSampling::Light}});
  if (const auto n = node.find("light_samples"))
    render.light_samples = read_int(*n, 1, kMaxLightSamples);
  if (const auto n = node.find("light_cutoff")) render.light_cutoff = read_positive(*n);
  if (const auto n = node.find("clamp")) render.clamp = read_positive(*n);
  if (const auto n = node.find("exposure")) {
    try {
      render.exposure = exposure_from_json(n->value());
    } catch (const std::invalid_argument& e) {
      n->fail(e.what());
    }
  }
  render.russian_roulette = render.lighting == LightingModel::Physical;
  if (const auto n = node.find("russian_roulette")) render.russian_roulette = read_bool(*n);
  return render;
}

}  // namespace geodesic
