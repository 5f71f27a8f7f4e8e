// Light sampling for the physical model (next-event estimation) and the density of the same
// strategy for directions found by BSDF sampling (multiple importance sampling). An emitter
// is chosen by power; then one of its geodesics from the shading point: one per image of the
// emitter under the manifold's group (server/render/prepare/emitters.h), and in S3 also the long way
// round (distance 2 pi - d), each weighted by how much light it can bring, up to
// render.light_cutoff (server/render/prepare/emitters.h). A point light at distance d gives irradiance I cos / A(d); an area light
// is sampled by solid angle (spheres: the cone they subtend) or by area with the Jacobian
// A(d) / cos (triangles), A(d) = d^2, sinh^2 d or sin^2 d. A horosphere {<x, l> = -1} (H3, a
// cusp's sky) is a sphere whose centre has gone to its ideal point: from outside its horoball
// it fills the cone about the tangent towards that point of sin alpha = 1 / -<x, l> (e^-d at
// distance d), from inside every direction. Compiled only with LIGHT_SAMPLING, and each kind
// of emitter only when the scene has one (HAS_POINT_LIGHTS, HAS_SPHERE_EMITTERS,
// HAS_TRIANGLE_EMITTERS, HAS_HOROSPHERE_EMITTERS).
#ifndef EMITTERS_GLSL
#define EMITTERS_GLSL
#if defined(LIGHT_SAMPLING)

const uint EMITTER_POINT = 0u;
const uint EMITTER_SPHERE = 1u;
const uint EMITTER_TRIANGLE = 2u;
const uint EMITTER_HOROSPHERE = 3u;
const float FULL_TURN = 6.28318530717958647692;

// True when every geodesic from a point at distance d from the sphere's centre meets it: the
// point is inside it, or (S3) the sphere holds the point's antipode (d + r >= pi), where every
// geodesic from the point passes. Its directions are then the whole sphere, on branch 0 alone.
bool sphereSurrounds(Emitter e, float d) {
#if defined(GEOMETRY_SPHERICAL)
  if (d + e.radius >= PI) return true;
#endif
  return d <= e.radius;
}

// The cosine of the half-angle of the cone a sphere subtends from distance d to its centre,
// sin(alpha) = sqrt(A(r) / A(d)); -1 (every direction) when it surrounds the point.
float sphereConeCos(Emitter e, float d) {
  if (sphereSurrounds(e, d)) return -1.0;
  return sqrt(max(0.0, 1.0 - sphereAreaFactor(e.radius) / sphereAreaFactor(d)));
}

#if defined(HAS_HOROSPHERE_EMITTERS)
// The cosine of the half-angle of the cone the horoball of l subtends from x, sin alpha =
// 1 / s for s = -<x, l>; -1 (every direction) from inside (s <= 1).
float horosphereConeCos(vec4 x, vec4 l) {
  float s = -modelInner(x, l);
  return s <= 1.0 ? -1.0 : sqrt(max(0.0, 1.0 - 1.0 / (s * s)));
}
#endif

// Branch b of the geodesics from a point at distance d: 0 the direct one, 1 the long way
// round (S3 only).
#if defined(GEOMETRY_SPHERICAL)
uint branchCount() { return 2u; }
#else
uint branchCount() { return 1u; }
#endif
float branchDistance(float d, uint branch) { return branch == 0u ? d : FULL_TURN - d; }

// How much the geodesics to the emitter's image c (and, for an antipodal pair, -c) may bring,
// seen from x: the selection
// weights of branch 0 and branch 1 (the long way round, S3; it counts when the cutoff exceeds
// pi). Inside a sphere only the direct branch reaches its surface first; a point light behind
// the surface (geometric normal ng, zero to skip the test) brings nothing: the sign of
// <c - x, ng> is that of the direction to c, as ng is tangent at x. The falloff A(d) comes
// from the two points without the distance (areaFactorBetween): this runs for every image of
// the emitter at every shading point, and sampleLight and lightPdf only need the same weights.
vec2 imageWeights(Emitter e, vec4 x, vec4 c, vec4 ng) {
#if defined(HAS_HOROSPHERE_EMITTERS)
  if (e.kind == EMITTER_HOROSPHERE) {  // 4 pi sin^2 alpha, as a sphere's A(r) / A(d) below
    float s = -modelInner(x, c);
    return vec2(s <= 1.0 ? 4.0 * PI : 4.0 * PI / (s * s), 0.0);
  }
#endif
#if defined(HAS_SPHERE_EMITTERS)
  if (e.kind == EMITTER_SPHERE && sphereSurrounds(e, geodesicDistance(x, c)))
    return vec2(4.0 * PI, 0.0);
#endif
  vec2 branches = vec2(1.0, branchCount() > 1u && frame.light_cutoff > PI ? 1.0 : 0.0);
  float spread = max(areaFactorBetween(x, c), 1e-12);  // A(2 pi - d) = A(d) in S3
#if defined(HAS_POINT_LIGHTS)
  if (e.kind == EMITTER_POINT) {
    // Its irradiance I cos / A(d): <c - x, ng> = cos sqrt(A(d)) (x is orthogonal to ng, and
    // the tangent towards c has length sqrt(A)); the long way round leaves by the opposite
    // direction.
    float side = modelInner(c - x, ng);
    // An antipodal pair (S3, -1 in the group): c and -c weigh the same, A(pi - d) = A(d), and
    // the one in front of the surface takes it all (sampleLight picks it).
    if (e.antipodal_pairs != 0u) side = abs(side);
    return branches * vec2(max(side, 0.0), max(-side, 0.0)) / (spread * sqrt(spread));
  }
#endif
  return branches * min(4.0 * PI, e.radiance.w / spread);
}

