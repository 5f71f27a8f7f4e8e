#include "render/prepare/emitters.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "common/shape_kinds.h"
#include "geometry/sampling.h"
#include "scene/cusp_neighbourhoods.h"
#include "scene/group_orbit.h"

namespace geodesic {
namespace {

constexpr double kPi = std::numbers::pi;
// "No cutoff" on the device: further than any float distance a ray can travel.
constexpr double kUnbounded = 1e30;

std::array<float, 4> to_float4(const Vec4& v) {
  return {float(v.x), float(v.y), float(v.z), float(v.w)};
}
std::array<float, 4> to_float4(const Vec3& v, double w) {
  return {float(v.x), float(v.y), float(v.z), float(w)};
}

// The cutoff the scene asks for, or the default: every image for a finite group (S3), one
// copy for the whole E3 or H3, and images within the domain's circumradius R of the cell's
// centre otherwise (at most 1 in H3, where the copies multiply exponentially; halved while
// they are too many, build_emitters).
double resolve_cutoff(const Scene& scene, double circumradius) {
  const GeometryKind k = scene.geometry;
  if (scene.render.light_cutoff > 0)
    return k == GeometryKind::Spherical ? std::min(scene.render.light_cutoff, 2 * kPi)
                                        : scene.render.light_cutoff;
  if (k == GeometryKind::Spherical) return 2 * kPi;
  if (scene.manifold.faces.empty()) return kUnbounded;
  return k == GeometryKind::Hyperbolic ? std::min(circumradius, 1.0) : circumradius;
}

// An image of an emitter: its distance from the cell's centre, the group element, and the
// emitter's centre (a horosphere's l) carried by it.
struct Image {
  double distance;
  Mat4 g;
  Vec4 center;
};

struct Emitting {
  GpuEmitter gpu{};
  double power = 0;
  double area = 0;             // a horosphere's: the sum of its shapes' areas in the domain
  std::vector<Image> images;  // horospheres: found with the emitter (one cusp, one emitter)
};

// Nearest first, at most kMaxImagesPerEmitter.
void keep_nearest(std::vector<Image>& images) {
  std::stable_sort(images.begin(), images.end(),
                   [](const Image& a, const Image& b) { return a.distance < b.distance; });
  images.resize(std::min(images.size(), kMaxImagesPerEmitter));
}

// Where the group holds -1 every image c of a point light comes with -c, and the two weigh
// the same up to the side of the surface they lie on: I |cos| / A(d) with A(pi - d) = A(d) in
// S3, the one in front taking it all. Light sampling then weighs a pair as one image
// (shaders/lights/emitters.glsl): the nearer of each pair is kept, so that kMaxImagesPerEmitter
// pairs cover twice as many images. Before, the Poincare space's 120 were cut to the nearest 64,
// and the light of the far ones, in front wherever their near antipodes are behind, was lost:
// its default scene was 25-29 % too dark at depth 0.
std::vector<Image> antipodal_representatives(std::vector<Image> images) {
  std::stable_sort(images.begin(), images.end(),
                   [](const Image& a, const Image& b) { return a.distance < b.distance; });
  std::vector<Image> kept;
  for (const Image& image : images)
    if (std::none_of(kept.begin(), kept.end(), [&](const Image& other) {
          return max_abs(other.center + image.center) <= 1e-9;
        }))
      kept.push_back(image);
  return kept;
}

bool same_horosphere(const Vec4& a, const Vec4& b) {
  return max_abs(a - b) <= 1e-7 * max_abs(a);
}

// `image` added to `images` unless its horoball is there already.
void add_distinct(std::vector<Image>& images, const Image& image) {
  if (std::none_of(images.begin(), images.end(),
                   [&](const Image& i) { return same_horosphere(i.center, image.center); }))
    images.push_back(image);
}

// The distinct horoballs g l within the cutoff of the cell's centre o, at signed distance
// log(-<o, g l>) = log((g l).w) (negative when o is inside).
std::vector<Image> horoball_images(const std::vector<Mat4>& group, const Vec4& l, double cutoff) {
  std::vector<Image> images;
  for (const Mat4& g : group) {
    const Vec4 image = g * l;
    const double d = std::log(image.w);
    if (d <= cutoff) add_distinct(images, {d, g, image});
  }
  return images;
}

// Emissive horospheres: one emitter per cusp (a horosphere that is an image h l_e of an
// earlier one, with its emission, joins its emitter and adds the horoballs its own elements
// reach, g l = g h l_e),
// its images the distinct horoballs. Its power, which sets how often it is chosen, is pi L
// times its area in the manifold, as a sphere light's: the cusp's cross-section, the sum of
// its horospheres' areas in the domain (scene/cusp_neighbourhoods.h). A horosphere with no
// finite area there (no faces; not at an ideal vertex) stands in as the sphere light at
// distance 1 from the cell's centre filling the cones its images fill from there:
// pi L 4 pi sinh^2(1) sum min(1, sin^2 alpha_i), sin alpha = e^-d for a horoball at distance
// d (the whole sphere from inside).
void add_horosphere_emitters(const Scene& scene, const std::vector<Mat4>& group, double cutoff,
                             std::vector<Emitting>& found, std::vector<uint32_t>& shape_emitter) {
  shape_emitter.assign(scene.shapes.size(), EmitterTable::kNone);
  const std::size_t first = found.size();
  for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
    const Shape& shape = scene.shapes[s];
    const Vec3 le = scene.materials[shape.material].emission;
    if (shape.kind != SHAPE_HOROSPHERE || luminance(le) <= 0) continue;
    const Vec4 l = shape.params.a;
    // Its horoballs near the cell; an emitter with one of them among its own holds the same
    // orbit (a cusp's), whether or not l itself lies within the cutoff: it joins that one.
    const std::vector<Image> own = horoball_images(group, l, cutoff);
    std::size_t e = first;
    std::optional<Mat4> h;  // l = h l_e for the emitter e it joins
    for (; e < found.size(); ++e) {
      if (found[e].gpu.radiance != to_float4(le, 0)) continue;
      for (const Image& theirs : found[e].images)
        for (const Image& mine : own)  // g_t l_e = g_m l
          if (!h && same_horosphere(theirs.center, mine.center))
            h = model::inverse_isometry(GeometryKind::Hyperbolic, mine.g) * theirs.g;
      if (h) break;
    }
    if (e == found.size()) {
      Emitting emitting;
      emitting.gpu.kind = uint32_t(EmitterKind::Horosphere);
      emitting.gpu.center = to_float4(l);
      emitting.gpu.radiance = to_float4(le, 0);
      found.push_back(emitting);
      h = Mat4::identity();
    }
    for (const Image& mine : own)  // g_m l = g_m h l_e
      add_distinct(found[e].images, {mine.distance, mine.g * *h, mine.center});
    found[e].area += horosphere_area_in_domain(scene.manifold, l);
    shape_emitter[s] = uint32_t(e);
  }
  for (std::size_t e = first; e < found.size(); ++e) {
    keep_nearest(found[e].images);
    double cones = 0;
    for (const Image& i : found[e].images) cones += std::min(1.0, std::exp(-2 * i.distance));
    const Vec3 le{found[e].gpu.radiance[0], found[e].gpu.radiance[1], found[e].gpu.radiance[2]};
    found[e].power = kPi * luminance(le) *
                     (std::isfinite(found[e].area) ? found[e].area
                                                   : 4 * kPi * std::pow(std::sinh(1.0), 2) * cones);
  }
}

GpuEmitter triangle_emitter(GeometryKind k, const Vec4 (&p)[3]) {
  GpuEmitter e{};
  const Vec4 centroid = model::normalize_point(k, p[0] + p[1] + p[2]);
  const Mat4 to_origin = model::translation_from(k, centroid);
  Vec3 q[3];
  double radius = 0;
  for (int i = 0; i < 3; ++i) {
    q[i] = model::chart(k, to_origin * p[i]);
    radius = std::max(radius, model::geodesic_distance(k, centroid, p[i]));
  }
  e.kind = uint32_t(EmitterKind::Triangle);
  e.center = to_float4(centroid);
  e.corner = to_float4(q[0], 1);
  e.edge1 = to_float4(q[1] - q[0], 0);
  e.edge2 = to_float4(q[2] - q[0], 0);
  e.radius = float(radius);
  return e;
}

}  // namespace

