// Error against run time for one scene (docs/benchmarks.md, "Convergence"): renders a
// high-sample reference once (or reads it from the cache path it is given), then renders again
// with another seed and, at checkpoints spaced about 25 % apart in samples, records the true
// relative RMSE against the reference and the estimate from the even/odd halves. Writes the
// series as CSV and prints one table row: fitted log-log slope, time to 5 % and 1 %, and the
// ratio estimate / true past 16 spp (median and range).
//
//   geodesic_convergence SCENE.json --reference REF.exr --csv OUT.csv [--width W] [--height H]
//                        [--ref-spp N] [--ref-time S] [--time S] [--device SEL] [--header]
//
// The reference's own noise: against a reference with its own relative error e_ref, the
// measured error^2 is the true error^2 plus e_ref^2 in expectation, so true^2 is taken as
// measured^2 - e_ref^2, with e_ref the reference's estimate from its halves (kept next to the
// EXR as REF.json). The reference renders N_ref samples, or fewer when --ref-time runs out
// first; test runs stop at N_ref / 4 samples so that the correction stays small (at most a
// quarter of the measured error^2).
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/prepare/image_io.h"
#include "render/prepare/relative_error.h"
#include "render/device/renderer.h"
#include "scene/scene_loader.h"

namespace fs = std::filesystem;
using namespace geodesic;

namespace {

struct Args {
  std::string scene, reference, csv, device;
  int width = 128, height = 128;
  uint32_t ref_spp = 65536;
  double ref_seconds = 90;
  double seconds = 30;
  bool header = false;
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(flag + ": needs a value");
      return argv[++i];
    };
    if (flag == "--reference") a.reference = value();
    else if (flag == "--csv") a.csv = value();
    else if (flag == "--width") a.width = std::stoi(value());
    else if (flag == "--height") a.height = std::stoi(value());
    else if (flag == "--ref-spp") a.ref_spp = uint32_t(std::stoul(value()));
    else if (flag == "--ref-time") a.ref_seconds = std::stod(value());
    else if (flag == "--time") a.seconds = std::stod(value());
    else if (flag == "--device") a.device = value();
    else if (flag == "--header") a.header = true;
    else if (flag[0] == '-') throw std::invalid_argument("unknown option " + flag);
    else a.scene = flag;
  }
  if (a.scene.empty() || a.reference.empty() || a.csv.empty())
    throw std::invalid_argument("usage: geodesic_convergence SCENE.json --reference REF.exr "
                                "--csv OUT.csv [--width W] [--height H] [--ref-spp N] "
                                "[--ref-time S] [--time S]");
  return a;
}

struct Reference {
  Image image;
  uint32_t spp = 0;
  double error = 0;  // its own estimated relative error
};

// Reads REF.exr + REF.json, or renders them (seed shifted so the test run's random streams
// are independent of the reference's).
Reference load_or_render_reference(const Args& args, Scene scene, VulkanContext& ctx) {
  const fs::path exr = args.reference, meta = fs::path(args.reference).replace_extension(".json");
  if (fs::exists(exr) && fs::exists(meta)) {
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(meta));
    std::fprintf(stderr, "reference: cached %s\n", exr.string().c_str());
    return {read_image(exr), j.at("spp").get<uint32_t>(), j.at("estimated_error").get<double>()};
  }
  scene.render.seed += 0x9E3779B9u;
  Renderer renderer(ctx, scene);
  const auto start = std::chrono::steady_clock::now();
  auto took = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  while (renderer.samples() < args.ref_spp && took() < args.ref_seconds) {
    const uint32_t batch = std::clamp(renderer.samples() / 4, 1u, 64u);
    renderer.add_samples(std::min(batch, args.ref_spp - renderer.samples()));
  }
  Reference ref{renderer.image(), renderer.samples(), renderer.estimated_error()};
  fs::create_directories(exr.parent_path().empty() ? fs::path(".") : exr.parent_path());
  write_image(exr, ref.image);
  std::ofstream(meta) << nlohmann::json{{"spp", ref.spp}, {"estimated_error", ref.error}}.dump()
                      << "\n";
  std::fprintf(stderr, "reference: %u spp in %.1f s, estimated error %.5f -> %s\n", ref.spp,
               took(), ref.error, exr.string().c_str());
  return ref;
}

struct Point {
  double seconds, cpu_seconds;  // of rendering: wall clock, and CPU time of all our threads
  uint32_t spp;
  double true_error, estimate;
};

double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Renders until `seconds` of rendering (checkpoint measurements not counted) or ref_spp / 4.
// CPU time is kept too: lavapipe renders on this process's threads, so it is the work done,
// whatever else the machine runs (wall-clock slopes suffer when the load changes mid-run).
std::vector<Point> measure(const Args& args, const Scene& scene, VulkanContext& ctx,
                           const Reference& ref) {
  Renderer renderer(ctx, scene);
  renderer.add_samples(1);  // compiles the pipeline outside the clock
  renderer.reset();
  std::vector<Point> points;
  double rendering = 0, cpu = 0;
  const uint32_t max_spp = std::max(32u, ref.spp / 4);
  while (rendering < args.seconds && renderer.samples() < max_spp) {
    // Checkpoints 25 % apart in samples (even on a log axis), the last one near the time limit.
    uint32_t batch = std::max(renderer.samples() / 4, 1u);
    if (renderer.samples() > 0) {
      const double per_sample = rendering / renderer.samples();
      batch = std::min(batch, uint32_t((args.seconds - rendering) / per_sample) + 1);
    }
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = cpu_now();
    renderer.add_samples(std::min(batch, max_spp - renderer.samples()));
    rendering += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cpu += cpu_now() - cpu_start;
    const double measured = relative_rmse(renderer.image(), ref.image);
    const double true_squared = measured * measured - ref.error * ref.error;
    points.push_back({rendering, cpu, renderer.samples(), std::sqrt(std::max(0.0, true_squared)),
                      renderer.estimated_error()});
  }
  return points;
}

