// Scene document → Scene: validates every field, then resolves material names, primitives
// and mesh files into the renderer's flat arrays. The format: docs/scene-format.md.
#include "scene/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "scene/json_path.h"
#include "scene/manifold_loader.h"
#include "scene/render_settings_loader.h"
#include "scene/scene_isometry.h"
#include "scene/shape.h"
#include "scene/mesh_loader.h"

namespace geodesic {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// Sines, relative distances and relative areas below this count as zero: far above double
// rounding of decimal input, far below anything a scene author means on purpose.
constexpr double kDegenerate = 1e-6;

// Far beyond any real scene (the bundled ones have at most 40 objects), and checked before an
// element is read: a document of a million objects is refused rather than built, and a
// polygon's convexity check (quadratic in its vertices) stays instant.
constexpr std::size_t kMaxObjects = 10000, kMaxLights = 1000, kMaxPolygonVertices = 1000;

// Requires an array of [min_size, max_size] elements; returns its size.
std::size_t expect_list(const JsonNode& node, std::size_t min_size, std::size_t max_size,
                        const std::string& what) {
  const std::size_t n = node.expect_array(min_size, what);
  if (n > max_size)
    node.fail("has " + std::to_string(n) + " elements; at most " + std::to_string(max_size) +
              " are allowed");
  return n;
}

Vec3 rotate(const Mat4& r, const Vec3& v) { return (r * Vec4(v, 0)).xyz(); }

Mat4 frame(const Vec3& x, const Vec3& y, const Vec3& z, const Vec3& origin) {
  Mat4 m = Mat4::identity();
  const Vec3 columns[4] = {x, y, z, origin};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) m.m[r][c] = columns[c][r];
  return m;
}

// R = Ry(yaw) · Rx(pitch) · Rroll, angles in degrees. Yaw turns about +y (positive turns
// -z towards -x), pitch about +x (positive raises -z towards +y), roll about the view axis
// -z (positive lowers +x towards -y).
Mat4 rotation_matrix(double yaw, double pitch, double roll) {
  const double k = std::numbers::pi / 180;
  const double cy = std::cos(yaw * k), sy = std::sin(yaw * k);
  const double cp = std::cos(pitch * k), sp = std::sin(pitch * k);
  const double cr = std::cos(roll * k), sr = std::sin(roll * k);
  const Mat4 ry = frame({cy, 0, -sy}, {0, 1, 0}, {sy, 0, cy}, {});
  const Mat4 rx = frame({1, 0, 0}, {0, cp, sp}, {0, -sp, cp}, {});
  const Mat4 rroll = frame({cr, -sr, 0}, {sr, cr, 0}, {0, 0, 1}, {});
  return ry * rx * rroll;
}

Mat4 read_rotation(const JsonNode& node) {
  node.expect_object({"yaw", "pitch", "roll"});
  auto angle = [&](const char* key) {
    const auto child = node.find(key);
    return child ? read_number(*child) : 0.0;
  };
  return rotation_matrix(angle("yaw"), angle("pitch"), angle("roll"));
}