// The emitter whose cdf range holds u (binary search).
uint chooseEmitter(float u) {
  uint lo = 0u, hi = EMITTER_COUNT - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (u < emitters[mid].cdf) hi = mid;
    else lo = mid + 1u;
  }
  return lo;
}

// The triangle emitter's model area density with respect to its barycentrics at chart point
// xc (chart around its centroid): sqrt det of the metric g = s^2 (I - K s^2 x x^T),
// s^2 = 1 / (1 + K |x|^2), on its edges.
float triangleAreaJacobian(Emitter e, vec3 xc) {
  float s2 = 1.0 / (1.0 + GEOMETRY_CURVATURE * dot(xc, xc));
  vec3 a = e.edge1.xyz, b = e.edge2.xyz;
  float xa = dot(xc, a), xb = dot(xc, b), k = GEOMETRY_CURVATURE * s2;
  float gaa = s2 * (dot(a, a) - k * xa * xa), gbb = s2 * (dot(b, b) - k * xb * xb);
  float gab = s2 * (dot(a, b) - k * xa * xb);
  return sqrt(max(gaa * gbb - gab * gab, 0.0));
}

struct LightSample {
  vec4 direction;  // unit tangent at the shading point
  vec4 position;   // the light point: on the emitter's surface, or the point light's image
  float distance;  // to the light point along `direction` (past pi: the long way round, S3)
  vec4 sphereCenter;   // a sphere emitter's image: the shadow geodesic stops at its surface
  float sphereRadius;  // 0 for other emitters
  vec4 horosphere;     // a horosphere emitter's image l, likewise; 0 for other emitters
  vec3 radiance;   // L_e, or I / A(d) for a point light
  float pdf;       // solid-angle density (point light: the probability of the choice)
  bool point;
};

// `count` images of emitter e and their branches, chosen by their weights seen from x:
// systematic sampling of the running sum of the weights at (k + u) / count of the total, k <
// count, so that each choice alone is in proportion to its weight, and together they cover the
// images as evenly as count samples can (an image of weight w is chosen floor or ceil of count
// w / total times). One walk over the images serves them all. The map from u to the choices is
// monotone, so samples stratified in u (the pixel's Sobol points, common/sampler.glsl) choose
// every image in close to its share. Returns count, or 0 when no image brings anything.
uint chooseImages(Emitter e, vec4 x, vec4 ng, float u, uint count,
                  out uint images[MAX_LIGHT_SAMPLES], out uint branches[MAX_LIGHT_SAMPLES],
                  out float choices[MAX_LIGHT_SAMPLES]) {
  // The weights are kept from the pass that sums them for the walk (2-4 % of the Poincare
  // sphere's time, whose 60 images each walk nearly passes over; docs/quotient-speed.md).
  vec2 weightsOf[EMITTER_IMAGES];
  float total = 0.0;
  for (uint j = 0u; j < e.image_count; ++j) {
    weightsOf[j] = imageWeights(e, x, lightImages[e.image_begin + j].center, ng);
    total += weightsOf[j].x + weightsOf[j].y;
  }
  if (total <= 0.0) return 0u;
  uint k = 0u, image = 0u, branch = 0u;
  float running = 0.0, weight = 0.0;
  for (uint j = 0u; j < e.image_count && k < count; ++j) {
    vec2 weights = weightsOf[j];
    for (uint b = 0u; b < branchCount(); ++b) {
      if (weights[b] <= 0.0) continue;
      image = j;
      branch = b;
      weight = weights[b];
      running += weight;
      for (; k < count && (float(k) + u) * total < running * float(count); ++k) {
        images[k] = image;
        branches[k] = branch;
        choices[k] = weight / total;
      }
    }
  }
  // Targets that rounding left past the float sum take the last image with weight.
  for (; k < count; ++k) {
    images[k] = image;
    branches[k] = branch;
    choices[k] = weight / total;
  }
  return count;
}

