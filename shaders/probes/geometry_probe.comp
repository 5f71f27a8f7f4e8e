#version 460
// Test probe: runs every model-geometry, capsule, shape, sampling, BSDF and random-number routine on a
// buffer of cases, so that tests/render/ can hold the float GLSL against the double C++ twins
// in server/geometry/ and tests/twins/. Compiled once per geometry like every entry point. One
// invocation per case; it computes all outputs.
#extension GL_GOOGLE_include_directive : require

layout(local_size_x = 64) in;

#include "common/random.glsl"
#include "common/sobol.glsl"
#include "common/sampling.glsl"
#include "geometry/model.glsl"
#include "geometry/capsule.glsl"
#include "geometry/parallelogram.glsl"
#include "geometry/triangle.glsl"
#include "common/gpu_types.h"
#include "integrator/chart_ray.glsl"
#include "primitives/shape_table.glsl"
#include "materials/bsdf.glsl"

// Layouts mirror ProbeCase and ProbeResult in tests/render/geometry_probe.h (std430).
struct ProbeCase {
  mat4 isometry;   // for inverseIsometry
  vec4 point;      // p, on the model
  vec4 tangent;    // v, a unit tangent at p
  vec4 target;     // q, a second point
  vec4 sphere;     // centre c, on the model
  vec4 loose;      // any 4-vector, for the normalisations
  vec4 params;     // t, radius, tMin, tMax
  vec4 plane;      // chart plane: unit normal, delta
  vec4 chart;      // xyz: a chart point; w: a chart parameter s
  vec4 normal;     // unit 3-vector for the sampling routines
  vec4 colour;     // linear RGB
  vec4 uv;         // xy: two uniform numbers for the sampling routines; zw: two densities
  uvec4 rng;       // pixel, sample index, seed, pcgHash input
  vec4 capsuleA;   // a capsule's axis: xyz one end, w radius
  vec4 capsuleB;   // xyz the other end, w the largest chart parameter sMax
  vec4 shapeA;     // a shape (primitives/shape_table.glsl): its vectors a and b,
  vec4 shapeB;
  vec4 shapeSize;  // x its size, y the tMax of its intersection
  uvec4 shapeKind; // x its kind
  vec4 triangleA;  // a triangle's corners (xyz); triangleA.w the largest chart parameter sMax
  vec4 triangleB;
  vec4 triangleC;
};

struct ProbeResult {
  vec4 scalars;            // intersectGeodesicSphere, geodesicDistance(p, q),
                           // modelInner(v, loose), luminance
  vec4 chartScalars;       // chartParameter(p, v, t), distanceFromChartParameter(p, v, s),
                           // GEOMETRY_CURVATURE, surfaceOffsetLength(p)
  vec4 origin;             // originPoint()
  vec4 geodesic;           // geodesicPoint(p, v, t)
  vec4 velocity;           // geodesicTangent(p, v, t)
  vec4 towards;            // geodesicDirection(p, q)
  mat4 translatedTo;       // translationTo(q)
  mat4 translatedFrom;     // translationFrom(q)
  mat4 inverse;            // inverseIsometry(isometry)
  vec4 planeNormal;        // chartPlaneNormal(p, plane)
  vec4 sphereNormal;       // sphereNormal(c, q)
  vec4 normalizedPoint;    // normalizePoint(loose)
  vec4 normalizedTangent;  // normalizeTangent(p, loose)
  vec4 chartOfPoint;       // chartPoint(p)
  vec4 lifted;             // liftChart(chart.xyz)
  vec4 chartVelocity;      // chartDirection(p, v)
  vec4 offset;             // offsetFromSurface(p, v)
  vec4 basisTangent;       // orthonormalBasis(normal)
  vec4 basisBitangent;
  vec4 cosineSample;       // sampleCosineHemisphere(normal, uv)
  uvec4 hashes;            // pcgHash(rng.w), rngSeed(rng.xyz), the state after the draws
  vec4 draws;              // four successive rngNext from that seed
  vec4 reflected;          // reflectInChartPlane(p, plane)
  vec4 triangleSample;     // sampleUniformTriangle(uv.xy), powerHeuristic(uv.z, uv.w)
  vec4 capsule;            // intersectCapsule(capsule, chart.xyz, normal.xyz, 0, sMax),
                           // capsuleNormal(capsule, chart.xyz)
  vec4 areas;              // areaFactorBetween(p, q), sphereAreaFactor(geodesicDistance(p, q))
  uvec4 sobol;             // sobolBits(rng.y, rng.w), nestedUniformScramble(rng.x, rng.z),
                           // sobolSecond(rng.y)
  uvec4 pathSeeds;         // pathSamplerSeed(rng.x, rng.y & 1, rng.z & 15, rng.w), the same
                           // for pairs 0 and 1
  vec4 bsdf;               // bsdfEvaluate(probeMaterial(colour, uv.y), normal, normal,
                           // cosineSample): f, pdf
  vec4 shapeHit;           // intersectShape(shape, p, v, 0, tMax)
  vec4 shapeNormal;        // shapeNormal(shape, q)
  vec4 triangle;           // intersectChartTriangle(shearLine(normal.xyz), chart.xyz, the
                           // triangle, 0, sMax): s (FAR_TRIANGLE: none) and the barycentrics
  vec4 parallelogram;      // intersectChartParallelogram(chart.xyz, normal.xyz, |chart|, the
                           // triangle's corners as a, b, c, 0, sMax): s, alpha, beta
};

