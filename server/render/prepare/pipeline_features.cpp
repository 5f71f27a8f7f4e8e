#include "render/prepare/pipeline_features.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/prepare/scene_bindings.h"

namespace geodesic {
namespace {

Mat4 from_float16(const Float16& f) {
  Mat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m.m[r][c] = f[size_t(c * 4 + r)];  // column-major
  return m;
}

// Equal up to float round-off of the packed matrices (entries reach cosh of the domain's
// size in H3, hence the relative part).
bool nearly_equal(const Mat4& a, const Mat4& b) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if (std::abs(a.m[r][c] - b.m[r][c]) > 1e-5 * (1 + std::abs(b.m[r][c]))) return false;
  return true;
}

bool is_translation(const Mat4& g) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 3; ++c)
      if (std::abs(g.m[r][c] - (r == c ? 1.0 : 0.0)) > 1e-6) return false;
  return std::abs(g.m[3][3] - 1) <= 1e-6;
}

// The one kind every face's pairing is, or Isometry when they differ.
Crossing crossing_of(GeometryKind k, const PackedScene& packed) {
  if (packed.faces.empty()) return Crossing::None;
  bool identity = true, translation = k == GeometryKind::Euclidean, reflection = true;
  for (size_t f = 0; f < packed.faces.size(); ++f) {
    const GpuCellFace& face = packed.faces[f];
    const Mat4 g = from_float16(face.pairing);
    const Vec3 normal{face.plane[0], face.plane[1], face.plane[2]};
    identity = identity && nearly_equal(g, Mat4::identity());
    translation = translation && is_translation(g);
    reflection = reflection && face.partner == f &&
                 nearly_equal(g, model::reflection_in_chart_plane(k, normal, face.plane[3]));
  }
  if (identity) return Crossing::ChartChange;
  if (translation) return Crossing::Translation;
  // A mirror reflects in its own face's plane, which the shader knows without the matrix;
  // that needs the face's chart to be the model's (one cell charted about the origin).
  if (reflection && packed.cells.size() == 1) return Crossing::Reflection;
  return Crossing::Isometry;
}

// Whether every cell's faces pair up as opposite planes, face 2k + 1 being face 2k's with its
// normal negated, exactly (in float: the exit search then computes what it did face by face).
bool faces_in_opposite_pairs(const PackedScene& packed) {
  if (packed.faces.empty()) return false;
  return std::all_of(packed.cells.begin(), packed.cells.end(), [&](const GpuCell& cell) {
    if (cell.face_count % 2 != 0) return false;
    for (uint32_t k = 0; k < cell.face_count; k += 2) {
      const auto& a = packed.faces[cell.face_begin + k].plane;
      const auto& b = packed.faces[cell.face_begin + k + 1].plane;
      if (b[0] != -a[0] || b[1] != -a[1] || b[2] != -a[2] || b[3] != a[3]) return false;
    }
    return true;
  });
}

// NAME=v0u,v1u,...: a list of constants for a shader's array.
std::string list_define(const char* name, const std::vector<uint32_t>& values) {
  std::string d = std::string(name) + "=";
  for (uint32_t v : values) d += std::to_string(v) + "u,";
  d.pop_back();
  return d;
}

// NAME=vec4(x,y,z,w),...: a list of vec4 constants, each float written as a float literal
// with the digits that give it back exactly (its sign too: -0.0, not the integer -0).
std::string vec4_list_define(const char* name, const std::vector<Float4>& values) {
  std::string d = std::string(name) + "=";
  char number[32];
  for (const Float4& v : values) {
    d += "vec4(";
    for (size_t k = 0; k < v.size(); ++k) {
      std::snprintf(number, sizeof number, "%.17g", double(v[k]));
      d += number;
      if (std::string(number).find_first_of(".e") == std::string::npos) d += ".0";
      d += k + 1 < v.size() ? "," : "),";
    }
  }
  d.pop_back();
  return d;
}

// The cell record's ranges in cellRecord's order (integrator/chart_ray.glsl).
std::string cell_ranges_define(const GpuCell& c) {
  return list_define("CELL_RANGES",
                     {c.face_begin, c.face_count, c.tube_begin, c.tube_count, c.always_begin,
                      c.sphere_begin, c.sphere_count, c.listed_begin, c.listed_count,
                      c.listed_pairs, c.shape_begin, c.shape_count, c.listed_hull_pairs,
                      c.listed_hull_lone});
}

