// The surface record a closest hit produces: where the ray stopped, the normals facing the
// incoming ray, and the material. Shared by closest-hit shaders and the ray-query kernel.
#ifndef SURFACE_GLSL
#define SURFACE_GLSL

struct Surface {
  vec3 position;
  float t;
  vec3 normal;          // shading normal, on the side the ray came from
  uint material;
  vec3 geometricNormal;  // true face normal, same side
  uint hit;              // 0 when the ray escaped
};

Surface noSurface() {
  Surface s;
  s.position = vec3(0.0);
  s.t = -1.0;
  s.normal = vec3(0.0, 0.0, 1.0);
  s.material = 0u;
  s.geometricNormal = vec3(0.0, 0.0, 1.0);
  s.hit = 0u;
  return s;
}

Surface facing(Surface s, vec3 rayDirection) {
  if (dot(s.geometricNormal, rayDirection) > 0.0) s.geometricNormal = -s.geometricNormal;
  if (dot(s.normal, s.geometricNormal) < 0.0) s.normal = -s.normal;
  return s;
}

Surface triangleSurface(uint primitive, vec2 barycentrics, Ray ray, float t) {
  uint i0 = indices[3u * primitive];
  uint i1 = indices[3u * primitive + 1u];
  uint i2 = indices[3u * primitive + 2u];
  vec3 a = positions[i0].xyz, b = positions[i1].xyz, c = positions[i2].xyz;
  float w = 1.0 - barycentrics.x - barycentrics.y;
  Surface s;
  s.position = w * a + barycentrics.x * b + barycentrics.y * c;
  s.t = t;
  s.geometricNormal = normalize(cross(b - a, c - a));
  s.normal = s.geometricNormal;
  if (triangles[primitive].smoothNormals != 0u) {
    vec3 n = w * normals[i0].xyz + barycentrics.x * normals[i1].xyz + barycentrics.y * normals[i2].xyz;
    if (dot(n, n) > 0.0) s.normal = normalize(n);
  }
  s.material = triangles[primitive].material;
  s.hit = 1u;
  return facing(s, ray.direction);
}

Surface sphereSurface(uint primitive, Ray ray, float t) {
  Sphere sphere = spheres[primitive];
  Surface s;
  s.t = t;
  vec3 p = geodesicPoint(ray, t);
  s.geometricNormal = normalize(p - sphere.centerRadius.xyz);
  // Project onto the sphere: removes the error of the ray parameter from the position.
  s.position = sphere.centerRadius.xyz + sphere.centerRadius.w * s.geometricNormal;
  s.normal = s.geometricNormal;
  s.material = sphere.material;
  s.hit = 1u;
  return facing(s, ray.direction);
}

#endif
