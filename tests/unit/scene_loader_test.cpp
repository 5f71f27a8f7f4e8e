// The scene document: bundled scenes load with the intended content, primitives become the
// right triangles, cameras the right poses, and every invalid document is rejected with a
// message naming the field.
#include "scene/scene_loader.h"

#include "scene_document.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <tuple>

namespace geodesic {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

Vec3 column(const Mat4& m, int c) { return {m.m[0][c], m.m[1][c], m.m[2][c]}; }

void expect_near(const Vec3& a, const Vec3& b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

void expect_orthonormal_pose(const Mat4& pose) {
  const Vec3 right = column(pose, 0), up = column(pose, 1), back = column(pose, 2);
  EXPECT_NEAR(length(right), 1, 1e-12);
  EXPECT_NEAR(length(up), 1, 1e-12);
  EXPECT_NEAR(dot(right, up), 0, 1e-12);
  expect_near(cross(right, up), back);  // right-handed
  for (int c = 0; c < 4; ++c) EXPECT_EQ(pose.m[3][c], c == 3 ? 1.0 : 0.0);
}

Vec3 triangle_normal(const TriangleMesh& mesh, std::size_t t) {
  const Vec3 a = mesh.positions[mesh.indices[3 * t]];
  return normalize(cross(mesh.positions[mesh.indices[3 * t + 1]] - a,
                         mesh.positions[mesh.indices[3 * t + 2]] - a));
}

Vec3 triangle_centroid(const TriangleMesh& mesh, std::size_t t) {
  Vec3 sum;
  for (int k = 0; k < 3; ++k) sum += mesh.positions[mesh.indices[3 * t + k]];
  return sum / 3;
}

// Every triangle of every mesh faces towards `point` (true) or away from it (false).
void expect_facing(const std::vector<TriangleMesh>& meshes, const Vec3& point, bool towards) {
  for (const TriangleMesh& mesh : meshes)
    for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t) {
      const double facing = dot(triangle_normal(mesh, t), point - triangle_centroid(mesh, t));
      EXPECT_EQ(facing > 0, towards) << "triangle " << t;
    }
}

std::vector<fs::path> bundled_scenes() {
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::directory_iterator(kSceneDocumentDir))
    if (entry.path().extension() == ".json") scenes.push_back(entry.path());
  return scenes;
}

TEST(SceneLoader, EveryBundledSceneLoads) {
  const auto scenes = bundled_scenes();
  EXPECT_GE(scenes.size(), 4u);
  for (const fs::path& path : scenes) {
    SCOPED_TRACE(path.string());
    Scene scene;
    EXPECT_NO_THROW(scene = load_scene_file(path));
    EXPECT_FALSE(scene.name.empty());
    // The camera is an isometry of the scene's geometry.
    EXPECT_LT(model::isometry_error(scene.geometry, scene.camera.pose), 1e-9);
    if (scene.geometry == GeometryKind::Euclidean) expect_orthonormal_pose(scene.camera.pose);
  }
}

TEST(SceneLoader, CornellBoxMatchesThePaperFigure) {
  const Scene scene = load_scene_file(kSceneDocumentDir / "cornell-box.json");
  ASSERT_EQ(scene.materials.size(), 6u);
  const char* names[] = {"white", "red", "green", "mirror", "blue", "glossy"};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(scene.materials[i].name, names[i]);  // document order
  expect_near(scene.materials[1].diffuse, {0.75, 0.15, 0.15});
  expect_near(scene.materials[2].diffuse, {0.15, 0.75, 0.15});
  expect_near(scene.materials[3].mirror, {0.8, 0.8, 0.8});
  EXPECT_EQ(scene.materials[5].shininess, 40);

  // Walls: left red, right green, floor, back and a ceiling of 4 quads around the window.
  ASSERT_EQ(scene.meshes.size(), 8u);
  for (const TriangleMesh& wall : scene.meshes) EXPECT_EQ(wall.indices.size(), 6u);
  EXPECT_EQ(scene.meshes[0].material, 1u);
  EXPECT_EQ(scene.meshes[1].material, 2u);
  expect_facing(scene.meshes, {0, 0, 0}, true);

  ASSERT_EQ(scene.spheres.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const Sphere& s = scene.spheres[i];
    for (int axis = 0; axis < 3; ++axis) EXPECT_LT(std::abs(s.center[axis]) + s.radius, 1.0);
    EXPECT_LT(s.center.y - s.radius, -0.95);  // resting near the floor
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_GT(length(s.center - scene.spheres[j].center), s.radius + scene.spheres[j].radius);
  }

  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_GT(scene.lights[0].position.y, 1.0);  // above the ceiling, light enters by the window
  expect_orthonormal_pose(scene.camera.pose);
  expect_near(column(scene.camera.pose, 3), {0, 0, 3.4});
  expect_near(-column(scene.camera.pose, 2), {0, 0, -1});
  EXPECT_EQ(scene.camera.fov_y_degrees, 45);
  EXPECT_EQ(scene.render.width, 512);
  EXPECT_EQ(scene.render.max_depth, 5);
  EXPECT_EQ(scene.render.spp, 64);
  expect_near(scene.render.ambient_light, {0.03, 0.03, 0.03});
}

