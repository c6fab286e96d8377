// Typed reads from yaml-cpp nodes; every problem becomes an Error (base/error.h).
#include "parse/yaml_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>

namespace rayspec {

bool isPlainScalar(const YAML::Node& n) {
  // yaml-cpp tags quoted scalars "!" and plain ones "?".
  return n.IsScalar() && n.Tag() != "!";
}

bool parseUintText(const std::string& s, uint64_t& out) {
  if (s.empty()) return false;
  int base = 10;
  size_t start = 0;
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    base = 16;
    start = 2;
  }
  uint64_t v = 0;
  for (size_t i = start; i < s.size(); ++i) {
    int d;
    char c = s[i];
    if (c >= '0' && c <= '9')
      d = c - '0';
    else if (base == 16 && c >= 'a' && c <= 'f')
      d = c - 'a' + 10;
    else if (base == 16 && c >= 'A' && c <= 'F')
      d = c - 'A' + 10;
    else
      return false;
    if (v > (std::numeric_limits<uint64_t>::max() - d) / base) return false;
    v = v * base + d;
  }
  out = v;
  return true;
}

bool parseFloatText(const std::string& s, double& out, bool& finite) {
  finite = true;
  if (s == ".nan" || s == ".NaN" || s == ".NAN") {
    out = std::numeric_limits<double>::quiet_NaN();
    finite = false;
    return true;
  }
  std::string body = s;
  double sign = 1;
  if (!body.empty() && (body[0] == '+' || body[0] == '-')) {
    sign = body[0] == '-' ? -1 : 1;
    body = body.substr(1);
  }
  if (body == ".inf" || body == ".Inf" || body == ".INF") {
    out = sign * std::numeric_limits<double>::infinity();
    finite = false;
    return true;
  }
  if (body.empty()) return false;
  // Only decimal notation: digits, '.', exponent (strtod would also take "nan", "inf", hex).
  for (char c : body)
    if (!((c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'))
      return false;
  errno = 0;
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size()) return false;
  if (errno == ERANGE && std::isinf(v)) return false;
  out = v;
  return true;
}

SourceLoc YamlReader::loc(const YAML::Node& n, const std::string& field) const {
  last_field_ = field;
  SourceLoc l;
  l.file = file_;
  l.field = field;
  try {
    if (n.IsDefined()) {
      YAML::Mark m = n.Mark();
      if (m.line >= 0) {
        l.line = m.line + 1;
        l.column = m.column + 1;
      }
    }
  } catch (const YAML::Exception&) {
  }
  return l;
}

void YamlReader::error(const YAML::Node& n, const std::string& field, const std::string& message) {
  errors_.push_back({loc(n, field), message});
}

void YamlReader::error(const SourceLoc& l, const std::string& message) {
  errors_.push_back({l, message});
}

void YamlReader::checkDuplicateKeys(const YAML::Node& n, const std::string& field) {
  if (n.IsSequence()) {
    for (size_t i = 0; i < n.size(); ++i)
      checkDuplicateKeys(n[i], field + "[" + std::to_string(i) + "]");
    return;
  }
  if (!n.IsMap()) return;
  std::map<std::string, int> first_line;
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : std::string("?");
    const std::string path = field.empty() ? key : field + "." + key;
    if (it->first.IsScalar()) {
      const SourceLoc at = loc(it->first, path);
      if (const auto [seen, fresh] = first_line.emplace(key, at.line); !fresh)
        error(at, "duplicate key '" + key + "' (first at line " + std::to_string(seen->second) +
                      "); each key may appear once");
    }
    checkDuplicateKeys(it->second, path);
  }
}

YAML::Node YamlReader::get(const YAML::Node& n, const char* key) {
  if (!n.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  for (auto it = n.begin(); it != n.end(); ++it)
    if (it->first.IsScalar() && it->first.Scalar() == key) return it->second;
  return YAML::Node(YAML::NodeType::Undefined);
}

bool YamlReader::has(const YAML::Node& n, const char* key) {
  return get(n, key).IsDefined();
}

bool YamlReader::expectMap(const YAML::Node& n, const std::string& field,
                           std::initializer_list<const char*> allowed) {
  return expectMap(n, field, allowed, nullptr, "");
}

bool YamlReader::expectMap(const YAML::Node& n, const std::string& field,
                           std::initializer_list<const char*> allowed,
                           const std::function<bool(const std::string&)>& more,
                           const std::string& more_text) {
  last_field_ = field;
  if (!n.IsMap()) {
    error(n, field, "expected a map");
    return false;
  }
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : std::string("?");
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    known = known || (more && more(key));
    if (!known) {
      std::string list;
      for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
      if (more) list += ", " + more_text;
      error(it->first, field.empty() ? key : field + "." + key,
            "unknown key '" + key + "' (expected one of: " + list + ")");
    }
  }
  return true;
}

bool YamlReader::expectSeq(const YAML::Node& n, const std::string& field) {
  last_field_ = field;
  if (!n.IsSequence()) {
    error(n, field, "expected a list");
    return false;
  }
  return true;
}

bool YamlReader::require(const YAML::Node& n, const std::string& field, const char* key) {
  if (has(n, key)) return true;
  error(n, field.empty() ? key : field + "." + key,
        std::string("missing required key '") + key + "'");
  return false;
}

std::optional<std::string> YamlReader::string(const YAML::Node& n, const std::string& field) {
  last_field_ = field;
  if (!n.IsScalar()) {
    error(n, field, "expected a string");
    return std::nullopt;
  }
  return n.Scalar();
}

std::optional<uint32_t> YamlReader::uint(const YAML::Node& n, const std::string& field,
                                         uint64_t max) {
  last_field_ = field;
  uint64_t v = 0;
  if (!isPlainScalar(n) || !parseUintText(n.Scalar(), v)) {
    error(n, field, "expected an unsigned integer (decimal or 0x hex)");
    return std::nullopt;
  }
  if (v > max) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "value %s is out of range (at most 0x%llX)", n.Scalar().c_str(),
                  static_cast<unsigned long long>(max));
    error(n, field, buf);
    return std::nullopt;
  }
  return static_cast<uint32_t>(v);
}

