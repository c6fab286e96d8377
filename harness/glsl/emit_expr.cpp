#include "glsl/emit_expr.h"

#include <cctype>
#include <map>

#include "glsl/glsl_literal.h"
#include "program/builtins.h"
#include "program/payload_words.h"

namespace rayspec {
namespace {

std::string problem(const std::string& what) {
  std::string id = "rayspec_error_";
  for (char ch : what) id += (std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_');
  return id + "()";
}

std::string literal(const Expr& e) {
  if (e.literal.empty()) return problem("empty literal");
  auto f = [&](size_t i) {
    return glslFloat(static_cast<float>(e.literal[i < e.literal.size() ? i : 0]));
  };
  switch (e.type) {
    case ValueType::Bool:
      return e.literal[0] != 0 ? "true" : "false";
    case ValueType::Uint:
      return glslUint(static_cast<uint32_t>(e.literal[0]));
    case ValueType::Float:
      return f(0);
    case ValueType::Vec2:
      return "vec2(" + f(0) + ", " + f(1) + ")";
    case ValueType::Vec3:
      return "vec3(" + f(0) + ", " + f(1) + ", " + f(2) + ")";
    case ValueType::Vec4:
      return "vec4(" + f(0) + ", " + f(1) + ", " + f(2) + ", " + f(3) + ")";
  }
  return problem("literal type");
}

// The GLSL a built-in is read as (program/builtin_table.h), the word<i>
// families by their index and hit by the stage; inlined in raygen, through
// the ray query (its candidate in any-hit and intersection, its committed
// intersection in closest-hit).
std::string builtin(const std::string& name, const StageContext& ctx) {
  const Stage stage = ctx.stage;
  if (auto w = attributeWordBuiltin(name)) return "rs_attr.words[" + std::to_string(*w) + "]";
  if (auto w = callWordBuiltin(name))  // callee.word3 -> callee.words[3]
    return std::string(w->callee ? "callee" : "call") + ".words[" + std::to_string(w->index) + "]";
  if (auto w = payloadWordBuiltin(name))  // payload.word3 -> payload.words[3]
    return std::string(w->child ? "child" : "payload") + ".words[" + std::to_string(w->index) + "]";
  if (name == "hit") {
    if (stage == Stage::ClosestHit) return "1u";
    if (stage == Stage::Miss) return "0u";
    return problem("hit outside closest_hit and miss");
  }
  const BuiltinInfo* info = findBuiltin(name);
  // A ray_query's getters read its own query (rs_query), inlined or not.
  if (!ctx.inlined || !info || isQueryBuiltin(builtinId(info)))
    return info && info->glsl ? info->glsl : problem("unknown builtin " + name);
  if (name == "ray_tmax")  // the hit's t, the committed t so far, the trace's tmax
    return stage == Stage::Intersection ? "rs_current_tmax()"
           : stage == Stage::Miss       ? "rs_q_tmax"
                                        : "rs_hit_t";
  const std::string spelled = rayQuerySpelling(*info, stage == Stage::ClosestHit);
  return spelled.empty() ? problem(name + " cannot be read by a ray query") : spelled;
}

std::string op(const Expr& e, const StageContext& ctx) {
  std::vector<std::string> a;
  for (const Expr& arg : e.args) a.push_back(emitExpr(arg, ctx));
  const std::string& n = e.name;
  auto need = [&](size_t count) {
    return a.size() >= count;
  };
  auto join = [&](const char* sep) {
    std::string s = "(";
    for (size_t i = 0; i < a.size(); ++i) s += (i ? sep : "") + a[i];
    return s + ")";
  };
  static const std::map<std::string, const char*> binary = {
      {"add", " + "}, {"sub", " - "},     {"mul", " * "},    {"div", " / "},
      {"mod", " % "}, {"eq", " == "},     {"ne", " != "},    {"lt", " < "},
      {"le", " <= "}, {"gt", " > "},      {"ge", " >= "},    {"and", " && "},
      {"or", " || "}, {"bit_and", " & "}, {"bit_or", " | "}, {"bit_xor", " ^ "}};
  if (auto it = binary.find(n); it != binary.end() && need(2)) return join(it->second);
  if ((n == "min" || n == "max" || n == "dot" || n == "cross") && need(2))
    return n + "(" + a[0] + ", " + a[1] + ")";
  if (n == "not" && need(1)) return "(!" + a[0] + ")";
  if (n == "odd" && need(1)) return "((" + a[0] + " & 1u) != 0u)";
  if (n == "bit_not" && need(1)) return "(~" + a[0] + ")";
  if (n == "mat3_mul" && need(4))
    return "(mat3(" + a[0] + ", " + a[1] + ", " + a[2] + ") * " + a[3] + ")";
  if (n == "mat3_tmul" && need(4))
    return "(transpose(mat3(" + a[0] + ", " + a[1] + ", " + a[2] + ")) * " + a[3] + ")";
  // A shift of 32 or more is undefined in GLSL: the amount modulo 32, as the model.
  if (n == "shl" && need(2)) return "(" + a[0] + " << (" + a[1] + " & 31u))";
  if (n == "shr" && need(2)) return "(" + a[0] + " >> (" + a[1] + " & 31u))";
  if (n == "float_bits" && need(1)) return "floatBitsToUint(" + a[0] + ")";
  if (n == "bits_float" && need(1)) return "uintBitsToFloat(" + a[0] + ")";
  if (n == "even" && need(1)) return "((" + a[0] + " & 1u) == 0u)";
  if ((n == "float" || n == "uint" || n == "length" || n == "normalize") && need(1))
    return n + "(" + a[0] + ")";
  if (n == "round" && need(1)) return "roundEven(" + a[0] + ")";
  if (n == "load" && need(2)) return a[0] + "[" + arrayIndex(a[0], a[1]) + "]";
  if (const auto words = wordArrayOfOp(n); words && need(1)) {
    const std::string array = wordArrayName(*words);  // payload_word: payload.words[i % N]
    return array + "[" + arrayIndex(array, a[0]) + "]";
  }
  if (n == "vec2" || n == "vec3" || n == "vec4") return n + join(", ");
  if ((n == "x" || n == "y" || n == "z" || n == "w") && need(1)) return a[0] + "." + n;
  if (n == "sphere_hit") return "rs_sphere_current().hit";
  if (n == "sphere_near") return "rs_sphere_current().t_near";
  if (n == "sphere_far") return "rs_sphere_current().t_far";
  if (n.rfind("shader_record_", 0) == 0 && need(1) && ctx.inlined) {  // glsl/emit_ray_query.h
    const std::string word =
        std::string(ctx.stage == Stage::Miss ? "rs_miss" : "rs_hit") + "_record_word(" + a[0] + ")";
    return n == "shader_record_float" ? "uintBitsToFloat(" + word + ")" : word;
  }
  if (n == "shader_record_uint" && need(1)) return "rs_shader_record_uint(" + a[0] + ")";
  if (n == "shader_record_float" && need(1)) return "rs_shader_record_float(" + a[0] + ")";
  if (n.rfind("light_", 0) == 0 && need(2)) return "rs_" + n + "(" + a[0] + ", " + a[1] + ")";
  return problem("op " + n + " with " + std::to_string(a.size()) + " args");
}

}  // namespace

std::string emitExpr(const Expr& e, const StageContext& ctx) {
  switch (e.kind) {
    case Expr::Kind::Literal:
      return literal(e);
    case Expr::Kind::Builtin:
      if (e.name == "barycentrics" && ctx.attribute_words) return "rs_attr.bary";
      return builtin(e.name, ctx);
    case Expr::Kind::Op:
      return op(e, ctx);
    case Expr::Kind::Local:
      return localName(e.name);
    case Expr::Kind::Constant:
      return "c_" + e.name;
    case Expr::Kind::RecordMember:
      return "rs_members." + e.name;
  }
  return problem("expression kind");
}

std::string localName(const std::string& name) {
  return "v_" + name;
}

std::string arrayIndex(const std::string& array, const std::string& index) {
  return "(" + index + ") % uint(" + array + ".length())";
}

const char* glslType(ValueType t) {
  switch (t) {
    case ValueType::Bool:
      return "bool";
    case ValueType::Uint:
      return "uint";
    case ValueType::Float:
      return "float";
    case ValueType::Vec2:
      return "vec2";
    case ValueType::Vec3:
      return "vec3";
    case ValueType::Vec4:
      return "vec4";
  }
  return "uint";
}

}  // namespace rayspec