TEST(SceneLoader, FurnaceIsAClosedInwardFacingBox) {
  const Scene scene = load_scene_file(kSceneDocumentDir / "furnace.json");
  ASSERT_EQ(scene.materials.size(), 1u);
  expect_near(scene.materials[0].diffuse, {0.5, 0.5, 0.5});
  expect_near(scene.materials[0].emission, {1, 1, 1});
  EXPECT_EQ(scene.meshes.size(), 6u);
  expect_facing(scene.meshes, column(scene.camera.pose, 3), true);
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_EQ(scene.render.max_depth, 30);
  expect_near(scene.render.ambient_light, {0, 0, 0});
}

TEST(SceneLoader, EmissiveSceneHasOnlyEmission) {
  const Scene scene = load_scene_file(kSceneDocumentDir / "emissive.json");
  EXPECT_TRUE(scene.lights.empty());
  for (const Material& m : scene.materials) {
    expect_near(m.diffuse + m.specular + m.mirror + m.ambient, {0, 0, 0});
    expect_near(m.emission, {0.2, 0.5, 0.8});
  }
}

TEST(SceneLoader, LookAtCameraLooksAtTheTarget) {
  const Scene scene = parse_patched(
      R"({"camera": {"position": [1, 2, 3], "look_at": [4, -1, 7], "up": [0, 2, 0], "fov_y": 60}})");
  const Mat4& pose = scene.camera.pose;
  expect_orthonormal_pose(pose);
  expect_near(-column(pose, 2), normalize(Vec3(3, -3, 4)));
  expect_near(column(pose, 3), {1, 2, 3});
  EXPECT_GT(column(pose, 1).y, 0);           // up stays up
  EXPECT_NEAR(column(pose, 0).y, 0, 1e-12);  // no roll: right is horizontal
  EXPECT_EQ(scene.camera.fov_y_degrees, 60);
}

TEST(SceneLoader, RotationCameraComposesYawPitchRoll) {
  auto pose_of = [](const std::string& rotation) {
    return parse_patched(R"({"camera": {"position": [1, 2, 3], "rotation": )" + rotation + "}}")
        .camera.pose;
  };
  const Mat4 identity = pose_of("{}");
  expect_orthonormal_pose(identity);
  expect_near(-column(identity, 2), {0, 0, -1});
  expect_near(column(identity, 3), {1, 2, 3});
  expect_near(-column(pose_of(R"({"yaw": 90})"), 2), {-1, 0, 0});   // turns left
  expect_near(-column(pose_of(R"({"pitch": 90})"), 2), {0, 1, 0});  // looks up
  const Mat4 rolled = pose_of(R"({"roll": 90})");
  expect_near(-column(rolled, 2), {0, 0, -1});
  expect_near(column(rolled, 0), {0, -1, 0});  // right side goes down
  // Pitch is applied before yaw: pitch 30 then yaw 90.
  const Mat4 both = pose_of(R"({"yaw": 90, "pitch": 30, "roll": 10})");
  expect_orthonormal_pose(both);
  expect_near(-column(both, 2), {-std::sqrt(3.0) / 2, 0.5, 0});
}

