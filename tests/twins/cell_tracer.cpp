#include "twins/cell_tracer.h"

#include <algorithm>
#include <limits>

namespace geodesic {

const CellFace& face_at(const std::vector<Cell>& cells, int face) {
  for (const Cell& cell : cells)
    if (face >= cell.face_begin && face < cell.face_begin + int(cell.faces.size()))
      return cell.faces[face - cell.face_begin];
  return cells.at(0).faces.at(size_t(face));
}

CellExit exit_cell(GeometryKind k, const std::vector<Cell>& cells, const CellRay& ray) {
  const Cell& cell = cells.at(size_t(ray.cell));
  const Vec4 p = cell.chart_isometry * ray.p, v = cell.chart_isometry * ray.v;
  const Vec3 o = model::chart(k, p), d = model::chart_direction(k, p, v);
  CellExit exit;
  exit.s = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < cell.faces.size(); ++i) {
    const int f = cell.face_begin + int(i);
    if (f == ray.entered_face) continue;
    const double towards = dot(cell.faces[i].normal, d);
    if (towards <= 0) continue;
    const double s = std::max(0.0, (cell.faces[i].delta - dot(cell.faces[i].normal, o)) / towards);
    if (s < exit.s) {
      exit.s = s;
      exit.face = f;
    }
  }
  exit.t = exit.face < 0 ? std::numeric_limits<double>::infinity()
                         : model::distance_from_chart_parameter(k, p, v, exit.s);
  return exit;
}

CellRay cross_face(GeometryKind k, const std::vector<Cell>& cells, const CellRay& ray, int face,
                   double t) {
  const CellFace& f = face_at(cells, face);
  CellRay next;
  next.p = model::normalize_point(k, f.pairing * model::geodesic_point(k, ray.p, ray.v, t));
  next.v = model::normalize_tangent(k, next.p, f.pairing * model::geodesic_tangent(k, ray.p, ray.v, t));
  next.cell = f.target_cell;
  next.entered_face = f.partner;
  return next;
}

}  // namespace geodesic