// The masks of the faces holding each of a one-cell space's tubes held by a pair of faces
// (those before always_begin; tube_culling.h), or none past kBakedTubeFaces of them.
std::vector<uint32_t> tube_face_masks(const PackedScene& packed) {
  const GpuCell& cell = packed.cells.at(0);
  std::vector<uint32_t> masks;
  if (cell.always_begin > kBakedTubeFaces) return masks;
  for (uint32_t i = 0; i < cell.always_begin; ++i) {
    const GpuTube& tube = packed.tubes[cell.tube_begin + i];
    masks.push_back((1u << tube.face_a) | (1u << tube.face_b));
  }
  return masks;
}

// A one-cell space's face planes in its order (all the packed faces are its own).
std::vector<Float4> face_planes_of(const PackedScene& packed) {
  std::vector<Float4> planes;
  for (const GpuCellFace& face : packed.faces)
    planes.push_back({face.plane[0], face.plane[1], face.plane[2], face.plane[3]});
  return planes;
}

// A one-cell space's listed spheres in its list's order: centre, then (radius, 0, 0, 0).
std::vector<Float4> listed_spheres_of(const PackedScene& packed) {
  const GpuCell& cell = packed.cells.at(0);
  std::vector<Float4> spheres;
  for (uint32_t i = 0; i < cell.sphere_count; ++i) {
    const GpuSphereRef& ref = packed.sphere_refs.at(cell.sphere_begin + i);
    const GpuSphere& sphere = packed.spheres.at(ref.sphere);
    spheres.push_back({sphere.center[0], sphere.center[1], sphere.center[2], sphere.center[3]});
    spheres.push_back({sphere.radius, 0.0f, 0.0f, 0.0f});
  }
  return spheres;
}

bool any_emitter_of_kind(const PackedScene& packed, EmitterKind kind) {
  return std::any_of(packed.emitters.begin(), packed.emitters.end(),
                     [&](const GpuEmitter& e) { return e.kind == uint32_t(kind); });
}

}  // namespace

const char* crossing_name(Crossing crossing) {
  switch (crossing) {
    case Crossing::None: return "none";
    case Crossing::ChartChange: return "chart-change";
    case Crossing::Translation: return "translation";
    case Crossing::Reflection: return "reflection";
    case Crossing::Isometry: return "isometry";
  }
  return "?";
}

PipelineFeatures scene_features(const Scene& scene, const PackedScene& packed) {
  PipelineFeatures f;
  f.geometry = scene.geometry;
  f.crossing = crossing_of(scene.geometry, packed);
  f.multiple_charts = std::any_of(packed.cells.begin(), packed.cells.end(), [](const GpuCell& c) {
    return !nearly_equal(from_float16(c.chart_isometry), Mat4::identity());
  });
  f.spheres = !packed.sphere_refs.empty();
  f.triangles = !packed.triangles.empty();
  f.tubes = !packed.tubes.empty();
  f.shapes = !packed.shape_refs.empty();
  const bool listable = f.crossing != Crossing::None || packed.cells.size() == 1;
  const bool analytic_list =
      listable && std::all_of(packed.cells.begin(), packed.cells.end(), [](const GpuCell& c) {
        return c.sphere_count <= kSphereListLength && c.shape_count <= kShapeListLength;
      });
  f.sphere_list = f.spheres && analytic_list;
  f.shape_list = f.shapes && analytic_list;
  f.triangle_list = f.triangles && (analytic_list || !(f.spheres || f.shapes)) && listable &&
                    std::all_of(packed.cell_geometry.begin(), packed.cell_geometry.end(),
                                [](const CellGeometry& g) {
                                  return g.triangle_count <= kTriangleListLength;
                                });
  f.single_cell = packed.cells.size() == 1;
  f.smooth_normals = std::any_of(packed.triangles.begin(), packed.triangles.end(),
                                 [](const GpuTriangle& t) { return t.smooth_normals != 0; });
  f.paper = scene.render.lighting == LightingModel::Paper;
  f.physical = !f.paper;
  f.light_sampling = f.physical && scene.render.light_sampling != LightSampling::Bsdf &&
                     !packed.emitters.empty();
  // BSDF sampling never finds a point light: without light sampling they do nothing.
  f.point_lights = f.paper ? !packed.lights.empty()
                           : f.light_sampling && any_emitter_of_kind(packed, EmitterKind::Point);
  f.sphere_emitters = f.light_sampling && any_emitter_of_kind(packed, EmitterKind::Sphere);
  f.triangle_emitters = f.light_sampling && any_emitter_of_kind(packed, EmitterKind::Triangle);
  f.horosphere_emitters =
      f.light_sampling && any_emitter_of_kind(packed, EmitterKind::Horosphere);
  // A shape that emits but is no light source (a kind light sampling has no code for).
  const bool unsampled_shapes =
      std::any_of(packed.shapes.begin(), packed.shapes.end(), [&](const GpuShape& shape) {
        const Vec3 le = scene.materials[shape.material].emission;
        return shape.emitter == EmitterTable::kNone && std::max({le.x, le.y, le.z}) > 0;
      });
  f.unsampled_emission = f.light_sampling && (!packed.every_light_image || unsampled_shapes);
  f.transmission = f.physical && std::any_of(scene.materials.begin(), scene.materials.end(),
                                             [](const Material& m) {
                                               return std::max({m.transmission.x, m.transmission.y,
                                                                m.transmission.z}) > 0;
                                             });
  f.point_light_count = f.paper ? uint32_t(packed.lights.size()) : 0;
  f.emitter_count = f.light_sampling ? uint32_t(packed.emitters.size()) : 0;
  if (f.light_sampling)
    for (const GpuEmitter& e : packed.emitters)
      f.emitter_images = std::max(f.emitter_images, e.image_count);
  f.max_crossings = f.crossing == Crossing::None ? 0 : uint32_t(scene.manifold.max_crossings);
  if (f.single_cell) f.cell_ranges = packed.cells[0];
  if (f.single_cell && f.tubes && f.crossing != Crossing::None)
    f.tube_faces = tube_face_masks(packed);
  if (f.single_cell && f.crossing != Crossing::None) f.face_planes = face_planes_of(packed);
  if (f.single_cell && f.sphere_list) f.listed_spheres = listed_spheres_of(packed);
  f.internal_walls = std::any_of(packed.faces.begin(), packed.faces.end(),
                                 [](const GpuCellFace& face) { return face.internal != 0; });
  f.opposite_faces = faces_in_opposite_pairs(packed);
  return f;
}

