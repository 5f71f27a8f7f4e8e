// The domain's edge tubes (HAS_TUBES): capsules in the cell's chart (server/scene/scene.h
// EdgeTube), tested analytically against each chart segment of a geodesic rather than through
// the acceleration structure: a segment starts and ends on the domain's faces, beside the
// tubes, where a tree of their triangles was deep and every box overlapped the segment. A line
// that misses a tube's infinite cylinder costs one quadratic's discriminant, and a tube is
// tested at all only when the segment comes near both faces that hold its axis.
#ifndef EDGE_TUBE_GLSL
#define EDGE_TUBE_GLSL
#if defined(HAS_TUBES)
#include "geometry/capsule.glsl"

// The chart parameter from which the current chart line lies within the cell's tube reach of
// its local face i (i < 32): 0 when it starts there, FAR when it never comes so near. The
// tracer's pass over the faces fills it (noteFaceReach) for nearFaces, which then reads no
// plane again.
float faceReachedAt[32];

// Face i's plane lies `height` above the line's start and the line approaches it at rate
// `towards` per unit of chart parameter.
void noteFaceReach(Cell c, uint i, float height, float towards) {
  if (i >= 32u) return;
  float beyond = height - c.tube_reach;
  faceReachedAt[i] = beyond <= 0.0 ? 0.0 : towards > 0.0 ? beyond / towards : FAR;
}

// Bit i set when local face i of the cell (i < 32) comes within its tube reach of the segment
// s in [0, sMax] of the line noteFaceReach saw: min(h(0), h(sMax)) <= reach, h linear in s
// (near_faces in server/render/tube_culling.h).
uint nearFaces(Cell c, float sMax) {
  uint near = 0u;
  for (uint i = 0u; i < min(c.face_count, 32u); ++i)
    if (faceReachedAt[i] <= sMax) near |= 1u << i;
  return near;
}

// Tests tube i against o + s d, s in (0, min(sMax, hit.s)]: the nearer hit.
void testTube(uint i, vec3 o, vec3 d, float sMax, inout ChartHit hit) {
  vec4 a = tubes[i].a;
  float s = intersectCapsule(a.xyz, tubes[i].b.xyz, a.w, o, d, 0.0, min(sMax, hit.s));
  if (s < FAR_CAPSULE) hit = ChartHit(3u, i, s, FAR, vec2(0.0));
}

// The nearest tube of the cell on o + s d, s in (0, sMax] (for a shadow ray any tube);
// kind 3 and the tube's index, or no hit. Only tubes both of whose faces are near are tested,
// each found from its pair of faces without reading the others (CellFace.tube_partners). The
// faces' reach is that noteFaceReach noted for this line.
ChartHit nearestTube(uint cell, vec3 o, vec3 d, float sMax, bool anyHit) {
  ChartHit hit = noChartHit();
  Cell c = cellRecord(cell);
  if (c.tube_count == 0u) return hit;
  uint near = nearFaces(c, sMax);
  for (uint pending = near; pending != 0u; pending &= pending - 1u) {
    CellFace face = cellFaces[c.face_begin + uint(findLSB(pending))];
    for (uint pairs = face.tube_partners & near; pairs != 0u; pairs &= pairs - 1u) {
      uint below = (1u << uint(findLSB(pairs))) - 1u;
      testTube(c.tube_begin + face.tubes + uint(bitCount(face.tube_partners & below)), o, d,
               sMax, hit);
      if (anyHit && hit.kind != 0u) return hit;
    }
  }
  for (uint i = c.tube_begin + c.always_begin; i < c.tube_begin + c.tube_count; ++i) {
    testTube(i, o, d, sMax, hit);
    if (anyHit && hit.kind != 0u) return hit;
  }
  return hit;
}

#endif
#endif
