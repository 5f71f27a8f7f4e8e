#include "render/prepare/cells.h"

#include <cmath>

namespace geodesic {
namespace {

// The signed permutation carrying the axis `sign * e_axis` to e_w (an isometry of S3).
Mat4 chart_isometry_for(int axis, int sign) {
  Mat4 p;
  for (int i = 0; i < 4; ++i) p.m[i][i] = 1;
  if (axis != 3) {
    p.m[axis][axis] = 0;
    p.m[3][3] = 0;
    p.m[3][axis] = sign;  // new w = sign * old axis coordinate
    p.m[axis][3] = sign;  // and the old w takes the axis' place
  } else if (sign < 0) {
    for (int i = 0; i < 4; ++i) p.m[i][i] = -1;
  }
  return p;
}

// The model point a cell's chart is centred on: P^-1 e_w = P^T e_w.
Vec4 centre_of(const Mat4& p) { return {p.m[3][0], p.m[3][1], p.m[3][2], p.m[3][3]}; }

bool same(const Vec4& a, const Vec4& b) {
  return std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z) + std::abs(a.w - b.w) <
         1e-9;
}

bool is_identity(const Mat4& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (g.m[i][j] != (i == j ? 1.0 : 0.0)) return false;
  return true;
}

std::vector<Cell> tesseract_atlas() {
  std::vector<Cell> cells;
  for (int axis = 0; axis < 4; ++axis)
    for (int sign : {1, -1}) cells.push_back({chart_isometry_for(axis, sign), 0, {}});
  for (size_t c = 0; c < cells.size(); ++c) {
    cells[c].face_begin = static_cast<int>(c * 6);
    for (int i = 0; i < 3; ++i)
      for (int sign : {1, -1}) {
        Vec3 normal;
        (i == 0 ? normal.x : i == 1 ? normal.y : normal.z) = sign;
        cells[c].faces.push_back({normal, 1.0, Mat4::identity(), -1, -1});
      }
  }
  // Past face (i, sign) of cell c lies the cell centred on P_c^T (sign e_i); it is entered
  // through its face looking back at c's centre.
  for (size_t c = 0; c < cells.size(); ++c)
    for (size_t f = 0; f < 6; ++f) {
      const Vec3 n = cells[c].faces[f].normal;
      const Mat4& p = cells[c].chart_isometry;
      // P^T (n, 0): column-vector product with the transpose.
      const Vec4 beyond{p.m[0][0] * n.x + p.m[1][0] * n.y + p.m[2][0] * n.z,
                        p.m[0][1] * n.x + p.m[1][1] * n.y + p.m[2][1] * n.z,
                        p.m[0][2] * n.x + p.m[1][2] * n.y + p.m[2][2] * n.z,
                        p.m[0][3] * n.x + p.m[1][3] * n.y + p.m[2][3] * n.z};
      for (size_t t = 0; t < cells.size(); ++t) {
        if (!same(centre_of(cells[t].chart_isometry), beyond)) continue;
        const Vec4 back = cells[t].chart_isometry * centre_of(p);  // c's centre, in t's frame
        for (size_t g = 0; g < 6; ++g) {
          const Vec3 m = cells[t].faces[g].normal;
          if (same({m.x, m.y, m.z, 0}, {back.x, back.y, back.z, 0})) {
            cells[c].faces[f].target_cell = static_cast<int>(t);
            cells[c].faces[f].partner = cells[t].face_begin + static_cast<int>(g);
          }
        }
      }
    }
  return cells;
}

// Whether face b's plane is face a's with its normal negated (N . X = w and -N . X = w), as
// the GPU reads them: in float.
bool opposite_in_float(const CellFace& a, const CellFace& b) {
  return float(b.normal.x) == -float(a.normal.x) && float(b.normal.y) == -float(a.normal.y) &&
         float(b.normal.z) == -float(a.normal.z) && float(b.delta) == float(a.delta);
}

// Each cell whose faces all come in opposite pairs lists each pair one after the other, so
// that its exit search takes a pair at a time (OPPOSITE_FACES, pipeline_features.cpp); the
// faces' partners are renumbered with them. A face has one opposite at most (two faces of a
// convex cell do not share a plane), so the first unmatched one found is its pair.
void list_opposite_faces_together(std::vector<Cell>& cells) {
  std::vector<int> moved_to;  // global face index: where it is listed now
  for (Cell& cell : cells) {
    const size_t n = cell.faces.size();
    std::vector<int> order;
    std::vector<bool> taken(n, false);
    for (size_t i = 0; i < n; ++i) {
      if (taken[i]) continue;
      for (size_t j = i + 1; j < n; ++j)
        if (!taken[j] && opposite_in_float(cell.faces[i], cell.faces[j])) {
          taken[i] = taken[j] = true;
          order.insert(order.end(), {int(i), int(j)});
          break;
        }
    }
    moved_to.resize(size_t(cell.face_begin) + n);
    for (size_t i = 0; i < n; ++i) moved_to[cell.face_begin + i] = cell.face_begin + int(i);
    if (order.size() != n) continue;  // not every face has its opposite: left as it is
    std::vector<CellFace> faces;
    for (size_t k = 0; k < n; ++k) {
      faces.push_back(cell.faces[order[k]]);
      moved_to[cell.face_begin + order[k]] = cell.face_begin + int(k);
    }
    cell.faces = std::move(faces);
  }
  for (Cell& cell : cells)
    for (CellFace& f : cell.faces)
      if (f.partner >= 0) f.partner = moved_to[f.partner];
}

// The cells, and their faces in the order the scene gives them.
std::vector<Cell> listed_cells(const Scene& scene) {
  // A domain cut into pieces charted apart (scene/chart_atlas.h): one cell per piece.
  if (!scene.manifold.pieces.empty()) {
    std::vector<Cell> cells;
    int face_begin = 0;
    for (const DomainPiece& piece : scene.manifold.pieces) {
      Cell cell{piece.chart_isometry, face_begin, {}};
      for (const PieceFace& f : piece.faces)
        cell.faces.push_back({f.normal, f.delta, f.pairing, f.target, f.partner, f.internal});
      face_begin += static_cast<int>(cell.faces.size());
      cells.push_back(std::move(cell));
    }
    return cells;
  }
  if (!scene.manifold.faces.empty()) {
    Cell cell{Mat4::identity(), 0, {}};
    for (const DomainFace& f : scene.manifold.faces)
      cell.faces.push_back({f.normal, f.delta, f.pairing, 0, f.partner});
    return {cell};
  }
  if (scene.geometry == GeometryKind::Spherical) return tesseract_atlas();
  return {Cell{Mat4::identity(), 0, {}}};
}

}  // namespace