// The light sample of emitter e through its image `image` on branch `branch`, chosen with
// probability `choice` (chooseImages), seen from x (unit local frame `local` at x); onLight
// picks the point on an area light. False when none applies.
bool sampleLightImage(Emitter e, uint image, uint branch, float choice, vec4 x, vec4 ng,
                      LocalFrame local, vec2 onLight, out LightSample ls) {
  ls = LightSample(vec4(0.0), vec4(0.0), 0.0, vec4(0.0), 0.0, vec4(0.0), vec3(0.0), 0.0, false);
#if defined(HAS_HOROSPHERE_EMITTERS)
  if (e.kind == EMITTER_HOROSPHERE) {
    // Directions towards the horoball: the cone about the tangent towards its ideal point,
    // l - s x for s = -<x, l>.
    vec4 l = lightImages[e.image_begin + image].center;
    float cosMax = horosphereConeCos(x, l);
    vec3 axis = cosMax > -1.0 ? toLocal(local, normalizeTangent(x, l + modelInner(x, l) * x))
                              : vec3(0.0, 0.0, 1.0);
    ls.direction = fromLocal(local, sampleUniformCone(axis, cosMax, onLight));
    // Past the offset from x's surface, as BSDF samples leave it: on the horosphere itself the
    // geodesic's own root at 0 is not a light point.
    float t = intersectHorosphere(x, ls.direction, l, surfaceOffsetLength(x), FAR);
    if (!(t < FAR)) return false;
    ls.distance = t;
    ls.position = normalizePoint(geodesicPoint(x, ls.direction, t));
    ls.horosphere = l;
    ls.radiance = e.radiance.rgb;
    ls.pdf = e.pmf * choice / (2.0 * PI * (1.0 - cosMax));
    return true;
  }
#endif
  mat4 g = lightImages[e.image_begin + image].isometry;
  vec4 c = lightImages[e.image_begin + image].center;
#if defined(HAS_POINT_LIGHTS)
  if (e.antipodal_pairs != 0u && modelInner(c - x, ng) < 0.0) c = -c;  // the pair's front one
#endif
  float d = geodesicDistance(x, c);
  float sign = branch == 0u ? 1.0 : -1.0;
  vec4 toward = geodesicDirection(x, c);
  if (dot(toward, toward) == 0.0 && e.kind != EMITTER_SPHERE) return false;
  ls.pdf = e.pmf * choice;
#if defined(HAS_POINT_LIGHTS)
  if (e.kind == EMITTER_POINT) {
    ls.position = c;
    ls.direction = sign * toward;
    ls.distance = branchDistance(d, branch);
    ls.radiance = e.radiance.rgb / max(sphereAreaFactor(ls.distance), 1e-12);
    ls.point = true;
    return true;
  }
#endif
#if defined(HAS_SPHERE_EMITTERS)
  if (e.kind == EMITTER_SPHERE) {
    // Directions towards the sphere: the cone it subtends.
    float cosMax = sphereConeCos(e, d);
    vec3 axis = cosMax > -1.0 ? sign * toLocal(local, toward) : vec3(0.0, 0.0, 1.0);
    ls.direction = fromLocal(local, sampleUniformCone(axis, cosMax, onLight));
    float t = intersectGeodesicSphere(x, ls.direction, c, e.radius, 0.0, FAR);
    if (t <= 0.0) return false;
    ls.distance = t;
    ls.position = normalizePoint(geodesicPoint(x, ls.direction, t));
    ls.sphereCenter = c;
    ls.sphereRadius = e.radius;
    ls.radiance = e.radiance.rgb;
    ls.pdf *= 1.0 / (2.0 * PI * (1.0 - cosMax));
    return true;
  }
#endif
#if defined(HAS_TRIANGLE_EMITTERS)
  // Triangle: a point by area, in the chart around its centroid.
  vec2 bary = sampleUniformTriangle(onLight);
  vec3 xc = e.corner.xyz + bary.x * e.edge1.xyz + bary.y * e.edge2.xyz;
  mat4 place = g * translationTo(e.center);
  vec4 q = liftChart(xc);
  vec4 y = normalizePoint(place * q);
  vec3 planeNormal = normalize(cross(e.edge1.xyz, e.edge2.xyz));
  vec4 normal = place * chartPlaneNormal(q, planeNormal, dot(planeNormal, e.corner.xyz));
  vec4 direct = geodesicDirection(x, y);
  if (dot(direct, direct) == 0.0) return false;
  float dy = geodesicDistance(x, y);
  ls.direction = sign * direct;
  ls.position = y;
  ls.distance = branchDistance(dy, branch);
  float cosLight = abs(modelInner(geodesicTangent(x, ls.direction, ls.distance), normal));
  if (cosLight <= 1e-7) return false;
  ls.radiance = e.radiance.rgb;
  ls.pdf *= 2.0 / triangleAreaJacobian(e, xc) * sphereAreaFactor(ls.distance) / cosLight;
  return true;
#else
  return false;
#endif
}

