// Tracing through cells, surfaces, shading and the integrators, included by an entry point
// after it defines traceChart().
#include "integrator/geodesic_tracer.glsl"
#include "primitives/surface.glsl"
#include "integrator/local_frame.glsl"
#include "lights/point_light.glsl"
#include "lights/emitters.glsl"
#include "materials/paper_material.glsl"
#include "materials/bsdf.glsl"
#include "integrator/paper_integrator.glsl"
#include "integrator/physical_integrator.glsl"
#include "integrator/path_tracer.glsl"
