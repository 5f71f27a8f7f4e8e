// Triangle meshes from files (OBJ, glTF/GLB and whatever else assimp imports).
#pragma once

#include <filesystem>

#include "geometry/vec.h"
#include "scene/scene.h"

namespace geodesic {

// Reads every mesh of the file, with node transforms applied and polygons triangulated,
// into one TriangleMesh in the file's coordinates. Normals are kept only when every part of
// the file has them (otherwise the mesh is flat-shaded). Points and lines are dropped.
// Throws std::runtime_error with the reason (unreadable file, no triangles).
TriangleMesh load_mesh_file(const std::filesystem::path& path);

// Maps x to rotation · (scale ⊙ x) + translation; only the upper-left 3x3 of rotation is
// used. Normals follow the inverse transpose, so they stay perpendicular under any scale.
void transform_mesh(TriangleMesh& mesh, const Vec3& scale, const Mat4& rotation,
                    const Vec3& translation);

}  // namespace geodesic