// The camera is an isometry: the transvection from the origin to its position, after a
// rotation at the origin that turns -z to the view direction (transported back there).
Camera read_camera(const JsonNode& node, GeometryKind kind) {
  node.expect_object({"position", "look_at", "up", "rotation", "fov_y", "pose"});
  Camera camera;
  if (const auto fov = node.find("fov_y")) {
    camera.fov_y_degrees = read_number(*fov);
    if (camera.fov_y_degrees <= 0 || camera.fov_y_degrees >= 180) fov->fail("must be in (0, 180)");
  }
  // The camera given directly as an isometry of the model (as the daemon reports it).
  if (const auto pose = node.find("pose")) {
    for (const char* other : {"position", "look_at", "up", "rotation"})
      if (node.find(other)) node.fail(std::string("give either \"pose\" or \"") + other + "\", not both");
    camera.pose = read_matrix(*pose);
    const double error = model::relative_isometry_error(kind, camera.pose);
    if (!(error < 1e-6))
      pose->fail(std::string("not an isometry of ") + geometry_name(kind) + " space (error " +
                 std::to_string(error) + " > 1e-06)");
    camera.pose = model::reorthonormalize(kind, camera.pose);
    return camera;
  }
  const Vec3 position = read_vec3(node.at("position"));
  const Mat4 to_position = model::translation(kind, position);
  const auto look_at = node.find("look_at");
  const auto up = node.find("up");
  const auto rotation = node.find("rotation");
  if (look_at && rotation) node.fail("give either \"look_at\" or \"rotation\", not both");
  if (up && !look_at) up->fail("only allowed together with \"look_at\"");

  if (look_at) {
    const Vec3 target = read_vec3(*look_at);
    if (length(target - position) <= kDegenerate * std::max(1.0, length(position)))
      look_at->fail("must differ from camera.position");
    const Vec4 p = model::exp_origin(kind, position);
    const Vec4 towards = model::geodesic_direction(kind, p, model::exp_origin(kind, target));
    const Vec3 view = (model::translation_from(kind, p) * towards).xyz();
    if (length(view) <= kDegenerate) look_at->fail("is the antipode of camera.position");
    const Vec3 up_hint = up ? read_vec3(*up) : Vec3(0, 1, 0);
    if (length(up_hint) == 0) up->fail("must be non-zero");
    const Vec3 forward = normalize(view);
    const Vec3 side = cross(forward, normalize(up_hint));
    if (length(side) <= kDegenerate)
      node.fail_field("up", "must not be parallel to the view direction");
    const Vec3 right = normalize(side);
    camera.pose = to_position * frame(right, cross(right, forward), -forward, {});
  } else {
    camera.pose = to_position * (rotation ? read_rotation(*rotation) : Mat4::identity());
  }
  return camera;
}

std::vector<Material> read_materials(const JsonNode& node) {
  if (!node.value().is_object()) node.fail("must be an object mapping names to materials");
  std::vector<Material> materials;
  for (const auto& item : node.value().items()) {
    const JsonNode m = node.at(item.key());
    m.expect_object({"ambient", "diffuse", "specular", "shininess", "mirror", "transmission",
                     "ior", "emission"});
    auto rgb = [&](const char* key) {
      const auto child = m.find(key);
      return child ? read_rgb(*child) : Vec3();
    };
    Material material{.name = item.key(),
                      .ambient = rgb("ambient"),
                      .diffuse = rgb("diffuse"),
                      .specular = rgb("specular"),
                      .mirror = rgb("mirror"),
                      .transmission = rgb("transmission"),
                      .emission = rgb("emission")};
    if (const auto shininess = m.find("shininess"))
      material.shininess = read_non_negative(*shininess);
    if (const auto ior = m.find("ior")) {
      material.ior = read_positive(*ior);
      if (material.ior > 10) ior->fail("must be <= 10 (an index of refraction)");
    }
    // The lobes share the light a surface reflects or transmits: together they may not
    // create energy.
    for (int c = 0; c < 3; ++c) {
      const double sum = material.diffuse[c] + material.specular[c] + material.mirror[c] +
                         material.transmission[c];
      if (sum > 1 + 1e-9)
        m.fail("diffuse + specular + mirror + transmission is " + std::to_string(sum) +
               " in channel " + "rgb"[c] + "; it must be <= 1 (energy conservation)");
    }
    materials.push_back(material);
  }
  return materials;
}

// Two counter-clockwise triangles corner, corner+u, corner+u+v, corner+v: the front side
// faces cross(u, v).
void append_quad(TriangleMesh& mesh, const Vec3& corner, const Vec3& u, const Vec3& v) {
  const auto base = static_cast<uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {corner, corner + u, corner + u + v, corner + v});
  mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

