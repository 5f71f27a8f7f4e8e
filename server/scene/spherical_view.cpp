#include "scene/spherical_view.h"

#include <algorithm>
#include <cmath>

#include "scene/group_orbit.h"

namespace geodesic {
namespace {

constexpr GeometryKind kS3 = GeometryKind::Spherical;

}  // namespace

std::vector<Mat4> spherical_group(const Manifold& manifold) {
  std::vector<Mat4> pairings;
  for (const DomainFace& face : manifold.faces) pairings.push_back(face.pairing);
  if (pairings.empty()) return {Mat4::identity()};
  try {
    // Every element of S3's group moves the origin by at most pi: a limit past it lists all.
    const GroupOrbit orbit(kS3, pairings, 4096, 4);
    std::vector<Mat4> group;
    for (const GroupElement& e : orbit.elements()) group.push_back(e.g);
    return group;
  } catch (const GroupOrbit::Stabilised&) {
  } catch (const GroupOrbit::TooLarge&) {
  }
  return {Mat4::identity()};
}

double orbit_irradiance(const std::vector<Mat4>& group, const Vec4& light, const Vec4& p) {
  double total = 0;
  bool antipodal = false;
  for (const Mat4& g : group) {
    const double s = std::sin(model::geodesic_distance(kS3, p, g * light));
    total += 1 / std::max(s * s, 1e-12);
    antipodal |= model::is_antipodal_map(g);
  }
  return antipodal ? total : 2 * total;
}

double antipode_clearance(const std::vector<Mat4>& group, const Polyhedron& domain,
                          double edge_radius, const std::vector<BallObstacle>& balls,
                          const Vec4& eye) {
  // Points along each edge, a fiftieth of its length apart (its chart segment is a geodesic).
  std::vector<Vec4> edge_points;
  constexpr int kSteps = 50;
  for (const auto& [a, b] : domain.edges)
    for (int i = 0; i <= kSteps; ++i) {
      const double t = double(i) / kSteps;
      edge_points.push_back(
          model::lift(kS3, domain.vertices[a] * (1 - t) + domain.vertices[b] * t));
    }
  // How far the surfaces reach from the origin: an image of the antipode farther out than
  // that plus the clearance found so far cannot come closer. Nearest images first.
  double reach = 0;
  for (const Vec4& e : edge_points)
    reach = std::max(reach, model::geodesic_distance(kS3, e, model::origin()) + edge_radius);
  for (const BallObstacle& b : balls)
    reach = std::max(reach, model::geodesic_distance(kS3, b.centre, model::origin()) + b.radius);
  std::vector<std::pair<double, Vec4>> images;
  for (const Mat4& g : group) {
    const Vec4 q = g * -eye;
    images.emplace_back(model::geodesic_distance(kS3, q, model::origin()), q);
  }
  std::sort(images.begin(), images.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  double clearance = INFINITY;
  for (const auto& [from_origin, q] : images) {
    if (from_origin - reach >= clearance) break;
    for (const Vec4& e : edge_points)
      clearance = std::min(clearance, model::geodesic_distance(kS3, q, e) - edge_radius);
    for (const BallObstacle& b : balls)
      clearance = std::min(clearance, model::geodesic_distance(kS3, q, b.centre) - b.radius);
  }
  return std::max(clearance, 0.0);
}

}  // namespace geodesic
