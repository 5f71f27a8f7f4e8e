// Every invalid scene document is rejected with a message naming the field and the reason.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "scene/shape.h"
#include "scene_document.h"

namespace geodesic {
namespace {

using Json = nlohmann::ordered_json;

TEST(SceneLoader, RejectsInvalidDocumentsNamingTheField) {
  const std::pair<std::string, std::string> cases[] = {
      {R"({"colour": 1})", R"((root): unknown field "colour")"},
      {R"({"name": 3})", "name: must be a string"},
      {R"({"geometry": null})", R"((root): missing required field "geometry")"},
      {R"({"geometry": "flat"})",
       R"(geometry: unknown geometry "flat" (expected "euclidean", "hyperbolic" or "spherical"))"},
      {R"({"manifold": {"type": "poincare-dodecahedral"}})",
       R"(manifold.type: "poincare-dodecahedral" is a spherical manifold, but the scene's geometry is euclidean)"},
      {R"({"manifold": 3})", "manifold: must be null or an object"},
      {R"({"camera": {"position": null}})", R"(camera: missing required field "position")"},
      {R"({"camera": {"position": [0, 0]}})", "camera.position: must be an array of 3 numbers"},
      {R"({"camera": {"position": [0, 2e6, 0]}})",
       "camera.position[1]: must have magnitude <= 1e6"},
      {R"({"camera": {"fov_y": 180}})", "camera.fov_y: must be in (0, 180)"},
      {R"({"camera": {"fov_y": "wide"}})", "camera.fov_y: must be a number"},
      {R"({"camera": {"look_at": [0, 0, 5]}})", "camera.look_at: must differ from camera.position"},
      {R"({"camera": {"look_at": [0, 0, 0], "up": [0, 0, 1]}})",
       "camera.up: must not be parallel to the view direction"},
      {R"({"camera": {"look_at": [0, -5, 5]}})",
       "camera.up: must not be parallel to the view direction"},
      {R"({"camera": {"look_at": [0, 0, 0], "up": [0, 0, 0]}})", "camera.up: must be non-zero"},
      {R"({"camera": {"look_at": [0, 0, 0], "rotation": {}}})",
       R"(camera: give either "look_at" or "rotation", not both)"},
      {R"({"camera": {"up": [0, 1, 0]}})", R"(camera.up: only allowed together with "look_at")"},
      {R"({"camera": {"rotation": {"yaw": "left"}}})", "camera.rotation.yaw: must be a number"},
      {R"({"camera": {"rotation": {"tilt": 1}}})", R"(camera.rotation: unknown field "tilt")"},
      {R"({"materials": []})", "materials: must be an object mapping names to materials"},
      {R"({"materials": {"red": {"glow": 1}}})", R"(materials.red: unknown field "glow")"},
      {R"({"materials": {"red": {"diffuse": [0.8, -0.1, 0.1]}}})",
       "materials.red.diffuse[1]: must be a finite number >= 0"},
      {R"({"materials": {"red": {"diffuse": "red"}}})",
       "materials.red.diffuse: must be a number or an array of 3 numbers"},
      {R"({"materials": {"red": {"emission": [1, 1]}}})",
       "materials.red.emission: must be a number or an array of 3 numbers"},
      {R"({"materials": {"red": {"shininess": -1}}})",
       "materials.red.shininess: must be a finite number >= 0"},
      {R"({"materials": {"red": {"diffuse": 0.6, "mirror": [0.1, 0.5, 0.1]}}})",
       "materials.red: diffuse + specular + mirror + transmission is 1.100000 in channel g; it "
       "must be <= 1 (energy conservation)"},
      {R"({"objects": {}})", "objects: must be an array of objects"},
      {R"({"lights": [{"type": "spot", "position": [0, 0, 0], "intensity": 1}]})",
       R"(lights[0].type: unknown light type "spot" (expected "point"))"},
      {R"({"lights": [{"type": "point", "position": [0, 0, 0], "intensity": [1, 1]}]})",
       "lights[0].intensity: must be a number or an array of 3 numbers"},
      {R"({"lights": [{"type": "point", "position": [0, 0, 0]}]})",
       R"(lights[0]: missing required field "intensity")"},
      {R"({"render": {"gamma": 1}})", R"(render: unknown field "gamma")"},
      {R"({"render": {"exposure": "bright"}})",
       R"(render.exposure: must be a number of stops in [-20, 20] or "auto")"},
      {R"({"render": {"exposure": 20.5}})",
       R"(render.exposure: must be a number of stops in [-20, 20] or "auto")"},
      {R"({"render": {"width": 0}})", "render.width: must be an integer in [1, 8192]"},
      {R"({"render": {"height": 1.5}})", "render.height: must be an integer in [1, 8192]"},
      {R"({"render": {"max_depth": 65}})", "render.max_depth: must be an integer in [0, 64]"},
      {R"({"render": {"spp": 0}})", "render.spp: must be an integer in [1, 1000000]"},
      {R"({"render": {"seed": -1}})", "render.seed: must be an unsigned integer"},
      {R"({"render": {"russian_roulette": 1}})", "render.russian_roulette: must be true or false"},
      {R"({"render": {"ambient": -0.1}})", "render.ambient: must be a finite number >= 0"},
      {R"({"render": {"lighting": "phong"}})",
       "render.lighting: unknown value \"phong\" (expected one of \"physical\", \"paper\")"},
      {R"({"render": {"light_sampling": "nee"}})",
       "render.light_sampling: unknown value \"nee\" (expected one of \"mis\", \"bsdf\", \"light\")"},
      {R"({"render": {"light_cutoff": 0}})", "render.light_cutoff: must be > 0"},
      {R"({"render": {"light_samples": 0}})", "render.light_samples: must be an integer in [1, 8]"},
      {R"({"render": {"light_samples": 9}})", "render.light_samples: must be an integer in [1, 8]"},
      {R"({"render": {"light_samples": 2.5}})",
       "render.light_samples: must be an integer in [1, 8]"},
      {R"({"render": {"clamp": -1}})", "render.clamp: must be > 0"},
      {R"({"materials": {"red": {"transmission": 0.5, "ior": 11}}})",
       "materials.red.ior: must be <= 10 (an index of refraction)"},
      {R"({"materials": {"red": {"diffuse": 0.5, "specular": 0.3, "transmission": 0.3}}})",
       "materials.red: diffuse + specular + mirror + transmission is 1.100000 in channel r; it "
       "must be <= 1 (energy conservation)"},
  };
  for (const auto& [patch, message] : cases) EXPECT_EQ(error_of(patch), message) << patch;
  EXPECT_EQ(error_of_document(Json::array()), "(root): must be an object");
}


// Each case is the document's only object, so every message starts with objects[0].
TEST(SceneLoader, RejectsInvalidObjectsNamingTheField) {
  const std::string sphere = R"({"type": "sphere", "material": "red", "center": [0, 0, 0], )";
  const std::string quad = R"({"type": "quad", "material": "red", "corner": [0, 0, 0], )";
  const std::string polygon = R"({"type": "polygon", "material": "red", "vertices": )";
  const std::string box = R"({"type": "box", "material": "red", "min": [0, 0, 0], )";
  const std::string mesh =
      R"({"type": "mesh", "material": "red", "file": "meshes/octahedron.obj", )";
  // The types the loader knows: its own, then the shape table's (scene/shape.h).
  std::string types = R"("sphere", "quad", "polygon", "box", "mesh", "domain_edges")";
  for (const ShapeKind* kind : shape_kinds()) {
    const std::string type = '"' + std::string(kind->type) + '"';
    types += kind == shape_kinds().back() ? " or " + type : ", " + type;
  }
  const std::pair<std::string, std::string> cases[] = {
      {"3", "objects[0]: must be an object"},
      {R"({"material": "red"})", R"(objects[0]: missing required field "type")"},
      {R"({"type": "cone", "material": "red"})",
       R"(objects[0].type: unknown object type "cone" (expected )" + types + ")"},
      {sphere + R"("radius": 1, "colour": "red"})", R"(objects[0]: unknown field "colour")"},
      {sphere + R"("radius": -1})", "objects[0].radius: must be > 0"},
      {sphere + R"("radius": 2e6})", "objects[0].radius: must be <= 1e6"},
      {sphere + R"("radius": "1"})", "objects[0].radius: must be a number"},
      {sphere + R"("radius": true})", "objects[0].radius: must be a number"},
      {R"({"type": "sphere", "material": "red", "center": [0, 0, 0]})",
       R"(objects[0]: missing required field "radius")"},
      {R"({"type": "sphere", "material": "blue", "center": [0, 0, 0], "radius": 1})",
       R"(objects[0].material: unknown material "blue")"},
      {R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})",
       R"(objects[0]: missing required field "material")"},
      {R"({"type": "sphere", "material": "red", "center": [0, "x", 0], "radius": 1})",
       "objects[0].center[1]: must be a number"},
      {quad + R"("edge_u": [1, 0, 0], "edge_v": [2, 0, 0]})",
       "objects[0]: degenerate quad: edge_u and edge_v must be non-zero and not parallel"},
      {quad + R"("edge_u": [0, 0, 0], "edge_v": [0, 1, 0]})",
       "objects[0]: degenerate quad: edge_u and edge_v must be non-zero and not parallel"},
      {polygon + "[[0, 0, 0], [1, 0, 0]]}",
       "objects[0].vertices: must be an array of at least 3 points"},
      {polygon + "[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.2]]}",
       "objects[0].vertices: polygon is not planar"},
      {polygon + "[[0, 0, 0], [2, 0, 0], [1, 0.5, 0], [2, 2, 0], [0, 2, 0]]}",
       "objects[0].vertices: polygon must be strictly convex (no reflex, repeated or collinear "
       "vertices)"},
      {polygon + "[[0, 0, 0], [1, 0, 0], [2, 0, 0]]}",
       "objects[0].vertices: degenerate polygon: it has no area"},
      {box + R"("max": [1, 1, 0]})", "objects[0].max[2]: must be greater than min[2]"},
      {box + R"("max": [1, 1, 1], "faces": ["+x", "+w"]})",
       R"(objects[0].faces[1]: must be one of "+x", "-x", "+y", "-y", "+z", "-z")"},
      {box + R"("max": [1, 1, 1], "faces": ["+x", "+x"]})",
       R"(objects[0].faces[1]: face "+x" is listed twice)"},
      {box + R"("max": [1, 1, 1], "faces": []})",
       "objects[0].faces: must be a non-empty array of face names"},
      {box + R"("max": [1, 1, 1], "rotation": {"yaw": 1, "spin": 2}})",
       R"(objects[0].rotation: unknown field "spin")"},
      {mesh + R"("scale": 0})", "objects[0].scale: must be > 0"},
      {mesh + R"("scale": [1, 2]})", "objects[0].scale: must be a number or an array of 3 numbers"},
      {mesh + R"("scale": [1, -2, 1]})", "objects[0].scale[1]: must be > 0"},
      {R"({"type": "mesh", "material": "red", "file": 7})", "objects[0].file: must be a string"},
  };
  for (const auto& [object, message] : cases)
    EXPECT_EQ(error_of(R"({"objects": [)" + object + "]}"), message) << object;
}

