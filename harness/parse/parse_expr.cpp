// Expressions of stage programs (see program/program.h for the syntax).
#include "parse/parse_parts.h"
#include "program/builtins.h"
#include "program/locals.h"
#include "program/ops.h"

namespace rayspec {
namespace {

// A plain number scalar -> literal; false when n is not a number.
bool numberLiteral(const YAML::Node& n, Expr& out) {
  if (!isPlainScalar(n)) return false;
  const std::string& s = n.Scalar();
  uint64_t u = 0;
  if (parseUintText(s, u) && u <= 0xFFFFFFFFull) {
    out.type = ValueType::Uint;
    out.literal = {static_cast<double>(u)};
    return true;
  }
  double d = 0;
  bool finite = true;
  if (parseFloatText(s, d, finite)) {
    out.type = ValueType::Float;
    out.literal = {d};
    return true;
  }
  return false;
}

// A scalar: true/false, a number, a built-in or an operator without arguments.
bool parseScalarExpr(YamlReader& r, const YAML::Node& n, const std::string& field, Expr& out) {
  out.kind = Expr::Kind::Literal;
  const std::string& s = n.Scalar();
  if (isPlainScalar(n) && (s == "true" || s == "false")) {
    out.type = ValueType::Bool;
    out.literal = {s == "true" ? 1.0 : 0.0};
    return true;
  }
  if (uint64_t u = 0; isPlainScalar(n) && parseUintText(s, u) && u > 0xFFFFFFFFull) {
    out.type = ValueType::Uint;  // the type checker holds it to an int64 or uint64 place
    out.literal = {static_cast<double>(u)};
    out.wide = u;
    return true;
  }
  if (numberLiteral(n, out)) return true;
  if (s.rfind("var.", 0) == 0) {  // a local variable (program/locals.h)
    out.kind = Expr::Kind::Local;
    out.name = s.substr(4);
    if (isLocalName(out.name) || isMemberName(out.name)) return true;
    r.error(n, field,
            "'" + s +
                "': a local's name is a lower-case letter, then letters, digits or _ (at most "
                "32); a struct's member is var.STRUCT.MEMBER");
    return false;
  }
  if (s.rfind("shader_record.", 0) == 0) {  // a member of pipeline.sbt.record_layout
    out.kind = Expr::Kind::RecordMember;
    out.name = s.substr(14);
    return true;
  }
  if (s.rfind("const.", 0) == 0) {  // a specialization constant (pipeline.constants)
    out.kind = Expr::Kind::Constant;
    out.name = s.substr(6);
    return true;
  }
  if (const std::optional<BuiltinName> b = builtinNamed(s)) {
    setBuiltin(out, b->id, b->word);
    return true;
  }
  if (const OpInfo* op = findOp(s); op && op->min_args == 0) {
    out.kind = Expr::Kind::Op;
    setOp(out, op->id);
    return true;
  }
  r.error(n, field,
          "unknown name '" + s + "' (not a number, a built-in, or an operator without arguments)");
  return false;
}

// A sequence: a vector literal of 2 to 4 numbers.
bool parseVectorLiteral(YamlReader& r, const YAML::Node& n, const std::string& field, Expr& out) {
  out.kind = Expr::Kind::Literal;
  if (n.size() < 2 || n.size() > 4) {
    r.error(n, field, "a vector literal has 2 to 4 numbers");
    return false;
  }
  for (size_t i = 0; i < n.size(); ++i) {
    Expr c;
    if (!numberLiteral(n[i], c)) {
      r.error(
          n[i], field + "[" + std::to_string(i) + "]",
          "a vector literal holds numbers only (build vectors from values with vec2/vec3/vec4)");
      return false;
    }
    out.literal.push_back(c.literal[0]);
  }
  out.type = n.size() == 2 ? ValueType::Vec2 : n.size() == 3 ? ValueType::Vec3 : ValueType::Vec4;
  return true;
}

// A map of one key: {op: args}.
bool parseOpExpr(YamlReader& r, const YAML::Node& n, const std::string& field, Expr& out) {
  if (n.size() != 1) {
    r.error(n, field, "an operator is written {op: args} with one key");
    return false;
  }
  auto it = n.begin();
  const std::string name = it->first.IsScalar() ? it->first.Scalar() : "?";
  const OpInfo* op = findOp(name);
  if (!op) {
    r.error(it->first, field + "." + name, "unknown operator '" + name + "'");
    return false;
  }
  out.kind = Expr::Kind::Op;
  setOp(out, op->id);
  const YAML::Node args = it->second;
  const std::string f = field + "." + name;
  if (args.IsNull()) return true;
  // A list is the argument list, except for a one-argument op given a
  // vector literal ({length: [1, 2, 3]}).
  if (args.IsSequence() && !(op->max_args == 1 && args.size() != 1)) {
    bool ok = true;
    for (size_t i = 0; i < args.size(); ++i) {
      Expr a;
      ok = parseExpr(r, args[i], f + "[" + std::to_string(i) + "]", a) && ok;
      out.args.push_back(std::move(a));
    }
    return ok;
  }
  Expr a;
  const bool ok = parseExpr(r, args, f, a);
  out.args.push_back(std::move(a));
  return ok;
}

}  // namespace

bool parseExpr(YamlReader& r, const YAML::Node& n, const std::string& field, Expr& out) {
  out = Expr();
  out.loc = r.loc(n, field);
  if (n.IsScalar()) return parseScalarExpr(r, n, field, out);
  if (n.IsSequence()) return parseVectorLiteral(r, n, field, out);
  if (n.IsMap()) return parseOpExpr(r, n, field, out);
  r.error(n, field, "expected an expression");
  return false;
}

}  // namespace rayspec
