// A capsule in a chart: the points within chart distance r of the segment [a, b]. Float twin
// of server/geometry/capsule.h (the comments there hold here).
#ifndef CAPSULE_GLSL
#define CAPSULE_GLSL

// The roots of A s^2 + 2 B s + C = 0 in increasing order (A > 0), without cancellation.
bool capsuleRoots(float A, float B, float C, out float s0, out float s1) {
  float h = B * B - A * C;
  s0 = s1 = 0.0;
  if (h < 0.0) return false;
  float q = -(B + (B < 0.0 ? -sqrt(h) : sqrt(h)));
  if (q == 0.0) return true;
  s0 = min(q / A, C / q);
  s1 = max(q / A, C / q);
  return true;
}

// The smallest s in (sMin, sMax] where o + s d meets the capsule's surface, or FAR_CAPSULE.
const float FAR_CAPSULE = 1e30;
float intersectCapsule(vec3 a, vec3 b, float r, vec3 o, vec3 d, float sMin, float sMax) {
  vec3 axis = b - a;
  float length2 = dot(axis, axis);
  vec3 oa = o - a;
  vec3 oPerp = oa - (dot(oa, axis) / length2) * axis;
  vec3 dPerp = d - (dot(d, axis) / length2) * axis;
  float A = dot(dPerp, dPerp), B = dot(oPerp, dPerp), C = dot(oPerp, oPerp) - r * r;
  if (B * B - A * C < 0.0 && C > 0.0) return FAR_CAPSULE;  // most lines: the cylinder missed
  float best = FAR_CAPSULE;
  float s0, s1;
  if (A > 0.0 && capsuleRoots(A, B, C, s0, s1)) {
    float y0 = dot(oa + s0 * d, axis), y1 = dot(oa + s1 * d, axis);
    if (y0 >= 0.0 && y0 <= length2 && s0 > sMin && s0 <= sMax) best = s0;
    else if (y1 >= 0.0 && y1 <= length2 && s1 > sMin && s1 <= sMax) best = s1;
  } else if (C > 0.0) {
    return FAR_CAPSULE;  // parallel to the axis and outside the cylinder
  }
  float dd = dot(d, d);
  for (int end = 0; end < 2; ++end) {
    vec3 oc = o - (end == 0 ? a : b);
    if (!capsuleRoots(dd, dot(oc, d), dot(oc, oc) - r * r, s0, s1)) continue;
    float y0 = dot(oa + s0 * d, axis), y1 = dot(oa + s1 * d, axis);
    bool beyond0 = end == 0 ? y0 < 0.0 : y0 > length2;
    bool beyond1 = end == 0 ? y1 < 0.0 : y1 > length2;
    if (beyond0 && s0 > sMin && s0 <= sMax && s0 < best) best = s0;
    if (beyond1 && s1 > sMin && s1 <= sMax && s1 < best) best = s1;
  }
  return best;
}

// The unit outward normal at chart point x on the capsule's surface.
vec3 capsuleNormal(vec3 a, vec3 b, vec3 x) {
  vec3 axis = b - a;
  float y = clamp(dot(x - a, axis) / dot(axis, axis), 0.0, 1.0);
  return normalize(x - (a + y * axis));
}

#endif
