#include "schema_check.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <stdexcept>

namespace geodesic::test {
namespace {

using nlohmann::json;

bool has_type(const json& value, const std::string& type) {
  if (type == "object") return value.is_object();
  if (type == "array") return value.is_array();
  if (type == "string") return value.is_string();
  if (type == "boolean") return value.is_boolean();
  if (type == "null") return value.is_null();
  if (type == "number") return value.is_number();
  if (type == "integer")
    return value.is_number_integer() ||
           (value.is_number_float() && std::floor(value.get<double>()) == value.get<double>());
  throw std::runtime_error("schema: unknown type " + type);
}

const std::set<std::string> kAnnotations = {"$schema", "$id", "$comment", "$defs", "title",
                                            "description", "examples", "default"};

}  // namespace

SchemaCheck::SchemaCheck(const std::filesystem::path& schema_file) {
  std::ifstream in(schema_file);
  if (!in) throw std::runtime_error("cannot read " + schema_file.string());
  root_ = json::parse(in);
}

std::vector<std::string> SchemaCheck::errors(const json& value, const std::string& pointer) const {
  std::vector<std::string> out;
  check(root_.at(json::json_pointer(pointer)), value, "(message)", out);
  return out;
}

void SchemaCheck::check(const json& schema, const json& value, const std::string& path,
                        std::vector<std::string>& out) const {
  auto fail = [&](const std::string& why) { out.push_back(path + ": " + why); };
  for (const auto& [keyword, arg] : schema.items()) {
    if (kAnnotations.count(keyword)) continue;
    if (keyword == "$ref") {
      const std::string ref = arg.get<std::string>();
      if (!ref.starts_with("#")) return fail("external $ref " + ref + " is not checked here");
      check(root_.at(json::json_pointer(ref.substr(1))), value, path, out);
    } else if (keyword == "type") {
      bool ok = false;
      for (const json& t : arg.is_array() ? arg : json::array({arg}))
        ok = ok || has_type(value, t.get<std::string>());
      if (!ok) fail("type is not " + arg.dump());
    } else if (keyword == "const") {
      if (value != arg) fail("must be " + arg.dump());
    } else if (keyword == "enum") {
      if (std::find(arg.begin(), arg.end(), value) == arg.end()) fail("not one of " + arg.dump());
    } else if (keyword == "required") {
      for (const json& key : arg)
        if (value.is_object() && !value.contains(key.get<std::string>()))
          fail("missing " + key.get<std::string>());
    } else if (keyword == "properties") {
      if (!value.is_object()) continue;
      for (const auto& [key, sub] : arg.items())
        if (value.contains(key)) check(sub, value[key], path + "." + key, out);
    } else if (keyword == "additionalProperties") {
      if (!value.is_object()) continue;
      const json& known = schema.value("properties", json::object());
      for (const auto& [key, sub] : value.items())
        if (!known.contains(key)) {
          if (arg.is_boolean() && !arg.get<bool>()) fail("unexpected field " + key);
          else if (arg.is_object()) check(arg, sub, path + "." + key, out);
        }
    } else if (keyword == "items") {
      if (!value.is_array()) continue;
      for (size_t i = 0; i < value.size(); ++i)
        check(arg, value[i], path + "[" + std::to_string(i) + "]", out);
    } else if (keyword == "minItems" || keyword == "maxItems") {
      if (!value.is_array()) continue;
      const bool min = keyword == "minItems";
      if (min ? value.size() < arg.get<size_t>() : value.size() > arg.get<size_t>())
        fail(keyword + " " + arg.dump());
    } else if (keyword == "minimum" || keyword == "maximum" || keyword == "exclusiveMinimum" ||
               keyword == "exclusiveMaximum") {
      if (!value.is_number()) continue;
      const double v = value.get<double>(), bound = arg.get<double>();
      const bool ok = keyword == "minimum"            ? v >= bound
                      : keyword == "maximum"          ? v <= bound
                      : keyword == "exclusiveMinimum" ? v > bound
                                                      : v < bound;
      if (!ok) fail(keyword + " " + arg.dump());
    } else if (keyword == "oneOf" || keyword == "anyOf") {
      std::vector<std::string> branch_errors;
      int matches = 0;
      for (size_t i = 0; i < arg.size(); ++i) {
        std::vector<std::string> sub;
        check(arg[i], value, path, sub);
        if (sub.empty()) ++matches;
        for (const auto& e : sub) branch_errors.push_back("[branch " + std::to_string(i) + "] " + e);
      }
      if (matches == 0) {
        fail(keyword + ": no branch matches");
        out.insert(out.end(), branch_errors.begin(), branch_errors.end());
      } else if (keyword == "oneOf" && matches > 1) {
        fail("oneOf: " + std::to_string(matches) + " branches match");
      }
    } else {
      fail("schema keyword " + keyword + " is not supported by this checker");
    }
  }
}

const SchemaCheck& ws_messages_schema() {
  static const SchemaCheck check(GEODESIC_SOURCE_DIR "/proto/ws-messages.schema.json");
  return check;
}

}  // namespace geodesic::test
