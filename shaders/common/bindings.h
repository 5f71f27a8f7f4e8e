// Descriptor binding numbers of set 0: the one definition, read by the shaders
// (common/scene_data.glsl) and by the host (server/render/prepare/scene_bindings.h), which both
// compile it (plain #defines: valid GLSL and C++). tests/unit/gpu_layout_test.cpp checks that
// each binding holds the block the host binds there.
#ifndef GEODESIC_BINDINGS_H
#define GEODESIC_BINDINGS_H

#define BINDING_SCENE 0          // the acceleration structure
#define BINDING_ACCUMULATION 1
#define BINDING_FRAME 2          // uniform block
#define BINDING_SPHERES 3
#define BINDING_MATERIALS 4
#define BINDING_LIGHTS 5         // the paper model's point lights
#define BINDING_POSITIONS 6
#define BINDING_NORMALS 7
#define BINDING_INDICES 8
#define BINDING_TRIANGLES 9
#define BINDING_RAY_COUNTS 10
#define BINDING_SPHERE_REFS 11
#define BINDING_CELLS 12
#define BINDING_CELL_FACES 13
#define BINDING_DIAGNOSTICS 14
#define BINDING_EMITTERS 15
#define BINDING_LIGHT_IMAGES 16
#define BINDING_TUBES 17
#define BINDING_SHAPES 18
#define BINDING_SHAPE_REFS 19
#define BINDING_LISTED 20        // the primitives of the cells that list their triangles
#define BINDING_COUNT 21

#endif