std::optional<double> YamlReader::number(const YAML::Node& n, const std::string& field,
                                         bool allow_nonfinite) {
  last_field_ = field;
  double v = 0;
  bool finite = true;
  uint64_t u = 0;
  if (isPlainScalar(n) && parseUintText(n.Scalar(), u)) return static_cast<double>(u);
  if (!isPlainScalar(n) || !parseFloatText(n.Scalar(), v, finite)) {
    error(n, field, "expected a number");
    return std::nullopt;
  }
  if (!finite && !allow_nonfinite) {
    error(n, field, "non-finite number not allowed here");
    return std::nullopt;
  }
  return v;
}

std::optional<uint32_t> YamlReader::flags(
    const YAML::Node& n, const std::string& field,
    const std::vector<std::pair<const char*, uint32_t>>& table) {
  last_field_ = field;
  if (!expectSeq(n, field)) return std::nullopt;
  uint32_t bits = 0;
  bool ok = true;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string f = field + "[" + std::to_string(i) + "]";
    const YAML::Node item = n[i];
    bool found = false;
    // A number stands for its bits (as a script's raw flag value); each must
    // be a known flag's.
    if (item.IsScalar() && !item.Scalar().empty() &&
        std::isdigit(static_cast<unsigned char>(item.Scalar()[0]))) {
      uint32_t known = 0;
      for (const auto& entry : table) known |= entry.second;
      const std::optional<uint32_t> raw = uint(item, f);
      if (!raw) {
        ok = false;
        continue;
      }
      if (*raw & ~known) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "bits 0x%X of %u are no known flag", *raw & ~known, *raw);
        error(item, f, buf);
        ok = false;
        continue;
      }
      bits |= *raw;
      continue;
    }
    if (item.IsScalar())
      for (const auto& [name, bit] : table)
        if (item.Scalar() == name) {
          bits |= bit;
          found = true;
        }
    if (!found) {
      std::string list;
      for (const auto& entry : table) list += std::string(list.empty() ? "" : ", ") + entry.first;
      error(item, f,
            "unknown flag '" + (item.IsScalar() ? item.Scalar() : std::string("?")) +
                "' (expected one of: " + list + ")");
      ok = false;
    }
  }
  if (!ok) return std::nullopt;
  return bits;
}

}  // namespace rayspec
