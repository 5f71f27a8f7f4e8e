// Euclidean E3: geodesics are straight lines and the metric is the dot product. Mirrors
// server/geometry/euclidean.h. Curved models provide the same functions in their own file.
#ifndef GEOMETRY_GLSL
#define GEOMETRY_GLSL

struct Ray {
  vec3 origin;
  vec3 direction;  // unit
};

vec3 geodesicPoint(Ray ray, float t) { return ray.origin + t * ray.direction; }

float geodesicDistance(vec3 a, vec3 b) { return length(b - a); }

// Unit tangent at `from` of the geodesic towards `to`.
vec3 geodesicDirection(vec3 from, vec3 to) { return normalize(to - from); }

// The metric g_p(u, v) at p.
float metricDot(vec3 p, vec3 u, vec3 v) { return dot(u, v); }

// Mirror reflection of direction d about the unit normal n (with the metric at p).
vec3 reflectDirection(vec3 p, vec3 d, vec3 n) { return d - 2.0 * metricDot(p, d, n) * n; }

// Camera ray through a direction given in the camera frame, moved by the camera isometry.
Ray cameraRay(mat4 pose, vec3 directionInCamera) {
  Ray r;
  r.origin = (pose * vec4(0.0, 0.0, 0.0, 1.0)).xyz;
  r.direction = normalize((pose * vec4(directionInCamera, 0.0)).xyz);
  return r;
}

// A spawn point off the surface along its normal: a fixed 1e-4 plus 2^-15 of p's magnitude
// (about 256 float ulps), so float round-off never lets a secondary ray hit the surface it
// leaves, while small objects far from the origin are not stepped over.
vec3 offsetFromSurface(vec3 p, vec3 n) {
  float scale = 1e-4 + (1.0 / 32768.0) * max(abs(p.x), max(abs(p.y), abs(p.z)));
  return p + scale * n;
}

#endif