TEST(SceneLoader, QuadFacesCrossOfItsEdges) {
  const Scene scene = parse_object(
      R"({"type": "quad", "material": "red", "corner": [1, 1, 1], "edge_u": [0, 0, 2], "edge_v": [3, 0, 0]})");
  ASSERT_EQ(scene.meshes.size(), 1u);
  const TriangleMesh& quad = scene.meshes[0];
  EXPECT_EQ(quad.indices.size(), 6u);
  EXPECT_TRUE(quad.normals.empty());
  EXPECT_EQ(quad.material, 0u);
  for (std::size_t t = 0; t < 2; ++t) expect_near(triangle_normal(quad, t), {0, 1, 0});
  expect_near(quad.positions[2], {4, 1, 3});  // corner + edge_u + edge_v
}

TEST(SceneLoader, PolygonBecomesAFanFollowingItsWinding) {
  // A regular hexagon in the tilted plane x + y + z = 1, counter-clockwise about (1,1,1).
  const Vec3 centre(1.0 / 3, 1.0 / 3, 1.0 / 3), n = normalize(Vec3(1, 1, 1));
  const Vec3 u = normalize(Vec3(1, -1, 0)), v = cross(n, u);
  Json vertices = Json::array();
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3;
    const Vec3 p = centre + u * std::cos(a) + v * std::sin(a);
    vertices.push_back({p.x, p.y, p.z});
  }
  const Json object = {{"type", "polygon"}, {"material", "red"}, {"vertices", vertices}};
  const Scene scene = parse_object(object.dump());
  const TriangleMesh& fan = scene.meshes.at(0);
  ASSERT_EQ(fan.indices.size(), 12u);
  for (std::size_t t = 0; t < 4; ++t) expect_near(triangle_normal(fan, t), n, 1e-12);
}

TEST(SceneLoader, BoxHasTwelveOutwardTriangles) {
  const Scene scene =
      parse_object(R"({"type": "box", "material": "red", "min": [-1, -2, -3], "max": [1, 2, 3]})");
  const TriangleMesh& box = scene.meshes.at(0);
  ASSERT_EQ(box.indices.size(), 36u);
  expect_facing({box}, {0, 0, 0}, false);
  std::set<std::tuple<double, double, double>> normals;
  for (std::size_t t = 0; t < 12; ++t) {
    const Vec3 n = triangle_normal(box, t);
    normals.insert({n.x, n.y, n.z});
  }
  EXPECT_EQ(normals.size(), 6u);  // each axis direction, twice each
  for (const Vec3& p : box.positions)
    expect_near({std::abs(p.x), std::abs(p.y), std::abs(p.z)}, {1, 2, 3});
}

TEST(SceneLoader, BoxFacesAndRotation) {
  const Scene one_face = parse_object(
      R"({"type": "box", "material": "red", "min": [0, 0, 0], "max": [1, 1, 1], "faces": ["+y"]})");
  ASSERT_EQ(one_face.meshes.at(0).indices.size(), 6u);
  expect_near(triangle_normal(one_face.meshes[0], 0), {0, 1, 0});

  // A 2x1x1 box turned a quarter about +y around its centre (1, 0.5, 0.5).
  const Scene turned = parse_object(
      R"({"type": "box", "material": "red", "min": [0, 0, 0], "max": [2, 1, 1], "rotation": {"yaw": 90}})");
  const TriangleMesh& box = turned.meshes.at(0);
  expect_facing({box}, {1, 0.5, 0.5}, false);
  for (const Vec3& p : box.positions) {
    EXPECT_NEAR(std::abs(p.x - 1), 0.5, 1e-12);
    EXPECT_NEAR(std::abs(p.z - 0.5), 1.0, 1e-12);
  }
}

TEST(SceneLoader, AcceptsTheTrivialManifoldAndGreyShorthand) {
  EXPECT_NO_THROW(parse_patched(R"({"manifold": {"type": "none"}})"));
  const Scene scene = parse_patched(R"({"materials": {"red": {"diffuse": 0.25}}})");
  expect_near(scene.materials[0].diffuse, {0.25, 0.25, 0.25});
  EXPECT_EQ(scene.materials[0].shininess, 1);
}

TEST(SceneLoader, MissingMeshFileNamesTheFieldAndPath) {
  const std::string expected =
      "objects[0].file: file not found: \"" + (kSceneDocumentDir / "meshes/nope.obj").string() + "\"";
  EXPECT_EQ(
      error_of(R"({"objects": [{"type": "mesh", "material": "red", "file": "meshes/nope.obj"}]})"),
      expected);
}

