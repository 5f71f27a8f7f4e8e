// The cells a ray is traced through: each cell is a convex region of one chart, with faces
// where a ray leaves it and what happens there (algorithm 1 of the paper, generalised).
//
//   quotient M/Γ        one cell, the fundamental domain; faces carry the pairing isometries
//   E3, H3 (no quotient) one cell without faces: the Klein chart of H3 is global
//   S3 (no quotient)     eight cells, the cubes of the tesseract projected onto S3: each chart
//                        is gnomonic about one of ±e_x, ±e_y, ±e_z, ±e_w and covers the cube
//                        [-1, 1]^3; crossing a cube face changes chart, not the point.
//
// A cell whose faces all come in opposite pairs (N . X = w and -N . X = w, in float) lists each
// pair one after the other, whatever order the domain gave them in: the exit search then takes
// a pair at a time (OPPOSITE_FACES, render/prepare/pipeline_features.h).
#pragma once

#include <vector>

#include "geometry/model.h"
#include "scene/scene.h"

namespace geodesic {

struct CellFace {
  Vec3 normal;       // outward unit normal in the cell's chart
  double delta;      // the face is normal . X = delta
  Mat4 pairing;      // model isometry applied to a ray leaving through this face
  int target_cell;   // the cell the ray continues in
  int partner;       // the face (global index) it enters through
  bool internal = false;  // a wall between pieces of one domain (scene/manifold.h PieceFace)
};

struct Cell {
  Mat4 chart_isometry;  // model -> this cell's frame; chart = (P p).xyz / (P p).w
  int face_begin = 0;   // global index of the first face
  std::vector<CellFace> faces;
};

std::vector<Cell> build_cells(const Scene& scene);

struct CameraPlacement {
  Mat4 pose;          // carried into the fundamental domain, re-orthonormalised
  uint32_t cell = 0;  // the cell whose chart holds the camera
};

// Where a camera pose lives in the cells: in a quotient it is carried into the domain by the
// face pairings (as a walking camera is); in S3's atlas, the cell charted nearest to it.
CameraPlacement place_camera(GeometryKind k, const std::vector<Cell>& cells, const Mat4& pose);

}  // namespace geodesic
