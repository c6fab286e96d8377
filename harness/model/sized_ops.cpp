// The model's meaning of the sized scalars' and vectors' ops
// (program/sized_types.h): integers wrap modulo 2^bits; a float16 or float64
// result is the exact one, and one that is not exact (or not normal) is a
// case error, since rounding and denormals are the device's choice;
// conversions and constructors as GLSL's; a vector's ops lane by lane.
#include <bit>
#include <cmath>
#include <optional>

#include "model/stage_interpreter.h"
#include "program/sized_values.h"

namespace rayspec {
namespace {

// x op y exactly in a double (sum, difference, product), or nullopt where
// rounding, overflow or a denormal would decide it; min, max as fmin, fmax.
std::optional<double> exactDouble(Op n, double x, double y) {
  if (n == Op::Min) return std::fmin(x, y);
  if (n == Op::Max) return std::fmax(x, y);
  const double r = n == Op::Add ? x + y : n == Op::Sub ? x - y : x * y;
  if (!std::isfinite(r) || !normalOrZero(r)) return std::nullopt;
  if (n == Op::Mul) {
    if (std::fma(x, y, -r) != 0 || (r == 0 && x != 0 && y != 0)) return std::nullopt;
    return r;
  }
  const double b = n == Op::Add ? y : -y;  // two-sum: r + err == x + b exactly
  const double bv = r - x;
  return (x - (r - bv)) + (b - bv) == 0 ? std::optional<double>(r) : std::nullopt;
}

uint64_t integerOp(Op n, ValueType t, uint64_t x, uint64_t y) {
  const bool is_signed = sizedType(t)->kind == SizedKind::Signed;
  const auto less = [&](uint64_t p, uint64_t q) {
    return is_signed ? static_cast<int64_t>(p) < static_cast<int64_t>(q) : p < q;
  };
  switch (n) {
    case Op::Add:
      return wrapToType(t, x + y);
    case Op::Sub:
      return wrapToType(t, x - y);
    case Op::Mul:
      return wrapToType(t, x * y);
    case Op::Min:
      return less(y, x) ? y : x;
    default:  // Max
      return less(x, y) ? y : x;
  }
}

// A value as a double: Uint, Float or a sized float.
double asDouble(ValueType t, const Val& v) {
  return t == ValueType::Uint ? v.u : t == ValueType::Float ? v.f[0] : sizedDouble(v);
}

// One lane's bits of a value of type t through a slot half its width.
uint64_t halvedLane(ValueType t, uint64_t x) {
  const SizedType* s = sizedType(t);
  const uint64_t low_half = (uint64_t{1} << (s->bits / 2)) - 1;
  if (sizedComponent(t) != ValueType::Float16) return x & ~low_half;
  // A normal float16: 11 significant bits, the low 8 of them (its
  // encoding's low byte) zero.
  const double d = std::bit_cast<double>(x);
  if (d == 0) return x;
  int exponent = 0;
  const double significand = std::ldexp(std::frexp(d, &exponent), 11);  // +-[1024, 2048)
  const double kept = std::trunc(significand / 256) * 256;
  return std::bit_cast<uint64_t>(std::ldexp(kept, exponent - 11));
}

}  // namespace

Val halvedSized(const Val& v) {
  Val r = v;
  for (int k = 0; k < componentCount(v.sized); ++k) r.x[k] = halvedLane(v.sized, v.x[k]);
  return r;
}

void halveMembers(SizedSlots& members) {
  for (auto& [type, lanes] : members.members) {
    Val v;
    v.sized = type;
    v.x = lanes;
    lanes = halvedSized(v).x;
  }
}

Val rotatedSized(const Val& v) {
  Val r = v;
  const int n = componentCount(v.sized);
  for (int k = 0; k < n; ++k) r.x[k] = v.x[(k + 1) % n];
  return r;
}

Val onesSized(ValueType t) {
  Val r = fromSized(t, 0);
  const uint64_t one = isSizedFloat(t) ? std::bit_cast<uint64_t>(1.0) : 1;
  for (int k = 0; k < componentCount(t); ++k) r.x[k] = one;
  return r;
}

bool sizedLess(ValueType t, const Val& a, const Val& b) {
  const SizedKind kind = sizedType(t)->kind;
  if (kind == SizedKind::Floating) return sizedDouble(a) < sizedDouble(b);
  if (kind == SizedKind::Signed) return static_cast<int64_t>(a.x[0]) < static_cast<int64_t>(b.x[0]);
  return a.x[0] < b.x[0];
}

bool sizedEqual(ValueType t, const Val& a, const Val& b) {
  return isSizedFloat(t) ? sizedDouble(a) == sizedDouble(b) : a.x[0] == b.x[0];
}

namespace {

// A scalar's bits as a lane: a sized scalar's, or a uint's (beside a uvec).
uint64_t scalarLane(ValueType t, const Val& v) {
  return t == ValueType::Uint ? uint64_t{v.u} : v.x[0];
}

// A lane of a sized vector of component `component` as a value.
Val fromLane(ValueType component, uint64_t x) {
  return component == ValueType::Uint ? fromUint(static_cast<uint32_t>(x))
                                      : fromSized(component, x);
}

}  // namespace

// Lane by lane; a scalar beside a vector is every lane's.
Val StageInterpreter::sizedArithmetic(const CExpr& e, const Val* a) {
  const ValueType t = e.type, component = sizedComponent(t);
  const auto lane = [&](int i, int k) {
    const ValueType at = e.args[i].type;
    return isSizedVector(at) ? a[i].x[k] : scalarLane(at, a[i]);
  };
  Val r = fromSized(t, 0);
  for (int k = 0; k < componentCount(t); ++k) {
    if (isSizedInteger(t)) {
      r.x[k] = integerOp(e.op, t, lane(0, k), lane(1, k));
      continue;
    }
    const std::optional<double> d =
        exactDouble(e.op, std::bit_cast<double>(lane(0, k)), std::bit_cast<double>(lane(1, k)));
    if (!d || (component == ValueType::Float16 && !exactInFloat16(*d))) inexact(e);
    r.x[k] = std::bit_cast<uint64_t>(d.value_or(0));
  }
  return r;
}

Val StageInterpreter::constructSized(const CExpr& e, const Val* a, size_t n) const {
  if (e.op >= Op::CompX && e.op <= Op::CompW) {  // x .. w of a sized vector
    const ValueType t = e.args[0].type;
    return fromLane(sizedComponent(t),
                    a[0].x[static_cast<int>(e.op) - static_cast<int>(Op::CompX)]);
  }
  const ValueType t = constructorTarget(e.op);
  Val r = fromSized(t, 0);
  for (size_t k = 0; k < static_cast<size_t>(componentCount(t)); ++k)
    r.x[k] = scalarLane(sizedComponent(t), a[n == 1 ? 0 : k]);
  return r;
}

Val StageInterpreter::convert(const CExpr& e, const Val& a) {
  const ValueType from = e.args[0].type;
  if (e.op == Op::HighWord) return fromUint(static_cast<uint32_t>(a.x[0] >> 32));
  if (e.op == Op::ToUint && isSizedInteger(from)) return fromUint(static_cast<uint32_t>(a.x[0]));
  if (e.op == Op::ToUint) {  // a sized float, truncated toward zero as Float's is
    const double d = sizedDouble(a);
    return fromUint(d <= 0 || std::isnan(d) ? 0u
                    : d >= 4294967295.0     ? 0xFFFFFFFFu
                                            : static_cast<uint32_t>(d));
  }
  if (e.op == Op::ToFloat) {  // from Float16 always exact, from Float64 when it is
    const double d = sizedDouble(a);
    if (!exactInFloat32(d)) inexact(e);
    return fromFloat(static_cast<float>(d));
  }
  const ValueType to = conversionTarget(e.op);
  if (isSizedInteger(to))
    return fromSized(to, wrapToType(to, from == ValueType::Uint ? uint64_t{a.u} : a.x[0]));
  const double d = asDouble(from, a);
  if (!normalOrZero(d) || (to == ValueType::Float16 && !exactInFloat16(d))) inexact(e);
  return fromSizedDouble(to, d);
}

void StageInterpreter::inexact(const CExpr& e) {
  if (!st_.error.empty()) return;
  const std::string field =
      e.src && !e.src->loc.field.empty() ? e.src->loc.field : std::string(e.src ? e.src->name : "");
  st_.error = "model: " + field + ": " + valueTypeName(e.type) +
              " result not exact (a device rounds it or flushes it as it chooses; keep sized "
              "float arithmetic exact)";
}

}  // namespace rayspec
