#include "cli/render_report.h"

#include <fstream>
#include <stdexcept>

namespace geodesic {
namespace {

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(path.string() + ": cannot write the report");
}

}  // namespace

void write_render_report(const std::filesystem::path& json_path, const RenderReport& r) {
  nlohmann::ordered_json json;
  json["scene"] = r.scene;
  json["geometry"] = r.geometry;
  json["width"] = r.width;
  json["height"] = r.height;
  json["device"] = r.device;
  json["backend"] = r.backend;
  json["samples"] = r.samples;
  json["seconds"] = r.seconds;
  json["estimated_error"] =
      r.estimated_error >= 0 ? nlohmann::ordered_json(r.estimated_error) : nullptr;
  json["stop"] = r.stop.to_json();
  json["stop"]["reached"] = r.stopped_by;
  json["non_finite_samples"] = r.non_finite_samples;
  json["truncated_geodesics"] = r.truncated_geodesics;
  json["series"] = r.log.to_json()["series"];
  write_file(json_path, json.dump(2) + "\n");
  std::filesystem::path csv_path = json_path;
  write_file(csv_path.replace_extension(".csv"), r.log.to_csv());
}

}  // namespace geodesic
