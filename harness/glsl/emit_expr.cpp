#include "glsl/emit_expr.h"

#include <cctype>

#include "glsl/glsl_literal.h"
#include "program/builtins.h"
#include "program/ops.h"
#include "program/payload_words.h"

namespace rayspec {
namespace {

std::string problem(const std::string& what) {
  std::string id = "rayspec_error_";
  for (char ch : what) id += (std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_');
  return id + "()";
}

// A sized scalar's literal: a Uint or Float constant converted (the
// checker holds the value to the type, so the conversion is exact).
std::string sizedLiteral(ValueType t, double v) {
  if (t == ValueType::Float64) return std::string(valueTypeGlsl(t)) + "(" + glslDouble(v) + ")";
  if (t == ValueType::Float16)
    return std::string(valueTypeGlsl(t)) + "(" + glslFloat(static_cast<float>(v)) + ")";
  const bool wide = v > 4294967295.0;
  return std::string(valueTypeGlsl(t)) + "(" +
         (wide ? std::to_string(static_cast<uint64_t>(v)) + "ul"
               : glslUint(static_cast<uint32_t>(v))) +
         ")";
}
// An int64's or uint64's literal over 32 bits (Expr::wide), exactly.
std::string sizedLiteral(const Expr& e) {
  if (!e.wide) return sizedLiteral(e.type, e.literal[0]);
  return std::string(valueTypeGlsl(e.type)) + "(" + std::to_string(e.wide) + "ul)";
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
    default:
      return sizedLiteral(e);
  }
}

// A word<i> family's word: payload.word3 -> payload.words[3].
std::string wordOf(const Expr& e) {
  const std::string i = "[" + std::to_string(e.word) + "]";
  if (const auto which = wordArrayOf(e.builtin)) return wordArrayName(*which) + i;
  return "rs_attr.words" + i;  // attribute.word<i>
}

// A sized family's member: payload.int8 -> payload.rs_int8,
// attribute.int8 -> rs_attr.rs_int8.
std::string sizedMemberOf(const Expr& e) {
  static const char* const kData[] = {"payload", "child", "call", "callee", "rs_attr"};
  const auto data = sizedDataOf(static_cast<Builtin>(e.builtin));
  return std::string(kData[static_cast<size_t>(*data)]) + "." +
         sizedMemberGlsl(static_cast<ValueType>(e.word));
}

// The GLSL a built-in is read as (program/builtin_table.h), the word<i>
// families by their index and hit by the stage; inlined in raygen, through
// the ray query (its candidate in any-hit and intersection, its committed
// intersection in closest-hit).
std::string builtin(const Expr& e, const StageContext& ctx) {
  const Stage stage = ctx.stage;
  if (isWordFamily(e.builtin)) return wordOf(e);
  if (isSizedFamily(e.builtin)) return sizedMemberOf(e);
  if (e.builtin == kBiHit) {
    if (stage == Stage::ClosestHit) return "1u";
    if (stage == Stage::Miss) return "0u";
    return problem("hit outside closest_hit and miss");
  }
  const BuiltinInfo* info = e.builtin < kBiCount ? &builtins()[e.builtin] : nullptr;
  // A ray_query's getters read its own query (rs_query), inlined or not.
  if (!ctx.inlined || !info || isQueryBuiltin(e.builtin))
    return info && info->glsl ? info->glsl : problem("unknown builtin " + e.name);
  if (e.builtin == kBiTmax)  // the hit's t, the committed t so far, the trace's tmax
    return stage == Stage::Intersection ? "rs_current_tmax()"
           : stage == Stage::Miss       ? "rs_q_tmax"
                                        : "rs_hit_t";
  const std::string spelled = rayQuerySpelling(*info, stage == Stage::ClosestHit);
  return spelled.empty() ? problem(e.name + " cannot be read by a ray query") : spelled;
}

// An op's GLSL pattern (program/op_table.h) with its arguments' GLSL: $i
// the i-th, $, $& $| all of them joined by ", ", " && ", " || ".
std::string expandPattern(const std::string& pattern, const std::vector<std::string>& a) {
  std::string out;
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '$' || i + 1 == pattern.size()) {
      out += pattern[i];
      continue;
    }
    const char next = pattern[++i];
    if (next >= '0' && next <= '9') {
      const size_t k = static_cast<size_t>(next - '0');
      out += k < a.size() ? a[k] : problem("missing argument " + std::to_string(k));
      continue;
    }
    const char* sep = next == ',' ? ", " : next == '&' ? " && " : " || ";
    for (size_t k = 0; k < a.size(); ++k) out += (k ? sep : "") + a[k];
  }
  return out;
}

// The ops whose GLSL depends on more than their arguments (a null pattern).
std::string spelledOp(const Expr& e, const std::vector<std::string>& a, const StageContext& ctx) {
  if (a.size() == 2 && e.op == Op::Load) return a[0] + "[" + arrayIndex(a[0], a[1]) + "]";
  if (const auto words = wordArrayOf(e.op); words && a.size() == 1) {
    const std::string array = wordArrayName(*words);  // payload_word: payload.words[i % N]
    return array + "[" + arrayIndex(array, a[0]) + "]";
  }
  const bool record_uint = e.op == Op::RecordUint, record_float = e.op == Op::RecordFloat;
  if ((record_uint || record_float) && a.size() == 1) {
    if (!ctx.inlined) return std::string("rs_") + e.name + "(" + a[0] + ")";
    const std::string word =  // glsl/emit_ray_query.h
        std::string(ctx.stage == Stage::Miss ? "rs_miss" : "rs_hit") + "_record_word(" + a[0] + ")";
    return record_float ? "uintBitsToFloat(" + word + ")" : word;
  }
  return problem("op " + e.name + " with " + std::to_string(a.size()) + " args");
}

std::string op(const Expr& e, const StageContext& ctx) {
  std::vector<std::string> a;
  for (const Expr& arg : e.args) a.push_back(emitExpr(arg, ctx));
  if (e.op == Op::None) return problem("op " + e.name + " not resolved");
  const OpInfo& info = opInfo(e.op);
  if (!info.glsl) return spelledOp(e, a, ctx);
  // sphere_* outside intersection: in a ray_query's aabb block, the
  // query's candidate's (program/ops.h; shaders/query_sphere.glsl).
  if (isSphereOp(e.op) && ctx.stage != Stage::Intersection) {
    const std::string own = "rs_sphere_current()";
    return "rs_cand_sphere(rs_query)" + std::string(info.glsl).substr(own.size());
  }
  if (static_cast<int>(a.size()) < info.min_args)
    return problem("op " + e.name + " with " + std::to_string(a.size()) + " args");
  return expandPattern(info.glsl, a);
}

}  // namespace

std::string emitExpr(const Expr& e, const StageContext& ctx) {
  switch (e.kind) {
    case Expr::Kind::Literal:
      return literal(e);
    case Expr::Kind::Builtin:
      if (e.builtin == kBiBarycentrics && ctx.attributeStruct()) return "rs_attr.bary";
      return builtin(e, ctx);
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
  const size_t dot = name.find('.');  // a struct's member: STRUCT.MEMBER
  if (dot != std::string::npos) return "v_" + name.substr(0, dot) + ".m_" + name.substr(dot + 1);
  return "v_" + name;
}

std::string arrayIndex(const std::string& array, const std::string& index) {
  return "(" + index + ") % uint(" + array + ".length())";
}

const char* glslType(ValueType t) {
  return valueTypeGlsl(t);
}

}  // namespace rayspec