class SceneFileTest : public ::testing::Test {
 protected:
  void TearDown() override { fs::remove(path_); }
  fs::path write(const std::string& text) {
    std::ofstream(path_) << text;
    return path_;
  }
  // One file per test: ctest runs tests in parallel processes.
  fs::path path_ = fs::temp_directory_path() /
                   (std::string("geodesic_") +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".json");
};

TEST_F(SceneFileTest, MissingFileNamesIt) {
  try {
    load_scene_file("/nonexistent/scene.json");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "/nonexistent/scene.json: cannot open file (missing or not a regular file)");
  }
}

TEST_F(SceneFileTest, InvalidJsonGivesFileAndPosition) {
  const fs::path path = write("{\n  \"geometry\": \"euclidean\",,\n}");
  try {
    load_scene_file(path);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path.string() + ": invalid JSON: parse error at line 2, column ", 0), 0u)
        << what;
  }
}

// JSON text cannot spell NaN or infinity, and nlohmann rejects overflowing literals.
TEST_F(SceneFileTest, OverflowingNumberIsInvalidJson) {
  const std::string text = Json::parse(kBase).dump();
  const std::string marker = "\"center\":[0,0,0]";
  std::string patched = text;
  patched.replace(text.find(marker), marker.size(), "\"center\":[0,1e400,0]");
  try {
    load_scene_file(write(patched));
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              path_.string() + ": invalid JSON: number overflow parsing '1e400'");
  }
}

// The schema documents the format; every field a bundled scene uses must be declared there.
TEST(SceneSchema, DeclaresEveryFieldTheBundledScenesUse) {
  std::ifstream in(fs::path(GEODESIC_SOURCE_DIR) / "proto" / "scene.schema.json");
  const Json schema = Json::parse(in);
  EXPECT_EQ(schema.at("$schema"), "https://json-schema.org/draft/2020-12/schema");
  EXPECT_EQ(schema.at("additionalProperties"), false);
  const Json& defs = schema.at("$defs");
  auto expect_declared = [](const Json& value, const Json& definition, const std::string& where) {
    EXPECT_EQ(definition.at("additionalProperties"), false) << where;
    for (const auto& item : value.items())
      EXPECT_TRUE(definition.at("properties").contains(item.key())) << where << "." << item.key();
  };
  for (const fs::path& path : bundled_scenes()) {
    std::ifstream scene_in(path);
    const Json scene = Json::parse(scene_in);
    expect_declared(scene, schema, path.filename().string());
    expect_declared(scene.at("camera"), defs.at("camera"), "camera");
    if (scene.contains("render")) expect_declared(scene.at("render"), defs.at("render"), "render");
    for (const auto& material : scene.at("materials").items())
      expect_declared(material.value(), defs.at("material"), "materials." + material.key());
    for (const Json& object : scene.at("objects")) {
      const std::string type = object.at("type");
      expect_declared(object, defs.at(type), type);
    }
    for (const Json& light : scene.value("lights", Json::array()))
      expect_declared(light, defs.at("point_light"), "light");
  }
}

}  // namespace
}  // namespace geodesic

namespace geodesic {
namespace {

TEST(SceneLoader, ObjectsMustLieInsideTheFundamentalDomain) {
  const auto doc = [](const std::string& object) {
    return nlohmann::ordered_json::parse(R"({"geometry": "euclidean",
      "manifold": {"type": "torus", "size": 2},
      "camera": {"position": [0, 0, 0]},
      "materials": {"m": {"diffuse": 0.5}},
      "objects": [{"type": "sphere", "material": "m", "center": [0, 0, 0], "radius": 0.5}, )" +
                                         object + "]}");
  };
  EXPECT_NO_THROW(parse_scene(doc(R"({"type": "sphere", "material": "m", "center": [0.4, 0, 0], "radius": 0.5})"), fs::path(".")));
  try {
    parse_scene(doc(R"({"type": "sphere", "material": "m", "center": [0.6, 0, 0], "radius": 0.5})"), fs::path("."));
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "objects[1]: must lie inside the fundamental domain (it crosses face 0)");
  }
  try {
    parse_scene(doc(R"({"type": "quad", "material": "m", "corner": [0, 0, 0], "edge_u": [2, 0, 0], "edge_v": [0, 0.5, 0]})"), fs::path("."));
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "objects[1]: must lie inside the fundamental domain (a vertex is beyond face 0)");
  }
}

}  // namespace
}  // namespace geodesic

