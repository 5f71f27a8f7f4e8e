// The `geodesic` command as a user runs it: exit codes, messages, and the files it writes.
#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "render/image_io.h"
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

TEST(Cli, ExrKeepsLinearRadianceAboveOne) {
  const auto out = temp_file(".exr");
  const CliRun r = run_cli("render " + source_path("scenes/furnace.json").string() + " -o " + out.string() +
                    " --spp 1 --width 8 --height 8");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image image = read_image(out);
  EXPECT_NEAR(image.at(4, 4, 0), 2.0, 0.02);  // the furnace's Le / (1 - rho), not clipped to 1
  std::filesystem::remove(out);
}

TEST(Cli, BadInputFailsWithAMessageNamingTheProblem) {
  const std::string cornell = source_path("scenes/cornell-box.json").string();
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {cornell + " -o x.tiff --spp 1", "unsupported output format \".tiff\""},
      {cornell + " -o x.png --spp 0", "--spp: must be an integer in [1, 16777216], not \"0\""},
      {cornell + " -o x.png --spp 2 --time 3", "--spp and --time: give one, not both"},
      {cornell + " -o x.png --backend warp", "--backend: must be auto, ray-query or pipeline"},
      {cornell + " -o x.png --device no-such-gpu", "no Vulkan device matches --device"},
      {cornell, "missing -o OUT.{png,exr,jpg}"},
      {"missing.json -o x.png", "missing.json: cannot open file"},
  };
  for (const auto& c : cases) {
    const CliRun r = run_cli("render " + c.args);
    EXPECT_EQ(r.exit_code, 1) << c.args;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
  }
}

TEST(Cli, DevicesListsARayTracingDevice) {
  const CliRun r = run_cli("devices");
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("can ray-trace"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace geodesic::test
