// What every entry point and hit shader includes first: data layout, random numbers,
// sampling, the scene's model geometry (chosen by a GEOMETRY_* define at compile time) and
// the chart ray / hit records.
#ifndef CORE_GLSL
#define CORE_GLSL
#include "common/scene_data.glsl"
#include "common/random.glsl"
#include "common/sobol.glsl"
#include "common/sampler.glsl"
#include "common/sampling.glsl"
#include "geometry/model.glsl"
#include "integrator/chart_ray.glsl"
#endif