double triangle_area_jacobian(GeometryKind k, const Vec3& x, const Vec3& e1, const Vec3& e2) {
  const double K = model::curvature(k), s2 = 1 / (1 + K * dot(x, x)), c = K * s2;
  const double xa = dot(x, e1), xb = dot(x, e2);
  const double gaa = s2 * (dot(e1, e1) - c * xa * xa), gbb = s2 * (dot(e2, e2) - c * xb * xb);
  const double gab = s2 * (dot(e1, e2) - c * xa * xb);
  return std::sqrt(std::max(gaa * gbb - gab * gab, 0.0));
}

double horosphere_cone_cos(const Vec4& x, const Vec4& l) {
  const double s = -model::inner(GeometryKind::Hyperbolic, x, l);
  return s <= 1 ? -1 : std::sqrt(std::max(0.0, 1 - 1 / (s * s)));
}

double triangle_area(GeometryKind k, const Vec4& a, const Vec4& b, const Vec4& c) {
  if (k == GeometryKind::Euclidean) return 0.5 * length(cross(b.xyz() - a.xyz(), c.xyz() - a.xyz()));
  const Vec4 corners[3] = {a, b, c};
  double angles = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec4 u = model::geodesic_direction(k, corners[i], corners[(i + 1) % 3]);
    const Vec4 v = model::geodesic_direction(k, corners[i], corners[(i + 2) % 3]);
    angles += std::acos(std::clamp(model::inner(k, u, v), -1.0, 1.0));
  }
  return k == GeometryKind::Hyperbolic ? kPi - angles : angles - kPi;
}