TriangleMesh read_quad(const JsonNode& node) {
  const Vec3 corner = read_vec3(node.at("corner"));
  const Vec3 u = read_vec3(node.at("edge_u"));
  const Vec3 v = read_vec3(node.at("edge_v"));
  if (length(cross(u, v)) <= kDegenerate * length(u) * length(v))
    node.fail("degenerate quad: edge_u and edge_v must be non-zero and not parallel");
  TriangleMesh mesh;
  append_quad(mesh, corner, u, v);
  return mesh;
}

// A planar, strictly convex polygon as a triangle fan; the vertex order sets the front side.
TriangleMesh read_polygon(const JsonNode& node) {
  const JsonNode list = node.at("vertices");
  const std::size_t n =
      expect_list(list, 3, kMaxPolygonVertices, "an array of at least 3 points");
  std::vector<Vec3> vertices;
  for (std::size_t i = 0; i < n; ++i) vertices.push_back(read_vec3(list[i]));

  // Newell's normal (twice the area vector), taken about vertex 0 to avoid cancellation far
  // from the origin: exact for planar polygons, a best fit otherwise.
  Vec3 centroid, newell;
  double size = 0;
  for (std::size_t i = 0; i < n; ++i) {
    centroid += vertices[i] / static_cast<double>(n);
    newell += cross(vertices[i] - vertices[0], vertices[(i + 1) % n] - vertices[0]);
    size = std::max(size, length(vertices[i] - vertices[0]));
  }
  if (length(newell) <= kDegenerate * size * size) list.fail("degenerate polygon: it has no area");
  const Vec3 normal = normalize(newell);
  for (const Vec3& vertex : vertices)
    if (std::abs(dot(vertex - centroid, normal)) > kDegenerate * size)
      list.fail("polygon is not planar");
  // Strictly convex iff every vertex lies strictly left of every edge it is not on.
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a = vertices[i], b = vertices[(i + 1) % n];
    for (std::size_t j = 0; j < n; ++j)
      if (j != i && j != (i + 1) % n &&
          dot(cross(b - a, vertices[j] - a), normal) <= kDegenerate * size * size)
        list.fail("polygon must be strictly convex (no reflex, repeated or collinear vertices)");
  }
  TriangleMesh mesh;
  mesh.positions = vertices;
  for (uint32_t i = 1; i + 1 < n; ++i) mesh.indices.insert(mesh.indices.end(), {0, i, i + 1});
  return mesh;
}

