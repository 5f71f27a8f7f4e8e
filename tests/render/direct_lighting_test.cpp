// Direct light from area lights against closed forms, in E3, H3 and S3: a small diffuse patch
// (albedo 0.5) at the origin facing +z, seen from just above, lit by one emissive sphere or
// quad (radiance 1). Its radiance is albedo / pi * E with
// - a sphere: E = L * (the cosine-weighted solid angle of the cone it subtends), a cone of
//   half-angle alpha, sin alpha = sqrt(A(r) / A(d)); pi L sin^2 alpha cos(theta) when the cone
//   is above the horizon, numerical quadrature of the cone when it straddles it;
// - a quad: E = L * integral over the light of cos_x cos_y / A(d) dA, Lambert's polygon formula
//   in E3 (after clipping to the upper half-space), numerical quadrature in double in H3 and
//   S3 (the quadrature itself is checked against Lambert in E3).
// - a horosphere (H3): the cone of sin alpha = e^-d towards its ideal point, as a sphere's.
// In S3 every light is also seen the long way round, through the antipode: the same cone (or
// the same points at distance 2 pi - d) in the opposite direction.
// Each configuration is rendered with MIS, light sampling alone, BSDF sampling alone and MIS
// with three light samples per vertex; all four must agree with the closed form within 2 %.
// Lights sit close to the surface, far from it, at grazing elevations and partly below the
// horizon.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "geometry/model.h"
#include "render/prepare/emitters.h"
#include "render_fixture.h"
#include "test_constants.h"

