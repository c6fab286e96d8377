// Typed live state in the generated programs (R-LIVE-STATE): locals of the
// sized types (program/sized_types.h: int8 .. float64 and their vectors,
// int32, uint's vectors), a struct of a few such members and now and then an
// array of one, set before the traces, calls or reports of a program and
// folded after them into one Uint it records (or reports as a hit kind). Each
// value is made of conversions of Uint expressions and literals, combined
// only by what the vocabulary defines as exact in its type: integers wrap
// (add, sub, mul, min, max); a float16 or float64 value stays a multiple of
// 1/4 of bounded magnitude, so every sum and product is exact and the fold
// to a Uint too. The model derives every bit the device must give. Drawn
// from a stream of its own (CaseGenerator::swapStreams): a case without typed
// state is the case the generator made before it drew any.
#include <algorithm>
#include <cmath>

#include "fuzz/program_generator.h"

namespace rayspec {
namespace {

// The chance a site (a live local across traces or calls, an intersection
// program) holds typed state: about a quarter of the cases hold some (79 of
// seeds 0..299, 84 of 88001..88304).
constexpr double kTypedChance = 0.12;

// A value as the case writes it. A float type's value (float16, float64 and
// their vectors') is a multiple of 2^-frac at most `bound` in magnitude (each
// lane's).
struct TypedValue {
  std::string text;
  double bound = 0;
  int frac = 0;
};

// A float value within what keeps it exact: quarters at most; a float16's
// 11 significant bits hold every multiple of 2^-frac up to 2^(11 - frac),
// and its fold (readParts) needs |v| <= 512; a float64's needs |v| <= 2^28.
bool fitsFloat(ValueType component, const TypedValue& v) {
  if (v.frac > 2) return false;
  if (component == ValueType::Float16) return v.bound * (1 << v.frac) <= 2048 && v.bound <= 512;
  return v.bound <= 268435456.0;
}

// The largest literal an integer component type (or uint, a uvec's) holds.
uint64_t largestLiteral(ValueType component) {
  if (component == ValueType::Uint) return 0xFFFFFFFFull;
  const SizedType* s = sizedType(component);
  const int bits = s->bits - (s->kind == SizedKind::Signed ? 1 : 0);
  return bits >= 64 ? ~uint64_t{0} : (uint64_t{1} << bits) - 1;
}

std::string spelling(ValueType t) {
  return valueTypeSpelling(t);
}

// a op b, with the bounds of a float result.
TypedValue combine(const std::string& op, const TypedValue& a, const TypedValue& b) {
  TypedValue r{"{" + op + ": [" + a.text + ", " + b.text + "]}", std::max(a.bound, b.bound),
               std::max(a.frac, b.frac)};
  if (op == "add" || op == "sub") r.bound = a.bound + b.bound;
  if (op == "mul") {
    r.bound = a.bound * b.bound;
    r.frac = a.frac + b.frac;
  }
  return r;
}

// The Uint parts of value `e` of type t, each lane's: an integer's low 32
// bits (a 64-bit one's high ones too), a float's value in quarters shifted
// to be positive (float16: v * 4 + 2048 in float32; float64: (v + 2^29) * 4),
// every step exact.
void readParts(const std::string& e, ValueType t, std::vector<std::string>& parts) {
  static const char* const kLanes[] = {"x", "y", "z", "w"};
  if (isSizedVector(t)) {
    for (int k = 0; k < componentCount(t); ++k)
      readParts("{" + std::string(kLanes[k]) + ": " + e + "}", sizedComponent(t), parts);
  } else if (t == ValueType::Uint) {
    parts.push_back(e);
  } else if (t == ValueType::Float16) {
    parts.push_back("{uint: {add: [{mul: [{float: " + e + "}, 4.0]}, 2048.0]}}");
  } else if (t == ValueType::Float64) {
    parts.push_back("{uint: {mul: [{add: [" + e + ", 536870912.0]}, 4.0]}}");
  } else {
    parts.push_back("{uint: " + e + "}");
    if (sizedType(t)->bits == 64) parts.push_back("{high: " + e + "}");
  }
}

// The parts as one Uint, pairs folded as a * 31 + b (so the order counts).
std::string foldParts(std::vector<std::string> parts) {
  while (parts.size() > 1) {
    std::vector<std::string> next;
    for (size_t i = 0; i + 1 < parts.size(); i += 2)
      next.push_back("{add: [{mul: [" + parts[i] + ", 31]}, " + parts[i + 1] + "]}");
    if (parts.size() % 2) next.push_back(parts.back());
    parts = std::move(next);
  }
  return parts.front();
}

// The values of one program's typed state, of the types it may draw.
class TypedDraws {
 public:
  TypedDraws(CaseGenerator& g, Stage stage, std::vector<ValueType> types)
      : g_(g), stage_(stage), types_(std::move(types)) {}