double domain_circumradius(GeometryKind k, const Manifold& m) {
  double r = 0;
  for (const Vec3& x : m.domain.vertices)  // a cusp's ideal vertex is infinitely far: skipped
    if (!ideal_vertex(k, x))
      r = std::max(r, model::geodesic_distance(k, model::origin(), model::lift(k, x)));
  return r;
}

std::vector<Mat4> group_elements_within(GeometryKind k, const Manifold& m, double radius,
                                        std::size_t max_elements) {
  if (m.faces.empty()) return {Mat4::identity()};
  std::vector<Mat4> pairings;
  for (const DomainFace& face : m.faces) pairings.push_back(face.pairing);
  // The tiles a generic geodesic segment from o to gamma o crosses are adjacent in turn, and
  // each has its centre within R of the segment: words whose prefixes stray at most R beyond
  // radius reach every element within it.
  std::vector<Mat4> found;
  try {
    const GroupOrbit orbit(k, pairings, max_elements, radius + domain_circumradius(k, m));
    for (const GroupElement& e : orbit.elements())
      if (e.displacement <= radius) found.push_back(e.g);
  } catch (const GroupOrbit::TooLarge&) {
    throw SceneError("render.light_cutoff: the light's images would need more than " +
                     std::to_string(max_elements) + " copies of the cell (within " +
                     std::to_string(radius) + " of its centre); lower it");
  } catch (const GroupOrbit::Stabilised&) {
    // Only an orbifold fixes the cell's centre; its light then has one image.
    found = {Mat4::identity()};
  }
  return found;
}

