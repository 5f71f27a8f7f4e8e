// Per-scene pipelines (render/prepare/pipeline_features.h): what each bundled scene compiles in,
// scene by scene and feature by feature. specialised_shaders_test.cpp holds what they leave out
// of the shaders, their images against the all-features pipeline's, and the pipeline cache.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "render/prepare/scene_bindings.h"
#include "render_fixture.h"

namespace geodesic::test {
namespace {

// The scene's pipeline feature `flag`, which its define `name` must say too.
bool feature(const Scene& scene, bool PipelineFeatures::*flag, const char* name) {
  const PipelineFeatures f = scene_features(scene, pack_scene(scene));
  const auto defines = f.defines();
  EXPECT_EQ(std::find(defines.begin(), defines.end(), name) != defines.end(), f.*flag) << name;
  return f.*flag;
}

TEST(PipelineFeatures, EachBundledSceneGetsItsPairingKindAndPrimitives) {
  struct Expected {
    const char* scene;
    Crossing crossing;
    bool spheres, triangles, tubes, paper;
  };
  const Expected expected[] = {
      {"cornell-box", Crossing::None, true, true, false, false},
      {"torus-cornell", Crossing::Translation, true, true, false, false},
      {"mirrored-dodecahedron", Crossing::Reflection, true, false, true, false},
      {"seifert-weber", Crossing::Isometry, true, false, true, false},
      {"poincare-sphere", Crossing::Isometry, true, false, true, false},
      {"spherical-spheres", Crossing::ChartChange, true, false, false, false},
      {"hyperbolic-spheres", Crossing::None, true, true, false, false},
      {"furnace", Crossing::None, false, true, false, false},
  };
  for (const Expected& e : expected) {
    const Scene scene = bundled_scene(e.scene);
    const PipelineFeatures f = scene_features(scene, pack_scene(scene));
    Scene other = scene;  // the other model: the same features otherwise
    other.render.lighting = e.paper ? LightingModel::Physical : LightingModel::Paper;
    const PipelineFeatures g = scene_features(other, pack_scene(other));
    EXPECT_EQ(g.paper, !e.paper) << e.scene;
    EXPECT_EQ(f.crossing, e.crossing) << e.scene << ": " << crossing_name(f.crossing);
    EXPECT_EQ(f.spheres, e.spheres) << e.scene;
    EXPECT_EQ(f.triangles, e.triangles) << e.scene;
    EXPECT_EQ(f.tubes, e.tubes) << e.scene;
    const auto defines = f.defines();
    EXPECT_EQ(std::find(defines.begin(), defines.end(), "HAS_TUBES") != defines.end(), e.tubes)
        << e.scene;
    EXPECT_EQ(f.uses_binding(kTubesBinding), e.tubes) << e.scene;
    EXPECT_EQ(f.paper, e.paper) << e.scene;
    EXPECT_NE(f.paper, f.physical) << e.scene << ": one lighting model";
  }
}

// A space of one cell, with faces or without, reads its cell at a uniform index (SINGLE_CELL);
// an atlas of cells (S3 charted in pieces) does not.
TEST(PipelineFeatures, SpacesOfOneCellReadItAtAUniformIndex) {
  const auto single = [](const char* name) {
    const Scene scene = bundled_scene(name);
    const PackedScene packed = pack_scene(scene);
    const PipelineFeatures f = scene_features(scene, packed);
    const auto defines = f.defines();
    EXPECT_EQ(std::find(defines.begin(), defines.end(), "SINGLE_CELL") != defines.end(),
              f.single_cell) << name;
    EXPECT_EQ(f.single_cell, packed.cells.size() == 1) << name;
    return f.single_cell;
  };
  for (const char* name : {"mirrored-dodecahedron", "seifert-weber", "poincare-sphere",
                           "torus-cornell", "quarter-turn-space", "cornell-box",
                           "hyperbolic-spheres"})
    EXPECT_TRUE(single(name)) << name;
  EXPECT_FALSE(single("spherical-spheres"));
  EXPECT_FALSE(all_features(GeometryKind::Hyperbolic).single_cell);
}

// A space of one cell bakes its record's index ranges in (CELL_RANGES, in cellRecord's order),
// so that the loops over its faces, tubes and listed primitives have constant bounds; neither
// an atlas of cells nor the all-features pipeline does. (EveryBundledScene/
// SpecialisedPipelines.RenderAsWithAllFeatures/* hold the images: the all-features pipeline
// reads the record's ranges.)
TEST(PipelineFeatures, OneCellsRangesAreBakedIn) {
  const auto baked = [](const char* name) -> std::string {
    const Scene scene = bundled_scene(name);
    const PackedScene packed = pack_scene(scene);
    const auto defines = scene_features(scene, packed).defines();
    const auto it = std::find_if(defines.begin(), defines.end(), [](const std::string& d) {
      return d.rfind("CELL_RANGES=", 0) == 0;
    });
    if (it == defines.end()) return "";
    EXPECT_EQ(packed.cells.size(), 1u) << name;
    return it->substr(std::strlen("CELL_RANGES="));
  };
  // face begin, count; tube begin, count, always-tested begin; sphere begin, count; listed
  // begin, count, pairs; shape begin, count; hull pairs, hull lone triangles.
  EXPECT_EQ(baked("mirrored-dodecahedron"), "0u,12u,0u,30u,30u,0u,3u,0u,0u,0u,0u,0u,0u,0u");
  EXPECT_EQ(baked("catalogue/coxeter-5-3-4"), "0u,4u,0u,6u,6u,0u,3u,0u,0u,0u,0u,0u,0u,0u");
  // The Cornell box: no faces, its triangles listed (16, as 8 parallelograms), its spheres.
  const Scene box = bundled_scene("cornell-box");
  const PackedScene packed = pack_scene(box);
  const GpuCell& cell = packed.cells.at(0);
  EXPECT_EQ(baked("cornell-box"),
            "0u,0u,0u,0u,0u,0u," + std::to_string(cell.sphere_count) + "u,0u,8u,8u,0u,0u," +
                std::to_string(cell.listed_hull_pairs) + "u," +
                std::to_string(cell.listed_hull_lone) + "u");
  for (const char* name : {"spherical-spheres", "catalogue/lens-3-1"})
    EXPECT_EQ(baked(name), "") << name;
  const auto all = all_features(GeometryKind::Hyperbolic).defines();
  EXPECT_TRUE(std::none_of(all.begin(), all.end(), [](const std::string& d) {
    return d.rfind("CELL_RANGES", 0) == 0;
  }));
}

// A space of one cell with at most kBakedTubeFaces tubes held by pairs of faces bakes in each
// such tube's pair as a mask of two face bits, in the packed tubes' order, 32 to a define
// (TUBE_FACES_0, TUBE_FACES_1, ...); spaces without tubes and the all-features pipeline do
// not. (EveryBundledScene/SpecialisedPipelines.RenderAsWithAllFeatures/* hold the images: the
// all-features pipeline finds the pairs from the face records.)
TEST(PipelineFeatures, OneCellsTubeFacesAreBakedIn) {
  const auto baked = [](const char* name) {
    const Scene scene = bundled_scene(name);
    const PackedScene packed = pack_scene(scene);
    const PipelineFeatures f = scene_features(scene, packed);
    std::vector<std::string> expected;
    for (size_t i = 0; i < f.tube_faces.size(); ++i) {
      const GpuTube& tube = packed.tubes.at(packed.cells.at(0).tube_begin + i);
      EXPECT_LT(tube.face_b, 32u) << name;
      EXPECT_EQ(f.tube_faces[i], (1u << tube.face_a) | (1u << tube.face_b)) << name << " " << i;
      if (i % kTubeFacesPerDefine == 0)
        expected.push_back("TUBE_FACES_" + std::to_string(i / kTubeFacesPerDefine) + "=");
      expected.back() += std::to_string(f.tube_faces[i]) + "u,";
    }
    for (std::string& d : expected) d.pop_back();
    std::vector<std::string> defines;
    for (const std::string& d : f.defines())
      if (d.rfind("TUBE_FACES", 0) == 0) defines.push_back(d);
    EXPECT_EQ(defines, expected) << name;
    if (!f.tube_faces.empty())
      EXPECT_EQ(f.tube_faces.size(), packed.cells.at(0).always_begin) << name;
    return f.tube_faces.size();
  };
  // A dodecahedron's 30 edges, each on two of its 12 faces; a cube's 12 on two of its 6; the
  // binary octahedral space's 36 in two defines.
  EXPECT_EQ(baked("mirrored-dodecahedron"), 30u);
  EXPECT_EQ(baked("seifert-weber"), 30u);
  EXPECT_EQ(baked("quarter-turn-space"), 12u);
  EXPECT_EQ(baked("catalogue/binary-octahedral"), 36u);
  // An atlas of lunes, the Cornell box and the others here have no tubes.
  for (const char* name : {"catalogue/lens-3-1", "cornell-box", "torus-cornell",
                           "figure-eight-knot"})
    EXPECT_EQ(baked(name), 0u) << name;
  EXPECT_TRUE(all_features(GeometryKind::Hyperbolic).tube_faces.empty());
}

// The floats of the define `name` (NAME=vec4(x,y,z,w),...) as glslang reads them (each literal
// to double, then to float), grouped by four; none when the define is absent.
std::vector<Float4> baked_vec4s(const std::vector<std::string>& defines, const std::string& name) {
  std::vector<Float4> values;
  for (const std::string& d : defines) {
    if (d.rfind(name + "=", 0) != 0) continue;
    const char* at = d.c_str() + name.size() + 1;
    while (*at) {
      EXPECT_EQ(std::string(at, 5), "vec4(") << name;
      at += 5;
      Float4 v;
      for (float& x : v) {
        char* end;
        x = float(std::strtod(at, &end));
        EXPECT_NE(std::string(at, size_t(end - at)).find_first_of(".e"), std::string::npos)
            << name << ": a float literal";
        at = end + 1;  // past ',' or ')'
      }
      values.push_back(v);
      if (*at == ',') ++at;
    }
  }
  return values;
}

// Bit for bit, the sign of zero too.
bool same_bits(const std::vector<Float4>& a, const std::vector<Float4>& b) {
  using Bits = std::array<uint32_t, 4>;
  return std::ranges::equal(a, b, [](const Float4& x, const Float4& y) {
    return std::bit_cast<Bits>(x) == std::bit_cast<Bits>(y);
  });
}

// A space of one cell bakes in its face planes (FACE_PLANES) and its listed spheres' centres
// and radii (LISTED_SPHERE_DATA), the floats exactly as packed; an atlas of cells and the
// all-features pipeline bake neither. (EveryBundledScene/SpecialisedPipelines.
// RenderAsWithAllFeatures/* hold the images: the all-features pipeline reads the records.)
TEST(PipelineFeatures, OneCellsPlanesAndListedSpheresAreBakedIn) {
  const auto check = [](const char* name, size_t faces, size_t spheres) {
    const Scene scene = bundled_scene(name);
    const PackedScene packed = pack_scene(scene);
    const auto defines = scene_features(scene, packed).defines();
    std::vector<Float4> planes, listed;
    if (faces > 0)
      for (const GpuCellFace& face : packed.faces)
        planes.push_back({face.plane[0], face.plane[1], face.plane[2], face.plane[3]});
    const GpuCell& cell = packed.cells.at(0);
    EXPECT_EQ(cell.sphere_count, spheres) << name;
    for (uint32_t i = 0; i < cell.sphere_count; ++i) {
      const GpuSphereRef& ref = packed.sphere_refs.at(cell.sphere_begin + i);
      const GpuSphere& sphere = packed.spheres.at(ref.sphere);
      listed.push_back({sphere.center[0], sphere.center[1], sphere.center[2], sphere.center[3]});
      listed.push_back({sphere.radius, 0, 0, 0});
    }
    EXPECT_EQ(planes.size(), faces) << name;
    EXPECT_TRUE(same_bits(baked_vec4s(defines, "FACE_PLANES"), planes)) << name;
    EXPECT_TRUE(same_bits(baked_vec4s(defines, "LISTED_SPHERE_DATA"), listed)) << name;
  };
  check("mirrored-dodecahedron", 12, 3);  // its planes hold zeros of both signs
  check("seifert-weber", 12, 1);
  check("quarter-turn-space", 6, 2);
  check("cornell-box", 0, 3);  // no faces: its spheres alone
  check("furnace", 0, 0);      // no spheres listed
  for (const char* name : {"spherical-spheres", "catalogue/lens-3-1"}) {
    const Scene scene = bundled_scene(name);
    const auto defines = scene_features(scene, pack_scene(scene)).defines();
    EXPECT_TRUE(baked_vec4s(defines, "FACE_PLANES").empty()) << name;
    EXPECT_TRUE(baked_vec4s(defines, "LISTED_SPHERE_DATA").empty()) << name;
  }
  const auto all = all_features(GeometryKind::Hyperbolic);
  EXPECT_TRUE(all.face_planes.empty() && all.listed_spheres.empty());
}

// Segments test their cell's spheres one by one where each cell holds at most
// kSphereListLength (and at most kShapeListLength shapes), in a space with faces or of one
// cell; the acceleration structure traces the triangles beside them.
// (EveryBundledScene/SpecialisedPipelines.RenderAsWithAllFeatures/* hold the images: the
// all-features pipeline traverses.)
TEST(PipelineFeatures, SmallCellsOfSpheresAreTestedOneByOne) {
  const auto listed = [](const Scene& scene) {
    return feature(scene, &PipelineFeatures::sphere_list, "SPHERE_LIST");
  };
  for (const char* name : {"mirrored-dodecahedron", "seifert-weber", "poincare-sphere"})
    EXPECT_TRUE(listed(bundled_scene(name))) << name;
  // Beside triangles, and in one cell without faces.
  for (const char* name : {"torus-cornell", "cornell-box", "hyperbolic-spheres"})
    EXPECT_TRUE(listed(bundled_scene(name))) << name;
  // Beside listed shapes.
  for (const char* name : {"horospheres", "figure-eight-knot", "whitehead-link"})
    EXPECT_TRUE(listed(bundled_scene(name))) << name;
  EXPECT_FALSE(listed(bundled_scene("furnace")));  // no spheres
  EXPECT_FALSE(all_features(GeometryKind::Hyperbolic).sphere_list);
  // A 3-torus holding n spheres: listed up to kSphereListLength.
  const auto torus = [](uint32_t n) {
    std::string objects;
    for (uint32_t i = 0; i < n; ++i)
      objects += std::string(i ? "," : "") + R"({"type": "sphere", "material": "m", "center": [)" +
                 std::to_string(-1.6 + 0.4 * i) + R"(, 0, 0], "radius": 0.1})";
    return scene_from_json(R"({"geometry": "euclidean", "manifold": {"type": "torus", "size": 4},
      "camera": {"position": [0, 0, 1.5], "look_at": [0, 0, 0]},
      "materials": {"m": {"diffuse": 0.5}}, "objects": [)" + objects + R"(],
      "lights": [{"type": "point", "position": [0, 1, 0], "intensity": 1}]})");
  };
  EXPECT_TRUE(listed(torus(kSphereListLength)));
  EXPECT_FALSE(listed(torus(kSphereListLength + 1)));
}

// Segments test their cell's triangles one by one, and traverse nothing, where each cell holds
// at most kTriangleListLength, its spheres and shapes are listed (or none).
// (EveryBundledScene/SpecialisedPipelines.RenderAsWithAllFeatures/* hold the images: the
// all-features pipeline traverses; TriangleProbe holds the test against its double twin.)
TEST(PipelineFeatures, SmallCellsOfTrianglesAreTestedOneByOne) {
  const auto listed = [](const Scene& scene) {
    const PipelineFeatures f = scene_features(scene, pack_scene(scene));
    EXPECT_TRUE(!f.triangle_list || !f.traced_boxes());  // nothing left to traverse
    return feature(scene, &PipelineFeatures::triangle_list, "TRIANGLE_LIST");
  };
  for (const char* name : {"cornell-box", "furnace", "quarter-turn-space"})
    EXPECT_TRUE(listed(bundled_scene(name))) << name;
  // No triangles.
  for (const char* name : {"mirrored-dodecahedron", "horospheres"})
    EXPECT_FALSE(listed(bundled_scene(name))) << name;
  EXPECT_FALSE(all_features(GeometryKind::Euclidean).triangle_list);
  // A box of n quads (2 n triangles): listed up to kTriangleListLength triangles.
  const auto quads = [](uint32_t n) {
    std::string objects;
    for (uint32_t i = 0; i < n; ++i)
      objects += std::string(i ? "," : "") +
                 R"({"type": "quad", "material": "m", "corner": [-1, -1, )" +
                 std::to_string(-1.0 + 0.05 * i) + R"(], "edge_u": [2, 0, 0], "edge_v": [0, 2, 0]})";
    return scene_from_json(R"({"geometry": "euclidean",
      "camera": {"position": [0, 0, 1.5], "look_at": [0, 0, 0]},
      "materials": {"m": {"diffuse": 0.5}}, "objects": [)" + objects + R"(],
      "lights": [{"type": "point", "position": [0, 1, 0], "intensity": 1}]})");
  };
  EXPECT_TRUE(listed(quads(kTriangleListLength / 2)));
  EXPECT_FALSE(listed(quads(kTriangleListLength / 2 + 1)));
}