  ValueType type() {
    const ValueType t = g_.oneOf(types_);
    vectors_ = vectors_ || isSizedVector(t);
    return t;
  }
  bool drewVectors() const { return vectors_; }

  // Locals of drawn types (one let).
  std::string locals(const std::vector<std::string>& names) {
    std::string let;
    for (const std::string& v : names) {
      const ValueType t = type();
      let += (let.empty() ? "" : ", ") + v + ": " + value(t, 2).text;
      readParts("var." + v, t, parts_);
    }
    return "{let: {" + let + "}}";
  }

  // A struct of 2 to 4 members of drawn types, most of them set (the others
  // stay zero).
  std::string structLocal(const std::string& name) {
    static const char* const kMembers[] = {"a", "b", "c", "d"};
    std::string members, set;
    const size_t n = 2 + g_.pick(3);
    for (size_t k = 0; k < n; ++k) {
      const ValueType t = type();
      const std::string member = name + "." + kMembers[k];
      members += (k ? ", " : "") + std::string(kMembers[k]) + ": " + spelling(t);
      if (g_.chance(0.85)) set += (set.empty() ? "" : ", ") + member + ": " + value(t, 1).text;
      readParts("var." + member, t, parts_);
    }
    const std::string declared = "{struct: {name: " + name + ", members: {" + members + "}}}";
    return set.empty() ? declared : declared + ", {set: {" + set + "}}";
  }

  // An array of 2 to 4 elements of a drawn type, some stored (the others
  // stay zero: the null initialiser), every one read.
  std::string arrayLocal(const std::string& name) {
    const ValueType t = type();
    const size_t n = 2 + g_.pick(3);
    std::string s =
        "{array: {name: " + name + ", of: " + spelling(t) + ", size: " + std::to_string(n) + "}}";
    for (size_t k = 0; k < n; ++k) {
      if (g_.chance(0.6))
        s += ", {store: {array: " + name + ", index: " + std::to_string(k) +
             ", value: " + value(t, 1).text + "}}";
      readParts("{load: [var." + name + ", " + std::to_string(k) + "]}", t, parts_);
    }
    return s;
  }

  std::string fold() const { return foldParts(parts_); }

  // A value of t: an atom, or one operation on it (with a value of t, a
  // literal, or for a vector's add, sub and mul a scalar of its component),
  // kept where it stays exact.
  TypedValue value(ValueType t, int depth) {
    static const std::vector<std::string> kOps = {"add", "sub", "mul", "min", "max"};
    const TypedValue a = isSizedVector(t) ? vectorAtom(t, depth) : scalarAtom(t, depth);
    if (depth <= 0 || g_.chance(0.35)) return a;
    const std::string op = g_.oneOf(kOps);
    const ValueType c = sizedComponent(t);
    const bool lane_op = op != "min" && op != "max";
    const uint64_t form = g_.pick(3);
    const TypedValue b = form == 0 && (lane_op || !isSizedVector(t)) ? literal(c)
                         : form == 1 && lane_op && isSizedVector(t)  ? value(c, depth - 1)
                                                                     : value(t, depth - 1);
    const TypedValue r = combine(op, a, b);
    return isSizedFloat(t) && !fitsFloat(c, r) ? a : r;
  }

 private:
  TypedValue scalarAtom(ValueType t, int depth) {
    if (t == ValueType::Uint) return {g_.uintExpr(stage_, 1)};
    return isSizedFloat(t) ? floatAtom(t) : integerAtom(t, depth);
  }

  // A float16 or float64 of halves below 8, or of a Uint's low bits.
  TypedValue floatAtom(ValueType t) {
    if (g_.chance(0.5)) {
      const double v = std::round(g_.eighths(-8, 8) * 2) / 2;
      return {"{" + spelling(t) + ": " + CaseGenerator::num(v) + "}", std::fabs(v),
              v == std::floor(v) ? 0 : 1};
    }
    const uint32_t mask = t == ValueType::Float16 ? 15 : 1048575;
    return {"{" + spelling(t) + ": {bit_and: [" + g_.uintExpr(stage_, 1) + ", " +
                std::to_string(mask) + "]}}",
            double(mask), 0};
  }

