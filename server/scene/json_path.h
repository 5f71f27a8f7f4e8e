// JSON reading with paths: every value carries its location in the scene document, so a
// validation error names the exact field, e.g. "objects[3].radius: must be > 0".
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "geometry/vec.h"
#include "scene/scene.h"

namespace geodesic {

// Coordinates beyond this are almost certainly unit mistakes, and would lose too much
// precision once the GPU squares them in float.
inline constexpr double kMaxCoordinate = 1e6;

// A view of one JSON value and its path ("" is the document root).
class JsonNode {
 public:
  JsonNode(const nlohmann::ordered_json& value, std::string path)
      : value_(&value), path_(std::move(path)) {}

  const nlohmann::ordered_json& value() const { return *value_; }
  const std::string& path() const { return path_; }

  [[noreturn]] void fail(const std::string& reason) const {
    throw SceneError((path_.empty() ? "(root)" : path_) + ": " + reason);
  }
  // For errors about a field that may be absent (and so has no node of its own).
  [[noreturn]] void fail_field(const std::string& key, const std::string& reason) const {
    throw SceneError(child_path(key) + ": " + reason);
  }

  // Requires an object whose keys are all in `allowed`.
  void expect_object(std::initializer_list<std::string_view> allowed) const {
    expect_object(std::span(allowed.begin(), allowed.size()));
  }
  void expect_object(std::span<const std::string_view> allowed) const {
    if (!value_->is_object()) fail("must be an object");
    for (const auto& item : value_->items())
      if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end())
        fail("unknown field \"" + item.key() + "\"");
  }

  std::optional<JsonNode> find(const std::string& key) const {
    const auto it = value_->find(key);
    if (it == value_->end()) return std::nullopt;
    return JsonNode(*it, child_path(key));
  }

  JsonNode at(const std::string& key) const {
    if (auto child = find(key)) return *child;
    fail("missing required field \"" + key + "\"");
  }

  // Requires an array of at least min_size elements; returns its size.
  std::size_t expect_array(std::size_t min_size, const std::string& what) const {
    if (!value_->is_array() || value_->size() < min_size) fail("must be " + what);
    return value_->size();
  }

  JsonNode operator[](std::size_t i) const {
    return JsonNode((*value_)[i], path_ + "[" + std::to_string(i) + "]");
  }

 private:
  std::string child_path(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
  }

  const nlohmann::ordered_json* value_;
  std::string path_;
};

inline double read_number(const JsonNode& node) {
  if (!node.value().is_number()) node.fail("must be a number");
  const double x = node.value().get<double>();
  if (!std::isfinite(x)) node.fail("must be a finite number");
  return x;
}

inline double read_non_negative(const JsonNode& node) {
  const auto& v = node.value();
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0)
    node.fail("must be a finite number >= 0");
  return v.get<double>();
}

// A length or scale factor: positive and within the coordinate range.
inline double read_positive(const JsonNode& node) {
  const double x = read_number(node);
  if (x <= 0) node.fail("must be > 0");
  if (x > kMaxCoordinate) node.fail("must be <= 1e6");
  return x;
}

inline std::string read_string(const JsonNode& node) {
  if (!node.value().is_string()) node.fail("must be a string");
  return node.value().get<std::string>();
}

inline int read_int(const JsonNode& node, int lo, int hi) {
  const auto& v = node.value();
  if (!v.is_number_integer() || v.get<int64_t>() < lo || v.get<int64_t>() > hi)
    node.fail("must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(v.get<int64_t>());
}

inline bool read_bool(const JsonNode& node) {
  if (!node.value().is_boolean()) node.fail("must be true or false");
  return node.value().get<bool>();
}

inline uint64_t read_uint64(const JsonNode& node) {
  if (!node.value().is_number_unsigned()) node.fail("must be an unsigned integer");
  return node.value().get<uint64_t>();
}

// A point or direction: [x, y, z] with every coordinate finite and within kMaxCoordinate.
inline Vec3 read_vec3(const JsonNode& node) {
  if (!node.value().is_array() || node.value().size() != 3)
    node.fail("must be an array of 3 numbers");
  double c[3];
  for (std::size_t i = 0; i < 3; ++i) {
    c[i] = read_number(node[i]);
    if (std::abs(c[i]) > kMaxCoordinate) node[i].fail("must have magnitude <= 1e6");
  }
  return {c[0], c[1], c[2]};
}

// An RGB triple [r, g, b] of finite values >= 0, or one number meaning grey.
inline Vec3 read_rgb(const JsonNode& node) {
  if (node.value().is_number()) {
    const double grey = read_non_negative(node);
    return {grey, grey, grey};
  }
  if (!node.value().is_array() || node.value().size() != 3)
    node.fail("must be a number or an array of 3 numbers");
  return {read_non_negative(node[0]), read_non_negative(node[1]), read_non_negative(node[2])};
}

// A 4x4 matrix as 4 rows of 4 numbers, acting on column vectors.
inline Mat4 read_matrix(const JsonNode& node) {
  if (node.expect_array(4, "an array of 4 rows of 4 numbers") != 4)
    node.fail("must be an array of 4 rows of 4 numbers");
  Mat4 g;
  for (std::size_t r = 0; r < 4; ++r) {
    const JsonNode row = node[r];
    if (row.expect_array(4, "a row of 4 numbers") != 4) row.fail("must be a row of 4 numbers");
    for (std::size_t c = 0; c < 4; ++c) g.m[r][c] = read_number(row[c]);
  }
  return g;
}

}  // namespace geodesic
