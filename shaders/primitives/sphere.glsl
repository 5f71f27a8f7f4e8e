// Ray-sphere intersection, stable for far or grazing rays (the discriminant is formed from
// the closest-approach vector, Ray Tracing Gems ch. 7). Mirrors server/geometry/euclidean.h.
#ifndef SPHERE_GLSL
#define SPHERE_GLSL

// Nearest t in (tMin, tMax) where origin + t*dir (dir unit) meets the sphere, or -1.
float intersectSphere(vec3 origin, vec3 dir, vec4 centerRadius, float tMin, float tMax) {
  vec3 f = origin - centerRadius.xyz;
  float r = centerRadius.w;
  float b = -dot(f, dir);
  vec3 l = f + b * dir;
  float disc = r * r - dot(l, l);
  if (disc < 0.0) return -1.0;
  float q = b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(disc);
  float c = dot(f, f) - r * r;
  float t0 = q != 0.0 ? c / q : 0.0;
  float t1 = q;
  if (t0 > t1) { float s = t0; t0 = t1; t1 = s; }
  if (t0 > tMin && t0 < tMax) return t0;
  if (t1 > tMin && t1 < tMax) return t1;
  return -1.0;
}

#endif
