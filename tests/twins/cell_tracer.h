// Double-precision twin of shaders/integrator/geodesic_tracer.glsl: where a geodesic leaves
// its cell and how it is carried across the face (the paper's algorithm 1 over cells). The
// tests hold the shader's behaviour and the manifolds' pairings to it.
#pragma once

#include <vector>

#include "render/prepare/cells.h"

namespace geodesic {

struct CellRay {
  Vec4 p;                 // model point
  Vec4 v;                 // unit tangent at p
  int cell = 0;
  int entered_face = -1;  // the face it came in through (never its exit); -1: none
};

struct CellExit {
  int face = -1;  // global face index; -1: the cell has no face ahead
  double s = 0;   // chart parameter of the exit
  double t = 0;   // arc length to the exit
};

// exitFace() of the shader: the first face the chart line moves towards.
CellExit exit_cell(GeometryKind k, const std::vector<Cell>& cells, const CellRay& ray);

// crossFace() of the shader: point and tangent at arc length t, mapped by the face's pairing
// and re-normalised onto the model.
CellRay cross_face(GeometryKind k, const std::vector<Cell>& cells, const CellRay& ray, int face,
                   double t);

// The face with global index `face` (cells number their faces consecutively).
const CellFace& face_at(const std::vector<Cell>& cells, int face);

}  // namespace geodesic
