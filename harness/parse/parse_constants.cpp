// pipeline.constants (specialization constants, read as `const.NAME`) and
// pipeline.specialize (the values some shaders take instead of the default).
#include "parse/parse_parts.h"
#include "program/locals.h"

namespace rayspec {
namespace {

// At most this many constants in a pipeline.
constexpr size_t kMaxSpecConstants = 16;

// A constant's literal: true / false, a whole number (Uint) or another number (Float).
std::optional<SpecConstant> constantLiteral(YamlReader& r, const YAML::Node& n,
                                            const std::string& field) {
  Expr e;
  if (!parseExpr(r, n, field, e)) return std::nullopt;
  if (e.kind != Expr::Kind::Literal || e.literal.size() != 1) {
    r.error(n, field, "a constant is true, false or a number");
    return std::nullopt;
  }
  if (e.wide) {  // a constant is 32 bits wide (bool, uint or float)
    r.error(n, field, "integer literal " + n.Scalar() + " does not fit in 32 bits");
    return std::nullopt;
  }
  SpecConstant k;
  k.type = e.type;
  k.value = e.literal[0];
  k.loc = r.loc(n, field);
  return k;
}

// The names of the shaders the case has (GeneratedShader names).
std::vector<std::string> shaderNames(const Pipeline& p) {
  std::vector<std::string> names = {Pipeline::shaderName(Stage::Raygen, 0)};
  for (size_t i = 0; i < p.other_raygens.size(); ++i)
    names.push_back(Pipeline::shaderName(Stage::Raygen, i, true));
  for (size_t i = 0; i < p.miss.size(); ++i) names.push_back(Pipeline::shaderName(Stage::Miss, i));
  for (size_t i = 0; i < p.hit_groups.size(); ++i) {
    const HitGroup& g = p.hit_groups[i];
    if (g.closest_hit) names.push_back(Pipeline::shaderName(Stage::ClosestHit, i));
    if (g.any_hit) names.push_back(Pipeline::shaderName(Stage::AnyHit, i));
    if (g.intersection) names.push_back(Pipeline::shaderName(Stage::Intersection, i));
  }
  for (size_t i = 0; i < p.callables.size(); ++i)
    names.push_back(Pipeline::shaderName(Stage::Callable, i));
  return names;
}

void parseShaderValues(YamlReader& r, const YAML::Node& n, const std::string& field, Pipeline& p,
                       std::map<size_t, double>& out) {
  if (!n.IsMap()) {
    r.error(n, field, "expected a map {CONSTANT: value, ...}");
    return;
  }
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string name = it->first.IsScalar() ? it->first.Scalar() : "?";
    const std::string f = field + "." + name;
    size_t k = 0;
    while (k < p.constants.size() && p.constants[k].name != name) ++k;
    if (k == p.constants.size()) {
      r.error(it->first, f, "no constant '" + name + "' in pipeline.constants");
      continue;
    }
    const auto v = constantLiteral(r, it->second, f);
    if (!v) continue;
    const ValueType want = p.constants[k].type;
    if (v->type != want && !(want == ValueType::Float && v->type == ValueType::Uint)) {
      r.error(it->second, f,
              std::string("constant '") + name + "' is a " + valueTypeName(want) + ", not a " +
                  valueTypeName(v->type));
      continue;
    }
    out[k] = v->value;
  }
}

}  // namespace

void parseConstants(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  if (!n.IsMap()) {
    r.error(n, "pipeline.constants", "expected a map {NAME: default value, ...}");
    return;
  }
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string name = it->first.IsScalar() ? it->first.Scalar() : "?";
    const std::string f = "pipeline.constants." + name;
    if (!isLocalName(name)) {
      r.error(it->first, f, "a constant's name is a lower-case letter, then letters, digits or _");
      continue;
    }
    if (p.constants.size() == kMaxSpecConstants) {
      r.error(it->first, f, "at most " + std::to_string(kMaxSpecConstants) + " constants");
      return;
    }
    auto k = constantLiteral(r, it->second, f);
    if (!k) continue;
    k->name = name;
    p.constants.push_back(*k);
  }
}

void parseSpecialize(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  if (!n.IsMap()) {
    r.error(n, "pipeline.specialize", "expected a map {SHADER: {CONSTANT: value}, ...}");
    return;
  }
  const std::vector<std::string> shaders = shaderNames(p);
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string shader = it->first.IsScalar() ? it->first.Scalar() : "?";
    const std::string f = "pipeline.specialize." + shader;
    if (std::find(shaders.begin(), shaders.end(), shader) == shaders.end()) {
      std::string list;
      for (const std::string& s : shaders) list += (list.empty() ? "" : ", ") + s;
      r.error(it->first, f, "no shader '" + shader + "' in this pipeline (" + list + ")");
      continue;
    }
    parseShaderValues(r, it->second, f, p, p.specialize[shader]);
  }
}

}  // namespace rayspec