// An axis-aligned box, optionally rotated about its centre: two triangles per listed face,
// front sides facing outwards.
TriangleMesh read_box(const JsonNode& node) {
  const Vec3 lo = read_vec3(node.at("min"));
  const Vec3 hi = read_vec3(node.at("max"));
  const JsonNode max_node = node.at("max");
  for (std::size_t c = 0; c < 3; ++c)
    if (hi[c] <= lo[c]) max_node[c].fail("must be greater than min[" + std::to_string(c) + "]");
  const auto rotation_node = node.find("rotation");
  const Mat4 rotation = rotation_node ? read_rotation(*rotation_node) : Mat4::identity();

  const char* names[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  bool wanted[6] = {true, true, true, true, true, true};
  if (const auto faces = node.find("faces")) {
    const std::size_t n = faces->expect_array(1, "a non-empty array of face names");
    std::fill(std::begin(wanted), std::end(wanted), false);
    for (std::size_t i = 0; i < n; ++i) {
      const std::string name = read_string((*faces)[i]);
      const auto it = std::find(std::begin(names), std::end(names), name);
      if (it == std::end(names))
        (*faces)[i].fail(R"(must be one of "+x", "-x", "+y", "-y", "+z", "-z")");
      bool& face = wanted[it - std::begin(names)];
      if (face) (*faces)[i].fail("face \"" + name + "\" is listed twice");
      face = true;
    }
  }
  const Vec3 d = hi - lo, centre = (lo + hi) / 2;
  const Vec3 dx(d.x, 0, 0), dy(0, d.y, 0), dz(0, 0, d.z);
  // Per face: a corner and edges u, v with cross(u, v) pointing out of the box.
  const Vec3 sides[6][3] = {{{hi.x, lo.y, lo.z}, dy, dz}, {lo, dz, dy},
                            {{lo.x, hi.y, lo.z}, dz, dx}, {lo, dx, dz},
                            {{lo.x, lo.y, hi.z}, dx, dy}, {lo, dy, dx}};
  TriangleMesh mesh;
  for (int f = 0; f < 6; ++f)
    if (wanted[f])
      append_quad(mesh, centre + rotate(rotation, sides[f][0] - centre),
                  rotate(rotation, sides[f][1]), rotate(rotation, sides[f][2]));
  return mesh;
}

TriangleMesh read_mesh(const JsonNode& node, const DocumentFiles& files) {
  const JsonNode file = node.at("file");
  const fs::path path = files.resolve(file);
  std::error_code error;
  if (!fs::is_regular_file(path, error)) file.fail("file not found: \"" + path.string() + "\"");

  Vec3 scale(1, 1, 1);
  if (const auto s = node.find("scale")) {
    if (s->value().is_array()) {
      if (s->value().size() != 3) s->fail("must be a number or an array of 3 numbers");
      scale = {read_positive((*s)[0]), read_positive((*s)[1]), read_positive((*s)[2])};
    } else {
      const double uniform = read_positive(*s);
      scale = {uniform, uniform, uniform};
    }
  }
  const auto position = node.find("position");
  const auto rotation = node.find("rotation");
  const Vec3 translation = position ? read_vec3(*position) : Vec3();
  const Mat4 turn = rotation ? read_rotation(*rotation) : Mat4::identity();

  TriangleMesh mesh;
  try {
    mesh = load_mesh_file(path);
  } catch (const std::exception& e) {
    file.fail("cannot load \"" + path.string() + "\": " + e.what());
  }
  transform_mesh(mesh, scale, turn, translation);
  return mesh;
}

struct MaterialTable {
  std::map<std::string, uint32_t> index;

  uint32_t lookup(const JsonNode& node) const {
    const std::string name = read_string(node);
    const auto it = index.find(name);
    if (it == index.end()) node.fail("unknown material \"" + name + "\"");
    return it->second;
  }
};

void read_object(const JsonNode& node, const MaterialTable& materials, const DocumentFiles& files,
                 Scene& scene) {
  if (!node.value().is_object()) node.fail("must be an object");
  const JsonNode type_node = node.at("type");
  const std::string type = read_string(type_node);
  if (type == "sphere")
    node.expect_object({"type", "material", "center", "radius"});
  else if (type == "quad")
    node.expect_object({"type", "material", "corner", "edge_u", "edge_v"});
  else if (type == "polygon")
    node.expect_object({"type", "material", "vertices"});
  else if (type == "box")
    node.expect_object({"type", "material", "min", "max", "rotation", "faces"});
  else if (type == "mesh")
    node.expect_object({"type", "material", "file", "position", "scale", "rotation"});
  else if (type == "domain_edges")
    node.expect_object({"type", "material", "radius"});
  else if (const ShapeKind* shape = find_shape_kind(type)) {
    node.expect_object(shape->fields);
    const uint32_t material = materials.lookup(node.at("material"));
    scene.shapes.push_back({shape->id, shape->read(node, scene.geometry), material});
    return;
  } else {
    std::vector<std::string> known{"sphere", "quad", "polygon", "box", "mesh", "domain_edges"};
    for (const ShapeKind* kind : shape_kinds()) known.emplace_back(kind->type);
    std::string list;
    for (size_t i = 0; i < known.size(); ++i)
      list += (i == 0 ? "" : i + 1 == known.size() ? " or " : ", ") + ('"' + known[i] + '"');
    type_node.fail("unknown object type \"" + type + "\" (expected " + list + ")");
  }
  const uint32_t material = materials.lookup(node.at("material"));

  if (type == "sphere") {
    const double radius = read_positive(node.at("radius"));
    if (scene.geometry == GeometryKind::Spherical && radius >= std::numbers::pi)
      node.at("radius").fail("must be < pi in spherical space");
    scene.spheres.push_back({read_vec3(node.at("center")), radius, material});
    return;
  }
  if (type == "domain_edges") {
    if (scene.manifold.faces.empty()) node.fail("\"domain_edges\" needs a manifold");
    const Vec3 emission = scene.materials[material].emission;
    if (std::max({emission.x, emission.y, emission.z}) > 0)
      node.at("material").fail("must not emit: edge tubes are not light sources");
    const double radius = read_positive(node.at("radius"));
    try {
      const auto tubes = make_edge_tubes(scene.geometry, scene.manifold.domain, radius, material);
      scene.tubes.insert(scene.tubes.end(), tubes.begin(), tubes.end());
    } catch (const SceneError& e) {
      node.at("radius").fail(e.what());
    }
    return;
  }
  TriangleMesh mesh = type == "quad"      ? read_quad(node)
                      : type == "polygon" ? read_polygon(node)
                      : type == "box"     ? read_box(node)
                                          : read_mesh(node, files);
  mesh.material = material;
  scene.meshes.push_back(std::move(mesh));
}

PointLight read_light(const JsonNode& node) {
  if (!node.value().is_object()) node.fail("must be an object");
  const JsonNode type = node.at("type");
  const std::string name = read_string(type);
  if (name != "point") type.fail("unknown light type \"" + name + "\" (expected \"point\")");
  node.expect_object({"type", "position", "intensity"});
  return {read_vec3(node.at("position")), read_rgb(node.at("intensity"))};
}

GeometryKind read_geometry(const JsonNode& node) {
  const std::string geometry = read_string(node);
  for (GeometryKind kind :
       {GeometryKind::Euclidean, GeometryKind::Hyperbolic, GeometryKind::Spherical})
    if (geometry == geometry_name(kind)) return kind;
  node.fail("unknown geometry \"" + geometry +
            "\" (expected \"euclidean\", \"hyperbolic\" or \"spherical\")");
}

// Signed geodesic distance from the model point q to a face plane (positive outside).
double distance_outside(GeometryKind kind, const Vec4& q, const DomainFace& face) {
  const double n_x = dot(face.normal, q.xyz());
  switch (kind) {
    case GeometryKind::Hyperbolic:
      return std::asinh((n_x - face.delta * q.w) / std::sqrt(1 - face.delta * face.delta));
    case GeometryKind::Spherical:
      return std::asin(std::clamp((n_x - face.delta * q.w) / std::sqrt(1 + face.delta * face.delta),
                                  -1.0, 1.0));
    default:
      return n_x - face.delta;
  }
}

// Scene objects live in the fundamental domain: the part of an object outside it would never
// be seen (rays only ever travel inside the domain). Edge tubes straddle faces on purpose.
void check_inside_domain(const JsonNode& objects, const Scene& scene,
                         const std::vector<int>& object_of_sphere,
                         const std::vector<int>& object_of_mesh) {
  const GeometryKind k = scene.geometry;
  constexpr double kSlack = 1e-9;
  for (size_t i = 0; i < scene.spheres.size(); ++i) {
    const Vec4 c = model::exp_origin(k, scene.spheres[i].center);
    for (size_t f = 0; f < scene.manifold.faces.size(); ++f)
      if (distance_outside(k, c, scene.manifold.faces[f]) + scene.spheres[i].radius > kSlack)
        objects[object_of_sphere[i]].fail("must lie inside the fundamental domain (it crosses face " +
                                          std::to_string(f) + ")");
  }
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    for (const Vec3& x : scene.meshes[m].positions)
      for (size_t f = 0; f < scene.manifold.faces.size(); ++f)
        if (distance_outside(k, model::exp_origin(k, x), scene.manifold.faces[f]) > 1e-6)
          objects[object_of_mesh[m]].fail(
              "must lie inside the fundamental domain (a vertex is beyond face " +
              std::to_string(f) + ")");
  }
}

