// Shading and the integrator, included by an entry point after it defines
// Surface traceSurface(Ray) and bool traceOccluded(Ray, float maxDistance).
#include "lights/point_light.glsl"
#include "materials/paper_material.glsl"
#include "integrator/path_tracer.glsl"