// A horosphere and a sphere beside n quads (2 n triangles) in H3, lit by a sphere light.
Scene horosphere_and_quads(uint32_t n) {
  std::string objects = R"({"type": "horosphere", "material": "m", "direction": [0, -1, 0],
                            "distance": 0.3},
                           {"type": "sphere", "material": "m", "center": [0.3, 0, -0.2],
                            "radius": 0.15})";
  for (uint32_t i = 0; i < n; ++i)
    objects += R"(, {"type": "quad", "material": "m", "corner": [-0.4, -0.2, )" +
               std::to_string(-0.5 - 0.02 * i) + R"(], "edge_u": [0.8, 0, 0],
                  "edge_v": [0, 0.4, 0]})";
  return scene_from_json(R"({"geometry": "hyperbolic",
    "camera": {"position": [0, 0.1, 0.6], "look_at": [0, -0.1, 0]},
    "materials": {"m": {"diffuse": 0.6}, "L": {"emission": 40}},
    "objects": [)" + objects + R"(, {"type": "sphere", "material": "L", "center": [0, 0.3, 0],
                                    "radius": 0.08}],
    "render": {"width": 32, "height": 32, "max_depth": 4}})");
}

// Segments test their cell's shapes one by one under sphere_list's condition (both or
// neither): the cusped spaces' two horospheres and four spheres traverse nothing, and beside
// triangles the acceleration structure holds the triangles alone. (RenderAsWithAllFeatures
// holds the bundled images, ListedShapesBesideTriangles the two mixed cases.)
TEST(PipelineFeatures, SmallCellsOfShapesAreTestedOneByOne) {
  const auto listed = [](const Scene& scene) {
    return feature(scene, &PipelineFeatures::shape_list, "SHAPE_LIST");
  };
  for (const char* name : {"horospheres", "figure-eight-knot", "whitehead-link"}) {
    const Scene scene = bundled_scene(name);
    EXPECT_TRUE(listed(scene)) << name;
    EXPECT_TRUE(scene_features(scene, pack_scene(scene)).sphere_list) << name;
  }
  for (const char* name : {"mirrored-dodecahedron", "cornell-box"})  // no shapes
    EXPECT_FALSE(listed(bundled_scene(name))) << name;
  EXPECT_FALSE(all_features(GeometryKind::Hyperbolic).shape_list);
  // Beside triangles: listed too (traversed), and the structure holds no shape boxes.
  for (uint32_t quads : {kTriangleListLength / 2, kTriangleListLength / 2 + 1}) {
    const Scene scene = horosphere_and_quads(quads);
    const PipelineFeatures f = scene_features(scene, pack_scene(scene));
    EXPECT_TRUE(f.shape_list && f.sphere_list) << quads;
    EXPECT_FALSE(f.traced_shapes() || f.traced_spheres()) << quads;
    EXPECT_EQ(f.triangle_list, quads <= kTriangleListLength / 2);
  }
}

