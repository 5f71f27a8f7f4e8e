// Bounding boxes of geodesic spheres in a chart. A geodesic sphere's chart image is a quadric
// {Y = (X, 1) : Y^T Q Y <= 0}; its axis-aligned box comes from the dual quadric Q^-1: the
// planes X_i = s tangent to it satisfy Q*_44 s^2 - 2 Q*_i4 s + Q*_ii = 0.
#pragma once

#include <optional>

#include "geometry/model.h"

namespace geodesic {

struct ChartBox {
  Vec3 lo, hi;
};

// The chart box of the sphere of radius r around the model point c (in the chart's frame),
// or nothing when its image is unbounded (S3: the ball reaches the chart's equator w = 0).
std::optional<ChartBox> sphere_chart_box(GeometryKind k, const Vec4& c, double r);

// Intersection of two boxes, or nothing when they are disjoint.
std::optional<ChartBox> intersect(const ChartBox& a, const ChartBox& b);

}  // namespace geodesic
