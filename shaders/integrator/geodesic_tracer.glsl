// The paper's algorithm 1, generalised to cells: trace a geodesic through the current cell's
// chart; when it reaches a face of the cell without hitting anything, carry it across (the
// face's pairing isometry, or a change of chart) and go on, up to MAX_CROSSINGS times. A space
// without faces (CELL_CROSSING undefined) traces one chart segment. Walls between the pieces of
// one domain (INTERNAL_WALLS) do not count: up to MAX_WALL_CROSSINGS of them, as a ray that
// starts on the edge all the pieces of a lune share passes through many at once. The crossing
// code is the pairing kind's only (PAIRING_*, server/render/prepare/pipeline_features.h). Edge tubes
// (HAS_TUBES) are tested in the chart beside the traversal (primitives/edge_tube.glsl).
// Needs ChartHit traceChart(vec3 o, vec3 d, float sMax, uint cell, vec4 p, vec4 v, bool any)
// from the entry point.
#ifndef GEODESIC_TRACER_GLSL
#define GEODESIC_TRACER_GLSL
#include "primitives/edge_tube.glsl"

const uint NO_FACE = ~0u;

// The chart line of the ray in its cell: origin o, direction d, and the ray in the cell frame.
struct ChartLine {
  vec3 o;
  vec3 d;
  vec4 p;  // chartIsometry * ray.p
  vec4 v;
};

ChartLine chartLineOf(GeodesicRay ray) {
  mat4 P = cellChartIsometry(ray.cell);
  ChartLine line;
  line.p = P * ray.p;
  line.v = P * ray.v;
  line.o = chartPoint(line.p);
  line.d = chartDirection(line.p, line.v);
  return line;
}

#if defined(CELL_CROSSING)
// Face f, whose plane lies `height` above the line's start and which the line approaches at
// rate `towards` per unit of chart parameter, as the exit found so far (face, at sExit) or not.
void considerExit(uint f, float height, float towards, GeodesicRay ray, inout float sExit,
                  inout uint face) {
  if (f != ray.enteredFace && towards > 0.0) {
    float s = max(0.0, height / towards);
    if (s < sExit) {
      sExit = s;
      face = f;
    }
  }
}

// Where the chart line leaves its convex cell: the smallest chart parameter over the faces it
// moves towards (NO_FACE and FAR for a cell without faces). With edge tubes (in a space of
// several cells: NOTES_FACE_REACH), the same pass over the faces notes which the line comes
// within the tubes' reach of (noteFaceReach). With
// OPPOSITE_FACES the faces come in pairs N . X = w, -N . X = w: one dot product with each of o
// and d serves both, and the line moves towards one of them at most.
uint exitFace(GeodesicRay ray, ChartLine line, out float sExit) {
  sExit = FAR;
  uint face = NO_FACE;
  Cell cell = cellRecord(ray.cell);
#if defined(NOTES_FACE_REACH)
  clearFaceReach();
#endif
#if defined(OPPOSITE_FACES)
  for (uint i = 0u; i < cell.face_count; i += 2u) {
    uint f = cell.face_begin + i;
    vec4 plane = facePlane(f);
    float towards = dot(plane.xyz, line.d), across = dot(plane.xyz, line.o);
    float height = plane.w - across, oppositeHeight = plane.w + across;
    // Chosen by selects, not branches: SIMD lanes would run both branches' divisions.
    bool forward = towards > 0.0;
    considerExit(forward ? f : f + 1u, forward ? height : oppositeHeight, abs(towards), ray,
                 sExit, face);
#if defined(NOTES_FACE_REACH)
    noteFaceReach(cell, i, height, towards, sExit);
    noteFaceReach(cell, i + 1u, oppositeHeight, -towards, sExit);
#endif
  }
#else
  for (uint i = 0u; i < cell.face_count; ++i) {
    uint f = cell.face_begin + i;
    vec4 plane = facePlane(f);
    float towards = dot(plane.xyz, line.d);
    float height = plane.w - dot(plane.xyz, line.o);  // above the face's plane, inside
    considerExit(f, height, towards, ray, sExit, face);
#if defined(NOTES_FACE_REACH)
    noteFaceReach(cell, i, height, towards, sExit);
#endif
  }
#endif
  return face;
}

