// A horosphere of H3, {x : <x, l> = -1} for the light-like l = Shape.a aimed at its ideal
// point; its horoball is {<x, l> > -1}. The derivation and the double twin are in
// server/scene/shapes/horosphere.cpp: along x(t) = p cosh t + v sinh t, with u = e^t,
// A u^2 + 2 u + C = 0 for A = <p + v, l>, C = <p - v, l> (both <= 0), solved without
// cancellation; the normal at q is q - l.
#ifndef HOROSPHERE_GLSL
#define HOROSPHERE_GLSL

// The arc length of the geodesic (p, v)'s first crossing of the horosphere of l in
// (tMin, tMax), or FAR. With l = alpha p + beta v + m (m orthogonal
// to both), A = beta - alpha, C = -alpha - beta and AC = <m, m>: the one of A, C that does not
// cancel is computed directly, the other from <m, m>.
float intersectHorosphere(vec4 p, vec4 v, vec4 l, float tMin, float tMax) {
  float alpha = -modelInner(p, l), beta = modelInner(v, l);
  vec4 m = l - alpha * p - beta * v;
  float mm = max(modelInner(m, m), 0.0);
  float discriminant = 1.0 - mm;
  if (discriminant < 0.0) return FAR;
  float a = beta <= 0.0 ? beta - alpha : mm / (-alpha - beta);
  float c = beta <= 0.0 ? mm / a : -alpha - beta;
  float q = -(1.0 + sqrt(discriminant));
  float enter = c < 0.0 ? log(c / q) : -FAR;  // C = 0: it came from the ideal point, inside
  float leave = a < 0.0 ? log(q / a) : FAR;   // A = 0: it runs into the ideal point
  if (enter > tMin && enter < tMax) return enter;
  if (leave > tMin && leave < tMax) return leave;
  return FAR;
}

// The unit normal at q on the horosphere of l, out of the horoball.
vec4 horosphereNormal(vec4 l, vec4 q) { return normalizeTangent(q, q - l); }

#endif