struct Fit {
  double slope = NAN, intercept = NAN;  // ln(error) = intercept + slope ln(x)
};

double seconds_of(const Point& p) { return p.seconds; }
double cpu_seconds_of(const Point& p) { return p.cpu_seconds; }
double spp_of(const Point& p) { return p.spp; }

// Least squares in log-log over the points past 16 spp, against wall-clock seconds, CPU
// seconds or samples (-0.5 for an unbiased renderer, whatever the time per sample does).
Fit fit_slope(const std::vector<Point>& points, double (*x_of)(const Point&) = seconds_of) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const Point& p : points) {
    if (p.spp <= 16 || p.true_error <= 0) continue;
    const double x = std::log(x_of(p)), y = std::log(p.true_error);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  Fit f;
  if (n < 2) return f;
  f.slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  f.intercept = (sy - f.slope * sx) / n;
  return f;
}

// Seconds to reach `level`: interpolated in log-log between the measured points that cross
// it, else extrapolated along the fit (and flagged).
std::string time_to(double level, const std::vector<Point>& points, const Fit& fit) {
  char text[48];
  for (size_t i = 0; i < points.size(); ++i) {
    if (points[i].true_error > level) continue;
    double t = points[i].seconds;
    if (i > 0 && points[i - 1].true_error > 0 && points[i].true_error > 0) {
      const Point &a = points[i - 1], &b = points[i];
      const double u = std::log(level / a.true_error) / std::log(b.true_error / a.true_error);
      t = std::exp(std::log(a.seconds) + u * std::log(b.seconds / a.seconds));
    }
    std::snprintf(text, sizeof text, "%.3g s", t);
    return text;
  }
  if (!(fit.slope < 0)) return "never";
  std::snprintf(text, sizeof text, "%.3g s (extrap.)",
                std::exp((std::log(level) - fit.intercept) / fit.slope));
  return text;
}

struct Ratios {
  double median = NAN, low = NAN, high = NAN;  // of estimate / true past 16 spp
};

Ratios estimate_over_true(const std::vector<Point>& points) {
  std::vector<double> r;
  for (const Point& p : points)
    if (p.spp > 16 && p.true_error > 0 && p.estimate > 0) r.push_back(p.estimate / p.true_error);
  if (r.empty()) return {};
  std::sort(r.begin(), r.end());
  return {r[r.size() / 2], r.front(), r.back()};
}

// The CSV the plot reads; `ideal` is the t^(-1/2) line through the first point past 16 spp.
void write_csv(const fs::path& path, const std::vector<Point>& points) {
  double anchor = NAN;
  for (const Point& p : points)
    if (p.spp > 16 && std::isnan(anchor)) anchor = p.true_error * std::sqrt(p.seconds);
  std::ofstream out(path);
  out << "seconds,cpu_seconds,spp,true_error,estimated_error,ideal\n";
  char line[160];
  for (const Point& p : points) {
    std::snprintf(line, sizeof line, "%.6f,%.6f,%u,%.8g,%.8g,%.8g\n", p.seconds, p.cpu_seconds,
                  p.spp, p.true_error, p.estimate, anchor / std::sqrt(p.seconds));
    out << line;
  }
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

}  // namespace

int main(int argc, char** argv) try {
  const Args args = parse(argc, argv);
  Scene scene = load_scene_file(args.scene);
  scene.render.width = args.width;
  scene.render.height = args.height;
  VulkanContext ctx(args.device);
  const Reference ref = load_or_render_reference(args, scene, ctx);
  const std::string name = fs::path(args.scene).stem().string();
  if (args.header)
    std::printf("%-22s %-8s %6s %5s %6s %6s %6s %10s %17s %8s %13s %s\n", "scene", "size",
                "ref", "spp", "slope", "(cpu)", "(spp)", "t(5%)", "t(1%)", "est/true", "(range)",
                "within 1.5x");
  if (ref.error < 1e-5) {  // the halves agree to float round-off: nothing to converge
    std::printf("%-22s %dx%-4d %6u  noise-free: the reference's halves agree (error < 1e-5)\n",
                name.c_str(), args.width, args.height, ref.spp);
    write_csv(args.csv, {});
    return 0;
  }
  const std::vector<Point> points = measure(args, scene, ctx, ref);
  write_csv(args.csv, points);
  const Point& last = points.back();
  const Fit fit = fit_slope(points);
  const double cpu_slope = fit_slope(points, cpu_seconds_of).slope;
  const double spp_slope = fit_slope(points, spp_of).slope;
  const Ratios ratio = estimate_over_true(points);
  std::printf("%-22s %dx%-4d %6u %5u %6.3f %6.3f %6.3f %10s %17s %8.3f  [%.3f, %.3f] %s\n",
              name.c_str(), args.width, args.height, ref.spp, last.spp, fit.slope, cpu_slope,
              spp_slope,
              time_to(0.05, points, fit).c_str(), time_to(0.01, points, fit).c_str(),
              ratio.median, ratio.low, ratio.high,
              ratio.low >= 1 / 1.5 && ratio.high <= 1.5 ? "yes" : "NO");
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "geodesic_convergence: %s\n", e.what());
  return 1;
}