// Carries the ray across `face` after arc length t: the point and tangent there, mapped by
// the face's pairing and re-normalised onto the model (float isometries drift otherwise).
GeodesicRay crossFace(GeodesicRay ray, uint face, float t) {
  CellFace f = cellFaces[face];
  vec4 q = geodesicPoint(ray.p, ray.v, t);
  vec4 u = geodesicTangent(ray.p, ray.v, t);
#if defined(PAIRING_TRANSLATION)
  q.xyz += f.pairing[3].xyz;  // E3: the tangent is unchanged, the point stays at w = 1
#elif defined(PAIRING_REFLECTION)
  q = reflectInChartPlane(q, f.plane);  // exact: from the face's plane, not a float matrix
  u = reflectInChartPlane(u, f.plane);
#elif defined(PAIRING_ISOMETRY)
  q = f.pairing * q;
  u = f.pairing * u;
#endif  // PAIRING_CHART_CHANGE: the point stays, only its chart changes
  GeodesicRay next;
  next.p = normalizePoint(q);
  next.v = normalizeTangent(next.p, u);
  next.cell = f.target_cell;
  next.enteredFace = f.partner;
  return next;
}
#endif

#if defined(CELL_CROSSING)
// Whether the chart segment o + s d, 0 <= s <= sMax, meets the box around what its cell traces
// (Cell.content_lo/hi): one that does not cannot hit anything there, and skips the traversal.
// Crossing a small domain's faces, most segments of a long geodesic run through the empty part
// of a cell. A segment on the box's boundary plane may be turned away: the box is padded
// beyond everything in it.
bool meetsCellContent(uint cellIndex, vec3 o, vec3 d, float sMax) {
  Cell cell = cellRecord(cellIndex);
  return segmentMeetsBox(cell.content_lo.xyz, cell.content_hi.xyz, o, d, sMax);
}
#endif

#if defined(GEOMETRY_SPHERICAL) && defined(CELL_CROSSING)
const float GEODESIC_PERIOD = 6.28318530717958647692 * (1.0 + 1e-4);
#endif

// Follows the geodesic until it hits something within arc length maxDistance. On a hit, `ray`
// is the segment that hit (its cell and start) and `travelled` the arc length before it.
bool followGeodesic(inout GeodesicRay ray, float maxDistance, bool anyHit, out ChartHit hit,
                    out float travelled) {
  travelled = 0.0;
#if !defined(CELL_CROSSING)
  ChartLine whole = chartLineOf(ray);
  float sWhole = maxDistance >= FAR ? FAR : chartParameter(whole.p, whole.v, maxDistance);
  ++tracedRays;
  hit = traceChart(whole.o, whole.d, sWhole, ray.cell, whole.p, whole.v, anyHit);
  return hit.kind != HIT_NONE;
#else
#if defined(INTERNAL_WALLS)
  uint walls = 0u;  // crossed between pieces of the domain: bounded apart from MAX_CROSSINGS
#endif
#if defined(GEOMETRY_SPHERICAL)
  // Every geodesic of S3 closes after one turn, 2 pi, and so does its image in a quotient: a
  // hit at t + 2 pi is one at t, so what it has not met in one turn it never meets. It then
  // ends as a miss instead of running on to the crossing cap (a little past 2 pi, for the
  // float sum of its segments, to keep the back of the surface it left).
  maxDistance = min(maxDistance, GEODESIC_PERIOD);
#endif
  for (uint crossing = 0u; crossing <= MAX_CROSSINGS;) {
    ChartLine line = chartLineOf(ray);
    float sExit;
    uint face = exitFace(ray, line, sExit);
    float tExit = face == NO_FACE ? FAR : distanceFromChartParameter(line.p, line.v, sExit);
    float remaining = maxDistance - travelled;
    bool last = face == NO_FACE || remaining <= tExit;
    float sMax = remaining < tExit ? chartParameter(line.p, line.v, remaining) : sExit;
    ++tracedRays;
    float sTrace = sMax;
#if defined(HAS_TUBES)
    // A tube hit bounds the traversal: only something nearer can replace it.
    ChartHit tube = nearestTube(ray.cell, line.o, line.d, sMax, anyHit);
    if (tube.kind != HIT_NONE && anyHit) {
      hit = tube;
      return true;
    }
    sTrace = min(sMax, tube.s);
#endif
    hit = meetsCellContent(ray.cell, line.o, line.d, sTrace)
              ? traceChart(line.o, line.d, sTrace, ray.cell, line.p, line.v, anyHit)
              : noChartHit();
#if defined(HAS_TUBES)
    if (hit.kind == HIT_NONE) hit = tube;
#endif
    if (hit.kind != HIT_NONE) return true;
    if (last) return false;
    travelled += tExit;
    ray = crossFace(ray, face, tExit);
    ++crossedFaces;
#if defined(INTERNAL_WALLS)
    if (cellFaces[face].internal != 0u) {
      if (++walls > MAX_WALL_CROSSINGS) break;
      continue;
    }
#endif
    ++crossing;
  }
  ++truncatedRays;  // ran out of crossings before reaching maxDistance
  return false;
#endif
}

// True when something lies on the geodesic within `distance` (a shadow ray).
bool occluded(GeodesicRay ray, float distance) {
  ChartHit hit;
  float travelled;
  return followGeodesic(ray, distance, true, hit, travelled);
}

#endif