PipelineFeatures all_features(GeometryKind geometry) {
  PipelineFeatures f;
  f.geometry = geometry;
  f.variant = PipelineVariant::AllFeatures;
  f.crossing = Crossing::Isometry;
  f.multiple_charts = f.spheres = f.triangles = f.smooth_normals = f.internal_walls = true;
  f.tubes = f.shapes = true;
  f.paper = f.physical = f.point_lights = f.light_sampling = true;
  f.sphere_emitters = f.triangle_emitters = f.transmission = true;
  f.horosphere_emitters = geometry == GeometryKind::Hyperbolic;  // horospheres exist in H3 alone
  f.unsampled_emission = true;
  return f;
}

std::string geometry_define(GeometryKind geometry) {
  std::string define = std::string("GEOMETRY_") + geometry_name(geometry);
  std::transform(define.begin(), define.end(), define.begin(),
                 [](unsigned char c) { return char(std::toupper(c)); });
  return define;
}

std::vector<std::string> PipelineFeatures::defines() const {
  std::vector<std::string> d{geometry_define(geometry)};
  auto flag = [&](bool on, const char* name) {
    if (on) d.emplace_back(name);
  };
  static const char* const kPairing[] = {"", "PAIRING_CHART_CHANGE", "PAIRING_TRANSLATION",
                                         "PAIRING_REFLECTION", "PAIRING_ISOMETRY"};
  flag(crossing != Crossing::None, "CELL_CROSSING");
  flag(crossing != Crossing::None, kPairing[int(crossing)]);
  flag(multiple_charts, "MULTIPLE_CHARTS");
  flag(spheres, "HAS_SPHERES");
  flag(triangles, "HAS_TRIANGLES");
  flag(tubes && crossing != Crossing::None, "HAS_TUBES");
  flag(shapes, "HAS_SHAPES");
  flag(sphere_list, "SPHERE_LIST");
  flag(shape_list, "SHAPE_LIST");
  flag(triangle_list, "TRIANGLE_LIST");
  flag(single_cell, "SINGLE_CELL");
  flag(smooth_normals, "HAS_SMOOTH_NORMALS");
  flag(paper, "LIGHTING_PAPER");
  flag(physical, "LIGHTING_PHYSICAL");
  flag(point_lights, "HAS_POINT_LIGHTS");
  flag(light_sampling, "LIGHT_SAMPLING");
  flag(sphere_emitters, "HAS_SPHERE_EMITTERS");
  flag(triangle_emitters, "HAS_TRIANGLE_EMITTERS");
  flag(horosphere_emitters, "HAS_HOROSPHERE_EMITTERS");
  flag(unsampled_emission, "UNSAMPLED_EMISSION");
  flag(transmission, "HAS_TRANSMISSION");
  flag(variant == PipelineVariant::Specialised && primitive_culling && traced_boxes() != triangles,
       "CULL_PRIMITIVES");
  flag(shared_cell_masks, "SHARED_CELL_MASKS");
  flag(internal_walls, "INTERNAL_WALLS");
  flag(opposite_faces, "OPPOSITE_FACES");
  flag(reads_cells(), "READS_CELLS");
  flag(traced_boxes(), "TRACED_BOXES");
  if (variant == PipelineVariant::Specialised) {
    d.push_back("POINT_LIGHT_COUNT=" + std::to_string(point_light_count) + "u");
    d.push_back("EMITTER_COUNT=" + std::to_string(emitter_count) + "u");
    if (light_sampling)
      d.push_back("EMITTER_IMAGES=" + std::to_string(std::max(emitter_images, 1u)) + "u");
    d.push_back("MAX_CROSSINGS=" + std::to_string(max_crossings) + "u");
    if (cell_ranges) d.push_back(cell_ranges_define(*cell_ranges));
    if (!face_planes.empty()) d.push_back(vec4_list_define("FACE_PLANES", face_planes));
    if (!listed_spheres.empty())
      d.push_back(vec4_list_define("LISTED_SPHERE_DATA", listed_spheres));
    for (size_t begin = 0; begin < tube_faces.size(); begin += kTubeFacesPerDefine) {
      const size_t end = std::min<size_t>(tube_faces.size(), begin + kTubeFacesPerDefine);
      const std::string name = "TUBE_FACES_" + std::to_string(begin / kTubeFacesPerDefine);
      d.push_back(list_define(name.c_str(), std::vector<uint32_t>(tube_faces.begin() + begin,
                                                                   tube_faces.begin() + end)));
    }
  }
  return d;
}

