// What a scene's pipeline needs, decided from the packed scene: the model geometry, the kind
// of face crossing, the primitive types, the lighting model and its lights and lobes. Each
// feature becomes a preprocessor define of the shaders (docs/pipelines.md lists them), so a
// scene's pipeline carries only its own code; the all-features variant is the baseline the
// benchmarks and tests compare against.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render/prepare/packed_scene.h"
#include "scene/scene.h"

namespace geodesic {

// How a ray leaving a cell through a face goes on.
enum class Crossing {
  None,         // no faces: one cell, the whole space in one chart
  ChartChange,  // S3's atlas: the point stays, only the chart changes
  Translation,  // E3 quotients whose pairings are all translations
  Reflection,   // every face mirrors the cell onto itself
  Isometry,     // general pairing isometries
};

enum class PipelineVariant { Specialised, AllFeatures };

// The most spheres a cell may hold for its segments to test them one by one (sphere_list).
constexpr uint32_t kSphereListLength = 8;
// The most shapes a cell may hold for its segments to test them one by one (shape_list).
constexpr uint32_t kShapeListLength = 8;
// The most triangles a cell may hold for its segments to test them one by one (triangle_list).
constexpr uint32_t kTriangleListLength = 32;
// The tube masks in one define (TUBE_FACES_k), an unrolled block of nearestTube's each.
constexpr uint32_t kTubeFacesPerDefine = 32;
// The most edge tubes held by a pair of faces whose masks a one-cell space bakes in
// (tube_faces): as many defines as nearestTube has blocks (TUBE_FACES_0 ... TUBE_FACES_3).
constexpr uint32_t kBakedTubeFaces = 4 * kTubeFacesPerDefine;

struct PipelineFeatures {
  GeometryKind geometry = GeometryKind::Euclidean;
  PipelineVariant variant = PipelineVariant::Specialised;
  Crossing crossing = Crossing::None;
  bool multiple_charts = false;  // cells charted about different points (S3's atlas)
  bool spheres = false, triangles = false, smooth_normals = false;
  bool tubes = false;  // the domain's edge tubes, intersected analytically
  bool shapes = false;  // analytic shapes (scene/shape.h), on boxes like spheres
  // Cells holding at most kSphereListLength spheres and kShapeListLength shapes each, in a
  // space with faces or of one cell: a chart segment tests its cell's spheres one by one
  // (SPHERE_LIST), and its shapes (SHAPE_LIST), and the acceleration structure holds only
  // triangles, as a traversal's setup, or a box instance's, costs more than a few analytic
  // tests (on lavapipe 7 % of a path in the mirrored dodecahedron; the cusped spaces' two
  // horospheres and four spheres, docs/pipelines.md). Both or neither: a traversal for the
  // boxes of one kind would find the other's too. Specialised pipelines only.
  bool sphere_list = false;
  bool shape_list = false;
  // Cells holding at most kTriangleListLength triangles each, their spheres and shapes listed
  // (or none), under sphere_list's condition on the space: a segment tests its cell's
  // triangles one by one too (those of a segment that meets their box) and nothing is
  // traversed. On lavapipe a ray query costs about what 30-40 triangle tests do
  // (docs/pipelines.md: the Cornell box's 16 triangles 1.12-1.33x the paths/s, 64 half).
  // Specialised pipelines only.
  bool triangle_list = false;
  // A space of one cell (every quotient but S3's atlas, E3 and H3 without a quotient): the
  // cell's record and its faces are read at indices the same for every ray (SINGLE_CELL), and
  // so are its listed triangles and spheres, which a CPU device loads once for a whole SIMD
  // group instead of gathering them lane by lane (on lavapipe 7-18 % of the quotients' paths/s,
  // 10 % of the Cornell box's CPU seconds). Specialised pipelines only.
  bool single_cell = false;
  bool paper = false, physical = false;  // lighting models compiled in
  bool point_lights = false;             // point-light code (eq. 2.2 or point emitters)
  bool light_sampling = false;           // next-event estimation and MIS
  bool sphere_emitters = false, triangle_emitters = false;
  bool horosphere_emitters = false;      // a cusp's emissive horospheres (H3, with shapes)
  // Emission that light sampling cannot offer: images of area lights past the cutoff, or an
  // emissive shape of a kind that is no light source. With NEE the path then goes on past its
  // last bounce to find it by BSDF sampling (weight 1 where light sampling could not have
  // produced it, 0 elsewhere), at the cost of one more geodesic; without it that light would
  // be lost at the last bounce.
  bool unsampled_emission = false;
  bool transmission = false;             // the dielectric lobe
  // The device can skip a primitive type during traversal (SKIP_AABBS / SKIP_TRIANGLES): set
  // by the caller, used where the scene lacks boxes (spheres, shapes) or triangles.
  bool primitive_culling = false;
  // More than eight cells: ray masks select cell % 8, and candidates of the other cells
  // sharing the bit are rejected by cell (triangles then need any-hit checks). A requirement
  // of the scene, in both variants.
  bool shared_cell_masks = false;
  // Walls between the pieces of a domain charted apart: crossing one starts no new copy of the
  // domain, so it does not count against MAX_CROSSINGS (MAX_WALL_CROSSINGS bounds them).
  bool internal_walls = false;
  // Every cell's faces come in opposite pairs, listed one after the other: face 2k + 1's plane
  // is face 2k's with the normal negated (N . X = w and -N . X = w), as in the dodecahedra, the
  // boxes and the flat and spherical spaces of the catalogue whose domains are symmetric about
  // their centre (build_cells lists such faces together, render/prepare/cells.h). A ray moves
  // towards at most one face of a pair, and the pair's two heights differ only in the sign of
  // one dot product, so the search for the exit face (exitFace) reads half the planes and
  // divides half as often (OPPOSITE_FACES; 4-10 % of those spaces' time on lavapipe,
  // docs/quotient-speed.md). Specialised pipelines only.
  bool opposite_faces = false;
  // Baked constants (specialised only): loop bounds the compiler can unroll or drop.
  uint32_t point_light_count = 0, emitter_count = 0, max_crossings = 0;
  uint32_t emitter_images = 0;  // the most images of one emitter (light sampling's weights)
  // A space of one cell's record (set with SINGLE_CELL): the index ranges in it (its
  // faces, tubes, listed spheres, shapes and triangles) baked in as constants (CELL_RANGES,
  // cellRecord in integrator/chart_ray.glsl), so that the loops over them have constant
  // bounds and indices, which the compiler unrolls, loading each plane or sphere once for the
  // SIMD group (on lavapipe 13-20 % of the one-cell quotients' CPU seconds, docs/quotient-speed.md).
  std::optional<GpuCell> cell_ranges;
  // With cell_ranges and edge tubes: for each tube that a pair of the cell's faces holds (the
  // first always_begin, at most kBakedTubeFaces), the mask of its two faces (TUBE_FACES_k
  // holds kTubeFacesPerDefine of them from k times that). A segment finds the tubes to test by
  // comparing the faces it comes near with each mask, in a loop of constants, where reading
  // the pairs from the face records took a loop per lane (with the near faces' pass of
  // constants, edge_tube.glsl, 14-33 % of the one-cell quotients' CPU seconds on lavapipe,
  // docs/quotient-speed.md). Specialised pipelines only.
  std::vector<uint32_t> tube_faces;
  // With cell_ranges and faces: the plane of each of the cell's faces (FACE_PLANES, as vec4
  // constants in its order), read by the passes over every face (the exit search, the tubes'
  // near faces) at their constant indices instead of loaded from the face records (lavapipe:
  // 2-3 % of the one-cell quotients' CPU seconds, docs/quotient-speed.md). Specialised only.
  std::vector<Float4> face_planes;
  // With cell_ranges and listed spheres: each listed sphere's model centre and, in the next
  // entry's x, its radius (LISTED_SPHERE_DATA, in the cell's list order), so that its test works
  // on constants, its radius's sinh and cosh folded by the compiler (lavapipe: 3-17 % of the
  // scenes' CPU seconds where spheres are listed in one cell). Specialised only.
  std::vector<Float4> listed_spheres;

