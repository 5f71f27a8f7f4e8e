#version 460
// Test probe: runs every geometry, sampling and random-number routine on a buffer of cases so
// that tests/render/glsl_reference_test.cpp can hold the float GLSL against the double C++
// twins in server/geometry/. One invocation per case; it computes all outputs.
#extension GL_GOOGLE_include_directive : require

layout(local_size_x = 64) in;

#include "common/random.glsl"
#include "common/sampling.glsl"
#include "geometry/euclidean.glsl"
#include "primitives/sphere.glsl"

// Layouts mirror ProbeCase and ProbeResult in the test (std430).
struct ProbeCase {
  mat4 pose;              // camera isometry
  vec4 origin;            // ray origin; w: tMin
  vec4 direction;         // unit ray direction; w: tMax
  vec4 sphere;            // centre, radius
  vec4 target;            // a second point; w: ray parameter for geodesicPoint
  vec4 normal;            // unit normal
  vec4 cameraDirection;   // direction in the camera frame
  vec4 colour;            // linear RGB
  vec4 uv;                // xy: two uniform numbers for sampleCosineHemisphere
  uvec4 rng;              // pixel, sample index, seed, pcgHash input
};

struct ProbeResult {
  vec4 scalars;           // intersectSphere, geodesicDistance, metricDot, luminance
  vec4 point;             // geodesicPoint(ray, target.w)
  vec4 towards;           // geodesicDirection(origin, target)
  vec4 reflected;         // reflectDirection(origin, direction, normal)
  vec4 offset;            // offsetFromSurface(origin, normal)
  vec4 cameraOrigin;      // cameraRay(pose, cameraDirection)
  vec4 cameraDirection;
  vec4 tangent;           // orthonormalBasis(normal)
  vec4 bitangent;
  vec4 cosineSample;      // sampleCosineHemisphere(normal, uv)
  uvec4 hashes;           // pcgHash(rng.w), rngSeed(rng.xyz), the state after the draws
  vec4 draws;             // four successive rngNext from that seed
};

layout(std430, binding = 0) readonly buffer Cases { ProbeCase cases[]; };
layout(std430, binding = 1) writeonly buffer Results { ProbeResult results[]; };
layout(push_constant) uniform Push { uint count; } push;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  ProbeCase c = cases[i];
  Ray ray = Ray(c.origin.xyz, c.direction.xyz);
  ProbeResult r;

  r.scalars = vec4(intersectSphere(ray.origin, ray.direction, c.sphere, c.origin.w, c.direction.w),
                   geodesicDistance(c.origin.xyz, c.target.xyz),
                   metricDot(c.origin.xyz, c.direction.xyz, c.normal.xyz),
                   luminance(c.colour.rgb));
  r.point = vec4(geodesicPoint(ray, c.target.w), 0.0);
  r.towards = vec4(geodesicDirection(c.origin.xyz, c.target.xyz), 0.0);
  r.reflected = vec4(reflectDirection(c.origin.xyz, c.direction.xyz, c.normal.xyz), 0.0);
  r.offset = vec4(offsetFromSurface(c.origin.xyz, c.normal.xyz), 0.0);

  Ray camera = cameraRay(c.pose, c.cameraDirection.xyz);
  r.cameraOrigin = vec4(camera.origin, 0.0);
  r.cameraDirection = vec4(camera.direction, 0.0);

  vec3 t, b;
  orthonormalBasis(c.normal.xyz, t, b);
  r.tangent = vec4(t, 0.0);
  r.bitangent = vec4(b, 0.0);
  r.cosineSample = vec4(sampleCosineHemisphere(c.normal.xyz, c.uv.xy), 0.0);

  uint state = rngSeed(c.rng.x, c.rng.y, c.rng.z);
  uint seed = state;
  r.draws = vec4(rngNext(state), rngNext(state), rngNext(state), rngNext(state));
  r.hashes = uvec4(pcgHash(c.rng.w), seed, state, 0u);

  results[i] = r;
}
