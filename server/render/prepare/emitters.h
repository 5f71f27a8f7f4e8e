// What the `physical` model samples light from: point lights, emissive spheres, emissive
// triangles and emissive horospheres (a cusp's sky), each chosen with probability proportional
// to its power, and each with its images
// under the manifold's group (the copies of the cell around the domain) that next-event
// estimation considers. Pure data, built without a device; read by
// shaders/lights/emitters.glsl.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "common/gpu_types.h"
#include "scene/scene.h"

namespace geodesic {

enum class EmitterKind : uint32_t { Point = 0, Sphere = 1, Triangle = 2, Horosphere = 3 };

// The emitter and its images as the shaders read them (shaders/common/gpu_types.h): an image
// is the isometry and the emitter's centre carried by it (computed in double), which is all
// that light sampling reads of every image at every shading point. A horosphere's "centre" is
// its light-like vector l ({<x, l> = -1}, scene/shapes/horosphere.cpp).
using GpuEmitter = gpu::Emitter;
using GpuLightImage = gpu::LightImage;

// Images kept per emitter: those within the cutoff of the cell's centre (the origin), at
// most this many, nearest first. In S3 the long way round is also taken when the cutoff
// exceeds pi. A horosphere's images are the distinct horoballs g l (the stabiliser of its cusp
// maps it to itself), and the horospheres of one cusp, which are images of each other (the
// ideal vertices of one class, scene/cusp_neighbourhoods.h), are one emitter: light sampling
// must not offer one horoball twice.
constexpr std::size_t kMaxImagesPerEmitter = MAX_EMITTER_IMAGES;

struct EmitterTable {
  std::vector<GpuEmitter> emitters;
  std::vector<GpuLightImage> images;          // the emitters' images (GpuEmitter ranges)
  std::vector<uint32_t> sphere_emitter;       // per scene sphere: its emitter, or kNone
  std::vector<std::vector<uint32_t>> triangle_emitter;  // per mesh, per triangle
  std::vector<uint32_t> shape_emitter;        // per scene shape: its emitter, or kNone
  double cutoff = 0;  // light_cutoff as resolved (geodesic distance)
  // Whether light sampling offers every image of every area light (sphere, triangle,
  // horosphere): a space without faces, or S3's finite group taken whole. Where it does not,
  // the images it leaves out are lit only by BSDF samples, also past the last bounce
  // (PipelineFeatures::unsampled_emission).
  bool every_image = true;
  static constexpr uint32_t kNone = ~0u;
};

// Throws SceneError ("render.light_cutoff: ...") when the cutoff asks for more group elements
// than the enumeration allows.
EmitterTable build_emitters(const Scene& scene);

// The model area element of a triangle with respect to its barycentrics, at chart point x of
// a chart centred near it: sqrt det of the metric g = s^2 (I - K s^2 x x^T), s^2 = 1 / (1 +
// K |x|^2), on the edges e1 and e2. Twin of triangleAreaJacobian (shaders/lights/emitters.glsl).
double triangle_area_jacobian(GeometryKind k, const Vec3& x, const Vec3& e1, const Vec3& e2);

// The cosine of the half-angle of the cone the horoball {<x, l> > -1} (H3) subtends from x,
// sin alpha = 1 / -<x, l>, about the unit tangent towards its ideal point, l + <x, l> x
// normalised; -1 (every direction) from inside. Twin of horosphereConeCos
// (shaders/lights/emitters.glsl).
double horosphere_cone_cos(const Vec4& x, const Vec4& l);

// The model area of the geodesic triangle abc (angle excess or defect in H3 and S3).
double triangle_area(GeometryKind k, const Vec4& a, const Vec4& b, const Vec4& c);

// The group elements gamma of the manifold with d(o, gamma o) <= radius (o the origin), as
// words in the face pairings (scene/group_orbit.h); the identity alone for the whole space.
// Throws SceneError past `max_elements`.
std::vector<Mat4> group_elements_within(GeometryKind k, const Manifold& m, double radius,
                                        std::size_t max_elements = 4096);

// Largest geodesic distance from the origin to a finite vertex of the fundamental domain (a
// cusp's ideal vertices are skipped).
double domain_circumradius(GeometryKind k, const Manifold& m);

}  // namespace geodesic
