// The `geodesic` command as a user runs it: exit codes, messages, and the files it writes.
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/prepare/exposure.h"
#include "render/prepare/image_io.h"
#include "render_fixture.h"

namespace geodesic::test {
namespace {

struct CliRun {
  int exit_code;
  std::string output;  // stdout and stderr together
};

CliRun run_cli(const std::string& args) {
  const std::string command = std::string(GEODESIC_CLI) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 512> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), output};
}

std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         (::testing::UnitTest::GetInstance()->current_test_info()->name() + name);
}

TEST(Cli, RendersThePngItWasAskedForAndReportsThroughput) {
  const auto out = temp_file(".png");
  const CliRun r = run_cli("render " + source_path("scenes/cornell-box.json").string() + " -o " + out.string() +
                    " --spp 2 --width 32 --height 24 --max-depth 1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("2 spp at 32x24, depth 1"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("M paths/s"), std::string::npos) << r.output;
  const Image image = read_image(out);
  EXPECT_EQ(image.width, 32);
  EXPECT_EQ(image.height, 24);
  // Left wall red, right wall green, in the 8-bit sRGB file too.
  EXPECT_GT(image.at(6, 10, 0), 2 * image.at(6, 10, 1));
  EXPECT_GT(image.at(25, 10, 1), 2 * image.at(25, 10, 0));
  std::filesystem::remove(out);
}

TEST(Cli, DumpShadersWritesTheScenesGlslSpirvAndFeatures) {
  const auto dir = temp_file("-dump");
  std::filesystem::remove_all(dir);
  const CliRun r = run_cli("render " + source_path("scenes/torus-cornell.json").string() + " -o " +
                           temp_file(".png").string() + " --spp 1 --width 16 --height 16" +
                           " --backend ray-query --dump-shaders " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("pipeline: euclidean translation"), std::string::npos) << r.output;
  for (const char* file : {"features.txt", "ray_query.comp.glsl", "ray_query.comp.spv"})
    EXPECT_GT(std::filesystem::file_size(dir / file), 100u) << file;
  std::ifstream features(dir / "features.txt");
  const std::string text{std::istreambuf_iterator<char>(features), {}};
  EXPECT_NE(text.find("#define PAIRING_TRANSLATION"), std::string::npos) << text;
  std::filesystem::remove_all(dir);
  std::filesystem::remove(temp_file(".png"));
}

TEST(Cli, ExrKeepsLinearRadianceAboveOne) {
  const auto out = temp_file(".exr");
  const CliRun r = run_cli("render " + source_path("scenes/furnace.json").string() + " -o " + out.string() +
                    " --spp 64 --width 8 --height 8");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image image = read_image(out);
  EXPECT_NEAR(mean(image).r, 2.0, 0.03);  // the furnace's Le / (1 - rho), not clipped to 1
  std::filesystem::remove(out);
}

// An 8-bit output is the radiance times 2^stops through the sRGB curve, code for code; the same
// seed renders the same radiance into the EXR, which exposure leaves alone.
void expect_exposed(const Image& radiance, const Image& png, double stops) {
  ASSERT_EQ(radiance.rgb.size(), png.rgb.size());
  const float scale = exposure_scale(stops);
  int off = 0, bright = 0;
  for (size_t i = 0; i < radiance.rgb.size(); ++i) {
    const int expected = to_srgb8(radiance.rgb[i] * scale);
    const int got = int(std::lround(png.rgb[i] > 0.0031308f
                                        ? 255 * (1.055 * std::pow(png.rgb[i], 1 / 2.4) - 0.055)
                                        : 255 * 12.92 * png.rgb[i]));
    off += std::abs(got - expected) > 1;
    bright += expected > to_srgb8(radiance.rgb[i]);
  }
  EXPECT_EQ(off, 0) << "of " << radiance.rgb.size() << " values";
  if (stops > 0) EXPECT_GT(bright, int(radiance.rgb.size() / 2));
}

TEST(Cli, ExposureScalesThePngAndLeavesTheExrRadiance) {
  const std::string base = "render " + source_path("scenes/cornell-box.json").string() +
                           " --spp 4 --width 24 --height 16 -o ";
  const auto exr = temp_file(".exr"), png = temp_file(".png"), auto_png = temp_file("-auto.png");
  ASSERT_EQ(run_cli(base + exr.string()).exit_code, 0);
  const CliRun plain = run_cli(base + exr.string() + " --exposure 1.5");  // EXR: no change
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  const Image radiance = read_image(exr);
  ASSERT_EQ(run_cli(base + png.string() + " --exposure 1.5").exit_code, 0);
  expect_exposed(radiance, read_image(png), 1.5);

  // Automatic: the stops that bring the log-average luminance to middle grey, printed.
  const CliRun automatic = run_cli(base + auto_png.string() + " --exposure auto");
  ASSERT_EQ(automatic.exit_code, 0) << automatic.output;
  const double stops = automatic_stops(radiance);
  char said[64];
  std::snprintf(said, sizeof said, "exposure %+.2f stops (auto)", stops);
  EXPECT_NE(automatic.output.find(said), std::string::npos) << automatic.output;
  expect_exposed(radiance, read_image(auto_png), stops);
  for (const auto& f : {exr, png, auto_png}) std::filesystem::remove(f);
}

TEST(Cli, BadInputFailsWithAMessageNamingTheProblem) {
  const std::string cornell = source_path("scenes/cornell-box.json").string();
  const std::string target = "--target-error: must be a relative error in (0, 1), not ";
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {cornell + " -o x.tiff --spp 1", "unsupported output format \".tiff\""},
      {cornell + " -o x.png --spp 0", "--spp: must be an integer in [1, 16777216], not \"0\""},
      {cornell + " -o x.png --light-samples 9",
       "--light-samples: must be an integer in [1, 8], not \"9\""},
      {cornell + " -o x.png --spp 2 --time 3", "--spp and --time: give one, not both"},
      {cornell + " -o x.png --spp 2 --target-error 0.1", "--spp and --target-error: give one"},
      {cornell + " -o x.png --time 2 --target-error 0.1", "--time and --target-error: give one"},
      {cornell + " -o x.png --target-error 0", target + "\"0\""},
      {cornell + " -o x.png --lighting phong", "--lighting: must be \"physical\" or \"paper\""},
      {cornell + " -o x.png --pipeline fast", "--pipeline: must be \"specialised\" or \"all-features\""},
      {cornell + " -o x.png --target-error 1.5", target + "\"1.5\""},
      {cornell + " -o x.png --target-error 5%", target + "\"5%\""},
      {cornell + " -o x.png --target-error", "--target-error: needs a value"},
      {cornell + " -o x.png --report r.csv", "--report: must name a .json file"},
      {cornell + " -o x.png --backend warp", "--backend: must be auto, ray-query or pipeline"},
      {cornell + " -o x.png --device no-such-gpu", "no Vulkan device matches --device"},
      {cornell, "missing -o OUT.{png,exr,jpg}"},
      {cornell + " -o x.png --exposure bright", "--exposure: must be a number of stops in [-20, 20] or \"auto\", not \"bright\""},
      {cornell + " -o x.png --exposure 21", "--exposure: must be a number of stops in [-20, 20]"},
      {"missing.json -o x.png", "missing.json: cannot open file"},
      {cornell + " -o x.png --camera 1,0,0", "--camera: must be 16 numbers (the camera isometry, row-major)"},
      {cornell + " -o x.png --camera 1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1,0", "--camera: must be 16 numbers"},
      {cornell + " -o x.png --camera 2,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1",
       "--camera: not an isometry of euclidean space (error"},
      // A mesh named by a document whose files are confined to a folder it is not in.
      {source_path("scenes/mesh-demo.json").string() + " -o x.png --scene-dir " +
           source_path("web").string(), "objects[8].file: file not found"},
  };
  for (const auto& c : cases) {
    const CliRun r = run_cli("render " + c.args);
    EXPECT_EQ(r.exit_code, 1) << c.args;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
  }
}

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  return nlohmann::json::parse(in);
}

