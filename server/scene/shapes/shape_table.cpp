// The C++ shape table: every kind of analytic shape (scene/shape.h), in the order of their
// numbers (shaders/common/shape_kinds.h; shape_table_test holds the order). A new kind adds
// its module's ShapeKind here.
#include <stdexcept>

#include "scene/shape.h"

namespace geodesic {

extern const ShapeKind kHorosphere;

const std::vector<const ShapeKind*>& shape_kinds() {
  static const std::vector<const ShapeKind*> kinds{&kHorosphere};
  return kinds;
}

const ShapeKind* find_shape_kind(std::string_view type) {
  for (const ShapeKind* kind : shape_kinds())
    if (kind->type == type) return kind;
  return nullptr;
}

const ShapeKind& shape_kind(uint32_t id) {
  if (id >= shape_kinds().size()) throw std::out_of_range("no shape kind " + std::to_string(id));
  return *shape_kinds()[id];
}

}  // namespace geodesic