namespace geodesic::test {
namespace {

constexpr double kAlbedo = 0.5;
constexpr GeometryKind kGeometries[] = {GeometryKind::Euclidean, GeometryKind::Hyperbolic,
                                        GeometryKind::Spherical};

std::string vec3_json(const Vec3& v) {
  return "[" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + "]";
}

// The patch at the origin, the camera 0.004 above it looking down (it sees 3.5e-5 around the
// patch's centre), and the light objects.
Scene patch_scene(GeometryKind k, const std::string& light, LightSampling sampling,
                  int light_samples) {
  Scene scene = scene_from_json(std::string(R"({"geometry": ")") + geometry_name(k) + R"(",
    "camera": {"position": [0, 0, 0.004], "look_at": [0, 0, 0], "fov_y": 1},
    "materials": {"patch": {"diffuse": 0.5}, "lamp": {"emission": 1}},
    "objects": [{"type": "quad", "material": "patch", "corner": [-0.001, -0.001, 0],
                 "edge_u": [0.002, 0, 0], "edge_v": [0, 0.002, 0]}, )" + light + R"(],
    "render": {"width": 16, "height": 16, "max_depth": 0, "lighting": "physical"}})");
  scene.render.light_sampling = sampling;
  scene.render.light_samples = light_samples;
  // One bounce, so that MIS weighs the light samples against the BSDF sample that finds the
  // light (at the last vertex light sampling counts alone). Not in S3, where that bounce would
  // come round to the patch and bring its own light back.
  if (k != GeometryKind::Spherical) scene.render.max_depth = 1;
  return scene;
}

const char* sampling_name(LightSampling s) {
  return s == LightSampling::Mis ? "mis" : s == LightSampling::Light ? "light" : "bsdf";
}

void expect_radiance(GeometryKind k, const std::string& light, double irradiance,
                     const std::string& what) {
  const double expected = kAlbedo / kPi * irradiance;
  // MIS also with three light samples per vertex, where the light strategy counts three times
  // in the power heuristic: these lights fill much of the sky, so its weights matter here.
  const std::pair<LightSampling, int> runs[] = {
      {LightSampling::Mis, 1}, {LightSampling::Light, 1}, {LightSampling::Bsdf, 1},
      {LightSampling::Mis, 3}};
  for (const auto& [sampling, light_samples] : runs) {
    Renderer renderer(device(), patch_scene(k, light, sampling, light_samples));
    renderer.add_samples(4096);
    const double got = luminance_of(mean(renderer.image()));
    EXPECT_NEAR(got, expected, 0.02 * expected) << geometry_name(k) << ", " << what << ", "
                                                << sampling_name(sampling) << " x" << light_samples;
    EXPECT_EQ(renderer.non_finite_samples(), 0u);
  }
}

// The cosine-weighted solid angle, max(0, w.z) over the directions w within alpha of the unit
// axis (midpoint rule in the polar angle and the azimuth).
double cone_integral(const Vec3& axis, double alpha) {
  Vec3 t = std::abs(axis.z) < 0.9 ? cross(axis, Vec3{0, 0, 1}) : cross(axis, Vec3{1, 0, 0});
  t = t / length(t);
  const Vec3 b = cross(axis, t);
  const int n = 1200;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double theta = alpha * (i + 0.5) / n, weight = std::sin(theta) * (alpha / n) * (2 * kPi / n);
    for (int j = 0; j < n; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / n;
      const Vec3 w = std::cos(theta) * axis + std::sin(theta) * (std::cos(phi) * t + std::sin(phi) * b);
      sum += std::max(0.0, w.z) * weight;
    }
  }
  return sum;
}

// Irradiance at the patch from a sphere of radiance 1, radius r, centre at distance d along
// the unit direction `axis`.
double sphere_irradiance(GeometryKind k, const Vec3& axis, double d, double r) {
  const double alpha = std::asin(std::sqrt(model::sphere_area_factor(k, r) /
                                           model::sphere_area_factor(k, d)));
  const double direct = axis.z >= std::sin(alpha) ? kPi * std::pow(std::sin(alpha), 2) * axis.z
                                                  : cone_integral(axis, alpha);
  return k == GeometryKind::Spherical ? direct + cone_integral(-1.0 * axis, alpha) : direct;
}

std::string sphere_json(const Vec3& axis, double d, double r) {
  return R"({"type": "sphere", "material": "lamp", "center": )" + vec3_json(d * axis) +
         R"(, "radius": )" + std::to_string(r) + "}";
}

TEST(DirectLight, SphereLightsMatchTheirClosedForms) {
  struct Case {
    const char* what;
    double elevation_degrees, d, r;
  };
  for (GeometryKind k : kGeometries) {
    const bool far_fits = k != GeometryKind::Spherical;  // S3's chart ends at pi / 2
    const Case cases[] = {
        {"close above the patch (0.02 from it)", 90, 0.12, 0.1},
        {"overhead, r 0.5 at 1", 90, 1.0, 0.5},
        {"far", 60, far_fits ? (k == GeometryKind::Euclidean ? 4.0 : 2.0) : 1.4,
         far_fits ? (k == GeometryKind::Euclidean ? 1.0 : 0.8) : 0.3},
        {"partly below the horizon", 10, 0.6, 0.3},
        {"grazing: its cone's lower edge 2 degrees above the horizon", 20, 0.5, 0.15},
    };
    for (const Case& c : cases) {
      const double e = c.elevation_degrees * kPi / 180;
      const Vec3 axis{std::cos(e), 0, std::sin(e)};
      expect_radiance(k, sphere_json(axis, c.d, c.r), sphere_irradiance(k, axis, c.d, c.r), c.what);
    }
  }
}

// A horosphere of radiance 1 (H3, a cusp's sky) at signed distance d from the patch, its ideal
// point along `axis`: from outside its horoball it fills the cone of sin alpha = e^-d about
// that direction (horosphere_test.cpp holds its angular size), from inside every direction.
TEST(DirectLight, HorosphereLightsMatchTheirClosedForms) {
  struct Case {
    const char* what;
    double elevation_degrees, d;
  };
  const Case cases[] = {
      {"close above the patch (0.05 from it)", 90, 0.05},
      {"overhead at 1", 90, 1.0},
      {"far", 60, 1.4},
      {"partly below the horizon", 15, 0.4},
      {"grazing: its cone's lower edge 2 degrees above the horizon", 20, -std::log(std::sin(kPi / 10))},
      {"the patch inside its horoball", 70, -0.5},
  };
  for (const Case& c : cases) {
    const double e = c.elevation_degrees * kPi / 180;
    const Vec3 axis{std::cos(e), 0, std::sin(e)};
    const double alpha = std::asin(std::exp(-std::max(c.d, 0.0)));
    const double irradiance = c.d <= 0                      ? kPi
                              : axis.z >= std::sin(alpha) ? kPi * std::exp(-2 * c.d) * axis.z
                                                            : cone_integral(axis, alpha);
    const std::string light = R"({"type": "horosphere", "material": "lamp", "direction": )" +
                              vec3_json(axis) + R"(, "distance": )" + std::to_string(c.d) + "}";
    expect_radiance(GeometryKind::Hyperbolic, light, irradiance, c.what);
  }
}

using ExpTriangle = std::array<Vec3, 3>;  // exponential coordinates, as the scene gives them

// The quad's two triangles as the loader makes them (scene_loader.cpp, append_quad).
std::vector<ExpTriangle> quad_triangles(const Vec3& corner, const Vec3& u, const Vec3& v) {
  return {{corner, corner + u, corner + u + v}, {corner, corner + u + v, corner + v}};
}

// Lambert's formula for a planar polygon of radiance 1 seen from the origin with normal +z,
// after clipping it to z >= 0: E = 1/2 sum_i angle(r_i, r_i+1) (z . unit(r_i x r_i+1)).
double lambert_irradiance(std::vector<Vec3> polygon) {
  std::vector<Vec3> clipped;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec3 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    if (a.z >= 0) clipped.push_back(a);
    if ((a.z >= 0) != (b.z >= 0)) clipped.push_back(a + (a.z / (a.z - b.z)) * (b - a));
  }
  double sum = 0;
  for (size_t i = 0; i < clipped.size(); ++i) {
    const Vec3 a = clipped[i] / length(clipped[i]);
    const Vec3 b = clipped[(i + 1) % clipped.size()] / length(clipped[(i + 1) % clipped.size()]);
    const Vec3 c = cross(a, b);
    if (length(c) > 0) sum += std::acos(std::clamp(dot(a, b), -1.0, 1.0)) * c.z / length(c);
  }
  return 0.5 * std::abs(sum);
}

