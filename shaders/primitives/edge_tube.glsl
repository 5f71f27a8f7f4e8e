// The domain's edge tubes (HAS_TUBES): capsules in the cell's chart (server/scene/scene.h
// EdgeTube), tested analytically against each chart segment of a geodesic rather than through
// the acceleration structure: a segment starts and ends on the domain's faces, beside the
// tubes, where a tree of their triangles was deep and every box overlapped the segment. A line
// that misses a tube's infinite cylinder costs one quadratic's discriminant, and a tube is
// tested at all only when the segment comes near both faces that hold its axis, and near both
// at once where those are the only near faces.
#ifndef EDGE_TUBE_GLSL
#define EDGE_TUBE_GLSL
#if defined(HAS_TUBES)
#include "geometry/capsule.glsl"

// Where along the segment s in [0, sMax] every near face is within the tubes' reach at once,
// [lo, hi] (empty when lo > hi): each near face, `beyond` the reach at s = 0 and approached at
// `towards` per unit of s, holds for s >= beyond / towards when it is approached and for
// s <= beyond / towards when it is left. A segment runs from the face it entered by to the one
// it leaves by, so those two are near, at its two ends; they hold one tube between them, which
// a point of the segment can meet only where it is within reach of both (a tube lies within its
// radius of both planes). When no other face is near and their spans do not meet, nothing is
// tested: most segments of a crossing geodesic pass a cell that way, far from its edges.
struct NearSpan {
  float lo, hi;
};

void narrowNearSpan(inout NearSpan span, float beyond, float towards) {
  float s = beyond / towards;
  span.lo = towards > 0.0 ? max(span.lo, s) : span.lo;
  span.hi = towards < 0.0 ? min(span.hi, s) : span.hi;
}

// The near faces, none when there are at most two and their span is empty (past a slack of
// 1e-4 of the segment and 1e-6 of the chart, far beyond float round-off; near_faces in
// server/render/prepare/tube_culling.h).
uint nearFacesMeeting(uint near, NearSpan span, float sMax) {
  float slack = 1e-4 * sMax + 1e-6;
  return bitCount(near) < 3 && span.lo > span.hi + slack ? 0u : near;
}

#if defined(CELL_RANGES)
// Bit i set when local face i of the cell (i < 32) comes within its tube reach of the segment
// o + s d, s in [0, sMax]: min(h(0), h(sMax)) <= reach, h linear in s, or none
// (nearFacesMeeting; near_faces in server/render/prepare/tube_culling.h). A one-cell space's face range is baked in, so this
// pass over every face has constant indices: each plane is loaded once for the SIMD group and
// the loop unrolls. That costs less than noting the faces during the exit search and reading
// back the few a line approaches, whose indices differ between lanes (a gather per plane):
// 6-18 % of those spaces' time on lavapipe (docs/quotient-speed.md, "Edge tubes found by
// passes of constants"). With OPPOSITE_FACES face 2k + 1 is face 2k's plane negated, so one pair
// takes one dot product with each of o and d; the results are the same to the bit.
uint nearFaces(Cell c, vec3 o, vec3 d, float sMax) {
  uint near = 0u;
  NearSpan span = NearSpan(0.0, sMax);
#if defined(OPPOSITE_FACES)
  for (uint i = 0u; i < min(c.face_count, 32u); i += 2u) {
    vec4 plane = facePlane(c.face_begin + i);
    float across = dot(plane.xyz, o), towards = dot(plane.xyz, d);
    float beyond = plane.w - across - c.tube_reach, opposite = plane.w + across - c.tube_reach;
    if (beyond <= 0.0 || beyond <= sMax * towards) {
      near |= 1u << i;
      narrowNearSpan(span, beyond, towards);
    }
    if (opposite <= 0.0 || opposite <= sMax * -towards) {
      near |= 2u << i;
      narrowNearSpan(span, opposite, -towards);
    }
  }
#else
  for (uint i = 0u; i < min(c.face_count, 32u); ++i) {
    vec4 plane = facePlane(c.face_begin + i);
    float beyond = plane.w - dot(plane.xyz, o) - c.tube_reach, towards = dot(plane.xyz, d);
    if (beyond <= 0.0 || beyond <= sMax * towards) {
      near |= 1u << i;
      narrowNearSpan(span, beyond, towards);
    }
  }
#endif
  return nearFacesMeeting(near, span, sMax);
}
#else
// The tracer's pass over the faces notes their reach (exitFace).
#define NOTES_FACE_REACH

// Which of the cell's local faces (i < 32) the current chart line comes within the cell's
// tube reach of, as the tracer's pass over the faces (exitFace) sees them: those it starts
// near, and those it moves towards and reaches before the exit found so far, which may be
// nearer once the pass ends (nearFaces checks them again against the segment's end), and the
// span of those it starts near.
uint nearAtStart = 0u, nearAhead = 0u;
NearSpan startSpan;

void clearFaceReach() {
  nearAtStart = nearAhead = 0u;
  startSpan = NearSpan(0.0, FAR);
}

// Face i's plane lies `height` above the line's start, the line approaches it at rate
// `towards` per unit of chart parameter, and the pass has found no exit before sExitSoFar.
void noteFaceReach(Cell c, uint i, float height, float towards, float sExitSoFar) {
  if (i >= 32u) return;
  float beyond = height - c.tube_reach;
  if (beyond <= 0.0) {
    nearAtStart |= 1u << i;
    narrowNearSpan(startSpan, beyond, towards);
  } else if (towards > 0.0 && beyond <= sExitSoFar * towards) nearAhead |= 1u << i;
}

