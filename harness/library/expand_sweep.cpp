// Expands a sweep file into its variants (expand_sweep.h).
#include "library/expand_sweep.h"

#include <cctype>
#include <map>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "base/result.h"
#include "parse/yaml_shape.h"

namespace rayspec {
namespace {

constexpr size_t kMaxVariants = 1024;        // cases one sweep may make
constexpr size_t kMaxLineBytes = 64u << 10;  // one substituted line
constexpr int kMaxSubstitutions = 10000;     // in one line
constexpr size_t kMaxSweepBytes = 8u << 20;  // all variants' text together

using Params = std::vector<std::pair<std::string, std::string>>;  // name -> YAML text, in order

SourceLoc locOf(const std::string& file, const YAML::Mark& m, const std::string& field) {
  return SourceLoc{file, m.line >= 0 ? m.line + 1 : 1, m.column >= 0 ? m.column + 1 : 1, field};
}

// A value's YAML text: a scalar as written, a list or map in flow style.
std::string valueText(const YAML::Node& n) {
  if (n.IsScalar()) return n.Scalar();
  YAML::Emitter out;
  out.SetSeqFormat(YAML::Flow);
  out.SetMapFormat(YAML::Flow);
  out << n;
  return out.c_str();
}

bool isParameterName(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

class Expander {
 public:
  Expander(const std::string& file, std::vector<Error>& errors) : file_(file), errors_(errors) {}

  void error(const YAML::Node& n, const std::string& field, const std::string& message) {
    errors_.push_back({locOf(file_, n.Mark(), field), message});
  }

  // rows: each a list of (name, text); every row names the same parameters.
  std::vector<Params> rows(const YAML::Node& n) {
    std::vector<Params> out;
    if (!n.IsDefined()) return {Params{}};
    if (!n.IsSequence() || n.size() == 0) {
      error(n, "sweep.rows", "expected a non-empty list of maps (parameter: value)");
      return {};
    }
    std::vector<std::string> first_names;
    for (size_t i = 0; i < n.size(); ++i) {
      const std::string field = "sweep.rows[" + std::to_string(i) + "]";
      if (!n[i].IsMap() || n[i].size() == 0) {
        error(n[i], field, "expected a map of parameter: value");
        return {};
      }
      Params row;
      std::vector<std::string> names;
      for (const auto& kv : n[i]) {
        const std::string key = kv.first.Scalar();
        if (!isParameterName(key)) {
          error(kv.first, field, "'" + key + "' is not a parameter name (letters, digits, _)");
          return {};
        }
        row.emplace_back(key, valueText(kv.second));
        names.push_back(key);
      }
      if (i == 0)
        first_names = names;
      else if (std::set<std::string>(names.begin(), names.end()) !=
               std::set<std::string>(first_names.begin(), first_names.end())) {
        error(n[i], field, "every row must name the same parameters as row 0");
        return {};
      }
      out.push_back(std::move(row));
    }
    return out;
  }

  // product: parameter -> non-empty list of values.
  std::vector<std::pair<std::string, std::vector<std::string>>> product(const YAML::Node& n) {
    std::vector<std::pair<std::string, std::vector<std::string>>> out;
    if (!n.IsDefined()) return out;
    if (!n.IsMap() || n.size() == 0) {
      error(n, "sweep.product", "expected a map of parameter: [values]");
      return out;
    }
    for (const auto& kv : n) {
      const std::string key = kv.first.Scalar();
      const std::string field = "sweep.product." + key;
      if (!isParameterName(key)) {
        error(kv.first, "sweep.product",
              "'" + key + "' is not a parameter name (letters, digits, _)");
        continue;
      }
      if (!kv.second.IsSequence() || kv.second.size() == 0) {
        error(kv.second, field, "expected a non-empty list of values");
        continue;
      }
      std::vector<std::string> values;
      for (const YAML::Node& v : kv.second) values.push_back(valueText(v));
      out.emplace_back(key, std::move(values));
    }
    return out;
  }

 private:
  const std::string& file_;
  std::vector<Error>& errors_;
};

// Replaces each ${name} in line, innermost first, and again in what a value
// brings in: `${boxes_${order}}` is ${boxes_forward} when order is forward.
// An unknown name is an error (once per place); so is a value that keeps
// bringing itself back.
std::string substitute(const std::string& line, const Params& params, const std::string& file,
                       int line_no, const std::string& field, std::vector<Error>* errors,
                       std::set<std::string>* used = nullptr) {
  std::string out = line;
  std::vector<size_t> opens;  // positions of the "${" not closed yet (one pass, left to right)
  std::set<std::string> unknown;
  int steps = 0;
  for (size_t i = 0; i < out.size();) {
    if (out[i] == '$' && i + 1 < out.size() && out[i + 1] == '{') {
      opens.push_back(i);
      i += 2;
      continue;
    }
    if (out[i] != '}' || opens.empty()) {
      ++i;
      continue;
    }
    const size_t open = opens.back();
    opens.pop_back();
    const std::string name = out.substr(open + 2, i - open - 2);
    const std::string* value = nullptr;
    for (const auto& [k, v] : params)
      if (k == name) value = &v;
    if (!value) {
      if (errors && unknown.insert(name).second) {
        std::string known;
        for (const auto& [k, v] : params) known += (known.empty() ? "" : ", ") + k;
        errors->push_back(
            {SourceLoc{file, line_no, static_cast<int>(open) + 1, field},
             "'${" + name + "}' names no parameter of the sweep (parameters: " + known + ")"});
      }
      ++i;
      continue;
    }
    if (++steps > kMaxSubstitutions ||
        out.size() - (i + 1 - open) + value->size() > kMaxLineBytes) {
      if (errors)
        errors->push_back({SourceLoc{file, line_no, 1, field},
                           "the parameters' values name each other too deeply (over " +
                               std::to_string(kMaxSubstitutions) +
                               " substitutions, or a line over " +
                               std::to_string(kMaxLineBytes >> 10) + " KiB)"});
      return {};
    }
    if (used) used->insert(name);
    out.replace(open, i + 1 - open, *value);
    i = open;  // the value may hold ${...} of its own, or complete an enclosing one
  }
  return out;
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

}  // namespace

bool isSweepFile(const std::string& path) {
  const std::string suffix = ".sweep.yaml";
  return path.size() > suffix.size() &&
         path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
}

namespace {

using Product = std::vector<std::pair<std::string, std::vector<std::string>>>;

// The block: from the line `sweep:` (at column 0) to the next line that
// starts another top-level key, as [begin, end) line indices. Only it is YAML
// before substitution; the rest may hold ${...} anywhere, even where YAML
// would not allow it.
Result<std::pair<int, int>> findSweepBlock(const std::vector<std::string>& lines,
                                           const std::string& file) {
  int block_begin = -1, block_end = static_cast<int>(lines.size());
  for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
    const std::string& l = lines[i];
    const bool top_key = !l.empty() && l[0] != ' ' && l[0] != '#' && l[0] != '\t';
    if (block_begin < 0 && l.rfind("sweep:", 0) == 0)
      block_begin = i;
    else if (block_begin >= 0 && top_key) {
      block_end = i;
      break;
    }
  }
  if (block_begin < 0)
    return Error{SourceLoc{file, 1, 1, "sweep"},
                 "a .sweep.yaml file needs a top-level `sweep:` block (cases/README.md, Sweeps)"};
  return std::pair{block_begin, block_end};
}

// The block as YAML (its line numbers those of the file).
Result<YAML::Node> loadSweepBlock(const std::vector<std::string>& lines, std::pair<int, int> block,
                                  const std::string& file) {
  std::string text(static_cast<size_t>(block.first), '\n');  // keeps yaml-cpp's line numbers
  for (int i = block.first; i < block.second; ++i) text += lines[i] + "\n";
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    return Error{locOf(file, e.mark, "sweep"), yamlTooDeepMessage()};
  } catch (const YAML::Exception& e) {
    return Error{locOf(file, e.mark, "sweep"), "malformed YAML: " + e.msg};
  }
  if (const auto problem = yamlShapeProblem(root))
    return Error{locOf(file, problem->mark, "sweep"), problem->message};
  if (!root.IsMap())
    return Error{SourceLoc{file, block.first + 1, 1, "sweep"},
                 "the `sweep:` line does not start a map (cases/README.md, Sweeps)"};
  return root;
}

// The sweep map's keys and name; false (errors said) when it cannot expand.
bool checkSweepMap(Expander& ex, const YAML::Node& sweep) {
  if (!sweep.IsMap()) {
    ex.error(sweep, "sweep", "expected a map with name, and rows and/or product");
    return false;
  }
  for (const auto& kv : sweep) {
    const std::string key = kv.first.Scalar();
    if (key != "name" && key != "rows" && key != "product")
      ex.error(kv.first, "sweep",
               "unknown key '" + key + "' (expected one of: name, rows, product)");
  }
  const YAML::Node name_node = sweep["name"];
  if (!name_node || !name_node.IsScalar() || name_node.Scalar().empty()) {
    ex.error(name_node ? name_node : sweep, "sweep.name",
             "missing: each variant's name, e.g. \"offset-${offset}\"");
    return false;
  }
  if (!sweep["rows"] && !sweep["product"]) {
    ex.error(sweep, "sweep", "needs rows or product (or both): the parameters and their values");
    return false;
  }
  return true;
}

// Whether the rows and the product can combine: no parameter in both, at
// most kMaxVariants cases. False with the error said.
bool checkCombination(Expander& ex, const YAML::Node& sweep, const std::vector<Params>& rows,
                      const Product& product) {
  for (const auto& [key, values] : product)
    for (const auto& [row_key, v] : rows.front())
      if (row_key == key) {
        ex.error(sweep["product"], "sweep.product." + key,
                 "'" + key + "' is also a parameter of the rows");
        return false;
      }
  size_t count = rows.size();
  for (const auto& [key, values] : product)
    count = count > kMaxVariants ? count : count * values.size();
  if (count > kMaxVariants) {
    ex.error(sweep, "sweep",
             "makes more than " + std::to_string(kMaxVariants) + " cases; split it");
    return false;
  }
  return true;
}

// Every combination's case text (the block's lines already blank): rows
// outermost, the product's last key fastest. Every variant is checked: a
// line over the limits, or a name that only this variant's values bring, is
// an error here too (said once).
void expandVariants(Expander& ex, const YAML::Node& sweep, const std::vector<std::string>& lines,
                    const std::vector<Params>& rows, const Product& product,
                    const std::string& file, const std::string& name, SweepExpansion& result) {
  const YAML::Node name_node = sweep["name"];
  size_t total_bytes = 0;
  std::vector<size_t> index(product.size(), 0);
  std::map<std::string, int> names_seen;
  std::set<std::string> errors_said;
  for (const Params& row : rows) {
    while (result.errors.empty()) {
      Params params = row;
      for (size_t k = 0; k < product.size(); ++k)
        params.emplace_back(product[k].first, product[k].second[index[k]]);
      std::vector<Error> found;
      const YAML::Mark nm = name_node.Mark();
      SweepVariant v;
      v.name = name + "/" +
               substitute(name_node.Scalar(), params, file, nm.line + 1, "sweep.name", &found,
                          &result.used);
      for (size_t i = 0; i < lines.size(); ++i)
        v.text +=
            substitute(lines[i], params, file, static_cast<int>(i) + 1, "", &found, &result.used) +
            "\n";
      for (Error& e : found) {
        if (!errors_said.insert(e.format()).second) continue;
        if (!result.variants.empty()) e.message += " (in variant " + v.name + ")";
        result.errors.push_back(std::move(e));
      }
      total_bytes += v.text.size();
      if (total_bytes > kMaxSweepBytes)
        ex.error(sweep, "sweep", "its cases' text grows beyond 8 MiB; split it");
      if (++names_seen[v.name] == 2)
        ex.error(name_node, "sweep.name",
                 "two variants are both named '" + v.name +
                     "': the name must use every parameter that varies");
      v.params = params;
      result.variants.push_back(std::move(v));
      size_t k = product.size();
      while (k > 0) {
        if (++index[k - 1] < product[k - 1].second.size()) break;
        index[k - 1] = 0;
        --k;
      }
      if (k == 0) break;
    }
  }
}

// A parameter no variant's text or name ever brings in is a mistake (a
// value written but never used: the variants would not differ by it).
void checkEveryParameterUsed(Expander& ex, const YAML::Node& sweep, const std::vector<Params>& rows,
                             const Product& product, const std::set<std::string>& used) {
  for (const auto& [key, values] : product)
    if (!used.count(key))
      ex.error(sweep["product"], "sweep.product." + key,
               "parameter '" + key + "' is never used: no ${" + key + "} in the case or its name");
  if (rows.empty()) return;
  for (const auto& [key, value] : rows.front())
    if (!used.count(key))
      ex.error(sweep["rows"], "sweep.rows",
               "parameter '" + key + "' is never used: no ${" + key + "} in the case or its name");
}

SweepExpansion expandChecked(const std::string& text, const std::string& file,
                             const std::string& name) {
  SweepExpansion result;
  Expander ex(file, result.errors);
  std::vector<std::string> lines = splitLines(text);
  const Result<std::pair<int, int>> block = findSweepBlock(lines, file);
  if (!block) {
    result.errors.push_back(block.error());
    return result;
  }
  const Result<YAML::Node> root = loadSweepBlock(lines, *block, file);
  if (!root) {
    result.errors.push_back(root.error());
    return result;
  }
  const YAML::Node sweep = (*root)["sweep"];
  if (!checkSweepMap(ex, sweep)) return result;
  const std::vector<Params> rows = ex.rows(sweep["rows"]);
  const Product product = ex.product(sweep["product"]);
  if (!result.errors.empty() || !checkCombination(ex, sweep, rows, product)) return result;
  for (int i = block->first; i < block->second && i < static_cast<int>(lines.size()); ++i)
    lines[i].clear();
  expandVariants(ex, sweep, lines, rows, product, file, name, result);
  checkEveryParameterUsed(ex, sweep, rows, product, result.used);
  if (!result.errors.empty()) result.variants.clear();
  return result;
}

}  // namespace

SweepExpansion expandSweep(const std::string& text, const std::string& file,
                           const std::string& name) {
  try {
    return expandChecked(text, file, name);
  } catch (const YAML::Exception& e) {
    // A shape yaml-cpp refuses to read (it throws on some): an error at its mark.
    SweepExpansion result;
    result.errors.push_back(
        {locOf(file, e.mark, "sweep"), "unexpected value in the sweep block: " + e.msg});
    return result;
  }
}

}  // namespace rayspec
