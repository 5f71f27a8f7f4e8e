// What every entry point and hit shader includes first: data layout, random numbers,
// sampling, the model geometry and the primitives' surface records.
#ifndef CORE_GLSL
#define CORE_GLSL
#include "common/scene_data.glsl"
#include "common/random.glsl"
#include "common/sampling.glsl"
#include "geometry/euclidean.glsl"
#include "primitives/sphere.glsl"
#include "primitives/surface.glsl"
#endif