// The document's content written about a frame of its own, moved to where the frame lies:
// every position and the camera (scene/scene_isometry.h, precise 20 units out in H3).
Scene placed(const JsonNode& node, Scene scene) {
  node.expect_object({"position", "rotation"});
  if (!scene.manifold.faces.empty())
    node.fail("only in a space without a quotient (a quotient's content lies in its domain)");
  const GeometryKind k = scene.geometry;
  const auto rotation = node.find("rotation");
  const Mat4 g = model::translation(k, read_vec3(node.at("position"))) *
                 (rotation ? read_rotation(*rotation) : Mat4::identity());
  return moved_scene(std::move(scene), g);
}

}  // namespace

Scene parse_scene(const Json& doc, const DocumentFiles& files) {
  const JsonNode root(doc, "");
  root.expect_object(
      {"name", "geometry", "manifold", "placement", "camera", "materials", "objects", "lights",
       "render"});
  Scene scene;
  if (const auto name = root.find("name")) scene.name = read_string(*name);
  scene.geometry = read_geometry(root.at("geometry"));
  if (const auto manifold = root.find("manifold"))
    scene.manifold = read_manifold(*manifold, scene.geometry, files);
  scene.camera = read_camera(root.at("camera"), scene.geometry);

  MaterialTable table;
  if (const auto materials = root.find("materials")) scene.materials = read_materials(*materials);
  for (uint32_t i = 0; i < scene.materials.size(); ++i) table.index[scene.materials[i].name] = i;

  if (const auto objects = root.find("objects")) {
    const std::size_t n = expect_list(*objects, 0, kMaxObjects, "an array of objects");
    std::vector<int> object_of_sphere, object_of_mesh;
    for (std::size_t i = 0; i < n; ++i) {
      read_object((*objects)[i], table, files, scene);
      object_of_sphere.resize(scene.spheres.size(), int(i));
      object_of_mesh.resize(scene.meshes.size(), int(i));
    }
    if (!scene.manifold.faces.empty())
      check_inside_domain(*objects, scene, object_of_sphere, object_of_mesh);
  }
  if (const auto lights = root.find("lights")) {
    const std::size_t n = expect_list(*lights, 0, kMaxLights, "an array of lights");
    for (std::size_t i = 0; i < n; ++i) scene.lights.push_back(read_light((*lights)[i]));
  }
  if (const auto render = root.find("render")) scene.render = read_render(*render);
  if (const auto placement = root.find("placement")) return placed(*placement, std::move(scene));
  return scene;
}

Scene load_scene_file(const fs::path& path) { return load_scene_file(path, path.parent_path()); }

Scene load_scene_file(const fs::path& path, const DocumentFiles& files) {
  std::error_code error;
  std::ifstream in(path);
  if (!fs::is_regular_file(path, error) || !in)
    throw SceneError(path.string() + ": cannot open file (missing or not a regular file)");
  Json doc;
  try {
    doc = Json::parse(in);
  } catch (const Json::exception& e) {
    // Syntax errors (with line and column) and number overflow (e.g. 1e400). Drop
    // nlohmann's "[json.exception.parse_error.101] " tag.
    const std::string what = e.what();
    const auto tag_end = what.find("] ");
    throw SceneError(path.string() + ": invalid JSON: " +
                     (tag_end == std::string::npos ? what : what.substr(tag_end + 2)));
  }
  return parse_scene(doc, files);
}

}  // namespace geodesic
