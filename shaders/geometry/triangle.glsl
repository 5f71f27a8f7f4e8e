// A chart line o + s d against a triangle abc given in the chart (geodesic triangles are flat
// there in every geometry). Float twin of server/geometry/model.h intersect_chart_triangle
// (the comments there hold here): the watertight test of Woop, Benthin and Wald (JCGT 2013),
// closed and two-sided, so a line through an edge or a vertex shared by two triangles meets at
// least one of them, as a traversal's triangle test does.
#ifndef TRIANGLE_GLSL
#define TRIANGLE_GLSL

// What the test needs of the line alone, computed once for all the triangles it meets: the
// axes (x, y, z) with z the direction's largest component (x and y swapped where it is
// negative, keeping the winding) and the shear that maps d onto z.
struct ShearedLine {
  uvec3 axis;
  vec3 shear;  // -d_x / d_z, -d_y / d_z, 1 / d_z
};

ShearedLine shearLine(vec3 d) {
  vec3 ad = abs(d);
  uint z = ad.x > ad.y ? (ad.x > ad.z ? 0u : 2u) : (ad.y > ad.z ? 1u : 2u);
  uint x = (z + 1u) % 3u, y = (x + 1u) % 3u;
  if (d[z] < 0.0) {
    uint swap = x;
    x = y;
    y = swap;
  }
  return ShearedLine(uvec3(x, y, z), vec3(-d[x] / d[z], -d[y] / d[z], 1.0 / d[z]));
}

// The s in (sMin, sMax] where the line meets the triangle, or FAR_TRIANGLE; uv: the
// barycentrics of b and c there (position (1 - u - v) a + u b + v c).
const float FAR_TRIANGLE = 1e30;
float intersectChartTriangle(ShearedLine line, vec3 o, vec3 a, vec3 b, vec3 c, float sMin,
                             float sMax, out vec2 uv) {
  uv = vec2(0.0);
  a -= o;
  b -= o;
  c -= o;
  uint x = line.axis.x, y = line.axis.y, z = line.axis.z;
  float ax = a[x] + line.shear.x * a[z], ay = a[y] + line.shear.y * a[z];
  float bx = b[x] + line.shear.x * b[z], by = b[y] + line.shear.y * b[z];
  float cx = c[x] + line.shear.x * c[z], cy = c[y] + line.shear.y * c[z];
  float U = cx * by - cy * bx, V = ax * cy - ay * cx, W = bx * ay - by * ax;
  if ((U < 0.0 || V < 0.0 || W < 0.0) && (U > 0.0 || V > 0.0 || W > 0.0)) return FAR_TRIANGLE;
  float det = U + V + W;
  if (det == 0.0) return FAR_TRIANGLE;  // the line in the triangle's plane, or no triangle
  float s = (U * a[z] + V * b[z] + W * c[z]) * line.shear.z / det;
  if (!(s > sMin && s <= sMax)) return FAR_TRIANGLE;
  uv = vec2(V, W) / det;
  return s;
}

#endif
