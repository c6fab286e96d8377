// Internal to the parse module: reading typed values from yaml-cpp nodes, with
// every problem recorded as an Error (base/error.h) at the node's position.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "parse/parse_case.h"

namespace rayspec {

class YamlReader {
 public:
  YamlReader(std::string file, std::vector<Error>& errors)
      : file_(std::move(file)), errors_(errors) {}

  const std::string& file() const { return file_; }
  size_t errorCount() const { return errors_.size(); }

  SourceLoc loc(const YAML::Node& n, const std::string& field) const;
  void error(const YAML::Node& n, const std::string& field, const std::string& message);
  void error(const SourceLoc& loc, const std::string& message);

  // Every map of the document names each key once: yaml-cpp keeps both of a
  // duplicate pair and a lookup would silently take one. Each second key is
  // an error at its line:col with its key path.
  void checkDuplicateKeys(const YAML::Node& n, const std::string& field = "");

  // The field read last: where an exception from yaml-cpp is reported.
  const std::string& lastField() const { return last_field_; }

  // The value of `key` in map n, or an undefined node.
  static YAML::Node get(const YAML::Node& n, const char* key);
  static bool has(const YAML::Node& n, const char* key);

  // A map whose keys are all in `allowed`; each unknown key is an error.
  bool expectMap(const YAML::Node& n, const std::string& field,
                 std::initializer_list<const char*> allowed);
  // The same, with the keys `more` accepts allowed too (named in the error
  // as `more_text`, e.g. "word0 .. word57").
  bool expectMap(const YAML::Node& n, const std::string& field,
                 std::initializer_list<const char*> allowed,
                 const std::function<bool(const std::string&)>& more, const std::string& more_text);
  bool expectSeq(const YAML::Node& n, const std::string& field);
  // Requires `key` present in map n; reports "missing" at n.
  bool require(const YAML::Node& n, const std::string& field, const char* key);

  std::optional<std::string> string(const YAML::Node& n, const std::string& field);
  // Unsigned integer (decimal or 0x hex) <= max.
  std::optional<uint32_t> uint(const YAML::Node& n, const std::string& field,
                               uint64_t max = 0xFFFFFFFFull);
  // Number; .nan / .inf only when allow_nonfinite.
  std::optional<double> number(const YAML::Node& n, const std::string& field,
                               bool allow_nonfinite = false);
  // A list of exactly N numbers.
  template <size_t N>
  std::optional<std::array<double, N>> numbers(const YAML::Node& n, const std::string& field,
                                               bool allow_nonfinite = false) {
    if (!n.IsSequence() || n.size() != N) {
      error(n, field, "expected a list of " + std::to_string(N) + " numbers");
      return std::nullopt;
    }
    std::array<double, N> out{};
    bool ok = true;
    for (size_t i = 0; i < N; ++i) {
      auto v = number(n[i], field + "[" + std::to_string(i) + "]", allow_nonfinite);
      if (v)
        out[i] = *v;
      else
        ok = false;
    }
    if (!ok) return std::nullopt;
    return out;
  }
  // A list of names, each looked up in table; returns the OR of their bits.
  std::optional<uint32_t> flags(const YAML::Node& n, const std::string& field,
                                const std::vector<std::pair<const char*, uint32_t>>& table);

  // Undefined behaviour found where the values are constants (R-UB); the
  // caller decides (parse_case.cpp): an error, or kept in a robustness probe.
  void undefinedBehaviour(const SourceLoc& loc, UndefinedReason reason,
                          const std::string& message) {
    undefined_.push_back({reason, loc, message});
  }
  const std::vector<StaticUndefined>& undefinedBehaviour() const { return undefined_; }

  // Programs that failed to parse (by field), so they are not type-checked too.
  void markBadProgram(const std::string& field) { bad_programs_.insert(field); }
  bool isBadProgram(const std::string& field) const { return bad_programs_.count(field) > 0; }

 private:
  std::vector<StaticUndefined> undefined_;
  std::set<std::string> bad_programs_;
  mutable std::string last_field_;
  std::string file_;
  std::vector<Error>& errors_;
};

// Plain-scalar number syntax shared with expressions.
bool isPlainScalar(const YAML::Node& n);
bool parseUintText(const std::string& s, uint64_t& out);               // 12, 0xFF
bool parseFloatText(const std::string& s, double& out, bool& finite);  // 1.5, -2, .nan, -.inf

}  // namespace rayspec