namespace geodesic {
namespace {

TEST(SceneLoader, CameraMayBeGivenAsAnIsometryMatrix) {
  const auto doc = [](const std::string& pose) {
    return nlohmann::ordered_json::parse(
        R"({"geometry": "hyperbolic", "camera": {"pose": )" + pose + R"(, "fov_y": 60}})");
  };
  // A boost by 0.5 along x: cosh and sinh of 0.5.
  const double c = std::cosh(0.5), s = std::sinh(0.5);
  const std::string boost = "[[" + std::to_string(c) + ", 0, 0, " + std::to_string(s) +
                            "], [0, 1, 0, 0], [0, 0, 1, 0], [" + std::to_string(s) + ", 0, 0, " +
                            std::to_string(c) + "]]";
  const Scene scene = parse_scene(doc(boost), fs::path("."));
  EXPECT_NEAR(scene.camera.pose.m[0][3], s, 1e-6);
  EXPECT_LT(model::isometry_error(GeometryKind::Hyperbolic, scene.camera.pose), 1e-12);
  try {
    parse_scene(doc("[[1, 0, 0, 0.5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]"), fs::path("."));
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("camera.pose: not an isometry of hyperbolic space (error ", 0), 0u)
        << e.what();
  }
}

// A pose 20 units out, as the daemon reports one there: its entries are ~2.4e8 and rounded to
// 17 digits, so g^T J g - J is off by ~10 in absolute terms; relative to its size it is an
// isometry, and it reads back with its point 20 out and its frame orthonormal.
TEST(SceneLoader, APoseTwentyUnitsOutIsAnIsometry) {
  const GeometryKind k = GeometryKind::Hyperbolic;
  const Mat4 g = model::translation(k, {0, 12, 16}) * model::rotation({1, 0.5, 0}, 0.7);
  std::string rows = "[";
  char number[40];
  for (int r = 0; r < 4; ++r) {
    rows += r ? ", [" : "[";
    for (int c = 0; c < 4; ++c) {
      std::snprintf(number, sizeof number, "%.17g", g.m[r][c]);
      rows += (c ? ", " : "") + std::string(number);
    }
    rows += "]";
  }
  rows += "]";
  const Scene scene = parse_scene(
      nlohmann::ordered_json::parse(R"({"geometry": "hyperbolic", "camera": {"pose": )" + rows + "}}"),
      fs::path("."));
  EXPECT_NEAR(length(model::log_origin(k, scene.camera.pose * model::origin())), 20, 1e-9);
  EXPECT_LT(model::relative_isometry_error(k, scene.camera.pose), 1e-15);
}

// Placement moves the content and the camera; a quotient refuses it, naming the field.
TEST(SceneLoader, PlacementMovesEverythingButNotAQuotient) {
  const auto doc = [](const std::string& manifold) {
    return nlohmann::ordered_json::parse(R"({"geometry": "euclidean", )" + manifold + R"(
      "placement": {"position": [100, 0, 0], "rotation": {"yaw": 90}},
      "camera": {"position": [0, 0, 0.5], "look_at": [0, 0, 0]},
      "materials": {"m": {"diffuse": 0.5}},
      "objects": [{"type": "sphere", "material": "m", "center": [0.1, 0, 0], "radius": 0.1}],
      "lights": [{"type": "point", "position": [0, 0.3, 0], "intensity": 1}]})");
  };
  const Scene scene = parse_scene(doc(""), fs::path("."));
  // yaw 90 turns +x to -z: the sphere at (0.1, 0, 0) goes to (100, 0, -0.1).
  EXPECT_NEAR(length(scene.spheres[0].center - Vec3{100, 0, -0.1}), 0, 1e-12);
  EXPECT_NEAR(length(scene.lights[0].position - Vec3{100, 0.3, 0}), 0, 1e-12);
  EXPECT_NEAR(length((scene.camera.pose * model::origin()).xyz() - Vec3{100.5, 0, 0}), 0, 1e-12);
  try {
    parse_scene(doc(R"("manifold": {"type": "torus", "size": 2},)"), fs::path("."));
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("placement: only in a space without a quotient", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace geodesic
