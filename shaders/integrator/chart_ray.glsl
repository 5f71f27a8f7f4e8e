// Rays as the model sees them (a point and unit tangent, in the model) and as the
// acceleration structure sees them (a straight line in one cell's chart).
#ifndef CHART_RAY_GLSL
#define CHART_RAY_GLSL

const float FAR = 1e30;

// TRACED_BOXES: boxes in the acceleration structure, shapes, and spheres unless each cell's
// are listed and tested one by one beside its triangles (defined by the host:
// PipelineFeatures::traced_boxes).

// Traversal skips the primitive type it never meets, where the device allows it: boxes or
// triangles.
#if defined(CULL_PRIMITIVES) && !defined(TRACED_BOXES)
#define PRIMITIVE_CULLING_FLAGS gl_RayFlagsSkipAABBEXT
#elif defined(CULL_PRIMITIVES) && !defined(HAS_TRIANGLES)
#define PRIMITIVE_CULLING_FLAGS gl_RayFlagsSkipTrianglesEXT
#else
#define PRIMITIVE_CULLING_FLAGS 0u
#endif

// Past eight cells, cells share ray-mask bits (cell % 8) and every candidate's cell is
// checked, so triangles cannot be accepted unseen.
#if defined(SHARED_CELL_MASKS)
#define CELL_OPACITY_FLAGS gl_RayFlagsNoOpaqueEXT
#else
#define CELL_OPACITY_FLAGS gl_RayFlagsOpaqueEXT
#endif
uint cellMask(uint cell) { return 1u << (cell % 8u); }

struct GeodesicRay {
  vec4 p;            // model point
  vec4 v;            // unit tangent at p
  uint cell;         // the cell whose chart traces it
  uint enteredFace;  // face it entered the cell through (~0u: none), never an exit
};

// The closest hit along one chart segment. kind: HIT_NONE, _TRIANGLE, _SPHERE, _TUBE or _SHAPE.
struct ChartHit {
  uint kind;
  uint index;       // global triangle, sphere, tube or shape index
  float s;          // chart parameter along o + s d
  float t;          // arc length (spheres; triangles fill it in later)
  vec2 barycentrics;
};

ChartHit noChartHit() { return ChartHit(HIT_NONE, 0u, FAR, FAR, vec2(0.0)); }

#if defined(READS_CELLS)
// A cell's record. In a space of one cell (SINGLE_CELL) every ray reads the same one, at an
// index the compiler sees is the same for all: one load for a SIMD group, not a gather.
Cell cellRecord(uint cell) {
#if defined(SINGLE_CELL)
  Cell c = cells[0u];
#if defined(CELL_RANGES)
  // Its index ranges baked in (pipeline_features.h): the loops over its faces, tubes and
  // listed primitives get constant bounds and indices, which the compiler unrolls.
  const uint r[14] = uint[](CELL_RANGES);
  c.face_begin = r[0];
  c.face_count = r[1];
  c.tube_begin = r[2];
  c.tube_count = r[3];
  c.always_begin = r[4];
  c.sphere_begin = r[5];
  c.sphere_count = r[6];
  c.listed_begin = r[7];
  c.listed_count = r[8];
  c.listed_pairs = r[9];
  c.shape_begin = r[10];
  c.shape_count = r[11];
  c.listed_hull_pairs = r[12];
  c.listed_hull_lone = r[13];
#endif
  return c;
#else
  return cells[cell];
#endif
}
#endif

// Whether the chart segment o + s d, 0 <= s <= sMax, meets the box [lo, hi] (a slab test).
bool segmentMeetsBox(vec3 lo, vec3 hi, vec3 o, vec3 d, float sMax) {
  vec3 inv = 1.0 / d;
  vec3 a = (lo - o) * inv;
  vec3 b = (hi - o) * inv;
  vec3 near = min(a, b);
  vec3 far = max(a, b);
  float enter = max(max(near.x, near.y), max(near.z, 0.0));
  float leave = min(min(far.x, far.y), min(far.z, sMax));
  return enter <= leave;
}

// Model -> cell frame. Only S3's atlas changes charts between cells; other spaces have one
// cell charted about the origin, so the identity compiles away there.
mat4 cellChartIsometry(uint cell) {
#if defined(MULTIPLE_CHARTS)
  return cells[cell].chart_isometry;
#else
  return mat4(1.0);
#endif
}

// The model ray (p, v) of a chart line o + s d, with p on the model's w > 0 part: the
// derivative of liftChart along d, made a unit tangent.
void modelRayOfChartLine(vec3 o, vec3 d, out vec4 p, out vec4 v) {
  p = liftChart(o);
  float lambda2 = 1.0 + GEOMETRY_CURVATURE * dot(o, o);
  vec4 dp = vec4(d, 0.0) / sqrt(lambda2) -
            GEOMETRY_CURVATURE * vec4(o, 1.0) * dot(o, d) / (lambda2 * sqrt(lambda2));
  v = normalizeTangent(p, dp);
}

// An intersection shader's chart line o + s' d, s' in [sMin, sMax] (its gl_WorldRay* and
// gl_RayT*), as the model ray (p, v) and the range of (p, v)'s own chart parameter s, which
// runs along chartDirection(p, v) = k d: s' = k s.
void boxRay(vec3 o, vec3 d, float sMin, float sMax, out vec4 p, out vec4 v, out float k,
            out vec2 range) {
  modelRayOfChartLine(o, d, p, v);
  k = dot(chartDirection(p, v), d) / dot(d, d);
  range = vec2(sMin / k, sMax >= FAR ? FAR : sMax / k);
}

// The arc length bound a primitive test that returns its first crossing of (p, v) needs for
// the chart segment s in [0, sMax]. In E3 and H3 the chart parameter increases with t, so the
// caller's s <= sMax bounds t as well: none (FAR), without an atanh per primitive and segment.
// S3's gnomonic chart parameter is periodic in t: only t up to sMax's arc length maps into it.
float firstCrossingBound(vec4 p, vec4 v, float sMax) {
#if defined(GEOMETRY_SPHERICAL)
  return sMax >= FAR ? FAR : distanceFromChartParameter(p, v, sMax);
#else
  return FAR;
#endif
}

#endif