std::vector<std::string> read_lines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(Cli, TargetErrorStopsAtTheFirstEstimateBelowIt) {
  const auto out = temp_file(".exr"), report = temp_file(".json");
  const CliRun r = run_cli("render " + source_path("scenes/cornell-box.json").string() + " -o " +
                           out.string() + " --target-error 0.08 --width 32 --height 32" +
                           " --max-depth 2 --report " + report.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = read_json(report);
  EXPECT_EQ(j.at("stop").at("reached"), "target_error");
  EXPECT_DOUBLE_EQ(j.at("stop").at("target_error").get<double>(), 0.08);
  EXPECT_TRUE(j.at("stop").at("spp").is_null());
  const double final_error = j.at("estimated_error").get<double>();
  EXPECT_GT(final_error, 0);
  EXPECT_LE(final_error, 0.08);
  const auto& series = j.at("series");
  ASSERT_GE(series.size(), 2u);
  EXPECT_EQ(series.back().at("spp"), j.at("samples"));
  EXPECT_DOUBLE_EQ(series.back().at("estimated_error").get<double>(), final_error);
  EXPECT_GE(j.at("samples").get<int>(), 8);
  // It went on while the estimate was above the target (or from too few samples to trust).
  const auto& before = series[series.size() - 2];
  EXPECT_TRUE(before.at("spp").get<int>() < 8 ||
              before.at("estimated_error").get<double>() > 0.08)
      << before;
  // The image is the render the report describes: the estimate is about its true error.
  EXPECT_EQ(read_image(out).width, 32);
  std::filesystem::remove(out);
  std::filesystem::remove(report);
  std::filesystem::remove(std::filesystem::path(report).replace_extension(".csv"));
}

// The summary and the report count non-finite samples and geodesics cut off at the crossing
// bound: none in the Euclidean box, some in the quarter-turn space even at the largest bound,
// 64 crossings (1.5 % of its geodesics: a few run through the gaps of the lattice of copies).
TEST(Cli, SummaryAndReportCountNonFiniteSamplesAndCutOffGeodesics) {
  for (const auto& [scene, cut_off] :
       {std::pair{"cornell-box", false}, std::pair{"quarter-turn-space", true}}) {
    const auto out = temp_file(".png"), report = temp_file(".json");
    const CliRun r = run_cli("render " + source_path(std::string("scenes/") + scene + ".json").string() +
                             " -o " + out.string() + " --spp 2 --width 24 --height 24 --report " +
                             report.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json j = read_json(report);
    EXPECT_EQ(j.at("non_finite_samples"), 0) << scene;
    const uint64_t truncated = j.at("truncated_geodesics").get<uint64_t>();
    EXPECT_EQ(truncated > 0, cut_off) << scene << ": " << truncated;
    EXPECT_NE(r.output.find("0 non-finite samples, " + std::to_string(truncated) + " geodesics cut off"),
              std::string::npos)
        << r.output;
    for (const auto& f : {out, report}) std::filesystem::remove(f);
    std::filesystem::remove(std::filesystem::path(report).replace_extension(".csv"));
  }
}

TEST(Cli, ReportJsonAndCsvCarryTheSameSeriesOfFallingError) {
  const auto out = temp_file(".png"), report = temp_file(".json");
  auto csv_path = report;
  csv_path.replace_extension(".csv");
  const CliRun r = run_cli("render " + source_path("scenes/cornell-box.json").string() + " -o " +
                           out.string() + " --spp 64 --width 24 --height 24 --max-depth 2" +
                           " --report " + report.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = read_json(report);
  EXPECT_EQ(j.at("scene"), source_path("scenes/cornell-box.json").string());
  EXPECT_EQ(j.at("geometry"), "euclidean");
  EXPECT_EQ(j.at("width"), 24);
  EXPECT_EQ(j.at("height"), 24);
  EXPECT_FALSE(j.at("device").get<std::string>().empty());
  EXPECT_FALSE(j.at("backend").get<std::string>().empty());
  EXPECT_EQ(j.at("samples"), 64);
  EXPECT_GT(j.at("seconds").get<double>(), 0);
  EXPECT_EQ(j.at("stop").at("spp"), 64);
  EXPECT_EQ(j.at("stop").at("reached"), "spp");

  const auto& series = j.at("series");
  const std::vector<std::string> csv = read_lines(csv_path);
  ASSERT_EQ(csv.size(), series.size() + 1);
  EXPECT_EQ(csv[0], "seconds,spp,estimated_error");
  ASSERT_GE(series.size(), 3u);  // batches start at one sample: several points
  EXPECT_EQ(series[0].at("spp"), 1);
  EXPECT_TRUE(series[0].at("estimated_error").is_null());  // one half is still empty
  for (size_t i = 0; i < series.size(); ++i) {
    double seconds = 0, error = -1;
    int spp = 0;
    ASSERT_GE(std::sscanf(csv[i + 1].c_str(), "%lf,%d,%lf", &seconds, &spp, &error), 2)
        << csv[i + 1];
    EXPECT_NEAR(seconds, series[i].at("seconds").get<double>(), 1e-6);
    EXPECT_EQ(spp, series[i].at("spp").get<int>());
    if (i > 0) {
      EXPECT_GT(series[i].at("seconds").get<double>(), series[i - 1].at("seconds").get<double>());
      EXPECT_GT(spp, series[i - 1].at("spp").get<int>());
      EXPECT_NEAR(error, series[i].at("estimated_error").get<double>(), 1e-6);
    }
  }
  // Error falls as 1/sqrt(spp): from the first estimate (2 or 3 spp) to 64 spp it shrinks
  // 4.6 to 5.7 times.
  const double first = series[1].at("estimated_error").get<double>();
  const double last = series.back().at("estimated_error").get<double>();
  EXPECT_LE(series[1].at("spp").get<int>(), 3);
  EXPECT_LT(last, first / 2.5);
  EXPECT_DOUBLE_EQ(j.at("estimated_error").get<double>(), last);
  std::filesystem::remove(out);
  std::filesystem::remove(report);
  std::filesystem::remove(csv_path);
}

TEST(Cli, DevicesListsARayTracingDevice) {
  const CliRun r = run_cli("devices");
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("can ray-trace"), std::string::npos) << r.output;
}

// A space known only by its generators: the default scene inside its Dirichlet domain.
TEST(Cli, GeneratorsRenderTheDefaultSceneInsideTheirSpace) {
  const auto out = temp_file(".png");
  const CliRun r = run_cli("render --generators " + source_path("catalogue/binary-tetrahedral.gen").string() +
                           " -o " + out.string() + " --spp 1 --width 16 --height 16");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image image = read_image(out);
  double brightest = 0;
  for (float v : image.rgb) brightest = std::max(brightest, double(v));
  EXPECT_GT(brightest, 0.2);  // spheres and edges, not an empty frame
  std::filesystem::remove(out);

  const auto bad = temp_file(".gen");
  std::ofstream(bad) << "# a short row\n1 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  const CliRun e = run_cli("render --generators " + bad.string() + " -o " + out.string());
  EXPECT_EQ(e.exit_code, 1);
  EXPECT_NE(e.output.find(bad.string() + ": matrix 1 (line 2): row 1 has 3 entries, not 4"),
            std::string::npos)
      << e.output;
  std::filesystem::remove(bad);
  const CliRun both = run_cli("render " + source_path("scenes/furnace.json").string() +
                              " --generators x.gen -o " + out.string());
  EXPECT_NE(both.output.find("give one of SCENE.json and --generators FILE.gen"), std::string::npos)
      << both.output;
}

// --help after any command prints the usage and does nothing else.
TEST(Cli, HelpAfterAnyCommandPrintsTheUsage) {
  for (const std::string command : {"render", "serve", "catalogue", "devices"}) {
    const CliRun r = run_cli(command + " --help");
    EXPECT_EQ(r.exit_code, 0) << command << "\n" << r.output;
    EXPECT_NE(r.output.find("render --generators FILE.gen"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--pipeline-cache DIR"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists("--help"));
}

// `geodesic catalogue` writes exactly the committed catalogue and its scenes.
TEST(Cli, CatalogueWritesTheCommittedFiles) {
  const auto root = temp_file("-catalogue");
  const CliRun r = run_cli("catalogue " + root.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto text = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  };
  int compared = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    const auto relative = std::filesystem::relative(entry.path(), root);
    EXPECT_EQ(text(entry.path()), text(source_path(relative.string()))) << relative;
    ++compared;
  }
  EXPECT_GE(compared, 2 * 25 + 1);  // .gen and scene per entry, and the README
  std::filesystem::remove_all(root);
}

TEST(Cli, SampleParallelPartsMergeIntoOneRenderOfAllTheirSamples) {
  const std::string scene = source_path("scenes/cornell-box.json").string() +
                            " --width 24 --height 16 --max-depth 2";
  const auto a = temp_file("-a.exr"), b = temp_file("-b.exr"), merged = temp_file("-merged.exr");
  const auto full = temp_file("-full.exr"), report = temp_file("-merge.json");
  const auto full_report = temp_file("-full.json");
  CliRun r = run_cli("render " + scene + " --samples-from 0 --samples 6 --accumulation " + a.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("samples [0, 6)"), std::string::npos) << r.output;
  r = run_cli("render " + scene + " --samples-from 6 --samples 6 --accumulation " + b.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run_cli("merge " + b.string() + " " + a.string() + " -o " + merged.string() + " --report " +
              report.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("2 parts, 12 spp at 24x16"), std::string::npos) << r.output;
  r = run_cli("render " + scene + " --spp 12 -o " + full.string() + " --report " + full_report.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;

  // The same samples, summed in another order: equal up to float round-off.
  const Image m = read_image(merged), f = read_image(full);
  ASSERT_EQ(m.rgb.size(), f.rgb.size());
  for (size_t i = 0; i < f.rgb.size(); ++i) ASSERT_NEAR(m.rgb[i], f.rgb[i], 1e-5 * (1 + f.rgb[i])) << i;
  const auto merge_json = nlohmann::json::parse(std::ifstream(report));
  const auto full_json = nlohmann::json::parse(std::ifstream(full_report));
  EXPECT_EQ(merge_json["samples"], 12);
  EXPECT_EQ(merge_json["parts"].size(), 2u);
  const double expected = full_json["estimated_error"].get<double>();
  EXPECT_NEAR(merge_json["estimated_error"].get<double>(), expected, 1e-4 * expected);

  // A part given twice overlaps itself.
  r = run_cli("merge " + a.string() + " " + a.string() + " -o " + merged.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("overlap"), std::string::npos) << r.output;
  for (const auto& file : {a, b, merged, full, report, full_report}) std::filesystem::remove(file);
  std::filesystem::remove(full_report.parent_path() / (full_report.stem().string() + ".csv"));
}

}  // namespace
}  // namespace geodesic::test
