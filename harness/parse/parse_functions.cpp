// pipeline.functions: user functions, defined once and called from any stage
// with `invoke`. Each call site gets a copy of the body (Stmt::then_) and the
// parameter list, so every walk over a stage's program sees what the stage
// may run, and the checker types the body in each calling stage.
#include <map>

#include "parse/parse_parts.h"
#include "program/locals.h"

namespace rayspec {
namespace {

struct FunctionDef {
  std::vector<std::pair<std::string, ValueType>> params;
  bool query = false;  // takes the caller's ray query
  Program body;
  size_t statements = 0;  // in the body, nested ones included
  bool ok = true;
};

size_t countStatements(const std::vector<Stmt>& block) {
  size_t n = block.size();
  for (const Stmt& s : block) n += countStatements(s.then_) + countStatements(s.else_);
  return n;
}
using FunctionDefs = std::map<std::string, FunctionDef>;

// At most this many statements copied into call sites, all told.
constexpr size_t kMaxExpandedStatements = 20000;

bool parseParams(YamlReader& r, const YAML::Node& n, const std::string& field, FunctionDef& def) {
  if (!n.IsMap()) {
    r.error(n, field, "expected a map {NAME: TYPE, ...}");
    return false;
  }
  bool ok = true;
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string name = it->first.IsScalar() ? it->first.Scalar() : "?";
    const std::string f = field + "." + name;
    auto type_name = r.string(it->second, f);
    const auto type = type_name ? valueTypeNamed(*type_name) : std::nullopt;
    if (!isLocalName(name) || !type) {
      r.error(it->first, f,
              "a parameter is NAME: TYPE (a lower-case name; bool, " + arrayTypeSpellings() + ")");
      ok = false;
      continue;
    }
    def.params.emplace_back(name, *type);
  }
  return ok;
}

FunctionDefs parseDefs(YamlReader& r, const YAML::Node& n) {
  FunctionDefs defs;
  if (!n.IsDefined()) return defs;
  if (!n.IsMap()) {
    r.error(n, "pipeline.functions",
            "expected a map {NAME: {params: {..}, query: true, do: [..]}}");
    return defs;
  }
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string name = it->first.IsScalar() ? it->first.Scalar() : "?";
    const std::string f = "pipeline.functions." + name;
    FunctionDef& def = defs[name];
    if (!isLocalName(name)) {
      r.error(it->first, f, "a function's name is a lower-case letter, then letters, digits or _");
      def.ok = false;
      continue;
    }
    const YAML::Node v = it->second;
    if (!r.expectMap(v, f, {"params", "query", "do"}) || !r.require(v, f, "do")) {
      def.ok = false;
      continue;
    }
    if (auto q = YamlReader::get(v, "query"); q.IsDefined()) {
      const auto takes = parseTrueFalse(r, q, f + ".query");
      def.ok = takes.has_value() && def.ok;
      def.query = takes.value_or(false);
    }
    if (auto p = YamlReader::get(v, "params"); p.IsDefined())
      def.ok = parseParams(r, p, f + ".params", def) && def.ok;
    def.ok = parseProgram(r, YamlReader::get(v, "do"), f + ".do", def.body) && def.ok;
    def.statements = countStatements(def.body);
  }
  return defs;
}

class Expander {
 public:
  Expander(YamlReader& r, const FunctionDefs& defs) : r_(r), defs_(defs) {}

  void block(std::vector<Stmt>& stmts) {
    for (Stmt& s : stmts) {
      if (s.kind == Stmt::Kind::Invoke) {
        invoke(s);
        continue;
      }
      block(s.then_);
      block(s.else_);
    }
  }

 private:
  // A call site that cannot be expanded keeps no arguments: its error is
  // the expansion's, not a second one from the checker.
  void invoke(Stmt& s) {
    if (!expand(s)) s.assigns.clear();
  }

  bool expand(Stmt& s) {
    const auto it = defs_.find(s.local);
    if (it == defs_.end()) {
      std::string known;
      for (const auto& [name, def] : defs_) known += (known.empty() ? "" : ", ") + name;
      r_.error(s.loc, "invoke: no function '" + s.local + "' in pipeline.functions (" +
                          (known.empty() ? std::string("none") : known) + ")");
      return false;
    }
    const FunctionDef& def = it->second;
    if (!def.ok) return false;  // its own error is reported
    if (!arguments(s, def)) return false;
    if (std::find(stack_.begin(), stack_.end(), s.local) != stack_.end() ||
        stack_.size() >= kMaxFunctionNesting) {
      r_.error(s.loc, "invoke " + s.local +
                          ": functions may not call themselves (GLSL has no "
                          "recursion) and nest at most " +
                          std::to_string(kMaxFunctionNesting) + " deep");
      return false;
    }
    copied_ += def.statements;
    if (copied_ > kMaxExpandedStatements) {
      if (copied_ - def.statements <= kMaxExpandedStatements)
        r_.error(s.loc, "functions expand to more than " + std::to_string(kMaxExpandedStatements) +
                            " statements");
      return false;
    }
    s.params = def.params;
    s.query_param = def.query;
    s.then_ = def.body;
    stack_.push_back(s.local);
    block(s.then_);
    stack_.pop_back();
    return true;
  }

  // The arguments by name, put in the parameters' order.
  bool arguments(Stmt& s, const FunctionDef& def) {
    std::vector<std::pair<std::string, Expr>> ordered;
    for (const auto& param : def.params) {
      const std::string& name = param.first;
      auto a = std::find_if(s.assigns.begin(), s.assigns.end(),
                            [&](const auto& x) { return x.first == name; });
      if (a == s.assigns.end()) {
        r_.error(s.loc, "invoke " + s.local + ": parameter '" + name + "' is not given (with:)");
        return false;
      }
      ordered.push_back(std::move(*a));
    }
    if (ordered.size() != s.assigns.size()) {
      r_.error(s.loc, "invoke " + s.local + ": an argument names no parameter of the function");
      return false;
    }
    s.assigns = std::move(ordered);
    return true;
  }

  YamlReader& r_;
  const FunctionDefs& defs_;
  std::vector<std::string> stack_;
  size_t copied_ = 0;
};

}  // namespace

void expandFunctions(YamlReader& r, const YAML::Node& functions, Pipeline& p) {
  const FunctionDefs defs = parseDefs(r, functions);
  Expander x(r, defs);
  x.block(p.raygen);
  for (Program& g : p.other_raygens) x.block(g);
  for (Program& m : p.miss) x.block(m);
  for (HitGroup& g : p.hit_groups)
    for (auto* prog : {&g.closest_hit, &g.any_hit, &g.intersection})
      if (*prog) x.block(**prog);
  for (Program& c : p.callables) x.block(c);
}

}  // namespace rayspec
