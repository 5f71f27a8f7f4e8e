// Shading happens in the tangent space at the origin: the transvection taking the hit point
// to the origin carries the surface's tangent vectors there, where the metric is the plain
// dot product of their xyz parts. So BSDFs and sampling are written once, for all geometries.
// In E3 translations leave tangent vectors unchanged, and the frame compiles away.
#ifndef LOCAL_FRAME_GLSL
#define LOCAL_FRAME_GLSL

#if defined(GEOMETRY_HYPERBOLIC) || defined(GEOMETRY_SPHERICAL)
struct LocalFrame {
  mat4 toOrigin;    // translationFrom(q)
  mat4 fromOrigin;  // translationTo(q)
};

LocalFrame localFrameAt(vec4 q) { return LocalFrame(translationFrom(q), translationTo(q)); }

// A unit tangent at q as a 3-vector at the origin, and back.
vec3 toLocal(LocalFrame f, vec4 u) { return normalize((f.toOrigin * u).xyz); }
vec4 fromLocal(LocalFrame f, vec3 u) { return f.fromOrigin * vec4(u, 0.0); }
#else
struct LocalFrame {
  uint unused;
};

LocalFrame localFrameAt(vec4 q) { return LocalFrame(0u); }
vec3 toLocal(LocalFrame f, vec4 u) { return u.xyz; }
vec4 fromLocal(LocalFrame f, vec3 u) { return vec4(u, 0.0); }
#endif

#endif
