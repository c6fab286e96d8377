// The model's meaning of the sized scalars' ops (program/sized_types.h):
// integers wrap modulo 2^bits; a float16 or float64 result is the exact one,
// and one that is not exact (or not normal) is a case error, since rounding
// and denormals are the device's choice; conversions as GLSL's constructors.
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

}  // namespace

Val halvedSized(const Val& v) {
  const SizedType* s = sizedType(v.sized);
  const uint64_t low_half = (uint64_t{1} << (s->bits / 2)) - 1;
  if (v.sized == ValueType::Float64) return fromSized(v.sized, v.x & ~low_half);
  if (v.sized != ValueType::Float16) return fromSized(v.sized, v.x & ~low_half);
  // A normal float16: 11 significant bits, the low 8 of them (its
  // encoding's low byte) zero.
  const double d = sizedDouble(v);
  if (d == 0) return v;
  int exponent = 0;
  const double significand = std::ldexp(std::frexp(d, &exponent), 11);  // +-[1024, 2048)
  const double kept = std::trunc(significand / 256) * 256;
  return fromSizedDouble(v.sized, std::ldexp(kept, exponent - 11));
}

bool sizedLess(ValueType t, const Val& a, const Val& b) {
  const SizedKind kind = sizedType(t)->kind;
  if (kind == SizedKind::Floating) return sizedDouble(a) < sizedDouble(b);
  if (kind == SizedKind::Signed) return static_cast<int64_t>(a.x) < static_cast<int64_t>(b.x);
  return a.x < b.x;
}

bool sizedEqual(ValueType t, const Val& a, const Val& b) {
  return isSizedFloat(t) ? sizedDouble(a) == sizedDouble(b) : a.x == b.x;
}

Val StageInterpreter::sizedArithmetic(const CExpr& e, const Val* a) {
  const ValueType t = e.type;
  if (isSizedInteger(t)) return fromSized(t, integerOp(e.op, t, a[0].x, a[1].x));
  const std::optional<double> r = exactDouble(e.op, sizedDouble(a[0]), sizedDouble(a[1]));
  if (!r || (t == ValueType::Float16 && !exactInFloat16(*r))) inexact(e);
  return fromSizedDouble(t, r.value_or(0));
}

Val StageInterpreter::convert(const CExpr& e, const Val& a) {
  const ValueType from = e.args[0].type;
  if (e.op == Op::HighWord) return fromUint(static_cast<uint32_t>(a.x >> 32));
  if (e.op == Op::ToUint && isSizedInteger(from)) return fromUint(static_cast<uint32_t>(a.x));
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
    return fromSized(to, wrapToType(to, from == ValueType::Uint ? uint64_t{a.u} : a.x));
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
