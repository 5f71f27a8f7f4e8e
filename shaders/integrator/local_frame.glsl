// Shading happens in the tangent space at the origin: the transvection taking the hit point
// to the origin carries the surface's tangent vectors there, where the metric is the plain
// dot product of their xyz parts. So BSDFs and sampling are written once, for all geometries.
#ifndef LOCAL_FRAME_GLSL
#define LOCAL_FRAME_GLSL

struct LocalFrame {
  mat4 toOrigin;    // translationFrom(q)
  mat4 fromOrigin;  // translationTo(q)
};

LocalFrame localFrameAt(vec4 q) { return LocalFrame(translationFrom(q), translationTo(q)); }

// A unit tangent at q as a 3-vector at the origin, and back.
vec3 toLocal(LocalFrame f, vec4 u) { return normalize((f.toOrigin * u).xyz); }
vec4 fromLocal(LocalFrame f, vec3 u) { return f.fromOrigin * vec4(u, 0.0); }

#endif