  // Spheres in the acceleration structure, as boxes: unless listed beside triangles (without
  // triangles nothing is traversed, and their boxes keep the structure from being empty).
  bool traced_spheres() const { return spheres && !(sphere_list && triangles); }
  // Shapes there, as boxes: as spheres.
  bool traced_shapes() const { return shapes && !(shape_list && triangles); }
  // Boxes in the acceleration structure (the define TRACED_BOXES).
  bool traced_boxes() const { return traced_spheres() || traced_shapes(); }
  // Whether segments read cell records (the define READS_CELLS, which declares the cell
  // buffer in shaders/common/scene_data.glsl): to cross faces, to pick a cell's chart, or for
  // the spheres and triangles a cell lists.
  bool reads_cells() const {
    return crossing != Crossing::None || multiple_charts || sphere_list || shape_list ||
           triangle_list;
  }

  // The preprocessor defines, one "NAME" or "NAME=VALUE" each, in a fixed order.
  std::vector<std::string> defines() const;
  // The descriptor bindings (shaders/common/scene_data.glsl) the shaders read.
  std::vector<uint32_t> bindings() const;
  bool uses_binding(uint32_t binding) const;
  // A readable one-line summary, e.g. "euclidean translation triangles paper point-lights".
  std::string summary() const;
};

PipelineFeatures scene_features(const Scene& scene, const PackedScene& packed);
// Every feature, chosen at run time from the frame uniforms as before specialisation.
PipelineFeatures all_features(GeometryKind geometry);

const char* crossing_name(Crossing crossing);
// "GEOMETRY_EUCLIDEAN", "GEOMETRY_HYPERBOLIC" or "GEOMETRY_SPHERICAL": what picks the model.
std::string geometry_define(GeometryKind geometry);

}  // namespace geodesic