// Listed shapes and spheres beside listed triangles (nothing traversed) and beside traversed
// ones (the structure holding triangles alone) render as the all-features pipeline, which
// traverses every box: same samples, so within the noise of the two.
TEST(ListedShapesBesideTriangles, RenderAsWithAllFeatures) {
  for (uint32_t quads : {kTriangleListLength / 2, kTriangleListLength / 2 + 1}) {
    const Scene scene = horosphere_and_quads(quads);
    Renderer all(device(), scene, BackendKind::RayQuery, PipelineVariant::AllFeatures);
    Renderer listed(device(), scene, BackendKind::RayQuery, PipelineVariant::Specialised);
    ASSERT_TRUE(listed.features().shape_list);
    all.add_samples(64);
    listed.add_samples(64);
    EXPECT_EQ(listed.non_finite_samples(), 0u);
    const double a = luminance_of(mean(listed.image())), b = luminance_of(mean(all.image()));
    EXPECT_GT(b, 0.01) << quads;  // the scene is lit
    const double noise = std::hypot(listed.estimated_error(), all.estimated_error());
    EXPECT_LE(relative_rms_difference(listed.image(), all.image()), 1.5 * noise) << quads;
    EXPECT_NEAR(a, b, 0.03 * b) << quads;
  }
}

