// A capsule in a chart: the points within chart distance r of the segment [a, b] (a cylinder
// with hemispherical caps). The domain's edge tubes are capsules in their cell's chart,
// intersected analytically by the tracer (shaders/primitives/edge_tube.glsl).
// shaders/geometry/capsule.glsl is the float twin of these routines, held to them by
// tests/render/capsule_probe_test.cpp.
#pragma once

#include "geometry/vec.h"

namespace geodesic {

struct Capsule {
  Vec3 a, b;  // the axis' ends, chart coordinates
  double radius = 0;
};

// The smallest s in (s_min, s_max] at which the chart line o + s d meets the capsule's surface
// (entering or leaving it), or +infinity. d need not be a unit vector.
double intersect_capsule(const Capsule& c, const Vec3& o, const Vec3& d, double s_min,
                         double s_max);

// The unit outward normal of the capsule's surface at chart point x: away from the nearest
// point of the axis.
Vec3 capsule_normal(const Capsule& c, const Vec3& x);

// Chart distance from x to the capsule's axis segment (its surface is where this equals r).
double distance_to_axis(const Capsule& c, const Vec3& x);

}  // namespace geodesic
