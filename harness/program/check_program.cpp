// checkProgram: statement kinds allowed per stage (table of cases/README.md),
// expression types of every slot, counters and record fields declared in the
// case's outputs.
#include <algorithm>
#include <string>

#include "program/builtins.h"
#include "program/check_expr.h"
#include "program/ops.h"
#include "program/payload_words.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

using namespace stage_letters;

struct StmtRule {
  Stmt::Kind kind;
  const char* name;
  StageMask stages;
};

// The statement table of cases/README.md.
constexpr StmtRule kStmtRules[] = {
    {Stmt::Kind::Count, "count", kAllStages},
    {Stmt::Kind::Record, "record", kAllStages},
    {Stmt::Kind::SetPayload, "payload", M | C | A},
    {Stmt::Kind::SetCall, "call_data", K},
    {Stmt::Kind::Ignore, "ignore", A},
    {Stmt::Kind::Terminate, "terminate", A},
    {Stmt::Kind::Report, "report", I},
    {Stmt::Kind::Trace, "trace", R | C | M},
    {Stmt::Kind::Call, "call", R | C | M | K},
    {Stmt::Kind::Light, "light", K},
    {Stmt::Kind::If, "if", kAllStages},
};

const StmtRule& ruleOf(Stmt::Kind k) {
  for (const StmtRule& r : kStmtRules)
    if (r.kind == k) return r;
  return kStmtRules[0];
}

std::string stageList(StageMask mask) {
  std::string s;
  for (int i = 0; i < 6; ++i) {
    if (!(mask & (1u << i))) continue;
    if (!s.empty()) s += ", ";
    s += stageName(static_cast<Stage>(i));
  }
  return s;
}

