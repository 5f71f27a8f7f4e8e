// The analytic shapes' kind numbers (Shape.kind in common/gpu_types.h): the one definition,
// compiled by the GLSL shape table (primitives/shape_table.glsl) and by each shape's C++
// module (server/scene/shapes/). A new shape takes the next number.
#ifndef GEODESIC_SHAPE_KINDS_H
#define GEODESIC_SHAPE_KINDS_H

#define SHAPE_HOROSPHERE 0u

#endif
