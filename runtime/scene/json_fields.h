// Typed reading of one JSON object of a scene file against its list of keys: each accessor
// reads a key if present and reports a wrong type, an out-of-range value or a malformed vector
// at the value's line and column with its JSON pointer; the constructor reports unknown keys
// (with a did-you-mean). Values that fail keep their defaults, so reading goes on and every
// error of a file is found.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "graph/diagnostics.h"
#include "graph/json_value.h"

namespace lg {

class JsonFields {
 public:
  // `what` names the object in messages ("material 'red'", "sphere_light").
  JsonFields(const JsonValue& object, std::string pointer, std::string what, std::vector<std::string> keys,
             Diagnostics& diagnostics);

  bool is_object() const { return object_.is_object(); }
  const JsonValue* get(std::string_view key) const { return object_.find(key); }
  std::string pointer(std::string_view key) const;
  const std::string& pointer() const { return pointer_; }
  Diagnostics& diagnostics() const { return d_; }
  void error_at(std::string_view key, const std::string& message) const;  // at the key's value
  void require(std::string_view key) const;                               // reports when absent

  void number(std::string_view key, float& out, double min, double max, std::string_view unit = {}) const;
  void integer(std::string_view key, int& out, int min, int max) const;
  void boolean(std::string_view key, bool& out) const;
  void string(std::string_view key, std::string& out) const;
  void vec3(std::string_view key, glm::vec3& out, double min, double max) const;
  // Returns false (after reporting) unless `key` is an array of `count` numbers from min to max.
  bool numbers(std::string_view key, std::vector<double>& out, size_t min_count, size_t max_count, double min,
               double max) const;

 private:
  const JsonValue& object_;
  std::string pointer_;
  std::string what_;
  Diagnostics& d_;
};

// "1", "0.25", "1e+06": a number as a message shows it.
std::string format_number(double v);

}  // namespace lg
