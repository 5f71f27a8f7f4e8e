// `geodesic merge PART.exr... -o OUT.{exr,png,jpg} [--accumulation ALL.exr] [--report R.json]`:
// sums the accumulations of a sample-parallel render's parts (geodesic render --samples-from K
// --samples N --accumulation PART.exr) into one image, as one render of all their samples.
// -o may be given several times: the same image in several formats.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/prepare/accumulation_file.h"
#include "render/prepare/exposure.h"
#include "render/prepare/image_io.h"

namespace geodesic {

int merge_command(int argc, char** argv) {
  std::vector<std::string> inputs;
  std::vector<std::string> outputs;
  std::string accumulation, report;
  Exposure exposure;
  for (int i = 0; i < argc; ++i) {
    const std::string flag = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(flag + ": needs a value");
      return argv[++i];
    };
    if (flag == "-o" || flag == "--output") outputs.push_back(value());
    else if (flag == "--accumulation") accumulation = value();
    else if (flag == "--report") report = value();
    else if (flag == "--exposure") {
      try {
        exposure = parse_exposure(value());
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("--exposure: " + std::string(e.what()));
      }
    }
    else if (!flag.empty() && flag[0] == '-') throw std::invalid_argument("unknown option " + flag);
    else inputs.push_back(flag);
  }
  if (inputs.empty()) throw std::invalid_argument("give the parts: PART.exr...");
  if (outputs.empty() && accumulation.empty())
    throw std::invalid_argument("missing -o OUT.{png,exr,jpg} (or --accumulation OUT.exr)");
  for (const std::string& output : outputs) check_output_format(output);

  std::vector<Accumulation> parts;
  for (const std::string& input : inputs) parts.push_back(read_accumulation(input));
  const Accumulation merged = merge_accumulations(parts);
  const double error = merged.estimated_error();
  if (!outputs.empty()) {
    const Image image = merged.image();
    const float scale = exposure_scale(exposure_stops(exposure, image));
    for (const std::string& output : outputs) write_image(output, image, scale);
  }
  if (!accumulation.empty()) write_accumulation(accumulation, merged);
  std::printf("%s: %zu parts, %u spp at %dx%d, estimated error %.6f\n",
              (outputs.empty() ? accumulation : outputs.front()).c_str(), parts.size(), merged.samples,
              merged.width, merged.height, error);
  if (!report.empty()) {
    nlohmann::json doc{{"view", merged.view},
                       {"width", merged.width},
                       {"height", merged.height},
                       {"samples", merged.samples},
                       {"estimated_error", error >= 0 ? nlohmann::json(error) : nullptr},
                       {"parts", nlohmann::json::array()}};
    for (size_t i = 0; i < parts.size(); ++i)
      doc["parts"].push_back({{"file", inputs[i]},
                              {"sample_start", parts[i].sample_start},
                              {"samples", parts[i].samples},
                              {"estimated_error", parts[i].estimated_error()}});
    std::ofstream out(report);
    out << doc.dump(2) << "\n";
    if (!out) throw std::runtime_error(report + ": cannot write");
  }
  return 0;
}

}  // namespace geodesic