// Diffuse, Phong (exponent 1 to 64) and mirror lobes in proportions the colour sets.
Material probeMaterial(vec3 colour, float u) {
  return Material(vec4(0.0), vec4(0.05 * colour, 0.0), vec4(0.04 * colour.bgr, 1.0 + 63.0 * u),
                  vec4(0.01 * colour.gbr, 0.0), vec4(0.0), vec4(0.0));
}

layout(std430, binding = 0) readonly buffer Cases { ProbeCase cases[]; };
layout(std430, binding = 1) writeonly buffer Results { ProbeResult results[]; };
layout(push_constant) uniform Push { uint count; } push;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  ProbeCase c = cases[i];
  vec4 p = c.point, v = c.tangent, q = c.target;
  float t = c.params.x;
  ProbeResult r;

  r.scalars = vec4(intersectGeodesicSphere(p, v, c.sphere, c.params.y, c.params.z, c.params.w),
                   geodesicDistance(p, q), modelInner(v, c.loose), luminance(c.colour.rgb));
  r.chartScalars = vec4(chartParameter(p, v, t), distanceFromChartParameter(p, v, c.chart.w),
                        GEOMETRY_CURVATURE, surfaceOffsetLength(p));
  r.origin = originPoint();
  r.geodesic = geodesicPoint(p, v, t);
  r.velocity = geodesicTangent(p, v, t);
  r.towards = geodesicDirection(p, q);
  r.translatedTo = translationTo(q);
  r.translatedFrom = translationFrom(q);
  r.inverse = inverseIsometry(c.isometry);
  r.planeNormal = chartPlaneNormal(p, c.plane.xyz, c.plane.w);
  r.sphereNormal = sphereNormal(c.sphere, q);
  r.normalizedPoint = normalizePoint(c.loose);
  r.normalizedTangent = normalizeTangent(p, c.loose);
  r.chartOfPoint = vec4(chartPoint(p), 0.0);
  r.lifted = liftChart(c.chart.xyz);
  r.chartVelocity = vec4(chartDirection(p, v), 0.0);
  r.offset = offsetFromSurface(p, v);
  r.reflected = reflectInChartPlane(p, c.plane);
  r.capsule = vec4(intersectCapsule(c.capsuleA.xyz, c.capsuleB.xyz, c.capsuleA.w, c.chart.xyz,
                                    c.normal.xyz, 0.0, c.capsuleB.w),
                   capsuleNormal(c.capsuleA.xyz, c.capsuleB.xyz, c.chart.xyz));

  vec2 uv;
  float s = intersectChartTriangle(shearLine(c.normal.xyz), c.chart.xyz, c.triangleA.xyz,
                                   c.triangleB.xyz, c.triangleC.xyz, 0.0, c.triangleA.w, uv);
  r.triangle = vec4(s, uv, 0.0);
  vec3 o = c.chart.xyz;
  vec2 alphaBeta;
  float sp = intersectChartParallelogram(o, c.normal.xyz, max(max(abs(o.x), abs(o.y)), abs(o.z)),
                                         c.triangleA.xyz, c.triangleB.xyz, c.triangleC.xyz, 0.0,
                                         c.triangleA.w, alphaBeta);
  r.parallelogram = vec4(sp, alphaBeta, 0.0);

  Shape shape = Shape(c.shapeA, c.shapeB, c.shapeSize.x, c.shapeKind.x, 0u, 0u);
  r.shapeHit = vec4(intersectShape(shape.kind, shape.a, shape.b, shape.size, p, v, 0.0,
                                   c.shapeSize.y), 0.0, 0.0, 0.0);
  r.shapeNormal = shapeNormal(shape, q);

  r.areas = vec4(areaFactorBetween(p, q), sphereAreaFactor(geodesicDistance(p, q)), 0.0, 0.0);

  vec3 tb, bb;
  orthonormalBasis(c.normal.xyz, tb, bb);
  r.basisTangent = vec4(tb, 0.0);
  r.basisBitangent = vec4(bb, 0.0);
  r.cosineSample = vec4(sampleCosineHemisphere(c.normal.xyz, c.uv.xy), 0.0);
  BsdfValue bsdf = bsdfEvaluate(probeMaterial(c.colour.rgb, c.uv.y), c.normal.xyz, c.normal.xyz,
                                r.cosineSample.xyz);
  r.bsdf = vec4(bsdf.f, bsdf.pdf);
  r.triangleSample = vec4(sampleUniformTriangle(c.uv.xy), powerHeuristic(c.uv.z, c.uv.w), 0.0);

  uint state = rngSeed(c.rng.x, c.rng.y, c.rng.z);
  uint seed = state;
  r.draws = vec4(rngNext(state), rngNext(state), rngNext(state), rngNext(state));
  r.hashes = uvec4(pcgHash(c.rng.w), seed, state, 0u);
  r.sobol = uvec4(sobolBits(c.rng.y, c.rng.w), nestedUniformScramble(c.rng.x, c.rng.z),
                  sobolSecond(c.rng.y));
  r.pathSeeds = uvec4(pathSamplerSeed(c.rng.x, c.rng.y & 1u, c.rng.z & 15u, c.rng.w),
                      pathSamplerSeed(c.rng.x, c.rng.y & 1u, 0u, c.rng.w),
                      pathSamplerSeed(c.rng.x, c.rng.y & 1u, 1u, c.rng.w), 0u);

  results[i] = r;
}
