// The analytic edge tubes (capsules intersected beside the traversal, with face culling)
// render what a fine triangle mesh of the same capsules renders: in the mirrored dodecahedron
// (reflections), Seifert-Weber (isometries) and the Poincare sphere (S3), the images differ by
// no more than two renders of the tubes themselves with different seeds, and no sample is
// NaN or infinite. The camera also sits on a face of the domain.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>

#include "render_fixture.h"

namespace geodesic::test {
namespace {

// A closed mesh of each capsule: a 48-sided cylinder (flat in the chart, where the capsule's
// side is ruled) and hemispheres of 12 rings, as exponential coordinates like every mesh.
TriangleMesh capsule_mesh(GeometryKind k, const std::vector<EdgeTube>& tubes) {
  constexpr int kSides = 48, kRings = 12;
  TriangleMesh mesh;
  mesh.material = tubes.front().material;
  for (const EdgeTube& t : tubes) {
    const Vec3 n = normalize(t.b - t.a);
    const Vec3 u = normalize(cross(n, std::abs(n.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    const Vec3 v = cross(n, u);
    // Rings from the far pole of a's cap to the far pole of b's: latitude -90 .. 90 degrees.
    std::vector<Vec3> ring_points;
    const int rings = 2 * (kRings + 1);
    for (int r = 0; r < rings; ++r) {
      const bool at_b = r > kRings;
      const double lat = std::numbers::pi / 2 * (at_b ? double(r - kRings - 1) / kRings
                                                      : double(r) / kRings - 1);
      const Vec3 centre = at_b ? t.b : t.a;
      for (int s = 0; s < kSides; ++s) {
        const double phi = 2 * std::numbers::pi * s / kSides;
        ring_points.push_back(centre + t.radius * (std::sin(lat) * n +
                                                   std::cos(lat) * (std::cos(phi) * u +
                                                                    std::sin(phi) * v)));
      }
    }
    const auto base = uint32_t(mesh.positions.size());
    for (const Vec3& x : ring_points)
      mesh.positions.push_back(model::log_origin(k, model::lift(k, x)));
    for (uint32_t r = 0; r + 1 < uint32_t(rings); ++r)
      for (uint32_t s = 0; s < kSides; ++s) {
        const uint32_t s1 = (s + 1) % kSides, r0 = base + r * kSides, r1 = r0 + kSides;
        mesh.indices.insert(mesh.indices.end(), {r0 + s, r1 + s1, r0 + s1, r0 + s, r1 + s, r1 + s1});
      }
  }
  return mesh;
}

Image render_seeded(Scene scene, uint64_t seed, uint32_t spp) {
  scene.render.seed = seed;
  Renderer renderer(device(), scene);
  renderer.add_samples(spp);
  EXPECT_EQ(renderer.non_finite_samples(), 0u);
  return renderer.image();
}

void expect_mesh_renders_the_same(Scene scene, uint32_t spp) {
  Scene meshed = scene;
  meshed.meshes.push_back(capsule_mesh(scene.geometry, scene.tubes));
  meshed.tubes.clear();
  const Image tubes1 = render_seeded(scene, 1, spp), tubes2 = render_seeded(scene, 2, spp);
  const Image mesh2 = render_seeded(meshed, 2, spp);
  const double noise = rms_difference(tubes1, tubes2);
  const double against_mesh = rms_difference(tubes1, mesh2);
  const double same_seed = rms_difference(tubes2, mesh2);
  std::printf("%s: RMS tubes vs mesh %.4f (same seed %.4f), tubes vs tubes %.4f\n",
              scene.name.c_str(), against_mesh, same_seed, noise);
  EXPECT_GT(mean(tubes1).r + mean(tubes1).g + mean(tubes1).b, 0.01);
  EXPECT_LE(against_mesh, 1.1 * noise + 2e-3);
}

TEST(EdgeTubes, RenderAsTheirFineMeshDoes) {
  for (const char* file : {"scenes/mirrored-dodecahedron.json", "scenes/seifert-weber.json",
                           "scenes/poincare-sphere.json"}) {
    Scene scene = small_scene(file, 64, 64);
    scene.name = file;
    expect_mesh_renders_the_same(scene, 8);
  }
}

TEST(EdgeTubes, ACameraOnAFaceSeesTheTubesAroundIt) {
  // On the centre of a face of the domain, looking at the domain's centre, the face's own
  // edges' tubes all around the view.
  std::ifstream file(source_path("scenes/mirrored-dodecahedron.json"));
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(file);
  const Scene plain = load_scene_file(source_path("scenes/mirrored-dodecahedron.json"));
  constexpr auto k = GeometryKind::Hyperbolic;
  const Polyhedron& domain = plain.manifold.domain;
  Vec3 centre;
  for (int i : domain.faces[0]) centre += domain.vertices[i] / double(domain.faces[0].size());
  const Vec3 at = model::log_origin(k, model::lift(k, centre));
  doc["camera"] = {{"position", {at.x, at.y, at.z}}, {"look_at", {0, 0, 0}}, {"fov_y", 80}};
  doc["render"]["width"] = 48;
  doc["render"]["height"] = 48;
  Scene scene = scene_from_json(doc.dump());
  scene.name = "camera on a face";
  expect_mesh_renders_the_same(scene, 8);
}

}  // namespace
}  // namespace geodesic::test
