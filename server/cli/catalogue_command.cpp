// `geodesic catalogue [ROOT]`: writes the manifold catalogue from its closed forms
// (server/scene/catalogue.cpp): ROOT/catalogue/<name>.gen and README.md, and a default scene
// per entry in ROOT/scenes/catalogue/<name>.json. Prints each entry's Dirichlet domain.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "scene/catalogue.h"
#include "scene/default_scene.h"
#include "scene/dirichlet_domain.h"

namespace geodesic {
namespace {

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

}  // namespace

int catalogue_command(int argc, char** argv) {
  if (argc > 1) throw std::invalid_argument("expected at most one argument, ROOT");
  if (argc == 1 && argv[0][0] == '-')
    throw std::invalid_argument(std::string("unknown option ") + argv[0] + " (catalogue [ROOT])");
  const std::filesystem::path root = argc == 1 ? argv[0] : ".";
  const auto data = root / "catalogue", scenes = root / "scenes" / "catalogue";
  std::filesystem::create_directories(data);
  std::filesystem::create_directories(scenes);
  write_file(data / "README.md", catalogue_readme());
  std::printf("%-22s %5s %6s %9s %12s %12s %9s %8s\n", "name", "faces", "verts", "elements",
              "volume", "expected", "iso.err", "seconds");
  for (const CatalogueEntry& e : catalogue()) {
    write_file(data / (e.name + ".gen"), catalogue_gen_text(e));
    const DirichletDomain d = dirichlet_domain(e.kind, e.generators);
    const auto scene = default_scene_document(
        e.title, e.kind, {{"type", "generators"}, {"file", "../../catalogue/" + e.name + ".gen"}}, d);
    write_file(scenes / (e.name + ".json"), scene.dump(2) + "\n");
    std::printf("%-22s %5zu %6zu %9zu %12.9f %12.9f %9.1e %8.3f\n", e.name.c_str(),
                d.manifold.faces.size(), d.manifold.domain.vertices.size(), d.elements, d.volume,
                e.volume, d.isometry_error, d.seconds);
  }
  return 0;
}

}  // namespace geodesic
