// An isometry applied to a whole scene: its objects, lights and camera. The renderer uses it to
// work in a frame centred on the camera (render/device/renderer.h), and tests to move a scene far from
// the origin. In H3 it composes in binary128 (geometry/wide_isometry.h), so a scene 20 units
// out is moved back to the origin as precisely as its double coordinates place it.
#pragma once

#include "geometry/model.h"
#include "geometry/wide_isometry.h"
#include "scene/scene.h"

namespace geodesic {

// `scene` moved by the isometry `g` of its geometry's model. Positions stay exponential
// coordinates at the origin; smooth normals (E3) turn with it. The manifold's group is left
// as it is: moving a quotient's content without its domain changes the scene, so callers move
// only scenes of a space without a quotient.
Scene moved_scene(Scene scene, const WideIsometry& g);
// The same with g given in double (the isometry nearest it).
Scene moved_scene(Scene scene, const Mat4& g);

}  // namespace geodesic