// Paths go on past their last bounce (UNSAMPLED_EMISSION) only where light sampling leaves
// some emission out: area lights in a quotient of E3 or H3, whose images past the cutoff it
// does not offer (torus-lamps; the cusps' skies). Not in a space without faces, nor in S3's
// finite quotients, where every image is offered, nor with point lights alone, which BSDF
// sampling never finds. Horospheres that glow are light sources.
TEST(PipelineFeatures, PathsGoPastTheLastBounceOnlyForEmissionLightSamplingLeavesOut) {
  const auto past = [](const Scene& scene) {
    return feature(scene, &PipelineFeatures::unsampled_emission, "UNSAMPLED_EMISSION");
  };
  for (const char* name : {"torus-lamps", "figure-eight-knot", "whitehead-link"})
    EXPECT_TRUE(past(bundled_scene(name))) << name;
  for (const char* name : {"cornell-box", "hyperbolic-lamps", "spherical-lamps", "horospheres",
                           "furnace", "mirrored-dodecahedron", "poincare-sphere"})
    EXPECT_FALSE(past(bundled_scene(name))) << name;
  const Scene lens = scene_from_json(R"({"geometry": "spherical",
    "manifold": {"type": "lens", "p": 5, "q": 2},
    "camera": {"position": [0, 0, 0.3], "look_at": [0, 0, 0]},
    "materials": {"m": {"diffuse": 0.5}, "L": {"emission": 1}},
    "objects": [{"type": "sphere", "material": "m", "center": [0.1, 0, 0], "radius": 0.05},
                {"type": "sphere", "material": "L", "center": [0, 0.1, 0], "radius": 0.03}]})");
  EXPECT_FALSE(past(lens));
  const Scene horospheres = bundled_scene("horospheres");
  const PipelineFeatures f = scene_features(horospheres, pack_scene(horospheres));
  EXPECT_TRUE(f.horosphere_emitters);
}