CameraPlacement place_camera(GeometryKind k, const std::vector<Cell>& cells, const Mat4& pose) {
  CameraPlacement out{model::reorthonormalize(k, pose), 0};
  if (cells.size() == 1) {
    for (int step = 0; step < 64; ++step) {
      const Vec3 x = model::chart(k, out.pose * model::origin());
      const CellFace* outside = nullptr;
      for (const CellFace& f : cells[0].faces)
        if (dot(f.normal, x) > f.delta) outside = &f;
      if (!outside) break;
      out.pose = model::reorthonormalize(k, outside->pairing * out.pose);
    }
    return out;
  }
  // The cell whose walls towards other cells hold the camera best (the nearest charted on a
  // tie: pieces of a lune all meet along one edge); in a domain cut into pieces, a camera beyond
  // the domain's boundary (a face whose pairing is not the identity) is carried back in first.
  for (int step = 0; step < 64; ++step) {
    double best_outside = INFINITY, best_w = -2;
    for (uint32_t c = 0; c < cells.size(); ++c) {
      const Vec4 q = cells[c].chart_isometry * (out.pose * model::origin());
      if (q.w <= 1e-9 && k == GeometryKind::Spherical) continue;  // beyond the chart's horizon
      const Vec3 x = model::chart(k, q);
      double outside = 0;
      for (const CellFace& f : cells[c].faces)
        if (is_identity(f.pairing)) outside = std::max(outside, dot(f.normal, x) - f.delta);
      if (outside < best_outside - 1e-12 || (outside < best_outside + 1e-12 && q.w > best_w)) {
        best_outside = std::min(best_outside, outside);
        best_w = q.w;
        out.cell = c;
      }
    }
    const Cell& cell = cells[out.cell];
    const Vec3 x = model::chart(k, cell.chart_isometry * (out.pose * model::origin()));
    const CellFace* outside = nullptr;
    for (const CellFace& f : cell.faces)
      if (dot(f.normal, x) > f.delta && !is_identity(f.pairing)) outside = &f;
    if (!outside) break;
    out.pose = model::reorthonormalize(k, outside->pairing * out.pose);
  }
  return out;
}

std::vector<Cell> build_cells(const Scene& scene) {
  std::vector<Cell> cells = listed_cells(scene);
  list_opposite_faces_together(cells);
  return cells;
}

}  // namespace geodesic
