// The in-memory scene: what the loader produces and the renderer consumes. Everything is
// resolved (materials by index, polygons and meshes as triangles). Positions are exponential
// coordinates at the origin (the end of the geodesic from the origin along the vector, of
// length |vector|: plain coordinates in E3); the renderer maps them into the model.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/model.h"
#include "geometry/vec.h"
#include "scene/manifold.h"

namespace geodesic {

// The paper's material coefficients (eq. 2.2) plus a perfect mirror, a dielectric and
// emission, RGB. The `physical` model reads diffuse, specular (normalised Phong), mirror and
// transmission as the weights of four lobes (tests/twins/bsdf.h, the double twin of shaders/materials/bsdf.glsl), summing to at most 1.
struct Material {
  std::string name;
  Vec3 ambient;          // k_a
  Vec3 diffuse;          // k_d, also the albedo of the Lambertian indirect bounce
  Vec3 specular;         // k_s
  double shininess = 1;  // k_e, the Phong roughness exponent
  Vec3 mirror;           // reflectance of a perfect mirror lobe
  Vec3 transmission;     // weight of the smooth dielectric lobe (physical model only)
  double ior = 1.5;      // its index of refraction, inside over outside
  Vec3 emission;         // emitted radiance L_e, from both sides
};

struct Sphere {
  Vec3 center;        // exponential coordinates
  double radius = 1;  // geodesic
  uint32_t material = 0;
};

// World-space triangles sharing one material. normals is empty (flat shading) or one per
// position (smooth shading, as exported by Blender).
struct TriangleMesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<uint32_t> indices;  // three per triangle
  uint32_t material = 0;
};

// The fundamental domain's edges drawn as tubes ("domain_edges"; the paper draws the
// dodecahedron's edges so): the capsule of chart radius `radius` about each edge, in the
// domain's chart about the origin (geometry/capsule.h), intersected analytically by the
// tracer. Only in quotients; the copies of the domain around an edge complete its tube.
struct EdgeTube {
  Vec3 a, b;  // the edge's ends, chart coordinates
  double radius = 0;
  uint32_t material = 0;
};

// An analytic shape of a kind in the shape table (scene/shape.h), e.g. a horosphere. Its
// parameters are model vectors and a length, so that an isometry moves any shape alike.
struct ShapeParams {
  Vec4 a, b;        // model vectors (points, tangents, ideal points), carried linearly
  double size = 0;  // a length, which isometries keep
};

struct Shape {
  uint32_t kind = 0;  // ShapeKind::id: SHAPE_* of shaders/common/shape_kinds.h
  ShapeParams params;
  uint32_t material = 0;
};

struct PointLight {
  Vec3 position;
  Vec3 intensity;  // RGB
};

struct Camera {
  // Isometry of the model taking the camera frame at the origin to the camera: the images of
  // the origin's right, up and back directions (the camera looks along -z) and of the origin.
  Mat4 pose = Mat4::identity();
  double fov_y_degrees = 45;
};

// `paper`: Novello et al.'s eq. 2.2 (ambient, diffuse and Phong terms, 0/1 shadows) plus their
// Monte Carlo indirect term (algorithm 3). `physical`: unbiased path tracing of the rendering
// equation (eq. 2.4) with next-event estimation and multiple importance sampling.
enum class LightingModel { Paper, Physical };

// How the physical model finds light: both strategies combined by MIS, BSDF sampling alone
// (point lights then contribute nothing), or light sampling alone (next-event estimation
// without MIS; emitters past the light cutoff are still found by BSDF sampling). The last two
// exist to check the first. The values are the shader's LIGHT_SAMPLING_* constants.
enum class LightSampling : uint32_t { Mis = 0, Bsdf = 1, Light = 2 };

// How linear radiance becomes a display value (PNG, JPEG, the browser's frames; an EXR keeps
// the radiance): scaled by 2^stops, or, when automatic, by the scale that brings the image's
// log-average luminance to middle grey (render/prepare/exposure.h).
struct Exposure {
  double stops = 0;
  bool automatic = false;
  bool operator==(const Exposure&) const = default;
};
constexpr double kMaxExposureStops = 20;
constexpr int kMaxLightSamples = 8;  // MAX_LIGHT_SAMPLES (shaders/common/gpu_types.h)

struct RenderSettings {
  int width = 512;
  int height = 512;
  int max_depth = 5;  // indirect bounces (the paper's d)
  int spp = 64;
  uint64_t seed = 1;
  Vec3 ambient_light;  // L_a of eq. 2.2
  // End paths at random, with probability 1 - max(throughput), and reweight survivors: the
  // same expected image from cheaper paths (as Cycles does). Paper model: after the first
  // bounce, off unless asked for; physical model: after the third, on unless turned off.
  bool russian_roulette = true;
  LightingModel lighting = LightingModel::Physical;
  LightSampling light_sampling = LightSampling::Mis;
  // Next-event estimation sums a light's images (one per copy of the cell, and in S3 the long
  // way round) whose centre is within this geodesic distance of the shading point. 0: the
  // default (see docs/scene-format.md).
  double light_cutoff = 0;
  // Light samples next-event estimation takes at each vertex, all of one emitter and through
  // one walk over its images (docs/scene-format.md): worth more than one where a light has
  // many images of like weight (the Poincare sphere), never where it has one.
  int light_samples = 1;
  // Largest luminance one sample may add (fireflies); 0: no clamp, the unbiased default.
  double clamp = 0;
  Exposure exposure;
};

struct Scene {
  std::string name;
  GeometryKind geometry = GeometryKind::Euclidean;
  Manifold manifold;  // no faces: the whole space
  Camera camera;
  std::vector<Material> materials;
  std::vector<Sphere> spheres;
  std::vector<TriangleMesh> meshes;
  std::vector<EdgeTube> tubes;
  std::vector<Shape> shapes;
  std::vector<PointLight> lights;
  RenderSettings render;
};

// A validation or parse failure; what() reads "<json path>: <reason>", e.g.
// "objects[3].radius: must be > 0".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace geodesic
