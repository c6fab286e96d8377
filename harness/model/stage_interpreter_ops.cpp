// The model's meaning of every op (program/ops.h): StageInterpreter::op and
// its helpers (stage_interpreter.h).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <new>

#include "model/hit_protocol.h"
#include "model/model_shading.h"
#include "model/query_run.h"
#include "model/stage_interpreter.h"

namespace rayspec {
namespace {

bool isVec(ValueType t) {
  return t == ValueType::Vec2 || t == ValueType::Vec3 || t == ValueType::Vec4;
}

// eq ne lt le gt ge of two sized scalars of type t.
Val compareSized(Op n, const Val* a, ValueType t) {
  Val r;
  const bool lt = sizedLess(t, a[0], a[1]), eq = sizedEqual(t, a[0], a[1]);
  r.b = n == Op::Eq   ? eq
        : n == Op::Ne ? !eq
        : n == Op::Lt ? lt
        : n == Op::Le ? lt || eq
        : n == Op::Gt ? !lt && !eq
                      : !lt;
  return r;
}

// eq ne lt le gt ge: Uint x Uint exactly, sized scalars by their type, else
// as doubles.
Val compare(Op n, const Val* a, ValueType t0, ValueType t1) {
  if (isSized(t0)) return compareSized(n, a, t0);
  Val r;
  const bool u = t0 == ValueType::Uint && t1 == ValueType::Uint;
  const double x = u ? a[0].u : static_cast<double>(t0 == ValueType::Uint ? a[0].u : a[0].f[0]);
  const double y = u ? a[1].u : static_cast<double>(t1 == ValueType::Uint ? a[1].u : a[1].f[0]);
  if (n == Op::Eq)
    r.b = x == y;
  else if (n == Op::Ne)
    r.b = x != y;
  else if (n == Op::Lt)
    r.b = x < y;
  else if (n == Op::Le)
    r.b = x <= y;
  else if (n == Op::Gt)
    r.b = x > y;
  else
    r.b = x >= y;
  return r;
}

// dot, length, normalize of vectors with cnt components.
Val vectorLength(Op n, const Val* a, int cnt) {
  Val r;
  float d = 0;
  const Val& b = n == Op::Dot ? a[1] : a[0];
  for (int k = 0; k < cnt; ++k) d = k == 0 ? a[0].f[0] * b.f[0] : d + a[0].f[k] * b.f[k];
  if (n == Op::Dot) return fromFloat(d);
  const float len = std::sqrt(d);
  if (n == Op::Length) return fromFloat(len);
  for (int k = 0; k < cnt; ++k) r.f[k] = a[0].f[k] / len;
  return r;
}

Val lightOp(Op n, const Val* a, const std::vector<uint32_t>* record_data) {
  static const std::vector<uint32_t> kNoRecord;
  const LightKind kind = n == Op::LightPoint  ? LightKind::Point
                         : n == Op::LightSpot ? LightKind::Spot
                                              : LightKind::Directional;
  Val r;
  r.f = lightColor(kind, {a[0].f[0], a[0].f[1], a[0].f[2]}, {a[1].f[0], a[1].f[1], a[1].f[2]},
                   record_data ? *record_data : kNoRecord);
  return r;
}

}  // namespace

// The record data a shader record read reads: the stage's own, or its hit
// object's (hitObjectGetShaderRecordBufferHandleNV; the planted HandleOwn
// fault reads the stage's own there too).
const std::vector<uint32_t>* StageInterpreter::recordDataRead(Op n, const StageEnv& env) const {
  if (n == Op::RecordUint || n == Op::RecordFloat ||
      sh_.fault_seam.hitObjectRecord(HitObjectRecordFault::HandleOwn))
    return env.record_data;
  return env.hit_object ? env.hit_object->record_data : nullptr;
}

bool StageInterpreter::opOnDemand(const CExpr& e, StageEnv& env, Val& r) {
  const Op n = e.op;
  switch (n) {
    case Op::SphereHit:
    case Op::SphereNear:
    case Op::SphereFar: {
      // An intersection program's own box, decided by its trace; elsewhere
      // (a ray_query's aabb block) the query's AABB candidate's, decided by
      // the query's traversal (program/ops.h).
      static const HitView kNone;
      const bool own = env.stage == Stage::Intersection;
      const QueryRun* q = env.query;
      const HitView* hv = own ? env.hit : q && q->cand ? &q->cand_view : nullptr;
      if (!hv) hv = &kNone;
      Traversal* tr = own ? env.traversal : q ? q->tr : nullptr;
      SphereRoots s =
          sphereRoots(hv->aabb_min, hv->aabb_max, hv->object_origin, hv->object_direction);
      if (n == Op::SphereHit)
        r.b = tr && hv != &kNone ? hits_.sphereHitDecision(*tr, *hv, s.hit, s.disc) : s.hit;
      else
        r.f[0] = n == Op::SphereNear ? s.t_near : s.t_far;
      return true;
    }
    case Op::RecordUint:
    case Op::RecordFloat:
    case Op::HitObjectRecordUint:
    case Op::HitObjectRecordFloat: {
      const std::vector<uint32_t>* data = recordDataRead(n, env);
      const uint32_t i = e.index;
      const uint32_t w = data && i < data->size() ? (*data)[i] : 0u;
      r = n == Op::RecordUint || n == Op::HitObjectRecordUint ? fromUint(w)
                                                              : fromFloat(std::bit_cast<float>(w));
      return true;
    }
    case Op::And:
    case Op::Or: {
      const bool is_and = n == Op::And;
      r.b = is_and;
      for (const CExpr& a : e.args) {
        const bool b = eval(a, env).b;
        if (is_and != b) {
          r.b = b;
          break;
        }
      }
      return true;
    }
    case Op::Load: {  // an element of an array local, index modulo its size
      const CExpr& array = e.args[0];
      const uint32_t n = std::max<uint32_t>(array.size, 1);
      const size_t slot = array.index + eval(e.args[1], env).u % n;
      r = slot < env.locals.size() ? env.locals[slot] : Val{};
      return true;
    }
    case Op::PayloadWord:
    case Op::ChildWord:
    case Op::CallWord:
    case Op::CalleeWord: {
      const uint32_t* w =
          ModelBuiltins::dataWord(*wordArrayOf(n), e.size, eval(e.args[0], env).u, env);
      r = fromUint(w ? *w : 0u);
      return true;
    }
    case Op::None:
      if (st_.error.empty())
        st_.error = "model: unknown op '" + (e.src ? e.src->name : std::string("?")) + "'";
      return true;
    default:
      return false;
  }
}

namespace {

// bit_and .. shr on Uint (a shift by b % 32, as the generated GLSL does),
// and the bit casts.
Val bitOp(Op n, const Val* a) {
  const uint32_t x = a[0].u, y = a[1].u;
  switch (n) {
    case Op::BitAnd:
      return fromUint(x & y);
    case Op::BitOr:
      return fromUint(x | y);
    case Op::BitXor:
      return fromUint(x ^ y);
    case Op::BitNot:
      return fromUint(~x);
    case Op::Shl:
      return fromUint(x << (y & 31u));
    case Op::Shr:
      return fromUint(x >> (y & 31u));
    case Op::FloatBits:
      return fromUint(std::bit_cast<uint32_t>(a[0].f[0]));
    default:  // BitsFloat
      return fromFloat(std::bit_cast<float>(x));
  }
}

// mat3_mul: c0 v.x + c1 v.y + c2 v.z; mat3_tmul: (c0.v, c1.v, c2.v).
Val matrixTimes(Op n, const Val* a) {
  const auto& v = a[3].f;
  Val r;
  for (int k = 0; k < 3; ++k)
    r.f[k] = n == Op::Mat3Mul ? a[0].f[k] * v[0] + a[1].f[k] * v[1] + a[2].f[k] * v[2]
                              : a[k].f[0] * v[0] + a[k].f[1] * v[1] + a[k].f[2] * v[2];
  return r;
}

Val crossProduct(const Val* a) {
  Val r;
  r.f = {a[0].f[1] * a[1].f[2] - a[0].f[2] * a[1].f[1],
         a[0].f[2] * a[1].f[0] - a[0].f[0] * a[1].f[2],
         a[0].f[0] * a[1].f[1] - a[0].f[1] * a[1].f[0], 0.0f};
  return r;
}

}  // namespace

namespace {

// An operator's argument slots, built in place: zeroing four Vals before
// filling them cost as much as the operator itself (a 4M-id launch
// interprets some 30 operators an id). Slots past the arguments read as zero.
union ArgSlots {
  ArgSlots() {}
  template <typename Eval>
  size_t fill(size_t count, Eval eval) {
    const size_t n = std::min<size_t>(count, 4);
    for (size_t i = 0; i < n; ++i) new (&v[i]) Val(eval(i));
    for (size_t i = n; i < 4; ++i) new (&v[i]) Val();
    return n;
  }
  operator Val*() { return v; }
  Val v[4];
};

// not, odd, even and the conversions of one scalar.
Val unaryOp(Op n, const Val& a) {
  Val r;
  switch (n) {
    case Op::Not:
      r.b = !a.b;
      return r;
    case Op::Odd:
      r.b = (a.u & 1u) != 0;
      return r;
    case Op::Even:
      r.b = (a.u & 1u) == 0;
      return r;
    case Op::ToFloat:
      return fromFloat(static_cast<float>(a.u));
    case Op::ToUint: {
      const float f = a.f[0];
      return fromUint(f <= 0 || std::isnan(f) ? 0u
                      : f >= 4294967295.0f    ? 0xFFFFFFFFu
                                              : static_cast<uint32_t>(f));
    }
    case Op::RoundEven:  // the default rounding mode: to nearest, ties to even
      return fromFloat(std::nearbyint(a.f[0]));
    default:
      return r;
  }
}

// The conversions of model/sized_ops.cpp: to a sized scalar, high, and
// float and uint of a sized scalar.
bool convertsSized(const CExpr& e) {
  const Op n = e.op;
  if (isConversion(n) || n == Op::HighWord) return true;
  return (n == Op::ToFloat || n == Op::ToUint) && isSized(e.args[0].type);
}

// vec2..vec4 (na arguments), the components, cross, the 3x3 products, dot,
// length and normalize of vectors of `components`.
Val vectorOp(Op n, const Val* a, size_t na, int components) {
  Val r;
  switch (n) {
    case Op::Vec2:
    case Op::Vec3:
    case Op::Vec4: {
      const int cnt = 2 + static_cast<int>(n) - static_cast<int>(Op::Vec2);
      for (int k = 0; k < cnt; ++k)
        r.f[k] = na == 1 ? a[0].f[0] : (k < static_cast<int>(na) ? a[k].f[0] : 0.0f);
      return r;
    }
    case Op::CompX:
    case Op::CompY:
    case Op::CompZ:
    case Op::CompW:
      return fromFloat(a[0].f[static_cast<int>(n) - static_cast<int>(Op::CompX)]);
    case Op::Cross:
      return crossProduct(a);
    case Op::Mat3Mul:
    case Op::Mat3TMul:
      return matrixTimes(n, a);
    case Op::Dot:
    case Op::Length:
    case Op::Normalize:
      return vectorLength(n, a, components);
    default:
      return r;
  }
}

// The sized vectors' constructors and components (model/sized_ops.cpp).
bool makesSized(const CExpr& e) {
  const Op n = e.op;
  if (isSizedConstructor(n)) return true;
  return n >= Op::CompX && n <= Op::CompW && isSizedVector(e.args[0].type);
}

}  // namespace

// The case labels of the ops made before op()'s switch.
#define RAYSPEC_CONVERSION_CASE(X, id, ...) case Op::To##id:
#define RAYSPEC_CONSTRUCTOR_CASE(X, id, ...) \
  case Op::Make##id##Vec2:                   \
  case Op::Make##id##Vec3:                   \
  case Op::Make##id##Vec4:

Val StageInterpreter::op(const CExpr& e, StageEnv& env) {
  const Op n = e.op;
  Val r;
  if (opOnDemand(e, env, r)) return r;
  ArgSlots a;  // every remaining op takes at most 4 arguments (vec4)
  const size_t na = a.fill(e.args.size(), [&](size_t i) { return eval(e.args[i], env); });
  if (convertsSized(e)) return convert(e, a[0]);
  if (makesSized(e)) return constructSized(e, a, na);
  switch (n) {
    case Op::BitAnd:
    case Op::BitOr:
    case Op::BitXor:
    case Op::BitNot:
    case Op::Shl:
    case Op::Shr:
    case Op::FloatBits:
    case Op::BitsFloat:
      return bitOp(n, a);
    case Op::Not:
    case Op::Odd:
    case Op::Even:
    case Op::ToFloat:
    case Op::ToUint:
    case Op::RoundEven:
      return unaryOp(n, a[0]);
    case Op::Vec2:
    case Op::Vec3:
    case Op::Vec4:
    case Op::CompX:
    case Op::CompY:
    case Op::CompZ:
    case Op::CompW:
    case Op::Cross:
    case Op::Mat3Mul:
    case Op::Mat3TMul:
    case Op::Dot:
    case Op::Length:
    case Op::Normalize:
      return vectorOp(n, a, na, componentCount(e.args[0].type));
    case Op::LightPoint:
    case Op::LightSpot:
    case Op::LightDirectional:
      return lightOp(n, a, env.record_data);
    case Op::Eq:
    case Op::Ne:
    case Op::Lt:
    case Op::Le:
    case Op::Gt:
    case Op::Ge:
      return compare(n, a, e.args[0].type, e.args[1].type);
    case Op::Mod:
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Min:
    case Op::Max:
      return arithmetic(e, a);
    case Op::SphereHit:  // evaluated on demand (opOnDemand)
    case Op::SphereNear:
    case Op::SphereFar:
    case Op::RecordUint:
    case Op::RecordFloat:
    case Op::HitObjectRecordUint:
    case Op::HitObjectRecordFloat:
    case Op::And:
    case Op::Or:
    case Op::Load:
    case Op::PayloadWord:
    case Op::ChildWord:
    case Op::CallWord:
    case Op::CalleeWord:
    case Op::HighWord:  // converted before the switch (convertsSized)
      RAYSPEC_SIZED_TYPES(RAYSPEC_CONVERSION_CASE, )
      RAYSPEC_VECTOR_ROWS(RAYSPEC_CONSTRUCTOR_CASE, )  // made before the switch (makesSized)
    case Op::None:
      break;
  }
  return r;
}
#undef RAYSPEC_CONVERSION_CASE
#undef RAYSPEC_CONSTRUCTOR_CASE

Val StageInterpreter::arithmetic(const CExpr& e, const Val* a) {
  const Op n = e.op;
  Val r;
  if (isSized(e.type)) return sizedArithmetic(e, a);
  // Uint x Uint, or float-wise with scalar broadcast.
  if (e.type == ValueType::Uint) {
    const uint32_t x = a[0].u, y = a[1].u;
    if (n == Op::Add)
      r.u = x + y;
    else if (n == Op::Sub)
      r.u = x - y;
    else if (n == Op::Mul)
      r.u = x * y;
    else if (n == Op::Mod && y == 0) {
      st_.divisionByZero(e);  // R-UB: the ray is undefined; the model goes on with 0
      r.u = 0;
    } else if (n == Op::Mod)
      r.u = x % y;
    else if (n == Op::Div && y == 0) {
      st_.divisionByZero(e);  // R-UB: the ray is undefined; the model goes on with all ones
      r.u = 0xFFFFFFFFu;
    } else if (n == Op::Div)
      r.u = x / y;
    else if (n == Op::Min)
      r.u = std::min(x, y);
    else if (n == Op::Max)
      r.u = std::max(x, y);
    return r;
  }
  const int cnt = componentCount(e.type);
  auto comp = [&](size_t i, int k) {
    if (e.args[i].type == ValueType::Uint) return static_cast<float>(a[i].u);
    return isVec(e.args[i].type) ? a[i].f[k] : a[i].f[0];
  };
  for (int k = 0; k < cnt; ++k) {
    const float x = comp(0, k), y = comp(1, k);
    if (n == Op::Add)
      r.f[k] = x + y;
    else if (n == Op::Sub)
      r.f[k] = x - y;
    else if (n == Op::Mul)
      r.f[k] = x * y;
    else if (n == Op::Div)
      r.f[k] = x / y;
    else if (n == Op::Min)
      r.f[k] = std::fmin(x, y);
    else if (n == Op::Max)
      r.f[k] = std::fmax(x, y);
  }
  return r;
}

}  // namespace rayspec