EmitterTable build_emitters(const Scene& scene) {
  const GeometryKind k = scene.geometry;
  EmitterTable table;
  const double circumradius = domain_circumradius(k, scene.manifold);
  table.cutoff = resolve_cutoff(scene, circumradius);
  std::vector<Emitting> found;

  // Images are chosen by their distance from the cell's centre, the same for every shading
  // point, so that light sampling and its density at BSDF-found hits agree everywhere.
  std::vector<Mat4> group;
  for (;;) {
    try {
      group = group_elements_within(k, scene.manifold, std::min(table.cutoff, kPi) + circumradius);
      break;
    } catch (const SceneError&) {
      // The default halves until the images fit: a kaleidoscope's tiny cells have thousands
      // of copies within its circumradius. A cutoff the scene asks for stands or fails.
      if (scene.render.light_cutoff > 0 || table.cutoff < 1e-3) throw;
      table.cutoff /= 2;
    }
  }
  // Where the group holds the antipodal map -1 (the Poincare space, lens spaces of even order),
  // x and -x are copies of one point: every geodesic from a surface point that runs past pi
  // crosses the copy of its own surface at the antipode. The long way round then brings no
  // light, and light sampling leaves it out (sampling it only costs variance).
  const bool antipodal = k == GeometryKind::Spherical &&
                         std::any_of(group.begin(), group.end(), model::is_antipodal_map);
  if (antipodal && table.cutoff > kPi) table.cutoff = kPi;
  for (const PointLight& light : scene.lights) {
    Emitting e;
    e.gpu.kind = uint32_t(EmitterKind::Point);
    e.gpu.center = to_float4(model::exp_origin(k, light.position));
    e.gpu.radiance = to_float4(light.intensity, 0);
    e.power = 4 * kPi * luminance(light.intensity);
    if (e.power > 0) found.push_back(e);
  }
  table.sphere_emitter.assign(scene.spheres.size(), EmitterTable::kNone);
  for (std::size_t s = 0; s < scene.spheres.size(); ++s) {
    const Sphere& sphere = scene.spheres[s];
    const Vec3 le = scene.materials[sphere.material].emission;
    const double area = 4 * kPi * model::sphere_area_factor(k, sphere.radius);
    if (luminance(le) <= 0) continue;
    Emitting e;
    e.gpu.kind = uint32_t(EmitterKind::Sphere);
    e.gpu.center = to_float4(model::exp_origin(k, sphere.center));
    e.gpu.radius = float(sphere.radius);
    e.gpu.radiance = to_float4(le, area);
    e.power = kPi * luminance(le) * area;
    table.sphere_emitter[s] = uint32_t(found.size());
    found.push_back(e);
  }
  table.triangle_emitter.resize(scene.meshes.size());
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    table.triangle_emitter[m].assign(mesh.indices.size() / 3, EmitterTable::kNone);
    const Vec3 le = scene.materials[mesh.material].emission;
    if (luminance(le) <= 0) continue;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      Vec4 p[3];
      for (int i = 0; i < 3; ++i) p[i] = model::exp_origin(k, mesh.positions[mesh.indices[t + i]]);
      const double area = triangle_area(k, p[0], p[1], p[2]);
      if (!(area > 0)) continue;  // degenerate: nothing to sample
      Emitting e;
      e.gpu = triangle_emitter(k, p);
      e.gpu.radiance = to_float4(le, area);
      e.power = 2 * kPi * luminance(le) * area;  // both sides emit
      table.triangle_emitter[m][t / 3] = uint32_t(found.size());
      found.push_back(e);
    }
  }

  add_horosphere_emitters(scene, group, table.cutoff, found, table.shape_emitter);
  double total = 0;
  for (const Emitting& e : found) total += e.power;
  double cdf = 0;
  for (Emitting& e : found) {
    e.gpu.pmf = float(e.power / total);
    cdf += e.power / total;
    e.gpu.cdf = float(cdf);
    if (e.gpu.kind != uint32_t(EmitterKind::Horosphere)) {
      const Vec4 c{e.gpu.center[0], e.gpu.center[1], e.gpu.center[2], e.gpu.center[3]};
      for (const Mat4& g : group) {
        const double d = model::geodesic_distance(k, model::origin(), g * c);
        if (d <= table.cutoff) e.images.push_back({d, g, g * c});
      }
      // Within a cutoff of pi every image's antipode is within it too.
      if (antipodal && table.cutoff >= kPi && e.gpu.kind == uint32_t(EmitterKind::Point)) {
        e.images = antipodal_representatives(std::move(e.images));
        e.gpu.antipodal_pairs = 1;
      }
      keep_nearest(e.images);
    }
    const bool area = e.gpu.kind != uint32_t(EmitterKind::Point);
    if (area && !(scene.manifold.faces.empty() ||
                  (k == GeometryKind::Spherical && table.cutoff >= kPi &&
                   e.images.size() == group.size())))
      table.every_image = false;
    e.gpu.image_begin = uint32_t(table.images.size());
    e.gpu.image_count = uint32_t(e.images.size());
    for (const Image& i : e.images) table.images.push_back({i.g.to_glsl(), to_float4(i.center)});
    table.emitters.push_back(e.gpu);
  }
  if (!table.emitters.empty()) table.emitters.back().cdf = 1.0f;
  return table;
}

}  // namespace geodesic