// Faces in opposite pairs (face 2k + 1 is face 2k's plane turned round, exactly) halve the
// exit search: the dodecahedra and the boxes. The lens space's and the cusped spaces' faces
// are not listed so. (EveryBundledScene/SpecialisedPipelines.
// RenderAsWithAllFeatures/* hold the images: the all-features pipeline searches face by face.)
TEST(PipelineFeatures, FacesInOppositePairsAreSearchedAPairAtATime) {
  const auto opposite = [](const Scene& scene) {
    return feature(scene, &PipelineFeatures::opposite_faces, "OPPOSITE_FACES");
  };
  // And the catalogue's domains symmetric about their centre, whose faces the Dirichlet
  // construction lists apart (build_cells lists them together).
  for (const char* name : {"mirrored-dodecahedron", "seifert-weber", "poincare-sphere",
                           "torus-cornell", "quarter-turn-space", "catalogue/3-torus",
                           "catalogue/hantzsche-wendt", "catalogue/binary-octahedral"})
    EXPECT_TRUE(opposite(bundled_scene(name))) << name;
  for (const char* name : {"catalogue/lens-7-3", "figure-eight-knot", "cornell-box"})
    EXPECT_FALSE(opposite(bundled_scene(name))) << name;
  EXPECT_FALSE(all_features(GeometryKind::Spherical).opposite_faces);
  // A pair that is not exactly opposite, by one float step of one offset or one normal
  // component, is searched face by face.
  const Scene box = bundled_scene("torus-cornell");
  const PackedScene packed = pack_scene(box);
  ASSERT_TRUE(scene_features(box, packed).opposite_faces);
  for (int component : {3, 0}) {
    PackedScene moved = packed;
    float& x = moved.faces[1].plane[component];
    x = std::nextafter(x, 10.0f);
    EXPECT_FALSE(scene_features(box, moved).opposite_faces) << component;
  }
}

