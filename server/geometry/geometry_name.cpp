#include "geometry/model.h"

namespace geodesic {

const char* geometry_name(GeometryKind kind) {
  switch (kind) {
    case GeometryKind::Hyperbolic: return "hyperbolic";
    case GeometryKind::Spherical: return "spherical";
    default: return "euclidean";
  }
}

}  // namespace geodesic