std::vector<uint32_t> PipelineFeatures::bindings() const {
  std::vector<uint32_t> b{kSceneBinding, kAccumulationBinding, kFrameBinding, kMaterialsBinding,
                          kRayCountsBinding, kDiagnosticsBinding};
  auto add = [&](bool on, std::initializer_list<uint32_t> list) {
    if (on) b.insert(b.end(), list);
  };
  add(spheres, {kSpheresBinding, kSphereRefsBinding});
  add(triangles, {kPositionsBinding, kIndicesBinding, kTrianglesBinding});
  add(smooth_normals, {kNormalsBinding});
  add(tubes && crossing != Crossing::None, {kTubesBinding});
  add(shapes, {kShapesBinding, kShapeRefsBinding});
  add(triangle_list, {kListedBinding});
  add(paper && point_lights, {kLightsBinding});
  add(reads_cells(), {kCellsBinding});
  add(crossing != Crossing::None, {kCellFacesBinding});
  add(light_sampling, {kEmittersBinding, kLightImagesBinding});
  std::sort(b.begin(), b.end());
  return b;
}

bool PipelineFeatures::uses_binding(uint32_t binding) const {
  const auto b = bindings();
  return std::find(b.begin(), b.end(), binding) != b.end();
}

std::string PipelineFeatures::summary() const {
  if (variant == PipelineVariant::AllFeatures)
    return std::string(geometry_name(geometry)) + " all-features";
  std::string s = geometry_name(geometry);
  auto word = [&](bool on, const std::string& w) {
    if (on) s += " " + w;
  };
  word(crossing != Crossing::None, crossing_name(crossing));
  word(multiple_charts, "charts");
  word(spheres, "spheres");
  word(triangles, "triangles");
  word(tubes, "tubes");
  word(shapes, "shapes");
  word(sphere_list, "sphere-list");
  word(shape_list, "shape-list");
  word(triangle_list, "triangle-list");
  word(single_cell, "one-cell");
  word(smooth_normals, "smooth-normals");
  word(true, paper ? "paper" : "physical");
  word(point_lights, paper ? "point-lights(" + std::to_string(point_light_count) + ")"
                            : std::string("point-lights"));
  word(light_sampling, "mis(" + std::to_string(emitter_count) + ")");
  word(sphere_emitters, "sphere-lights");
  word(triangle_emitters, "triangle-lights");
  word(horosphere_emitters, "horosphere-lights");
  word(unsampled_emission, "past-last-bounce");
  word(transmission, "refraction");
  word(shared_cell_masks, "shared-cell-masks");
  word(internal_walls, "internal-walls");
  word(opposite_faces, "opposite-faces");
  return s;
}

}  // namespace geodesic
