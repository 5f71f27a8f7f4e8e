// Tracing through cells, surfaces, shading and the integrator, included by an entry point
// after it defines traceChart().
#include "integrator/geodesic_tracer.glsl"
#include "primitives/surface.glsl"
#include "integrator/local_frame.glsl"
#include "lights/point_light.glsl"
#include "materials/paper_material.glsl"
#include "integrator/path_tracer.glsl"
