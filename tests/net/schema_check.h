// A small JSON Schema (2020-12) checker for the keywords proto/ws-messages.schema.json uses
// (Debian has no C++ validator). A keyword it does not know is reported as an error, so the
// schema cannot outgrow the checker unnoticed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace geodesic::test {

class SchemaCheck {
 public:
  explicit SchemaCheck(const std::filesystem::path& schema_file);

  // What is wrong with `value` against the subschema at JSON pointer `pointer` ("" is the root,
  // "/$defs/server_message" one definition); empty when it is valid.
  std::vector<std::string> errors(const nlohmann::json& value,
                                  const std::string& pointer = "") const;

 private:
  void check(const nlohmann::json& schema, const nlohmann::json& value, const std::string& path,
             std::vector<std::string>& out) const;

  nlohmann::json root_;
};

// The checker for proto/ws-messages.schema.json, loaded once.
const SchemaCheck& ws_messages_schema();

}  // namespace geodesic::test
