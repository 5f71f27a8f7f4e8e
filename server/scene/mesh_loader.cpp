#include "scene/mesh_loader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <stdexcept>

namespace geodesic {

TriangleMesh load_mesh_file(const std::filesystem::path& path) {
  Assimp::Importer importer;
  // Only triangles are renderable: sorting by primitive type lets assimp drop the rest.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* ai = importer.ReadFile(
      path.string(), aiProcess_Triangulate | aiProcess_SortByPType |
                         aiProcess_PreTransformVertices | aiProcess_JoinIdenticalVertices);
  if (ai == nullptr) throw std::runtime_error(importer.GetErrorString());

  bool all_have_normals = ai->mNumMeshes > 0;
  for (unsigned m = 0; m < ai->mNumMeshes; ++m)
    all_have_normals = all_have_normals && ai->mMeshes[m]->HasNormals();

  TriangleMesh mesh;
  for (unsigned m = 0; m < ai->mNumMeshes; ++m) {
    const aiMesh& part = *ai->mMeshes[m];
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    for (unsigned v = 0; v < part.mNumVertices; ++v) {
      const aiVector3D& p = part.mVertices[v];
      mesh.positions.emplace_back(p.x, p.y, p.z);
      if (all_have_normals) {
        const aiVector3D& n = part.mNormals[v];
        mesh.normals.emplace_back(n.x, n.y, n.z);
      }
    }
    for (unsigned f = 0; f < part.mNumFaces; ++f) {
      const aiFace& face = part.mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (unsigned k = 0; k < 3; ++k) mesh.indices.push_back(base + face.mIndices[k]);
    }
  }
  if (mesh.indices.empty()) throw std::runtime_error("the file contains no triangles");
  return mesh;
}

void transform_mesh(TriangleMesh& mesh, const Vec3& scale, const Mat4& rotation,
                    const Vec3& translation) {
  for (Vec3& p : mesh.positions) p = (rotation * Vec4(p * scale, 0)).xyz() + translation;
  const Vec3 inverse_scale(1 / scale.x, 1 / scale.y, 1 / scale.z);
  for (Vec3& n : mesh.normals) n = normalize((rotation * Vec4(n * inverse_scale, 0)).xyz());
}

}  // namespace geodesic