ValueType fieldValueType(const RecordField& f) {
  if (f.type == FieldType::Uint) return ValueType::Uint;
  switch (f.words) {
    case 2:
      return ValueType::Vec2;
    case 3:
      return ValueType::Vec3;
    case 4:
      return ValueType::Vec4;
    default:
      return ValueType::Float;
  }
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

class Checker {
 public:
  Checker(Stage stage, const std::vector<std::string>& counters,
          const std::vector<std::string>& fields)
      : stage_(stage), counters_(counters), fields_(fields) {}

  std::optional<ProgramError> block(std::vector<Stmt>& stmts) {
    for (Stmt& s : stmts)
      if (auto r = stmt(s)) return r;
    return std::nullopt;
  }

 private:
  std::optional<ProgramError> stmt(Stmt& s) {
    const StmtRule& rule = ruleOf(s.kind);
    if (!(rule.stages & stageBit(stage_)))
      return ProgramError{std::string("'") + rule.name + "' is not allowed in " +
                              stageName(stage_) + " (allowed in: " + stageList(rule.stages) + ")",
                          s.loc};
    switch (s.kind) {
      case Stmt::Kind::Count:
        if (!contains(counters_, s.counter))
          return ProgramError{"counter '" + s.counter + "' is not declared in outputs.counters",
                              s.loc};
        return std::nullopt;
      case Stmt::Kind::Record:
        return record(s);
      case Stmt::Kind::SetPayload:
        return dataFields(s, Data::Payload);
      case Stmt::Kind::SetCall:
        return dataFields(s, Data::CallData);
      case Stmt::Kind::Ignore:
      case Stmt::Kind::Terminate:
        return std::nullopt;
      case Stmt::Kind::Report: {
        if (auto r = as(s.t, ValueType::Float, "report t")) return r;
        if (auto r = as(s.hit_kind, ValueType::Uint, "report kind")) return r;
        if (s.hit_kind.kind == Expr::Kind::Literal && s.hit_kind.literal[0] > 127)
          return ProgramError{"report kind must be in 0..127", s.hit_kind.loc};
        if (s.attribute.size() > 1) return ProgramError{"report takes one attribute", s.loc};
        for (Expr& e : s.attribute)
          if (auto r = as(e, ValueType::Vec2, "report attribute")) return r;
        if (auto r = block(s.then_)) return r;
        return block(s.else_);
      }
      case Stmt::Kind::Trace:
        return trace(s);
      case Stmt::Kind::Call:
        if (auto r = as(s.call_index, ValueType::Uint, "call index")) return r;
        return dataFields(s, Data::Call);
      case Stmt::Kind::Light:
        if (s.light != "point" && s.light != "spot" && s.light != "directional")
          return ProgramError{"unknown light '" + s.light + "' (point, spot, directional)", s.loc};
        return std::nullopt;
      case Stmt::Kind::If:
        if (auto r = as(s.cond, ValueType::Bool, "if condition")) return r;
        if (auto r = block(s.then_)) return r;
        return block(s.else_);
    }
    return ProgramError{"unknown statement", s.loc};
  }

  std::optional<ProgramError> as(Expr& e, ValueType want, const std::string& what) {
    return checkExprAs(e, stage_, want, what);
  }

  std::optional<ProgramError> record(Stmt& s) {
    for (auto& [name, value] : s.assigns) {
      const RecordField* f = findRecordField(name);
      if (!f) return ProgramError{"unknown per-ray field '" + name + "'", value.loc};
      if (f->automatic)
        return ProgramError{"per-ray field '" + name +
                                "' is automatic (kept by the harness); it cannot be recorded",
                            value.loc};
      if (!contains(fields_, name))
        return ProgramError{"per-ray field '" + name + "' is not declared in outputs.per_ray",
                            value.loc};
      if (auto r = as(value, fieldValueType(*f), "record " + name)) return r;
    }
    return std::nullopt;
  }

  // payload / call_data fields (color, value), for a payload also its words
  // (word<i>), and for `call` also position, normal.
  enum class Data { Payload, CallData, Call };
  std::optional<ProgramError> dataFields(Stmt& s, Data data) {
    const bool call = data == Data::Call;
    for (auto& [name, value] : s.assigns) {
      ValueType want;
      if (name == "color")
        want = ValueType::Vec4;
      else if (name == "value" || (data == Data::Payload && payloadWordField(name)))
        want = ValueType::Uint;
      else if (call && (name == "position" || name == "normal"))
        want = ValueType::Vec3;
      else
        return ProgramError{"unknown field '" + name + "' (" +
                                (call                    ? "position, normal, color, value"
                                 : data == Data::Payload ? "color, value, word0 .. word9"
                                                         : "color, value") +
                                ")",
                            value.loc};
      if (auto r = as(value, want, name)) return r;
    }
    return std::nullopt;
  }

  std::optional<ProgramError> trace(Stmt& s) {
    TraceArgs& t = s.trace;
    struct Slot {
      std::vector<Expr>* exprs;
      const char* name;
      ValueType type;
    };
    Slot slots[] = {
        {&t.origin, "origin", ValueType::Vec3},
        {&t.direction, "direction", ValueType::Vec3},
        {&t.tmin, "tmin", ValueType::Float},
        {&t.tmax, "tmax", ValueType::Float},
        {&t.flags, "flags", ValueType::Uint},
        {&t.cull_mask, "cull_mask", ValueType::Uint},
        {&t.sbt_offset, "sbt_offset", ValueType::Uint},
        {&t.sbt_stride, "sbt_stride", ValueType::Uint},
        {&t.miss, "miss", ValueType::Uint},
    };
    for (Slot& slot : slots) {
      if (slot.exprs->size() > 1)
        return ProgramError{std::string("trace ") + slot.name + " given twice", s.loc};
      if (slot.exprs->empty() && stage_ != Stage::Raygen && (slot.type == ValueType::Vec3))
        return ProgramError{std::string("trace outside raygen needs '") + slot.name + "'", s.loc};
      for (Expr& e : *slot.exprs)
        if (auto r = as(e, slot.type, std::string("trace ") + slot.name)) return r;
    }
    return dataFields(s, Data::Payload);  // the payload the trace starts with
  }

  Stage stage_;
  const std::vector<std::string>& counters_;
  const std::vector<std::string>& fields_;
};

}  // namespace

std::optional<ProgramError> checkProgram(Program& p, Stage stage,
                                         const std::vector<std::string>& counters,
                                         const std::vector<std::string>& per_ray_fields) {
  return Checker(stage, counters, per_ray_fields).block(p);
}

}  // namespace rayspec