// How far y lies from the surface of the emitter's image c (from c itself for a point light or
// a triangle's centroid): the image a geodesic ending at y met is the one that passes closest.
float imageMiss(Emitter e, vec4 y, vec4 c) {
#if defined(HAS_HOROSPHERE_EMITTERS)
  if (e.kind == EMITTER_HOROSPHERE) return abs(log(max(-modelInner(y, c), 1e-30)));
#endif
  float d = geodesicDistance(y, c);
  return e.kind == EMITTER_SPHERE ? abs(d - e.radius) : d;
}

// The density with which sampleLight at x would have produced the direction `direction` that
// reached emitter `index` after arc length t, arriving at cosine cosLight to its surface.
float lightPdf(uint index, vec4 x, vec4 direction, float t, float cosLight) {
  Emitter e = emitters[index];
#if defined(HAS_POINT_LIGHTS)
  if (e.kind == EMITTER_POINT) return 0.0;  // no direction finds a point
#endif
  vec4 y = normalizePoint(geodesicPoint(x, direction, t));  // the hit point, in x's copy
  uint branch = branchCount() > 1u && t > PI ? 1u : 0u;
  // The total weight of the images, and the image the geodesic met: the one whose surface
  // passes closest to y, in the same pass. (A space without faces has one image, the emitter
  // itself; there y, far along a long geodesic, may be too imprecise in float for this test:
  // H3 chords of length 10 lose 0.05.)
  float total = 0.0, best = FAR;
  uint image = 0u;
  vec2 met = vec2(0.0);
  for (uint j = 0u; j < e.image_count; ++j) {
    vec4 cj = lightImages[e.image_begin + j].center;
    vec2 weights = imageWeights(e, x, cj, vec4(0.0));
    total += weights.x + weights.y;
#if defined(CELL_CROSSING)
    float miss = imageMiss(e, y, cj);
    if (miss >= best) continue;
    best = miss;
    image = j;
#endif
    met = weights;
  }
  if (total <= 0.0) return 0.0;
#if defined(CELL_CROSSING)
  // A copy of the emitter beyond the cutoff: light sampling never picks it.
  float slack = 1e-3 * (1.0 + t);
  bool surface = e.kind == EMITTER_SPHERE || e.kind == EMITTER_HOROSPHERE;
  if (best > (surface ? slack : e.radius + slack)) return 0.0;
#endif
#if defined(HAS_HOROSPHERE_EMITTERS)
  if (e.kind == EMITTER_HOROSPHERE) {
    float cosMax = horosphereConeCos(x, lightImages[e.image_begin + image].center);
    return e.pmf * (met.x / total) / (2.0 * PI * (1.0 - cosMax));
  }
#endif
  mat4 g = lightImages[e.image_begin + image].isometry;
  float d = geodesicDistance(x, lightImages[e.image_begin + image].center);
#if defined(HAS_SPHERE_EMITTERS)
  if (e.kind == EMITTER_SPHERE && sphereSurrounds(e, d)) branch = 0u;  // sampled on branch 0
#endif
  float choice = (branch == 0u ? met.x : met.y) / total;
  if (choice <= 0.0) return 0.0;
#if defined(HAS_SPHERE_EMITTERS)
  if (e.kind == EMITTER_SPHERE) {
    float cosMax = sphereConeCos(e, d);
    return e.pmf * choice / (2.0 * PI * (1.0 - cosMax));
  }
#endif
#if defined(HAS_TRIANGLE_EMITTERS)
  vec3 xc = chartPoint(translationFrom(e.center) * (inverseIsometry(g) * y));
  return e.pmf * choice * 2.0 / triangleAreaJacobian(e, xc) * sphereAreaFactor(t) /
         max(cosLight, 1e-7);
#else
  return 0.0;
#endif
}

#endif  // LIGHT_SAMPLING
#endif
