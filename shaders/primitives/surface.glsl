// The surface record a closest hit produces, in the model: where the geodesic stopped, the
// normals facing it, the direction it arrived in, and the material. Shared by both entry
// points.
#ifndef SURFACE_GLSL
#define SURFACE_GLSL
#if defined(HAS_TUBES)
#include "geometry/capsule.glsl"
#endif
#include "primitives/shape_candidate.glsl"

struct Surface {
  vec4 position;         // model point q
  vec4 normal;           // unit shading normal at q, on the side the ray came from
  vec4 geometricNormal;  // unit face normal at q, same side
  vec4 incoming;         // unit tangent of the arriving geodesic at q
  uint material;
  uint hit;              // 0 when the ray escaped
  uint cell;             // the cell the hit was found in
  uint emitter;          // index into emitters, ~0u when the surface does not emit
  float t;               // arc length along the segment that hit
  bool frontFace;        // the ray arrived on the outer (sphere) or front (triangle) side
  bool horizon;          // past the float horizon (SURFACE_HORIZON_W, SHAPE_HORIZON_W)
};

Surface noSurface() {
  Surface s;
  s.position = originPoint();
  s.normal = s.geometricNormal = s.incoming = vec4(0.0, 0.0, 1.0, 0.0);
  s.material = 0u;
  s.hit = 0u;
  s.cell = 0u;
  s.emitter = ~0u;
  s.t = FAR;
  s.frontFace = true;
  s.horizon = false;
  return s;
}

Surface facing(Surface s) {
  s.frontFace = modelInner(s.geometricNormal, s.incoming) <= 0.0;
  if (!s.frontFace) s.geometricNormal = -s.geometricNormal;
  if (modelInner(s.normal, s.geometricNormal) < 0.0) s.normal = -s.normal;
  return s;
}

// The surface at chart point x of the ray's cell, on the chart plane n . X = delta (unit n;
// geodesic planes are flat in the chart), reached at chart parameter sHit of the ray's
// segment: position, normals, arc length and arriving tangent; material and emitter are the
// caller's.
Surface chartSurface(GeodesicRay ray, vec3 x, vec3 n, float delta, float sHit) {
  Surface s;
  s.hit = 1u;
  s.horizon = false;
  s.cell = ray.cell;
  mat4 P = cellChartIsometry(ray.cell);
  mat4 toModel = transpose(P);  // signed permutations: P^-1 = P^T
  vec4 qCell = liftChart(x);
  s.position = toModel * qCell;
  s.geometricNormal = toModel * chartPlaneNormal(qCell, n, delta);
  s.normal = s.geometricNormal;
  s.t = distanceFromChartParameter(P * ray.p, P * ray.v, sHit);
  s.incoming = geodesicTangent(ray.p, ray.v, s.t);
  return s;
}

// The surface hit by `ray` (whose current segment produced `hit`): a triangle, a sphere, an
// edge tube or a shape (ChartHit.kind).
Surface hitSurface(GeodesicRay ray, ChartHit hit) {
  Surface s;
  s.hit = 1u;
  s.horizon = false;
  s.cell = ray.cell;
#if defined(HAS_SPHERES) || defined(HAS_SHAPES)
  if (hit.kind == HIT_SPHERE || hit.kind == HIT_SHAPE) {  // found in the model, at arc length t
    s.position = normalizePoint(geodesicPoint(ray.p, ray.v, hit.t));
    s.incoming = geodesicTangent(ray.p, ray.v, hit.t);
    s.t = hit.t;
#if defined(HAS_SHAPES)
    if (hit.kind == HIT_SHAPE) {
      Shape shape = shapes[hit.index];
      s.geometricNormal = shapeNormal(shape, s.position);
      s.material = shape.material;
      s.emitter = shape.emitter;
      s.horizon = !(s.position.w <= SHAPE_HORIZON_W);
    }
#endif
#if defined(HAS_SPHERES)
    if (hit.kind == HIT_SPHERE) {
      Sphere sphere = spheres[hit.index];
      s.geometricNormal = sphereNormal(sphere.center, s.position);
      s.material = sphere.material;
      s.emitter = sphere.emitter;
    }
#endif
    s.normal = s.geometricNormal;
    return facing(s);
  }
#endif
#if defined(HAS_TUBES)
  if (hit.kind == HIT_TUBE) {  // an edge tube: its capsule's normal in the chart, as a plane's
    Tube tube = tubes[hit.index];
    mat4 P = cellChartIsometry(ray.cell);
    vec4 p = P * ray.p;
    vec3 x = chartPoint(p) + hit.s * chartDirection(p, P * ray.v);
    vec3 n = capsuleNormal(tube.a.xyz, tube.b.xyz, x);
    s = chartSurface(ray, x, n, dot(n, x), hit.s);
    s.material = tube.material;
    s.emitter = ~0u;
    return facing(s);
  }
#endif
#if defined(HAS_TRIANGLES)
  // Triangle: exact in the cell's chart (geodesic planes are flat there).
  uint i0 = indices[3u * hit.index], i1 = indices[3u * hit.index + 1u],
       i2 = indices[3u * hit.index + 2u];
  vec3 a = positions[i0].xyz, b = positions[i1].xyz, c = positions[i2].xyz;
  float w = 1.0 - hit.barycentrics.x - hit.barycentrics.y;
  vec3 x = w * a + hit.barycentrics.x * b + hit.barycentrics.y * c;
  vec3 planeNormal = normalize(cross(b - a, c - a));
  s = chartSurface(ray, x, planeNormal, dot(planeNormal, a), hit.s);
  TriangleInfo info = triangles[hit.index];
#if defined(HAS_SMOOTH_NORMALS)
  if (info.smooth_normals != 0u) {  // E3 meshes only: model tangents per vertex
    vec4 n = w * normals[i0] + hit.barycentrics.x * normals[i1] + hit.barycentrics.y * normals[i2];
    if (dot(n, n) > 0.0) s.normal = normalizeTangent(s.position, n);
  }
#endif
  s.material = info.material;
  s.emitter = info.emitter;
  return facing(s);
#else
  return noSurface();  // unreachable: without triangles every hit is a box's or a tube's
#endif
}

#if defined(GEOMETRY_HYPERBOLIC)
// Shading at a float H3 point d from the chart's origin (the camera's frame in plain H3, the
// cell's centre in a quotient) cancels products of size e^2d: a sphere's normal carried to the
// origin's tangent space is off by 1e-3 rad on average at d = 6, 8e-3 at 7 (5e-2 at worst),
// and from 8 on the normal itself comes out zero, which ends in a NaN sample (docs/numerics.md,
// "The float horizon"). So a hit farther out than d = 7 is seen, with its emission, but no
// path goes on from it, whatever the primitive (shapes stop earlier, at SHAPE_HORIZON_W).
const float SURFACE_HORIZON_W = 548.317035;  // cosh 7
#endif

Surface surfaceOf(GeodesicRay ray, ChartHit hit) {
  Surface s = hitSurface(ray, hit);
#if defined(GEOMETRY_HYPERBOLIC)
  s.horizon = s.horizon || !(s.position.w <= SURFACE_HORIZON_W);
#endif
  return s;
}

#endif