// Bit i set when local face i of the cell (i < 32) comes within its tube reach of the segment
// o + s d, s in [0, sMax], of the line noteFaceReach saw: min(h(0), h(sMax)) <= reach, h
// linear in s, or none (nearFacesMeeting; near_faces in server/render/prepare/tube_culling.h).
// Only the faces ahead that the pass kept are read again, a few of the cell's faces.
uint nearFaces(Cell c, vec3 o, vec3 d, float sMax) {
  uint near = nearAtStart;
  NearSpan span = NearSpan(startSpan.lo, min(startSpan.hi, sMax));
  for (uint pending = nearAhead; pending != 0u; pending &= pending - 1u) {
    uint i = uint(findLSB(pending));
    vec4 plane = cellFaces[c.face_begin + i].plane;
    float beyond = plane.w - dot(plane.xyz, o) - c.tube_reach, towards = dot(plane.xyz, d);
    if (beyond <= sMax * towards) {
      near |= 1u << i;
      narrowNearSpan(span, beyond, towards);
    }
  }
  return nearFacesMeeting(near, span, sMax);
}
#endif

// Tests tube i against o + s d, s in (0, min(sMax, hit.s)]: the nearer hit.
void testTube(uint i, vec3 o, vec3 d, float sMax, inout ChartHit hit) {
  vec4 a = tubes[i].a;
  float s = intersectCapsule(a.xyz, tubes[i].b.xyz, a.w, o, d, 0.0, min(sMax, hit.s));
  if (s < FAR_CAPSULE) hit = ChartHit(HIT_TUBE, i, s, FAR, vec2(0.0));
}

// In nearestTube (its near, c, o, d, sMax, hit and anyHit): tests, in index order, the tubes
// BASE + k of the baked masks FACES (at most 32) whose two faces are both near, keeping the
// nearest hit; a shadow ray returns on its first.
#define TEST_MARKED_TUBES(FACES, BASE)                                                        \
  {                                                                                           \
    const uint tubeFaces[] = uint[](FACES);                                                   \
    uint candidates = 0u; /* bit k: tube BASE + k */                                          \
    for (uint k = 0u; k < uint(tubeFaces.length()); ++k)                                      \
      if ((near & tubeFaces[k]) == tubeFaces[k]) candidates |= 1u << k;                       \
    for (; candidates != 0u; candidates &= candidates - 1u) {                                 \
      testTube(c.tube_begin + BASE + uint(findLSB(candidates)), o, d, sMax, hit);             \
      if (anyHit && hit.kind != HIT_NONE) return hit;                                         \
    }                                                                                         \
  }

// The nearest tube of the cell on o + s d, s in (0, sMax] (for a shadow ray any tube);
// HIT_TUBE and the tube's index, or no hit. Only tubes both of whose faces are near are tested:
// in a one-cell space from the baked masks of their faces (TUBE_FACES_k), elsewhere each found
// from its pair of faces without reading the others (CellFace.tube_partners).
ChartHit nearestTube(uint cell, vec3 o, vec3 d, float sMax, bool anyHit) {
  ChartHit hit = noChartHit();
  Cell c = cellRecord(cell);
  if (c.tube_count == 0u) return hit;
  uint near = nearFaces(c, o, d, sMax);
#if defined(TUBE_FACES_0)
  // A one-cell space's tubes held by pairs of faces (at most 128), each as the mask of its two
  // faces (PipelineFeatures::tube_faces), 32 to a define: a loop of constants marks those with
  // both faces near, then each marked one is tested, in the order of the pairs' loop below. A
  // loop over the near faces' records ran a different number of times in each lane and
  // gathered its loads: 5-23 % of those spaces' time on lavapipe, beside the pass above. (One
  // loop over the chunks was not unrolled, and lost it all: one block each.)
  TEST_MARKED_TUBES(TUBE_FACES_0, 0u)
#if defined(TUBE_FACES_1)
  TEST_MARKED_TUBES(TUBE_FACES_1, 32u)
#endif
#if defined(TUBE_FACES_2)
  TEST_MARKED_TUBES(TUBE_FACES_2, 64u)
#endif
#if defined(TUBE_FACES_3)
  TEST_MARKED_TUBES(TUBE_FACES_3, 96u)
#endif
#else
  for (uint pending = near; pending != 0u; pending &= pending - 1u) {
    CellFace face = cellFaces[c.face_begin + uint(findLSB(pending))];
    for (uint pairs = face.tube_partners & near; pairs != 0u; pairs &= pairs - 1u) {
      uint below = (1u << uint(findLSB(pairs))) - 1u;
      testTube(c.tube_begin + face.tubes + uint(bitCount(face.tube_partners & below)), o, d,
               sMax, hit);
      if (anyHit && hit.kind != HIT_NONE) return hit;
    }
  }
#endif
  for (uint i = c.tube_begin + c.always_begin; i < c.tube_begin + c.tube_count; ++i) {
    testTube(i, o, d, sMax, hit);
    if (anyHit && hit.kind != HIT_NONE) return hit;
  }
  return hit;
}

#endif
#endif
