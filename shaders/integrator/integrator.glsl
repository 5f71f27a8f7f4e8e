// Tracing through cells, surfaces, shading and the integrators, included by an entry point
// after it defines traceChart(). Each lighting model, its lights and its materials come in
// only when the pipeline's features ask for them (server/render/prepare/pipeline_features.h).
#include "integrator/geodesic_tracer.glsl"
#include "primitives/surface.glsl"
#include "integrator/local_frame.glsl"
#if defined(LIGHTING_PAPER)
#include "lights/point_light.glsl"
#include "materials/paper_material.glsl"
#include "integrator/paper_integrator.glsl"
#endif
#if defined(LIGHTING_PHYSICAL)
#include "lights/emitters.glsl"
#include "materials/bsdf.glsl"
#include "integrator/physical_integrator.glsl"
#endif
#include "integrator/path_tracer.glsl"