TEST(PipelineFeatures, BuffersOnlyForWhatTheSceneHas) {
  // Triangles (12, listed: its one cell's record gives their range), emitters, no spheres, no
  // faces.
  const Scene furnace = bundled_scene("furnace");
  const PipelineFeatures f = scene_features(furnace, pack_scene(furnace));
  for (uint32_t unused : {kSpheresBinding, kSphereRefsBinding, kLightsBinding,
                          kCellFacesBinding, kNormalsBinding})
    EXPECT_FALSE(f.uses_binding(unused)) << unused;
  for (uint32_t used : {kPositionsBinding, kTrianglesBinding, kEmittersBinding, kCellsBinding,
                        kListedBinding})
    EXPECT_TRUE(f.uses_binding(used)) << used;
  // Without the list, no cell record and no listed primitives.
  PipelineFeatures traversed = f;
  traversed.triangle_list = false;
  EXPECT_FALSE(traversed.uses_binding(kCellsBinding));
  EXPECT_FALSE(traversed.uses_binding(kListedBinding));
  // The all-features pipeline traverses: every binding but the list's.
  EXPECT_EQ(all_features(GeometryKind::Euclidean).bindings().size(),
            size_t(kSceneBindingCount) - 1);
  EXPECT_FALSE(all_features(GeometryKind::Euclidean).uses_binding(kListedBinding));
}

}  // namespace
}  // namespace geodesic::test