TEST(SceneLoader, RejectsEdgeTubesThatCannotBeDrawn) {
  const std::string edges = R"({"type": "domain_edges", "material": "red", "radius": )";
  EXPECT_EQ(error_of(R"({"objects": [)" + edges + "0.1}]}"),
            R"(objects[0]: "domain_edges" needs a manifold)");
  const std::string torus = R"("manifold": {"type": "torus", "size": 4}, )";
  EXPECT_EQ(error_of("{" + torus + R"("materials": {"red": {"emission": [1, 1, 1]}}, "objects": [)" +
                     edges + "0.1}]}"),
            "objects[0].material: must not emit: edge tubes are not light sources");
  EXPECT_EQ(parse_patched("{" + torus + R"("objects": [)" + edges + "0.1}]}").tubes.size(), 12u);
  EXPECT_EQ(error_of(R"({"geometry": "hyperbolic", "camera": {"position": [0, 0, 0.1]},
                        "manifold": {"type": "seifert-weber"}, "objects": [)" +
                     edges + "0.3}]}"),
            "objects[0].radius: tubes of chart radius 0.300000 leave the hyperbolic chart (|X| >= 1)");
}


// A document built in memory can hold non-finite numbers; they are rejected by field.
TEST(SceneLoader, RejectsNonFiniteNumbers) {
  Json doc = Json::parse(kBase);
  doc["objects"][0]["center"][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(error_of_document(doc), "objects[0].center[1]: must be a finite number");
  doc = Json::parse(kBase);
  doc["materials"]["red"]["emission"] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of_document(doc), "materials.red.emission: must be a finite number >= 0");
}


}  // namespace
}  // namespace geodesic