  // An integer converted from a Uint expression (mostly: a value the device
  // computes), a Uint literal (wrapped to its bits) or another integer
  // type's value (extended by its signedness).
  TypedValue integerAtom(ValueType t, int depth) {
    const uint64_t form = g_.pick(10);
    if (form == 0) return {"{" + spelling(t) + ": " + std::to_string(g_.pick(1ull << 32)) + "}"};
    std::vector<ValueType> others;
    for (ValueType o : types_)
      if (o != t && isSizedInteger(o) && !isSizedVector(o)) others.push_back(o);
    if (form < 3 && depth > 0 && !others.empty())
      return {"{" + spelling(t) + ": " + integerAtom(g_.oneOf(others), 0).text + "}"};
    return {"{" + spelling(t) + ": " + g_.uintExpr(stage_, 1) + "}"};
  }

  // A vector of a value per lane, or of one value (splat).
  TypedValue vectorAtom(ValueType t, int depth) {
    const ValueType c = sizedComponent(t);
    if (g_.chance(0.25)) {
      const TypedValue s = scalarAtom(c, depth);
      return {"{" + spelling(t) + ": " + s.text + "}", s.bound, s.frac};
    }
    TypedValue v{"{" + spelling(t) + ": ["};
    for (int k = 0; k < componentCount(t); ++k) {
      const TypedValue lane = value(c, depth - 1);
      v.text += (k ? ", " : "") + lane.text;
      v.bound = std::max(v.bound, lane.bound);
      v.frac = std::max(v.frac, lane.frac);
    }
    v.text += "]}";
    return v;
  }

  // A literal the partner's (component) type takes: halves for a float,
  // small or any number the type holds for an integer.
  TypedValue literal(ValueType component) {
    if (isSizedFloat(component)) {
      const double v = std::round(g_.eighths(-4, 4) * 2) / 2;
      return {CaseGenerator::num(v), std::fabs(v), v == std::floor(v) ? 0 : 1};
    }
    const uint64_t largest = largestLiteral(component);
    return {
        std::to_string(1 + g_.pick(g_.chance(0.6) ? std::min<uint64_t>(largest, 200) : largest))};
  }

  CaseGenerator& g_;
  Stage stage_;
  std::vector<ValueType> types_;
  bool vectors_ = false;
  std::vector<std::string> parts_;  // the Uint parts of what was drawn, in order
};

}  // namespace

std::vector<ValueType> ProgramGenerator::typedTypes() const {
  std::vector<ValueType> types;
  for (ValueType t : enumValues<ValueType>())
    if (isSized(t) && allowsType(g_.allowed_, t)) types.push_back(t);
  return types;
}

ProgramGenerator::TypedState ProgramGenerator::typedState(Stage stage) {
  g_.swapStreams();
  TypedState s;
  if (g_.chance(kTypedChance)) {
    TypedDraws draw(g_, stage, typedTypes());
    std::vector<std::string> names(1 + g_.pick(2));
    for (std::string& n : names) n = local();
    s.before = draw.locals(names);
    if (g_.chance(0.4)) s.before += ", " + draw.structLocal(local());
    if (g_.chance(0.2)) {
      feature("sized-array");
      s.before += ", " + draw.arrayLocal(local());
    }
    if (draw.drewVectors()) feature("sized-vector");
    s.fold = draw.fold();
  }
  g_.swapStreams();
  return s;
}

// The last report at the sphere's entry (not before tmin), the nearest t the
// other reports take: where one of them committed that t, this one is still
// inside (R-CAND-AABB-CLOSED) and replaces it, so the closest-hit (which
// records hit_kind: typed_kind_) mostly reads the folded kind.
void ProgramGenerator::typedReports(std::vector<std::string>& crossing) {
  const TypedState typed = typedState(Stage::Intersection);
  if (typed.fold.empty()) return;
  feature("sized-across-report");
  typed_kind_ = true;
  crossing.insert(crossing.begin(), typed.before);
  crossing.push_back("{report: {t: {max: [sphere_near, ray_tmin]}, kind: {bit_and: [" + typed.fold +
                     ", 127]}}}");
}

}  // namespace rayspec