// Irradiance at the patch from geodesic triangles of radiance 1 (both sides emit), by
// quadrature in the chart at the origin, where they are flat: each triangle cut into n^2
// pieces evaluated at their centroids, weighted by the model's area element there. In S3 the
// long way round adds the same points at distance 2 pi - d, arriving from the other side.
double triangles_irradiance(GeometryKind k, const std::vector<ExpTriangle>& triangles) {
  const int n = 300;
  double sum = 0;
  for (const ExpTriangle& t : triangles) {
    Vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = model::chart(k, model::exp_origin(k, t[i]));
    const Vec3 e1 = q[1] - q[0], e2 = q[2] - q[0];
    const Vec3 normal = cross(e1, e2) / length(cross(e1, e2));
    const double delta = dot(normal, q[0]), piece = 0.5 / (double(n) * n);
    auto add = [&](double s, double r) {
      const Vec3 x = q[0] + s * e1 + r * e2;
      const Vec4 y = model::lift(k, x);
      const double d = model::geodesic_distance(k, model::origin(), y);
      const double cos_x = model::geodesic_direction(k, model::origin(), y).z;
      const double cos_y = std::abs(model::inner(k, model::geodesic_direction(k, y, model::origin()),
                                                 model::chart_plane_normal(k, y, normal, delta)));
      const double area = triangle_area_jacobian(k, x, e1, e2) * piece;
      const double falloff = model::sphere_area_factor(k, d);
      sum += std::max(0.0, cos_x) * cos_y / falloff * area;
      if (k == GeometryKind::Spherical) sum += std::max(0.0, -cos_x) * cos_y / falloff * area;
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        add((i + 1.0 / 3) / n, (j + 1.0 / 3) / n);
        if (i + j < n - 1) add((i + 2.0 / 3) / n, (j + 2.0 / 3) / n);
      }
  }
  return sum;
}

struct Quad {
  const char* what;
  Vec3 corner, u, v;
};

const Quad kQuads[] = {
    {"0.2 wide, 0.2 above", {-0.1, -0.1, 0.2}, {0, 0.2, 0}, {0.2, 0, 0}},
    {"0.1 wide, 0.03 above (close)", {-0.05, -0.05, 0.03}, {0.1, 0, 0}, {0, 0.1, 0}},
    {"upright beside the patch, partly below the horizon", {0.05, -0.1, -0.05}, {0, 0.2, 0}, {0, 0, 0.15}},
    {"tilted, 0.8 away (far)", {0.3, -0.4, 0.5}, {0.5, 0, 0.2}, {0, 0.8, 0}},
};

// The quadrature is the reference for H3 and S3: in E3 it must agree with Lambert's formula.
TEST(DirectLight, QuadratureAgreesWithLambertsFormulaInE3) {
  for (const Quad& q : kQuads) {
    const double lambert = lambert_irradiance({q.corner, q.corner + q.u, q.corner + q.u + q.v, q.corner + q.v});
    EXPECT_NEAR(triangles_irradiance(GeometryKind::Euclidean, quad_triangles(q.corner, q.u, q.v)),
                lambert, 2e-4 * lambert)
        << q.what;
  }
}

TEST(DirectLight, QuadLightsMatchTheirClosedForms) {
  for (GeometryKind k : kGeometries)
    for (const Quad& q : kQuads) {
      const double irradiance =
          k == GeometryKind::Euclidean
              ? lambert_irradiance({q.corner, q.corner + q.u, q.corner + q.u + q.v, q.corner + q.v})
              : triangles_irradiance(k, quad_triangles(q.corner, q.u, q.v));
      const std::string light = R"({"type": "quad", "material": "lamp", "corner": )" +
                                vec3_json(q.corner) + R"(, "edge_u": )" + vec3_json(q.u) +
                                R"(, "edge_v": )" + vec3_json(q.v) + "}";
      expect_radiance(k, light, irradiance, q.what);
    }
}

}  // namespace
}  // namespace geodesic::test
