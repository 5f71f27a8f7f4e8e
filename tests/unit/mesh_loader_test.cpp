// Mesh files through assimp: triangle counts, normals and the model-to-world transform, on
// the octahedron in scenes/meshes (OBJ without normals, glTF with flat normals).
#include "scene/mesh_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "scene/scene_loader.h"

namespace geodesic {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(GEODESIC_SOURCE_DIR) / "scenes";
const fs::path kMeshes = kScenes / "meshes";

Vec3 face_normal(const TriangleMesh& mesh, std::size_t triangle) {
  const Vec3 a = mesh.positions[mesh.indices[3 * triangle]];
  const Vec3 b = mesh.positions[mesh.indices[3 * triangle + 1]];
  const Vec3 c = mesh.positions[mesh.indices[3 * triangle + 2]];
  return normalize(cross(b - a, c - a));
}

Vec3 face_centroid(const TriangleMesh& mesh, std::size_t triangle) {
  Vec3 sum;
  for (int k = 0; k < 3; ++k) sum += mesh.positions[mesh.indices[3 * triangle + k]];
  return sum / 3;
}

bool has_vertex(const TriangleMesh& mesh, const Vec3& want) {
  for (const Vec3& p : mesh.positions)
    if (length(p - want) < 1e-9) return true;
  return false;
}

// An octahedron's outward face normal points from its centre to the face's centroid.
void expect_outward_octahedron(const TriangleMesh& mesh, const Vec3& centre = {}) {
  ASSERT_EQ(mesh.indices.size(), 24u);
  for (std::size_t t = 0; t < 8; ++t) {
    const Vec3 n = face_normal(mesh, t);
    EXPECT_NEAR(dot(n, normalize(face_centroid(mesh, t) - centre)), 1.0, 1e-6) << "t " << t;
  }
}

TEST(MeshLoader, ReadsObjWithoutNormals) {
  const TriangleMesh mesh = load_mesh_file(kMeshes / "octahedron.obj");
  EXPECT_EQ(mesh.positions.size(), 6u);
  EXPECT_TRUE(mesh.normals.empty());
  expect_outward_octahedron(mesh);
  for (const Vec3& p : mesh.positions) EXPECT_NEAR(length(p), 1.0, 1e-12);
}

TEST(MeshLoader, ReadsGltfWithNormals) {
  const TriangleMesh mesh = load_mesh_file(kMeshes / "octahedron.gltf");
  expect_outward_octahedron(mesh);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  // Flat normals: every corner of a triangle carries that triangle's face normal.
  for (std::size_t t = 0; t < 8; ++t)
    for (int k = 0; k < 3; ++k) {
      const Vec3 n = mesh.normals[mesh.indices[3 * t + k]];
      EXPECT_NEAR(dot(n, face_normal(mesh, t)), 1.0, 1e-6);
    }
}

TEST(MeshLoader, TransformAppliesScaleRotationThenTranslation) {
  TriangleMesh mesh = load_mesh_file(kMeshes / "octahedron.obj");
  Mat4 quarter_turn_about_y = Mat4::identity();  // x -> -z, z -> x
  quarter_turn_about_y.m[0][0] = quarter_turn_about_y.m[2][2] = 0;
  quarter_turn_about_y.m[0][2] = 1;
  quarter_turn_about_y.m[2][0] = -1;
  transform_mesh(mesh, {2, 3, 4}, quarter_turn_about_y, {10, 20, 30});
  // (1,0,0) scales to (2,0,0), turns to (0,0,-2); (0,0,1) scales to (0,0,4), turns to (4,0,0).
  const Vec3 expected[6] = {{10, 20, 28}, {10, 20, 32}, {10, 23, 30},
                            {10, 17, 30}, {14, 20, 30}, {6, 20, 30}};
  ASSERT_EQ(mesh.positions.size(), 6u);
  for (const Vec3& want : expected)
    EXPECT_TRUE(has_vertex(mesh, want)) << want.x << " " << want.y << " " << want.z;
}

TEST(MeshLoader, NormalsStayPerpendicularUnderNonUniformScale) {
  TriangleMesh mesh = load_mesh_file(kMeshes / "octahedron.gltf");
  transform_mesh(mesh, {3, 1, 0.5}, Mat4::identity(), {});
  for (std::size_t t = 0; t < 8; ++t) {
    const Vec3 n = mesh.normals[mesh.indices[3 * t]];
    EXPECT_NEAR(length(n), 1.0, 1e-12);
    EXPECT_NEAR(dot(n, face_normal(mesh, t)), 1.0, 1e-6) << "triangle " << t;
  }
}

TEST(MeshLoader, SceneMeshIsScaledAndPlacedRelativeToTheSceneFile) {
  const auto doc = nlohmann::ordered_json::parse(R"({
    "geometry": "euclidean", "camera": {"position": [0, 0, 9]}, "materials": {"m": {}},
    "objects": [{"type": "mesh", "material": "m", "file": "meshes/octahedron.gltf",
                 "scale": 2, "position": [1, 2, 3], "rotation": {"yaw": 45}}]})");
  const Scene scene = parse_scene(doc, kScenes);
  const TriangleMesh& mesh = scene.meshes.at(0);
  expect_outward_octahedron(mesh, {1, 2, 3});
  EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
  for (const Vec3& p : mesh.positions) EXPECT_NEAR(length(p - Vec3(1, 2, 3)), 2, 1e-6);
  // (1, 0, 0) scaled by 2, turned 45 degrees from +x towards -z, moved by (1, 2, 3).
  EXPECT_TRUE(has_vertex(mesh, Vec3(1 + std::sqrt(2.0), 2, 3 - std::sqrt(2.0))));
}

TEST(MeshLoader, MeshDemoPlacesTheOctahedronInsideTheBox) {
  const Scene scene = load_scene_file(kScenes / "mesh-demo.json");
  const TriangleMesh& mesh = scene.meshes.back();
  expect_outward_octahedron(mesh, {0, -0.5, 0});
  for (const Vec3& p : mesh.positions)
    for (int axis = 0; axis < 3; ++axis) EXPECT_LT(std::abs(p[axis]), 1.0);
}

TEST(MeshLoader, MissingFileThrows) {
  EXPECT_THROW(load_mesh_file(kMeshes / "does-not-exist.obj"), std::runtime_error);
}

TEST(MeshLoader, FileWithoutTrianglesThrows) {
  const fs::path path = fs::temp_directory_path() / "geodesic_mesh_loader_lines.obj";
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n";
  EXPECT_THROW(load_mesh_file(path), std::runtime_error);
  fs::remove(path);
}

}  // namespace
}  // namespace geodesic
