// checkProgram: statement kinds allowed per stage (table of cases/README.md),
// expression types of every slot, counters and record fields declared in the
// case's outputs.
#include <algorithm>
#include <string>
#include <utility>

#include "program/builtins.h"
#include "program/check_bit_casts.h"
#include "program/check_expr.h"
#include "program/constant_value.h"
#include "program/hit_object.h"
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
    {Stmt::Kind::RayQuery, "ray_query", kAllStages},
    {Stmt::Kind::Candidates, "ray_query", kAllStages},
    {Stmt::Kind::Confirm, "confirm", kAllStages},
    {Stmt::Kind::Generate, "generate", kAllStages},
    {Stmt::Kind::TerminateQuery, "terminate_query", kAllStages},
    {Stmt::Kind::RayQueries, "ray_queries", kAllStages},
    {Stmt::Kind::RestartQuery, "restart_query", kAllStages},
    {Stmt::Kind::ExecuteHitObject, "execute", R | C | M},
    {Stmt::Kind::RecordMiss, "record_miss", R | C | M},
    {Stmt::Kind::RecordEmpty, "record_empty", R | C | M},
    {Stmt::Kind::RecordHit, "record_hit", R | C | M},
    {Stmt::Kind::Reorder, "reorder", R},
    {Stmt::Kind::If, "if", kAllStages},
    {Stmt::Kind::Let, "let", kAllStages},
    {Stmt::Kind::Set, "set", kAllStages},
    {Stmt::Kind::Array, "array", kAllStages},
    {Stmt::Kind::Struct, "struct", kAllStages},
    {Stmt::Kind::Store, "store", kAllStages},
    {Stmt::Kind::Repeat, "repeat", kAllStages},
    {Stmt::Kind::Break, "break", kAllStages},
    {Stmt::Kind::Continue, "continue", kAllStages},
    {Stmt::Kind::Switch, "switch", kAllStages},
    {Stmt::Kind::Case, "case", kAllStages},
    {Stmt::Kind::Invoke, "invoke", kAllStages},
    {Stmt::Kind::Return, "return", kAllStages},
};

const StmtRule& ruleOf(Stmt::Kind k) {
  for (const StmtRule& r : kStmtRules)
    if (r.kind == k) return r;
  return kStmtRules[0];
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
          const std::vector<std::string>& fields, const std::vector<SpecConstant>& constants,
          const ShaderRecordLayout* record_layout, std::vector<InterfaceUse>* interface_uses)
      : stage_(stage), counters_(counters), fields_(fields) {
    scope_.setConstants(&constants);
    scope_.setRecordLayout(record_layout);
    scope_.waiveInterfaceRules(interface_uses);
  }

  std::optional<ProgramError> block(std::vector<Stmt>& stmts) {
    scope_.openBlock();
    std::optional<ProgramError> r;
    for (Stmt& s : stmts)
      if ((r = stmt(s))) break;
    scope_.closeBlock();
    return r;
  }

 private:
  std::optional<ProgramError> stmt(Stmt& s) {
    const StmtRule& rule = ruleOf(s.kind);
    const auto q = forbiddenInterface(stage_, builtin_needs::InPayload);
    const bool waived =
        s.kind == Stmt::Kind::SetPayload && q && scope_.letThrough(*q, "payload", s.loc);
    if (!(rule.stages & stageBit(stage_)) && !waived)
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
        for (auto& [name, value] : s.assigns)
          if (auto r =
                  as(value, sizedMemberField(name).value_or(ValueType::Uint), "report " + name))
            return r;
        if (auto r = block(s.then_)) return r;
        return block(s.else_);
      }
      case Stmt::Kind::Trace:
        if (auto r = notInCandidates(s, "trace")) return r;
        return trace(s);
      case Stmt::Kind::Call:
        if (auto r = notInCandidates(s, "call")) return r;
        if (auto r = as(s.call_index, ValueType::Uint, "call index")) return r;
        return dataFields(s, Data::Call);
      case Stmt::Kind::Light:
        if (s.light != "point" && s.light != "spot" && s.light != "directional")
          return ProgramError{"unknown light '" + s.light + "' (point, spot, directional)", s.loc};
        return std::nullopt;
      case Stmt::Kind::ExecuteHitObject:
      case Stmt::Kind::RecordMiss:
      case Stmt::Kind::RecordEmpty:
      case Stmt::Kind::RecordHit:
      case Stmt::Kind::Reorder:
        return hitObjectStatement(s);
      case Stmt::Kind::If:
        if (auto r = as(s.cond, ValueType::Bool, "if condition")) return r;
        if (auto r = block(s.then_)) return r;
        return block(s.else_);
      case Stmt::Kind::RayQuery:
        return rayQuery(s);
      case Stmt::Kind::RayQueries:
        return rayQueries(s);
      case Stmt::Kind::RestartQuery:
        return restartQuery(s);
      case Stmt::Kind::Candidates:
      case Stmt::Kind::Confirm:
      case Stmt::Kind::Generate:
      case Stmt::Kind::TerminateQuery:
        return queryStatement(s);
      default:
        return controlFlow(s);
    }
    return ProgramError{"unknown statement", s.loc};
  }

  // let, set, array, store, repeat, break, continue, switch, invoke, return.
  std::optional<ProgramError> controlFlow(Stmt& s) {
    switch (s.kind) {
      case Stmt::Kind::Let:
        return let(s);
      case Stmt::Kind::Set:
        return set(s);
      case Stmt::Kind::Array:
        return array(s);
      case Stmt::Kind::Struct:
        return structure(s);
      case Stmt::Kind::Store:
        return store(s);
      case Stmt::Kind::Repeat:
        return repeat(s);
      case Stmt::Kind::Break:
        // In a ray_query's candidate block, outside any repeat: leaves the
        // query's proceed loop (GLSL's break leaves the innermost loop); in
        // a stepped query's (ray_queries) it would leave the loop that steps
        // them all.
        if (breakable_.empty() && candidate_block_ && stepped_block_)
          return ProgramError{
              "'break' in a candidate block of a ray_queries query: the queries are stepped "
              "in turn in one loop, which a break would leave for all of them (use "
              "terminate_query to end this one)",
              s.loc};
        if (breakable_.empty() && candidate_block_) return std::nullopt;
        if (breakable_.empty() || breakable_.back() != 'L')
          return ProgramError{breakable_.empty()
                                  ? "'break' outside a repeat"
                                  : "'break' directly in a switch case (GLSL would leave the "
                                    "switch, not the repeat): put it in an if",
                              s.loc};
        return std::nullopt;
      case Stmt::Kind::Continue:
        if (breakable_.empty() && candidate_block_) return std::nullopt;  // the next candidate
        if (std::find(breakable_.begin(), breakable_.end(), 'L') == breakable_.end())
          return ProgramError{"'continue' outside a repeat", s.loc};
        return std::nullopt;
      case Stmt::Kind::Switch:
        return switchStmt(s);
      case Stmt::Kind::Invoke:
        return invoke(s);
      case Stmt::Kind::Return:
        if (candidate_block_)
          return ProgramError{
              "'return' in a ray_query's triangle or aabb block (it would leave "
              "the stage in the middle of the query's traversal)",
              s.loc};
        return std::nullopt;
      default:
        return ProgramError{"'case' outside a switch", s.loc};
    }
  }

  // ray_query: its fields as a trace's (no SBT fields: a query runs no
  // shader), its candidate blocks the body of its proceed loop (a break or
  // continue outside any repeat leaves it or goes on to the next candidate;
  // no return, no trace or call: the model may run a block again to try
  // another legal order), then `after`.
  std::optional<ProgramError> rayQuery(Stmt& s) {
    if (query_depth_ >= kMaxQueryNesting)
      return ProgramError{
          "ray_query nested more than " + std::to_string(kMaxQueryNesting) + " deep", s.loc};
    if (auto r = traceFields(s, "ray_query", 6)) return r;
    using Block = LocalScope::QueryBlock;
    const Block outer = scope_.queryBlock();
    const bool outer_candidates = candidate_block_, outer_stepped = stepped_block_;
    std::vector<char> loops;
    std::swap(loops, breakable_);
    ++query_depth_;
    std::optional<ProgramError> r;
    scope_.openBlock();  // as the model's compiler opens them (model_program.cpp)
    stepped_block_ = std::exchange(stepped_member_, false);
    for (Stmt& c : s.then_) {
      scope_.setQueryBlock(c.size == 0 ? Block::Triangle : Block::Aabb);
      candidate_block_ = true;
      if (!r) r = block(c.then_);
    }
    scope_.closeBlock();
    std::swap(loops, breakable_);
    candidate_block_ = outer_candidates;
    stepped_block_ = outer_stepped;
    scope_.setQueryBlock(Block::After);
    if (!r) r = block(s.else_);
    --query_depth_;
    scope_.setQueryBlock(outer);
    return r;
  }

  // ray_queries: its ray queries checked as ray_query statements in one
  // block (as the model's compiler opens then_), their candidate blocks
  // marked stepped (no break: it would leave the loop stepping them all).
  std::optional<ProgramError> rayQueries(Stmt& s) {
    scope_.openBlock();
    std::optional<ProgramError> r;
    for (Stmt& q : s.then_) {
      stepped_member_ = true;
      if (!r) r = rayQuery(q);
    }
    stepped_member_ = false;
    scope_.closeBlock();
    return r;
  }

  // restart_query: in a candidate block of the innermost query, outside any
  // repeat (the GLSL goes on to the next proceed with `continue`) and any
  // function (a rayQueryEXT parameter's loop is the caller's).
  std::optional<ProgramError> restartQuery(Stmt& s) {
    using Block = LocalScope::QueryBlock;
    const Block b = scope_.queryBlock();
    if (!candidate_block_ || (b != Block::Triangle && b != Block::Aabb))
      return ProgramError{
          "'restart_query' initializes the query whose candidate it decides: only in a "
          "ray_query's triangle or aabb block (not in `after`, nor in a function)",
          s.loc};
    if (std::find(breakable_.begin(), breakable_.end(), 'L') != breakable_.end())
      return ProgramError{
          "'restart_query' inside a repeat: the block ends at a restart (the query's loop "
          "goes on with the new ray), which a repeat's loop would hold back",
          s.loc};
    return traceFields(s, "restart_query", 6);
  }

  // confirm (a triangle block), generate (an AABB block), terminate_query
  // (either), of the innermost ray_query.
  std::optional<ProgramError> queryStatement(Stmt& s) {
    using Block = LocalScope::QueryBlock;
    const Block b = scope_.queryBlock();
    if (s.kind == Stmt::Kind::Confirm && b != Block::Triangle)
      return ProgramError{
          "'confirm' commits a triangle candidate: only in a ray_query's "
          "triangle block",
          s.loc};
    if (s.kind == Stmt::Kind::Generate && b != Block::Aabb)
      return ProgramError{"'generate' commits an AABB candidate: only in a ray_query's aabb block",
                          s.loc};
    if (s.kind == Stmt::Kind::TerminateQuery && b != Block::Triangle && b != Block::Aabb)
      return ProgramError{"'terminate_query' only in a ray_query's triangle or aabb block", s.loc};
    if (s.kind == Stmt::Kind::Candidates)
      return ProgramError{"a candidate block outside a ray_query", s.loc};
    if (s.kind == Stmt::Kind::Generate) return as(s.t, ValueType::Float, "generate t");
    return std::nullopt;
  }

  std::optional<ProgramError> notInCandidates(const Stmt& s, const char* what) {
    if (!candidate_block_ && !candidate_frame_) return std::nullopt;
    return ProgramError{std::string("'") + what +
                            "' in a ray_query's triangle or aabb block: the model may run a "
                            "block again in another legal order, which it cannot do to a "
                            "trace or call",
                        s.loc};
  }

  std::optional<ProgramError> declare(const Stmt& s, const std::string& name, LocalInfo info) {
    if (!isLocalName(name))
      return ProgramError{
          "local name '" + name + "': a lower-case letter, then letters, digits or _ (at most 32)",
          s.loc};
    if (scope_.find(name))
      return ProgramError{"local '" + name + "' is already declared here", s.loc};
    scope_.declare(name, info);
    return std::nullopt;
  }

  std::optional<ProgramError> let(Stmt& s) {
    for (auto& [name, value] : s.assigns) {
      if (auto r = checkExpr(value, stage_, &scope_)) return r;
      if (auto r = declare(s, name, {value.type})) return r;
    }
    return std::nullopt;
  }

  std::optional<ProgramError> set(Stmt& s) {
    for (auto& [name, value] : s.assigns) {
      if (auto problem = scope_.memberProblem(name))
        return ProgramError{"set " + name + ": " + *problem, value.loc};
      const LocalInfo* info = scope_.find(name);
      if (!info || info->elements || info->read_only)
        return ProgramError{"set " + name + ": " +
                                (!info            ? "no local of that name is declared here"
                                 : info->elements ? "an array (write an element with store)"
                                                  : "a repeat's variable is read-only"),
                            value.loc};
      if (auto r = as(value, info->type, "set " + name)) return r;
    }
    return std::nullopt;
  }

  std::optional<ProgramError> array(Stmt& s) {
    if (s.size < 1 || s.size > kMaxArrayElements || s.local_type == ValueType::Bool)
      return ProgramError{"array " + s.local + ": 1 to " + std::to_string(kMaxArrayElements) +
                              " elements of uint, float, vec2, vec3 or vec4",
                          s.loc};
    return declare(s, s.local, {s.local_type, s.size});
  }

  // struct: the struct (a name only: read or set whole it is an error) and
  // each member a local NAME.MEMBER of its type, zero.
  std::optional<ProgramError> structure(Stmt& s) {
    if (s.params.empty() || s.params.size() > kMaxStructMembers)
      return ProgramError{
          "struct " + s.local + ": 1 to " + std::to_string(kMaxStructMembers) + " members", s.loc};
    for (size_t i = 0; i < s.params.size(); ++i) {
      const std::string& member = s.params[i].first;
      if (!isLocalName(member))
        return ProgramError{"struct " + s.local + ": member name '" + member +
                                "': a lower-case letter, then letters, digits or _ (at most 32)",
                            s.loc};
      for (size_t j = 0; j < i; ++j)
        if (s.params[j].first == member)
          return ProgramError{"struct " + s.local + ": member '" + member + "' twice", s.loc};
    }
    if (auto r = declare(s, s.local, {ValueType::Uint, 0, true, true})) return r;
    for (const auto& [member, type] : s.params)
      scope_.declare(memberLocal(s.local, member), {type});
    return std::nullopt;
  }

  std::optional<ProgramError> store(Stmt& s) {
    if (const auto words = wordArrayOfStore(s.local)) return storeWord(s, *words);
    const LocalInfo* info = scope_.find(s.local);
    if (!info || !info->elements)
      return ProgramError{"store: '" + s.local + "' is not an array declared here", s.loc};
    if (auto r = as(s.index, ValueType::Uint, "store index")) return r;
    for (auto& [name, value] : s.assigns)
      if (auto r = as(value, info->type, "store value")) return r;
    return std::nullopt;
  }

  // store: {array: payload.words | call.words, ...}: a word of the incoming
  // payload (where `payload:` may write) or callable data (where `call_data:` may).
  std::optional<ProgramError> storeWord(Stmt& s, WordArray words) {
    const StmtRule& writer =
        ruleOf(words == WordArray::Payload ? Stmt::Kind::SetPayload : Stmt::Kind::SetCall);
    if (!(writer.stages & stageBit(stage_)))
      return ProgramError{s.local + " is not writable in " + stageName(stage_) +
                              " (allowed in: " + stageList(writer.stages) + ")",
                          s.loc};
    if (auto r = as(s.index, ValueType::Uint, "store index")) return r;
    for (auto& [name, value] : s.assigns)
      if (auto r = as(value, ValueType::Uint, "store value")) return r;
    return std::nullopt;
  }

  std::optional<ProgramError> repeat(Stmt& s) {
    if (auto r = as(s.count, ValueType::Uint, "repeat count")) return r;
    if (auto r = as(s.from, ValueType::Uint, "repeat from")) return r;
    if (const auto n = constantUint(s.count); n && *n > kMaxLoopTrips)
      return ProgramError{
          "repeat count " + std::to_string(*n) + " is above " + std::to_string(kMaxLoopTrips),
          s.count.loc};
    scope_.openBlock();
    std::optional<ProgramError> r;
    if (!s.local.empty()) r = declare(s, s.local, {ValueType::Uint, 0, true});
    breakable_.push_back('L');
    if (!r) r = block(s.then_);
    breakable_.pop_back();
    scope_.closeBlock();
    return r;
  }

  std::optional<ProgramError> switchStmt(Stmt& s) {
    if (auto r = as(s.cond, ValueType::Uint, "switch value")) return r;
    breakable_.push_back('S');
    std::optional<ProgramError> r;
    std::vector<uint32_t> labels;
    for (Stmt& c : s.then_) {
      if (c.kind != Stmt::Kind::Case || std::count(labels.begin(), labels.end(), c.size))
        r = ProgramError{"switch case " + std::to_string(c.size) + " is given twice", c.loc};
      labels.push_back(c.size);
      if (!r) r = block(c.then_);
      if (r) break;
    }
    if (!r) r = block(s.else_);
    breakable_.pop_back();
    return r;
  }

  // The arguments in the caller's scope, the body in a frame of its own.
  std::optional<ProgramError> invoke(Stmt& s) {
    if (s.assigns.size() != s.params.size())
      return ProgramError{
          "invoke " + s.local + ": takes " + std::to_string(s.params.size()) + " argument(s)",
          s.loc};
    for (size_t i = 0; i < s.params.size(); ++i)
      if (auto r = as(s.assigns[i].second, s.params[i].second,
                      "invoke " + s.local + " argument " + s.params[i].first))
        return r;
    const LocalScope::QueryBlock query = scope_.queryBlock();
    if (s.query_param && query == LocalScope::QueryBlock::None)
      return ProgramError{"invoke " + s.local +
                              ": the function takes a ray query (query: true); invoke it in a "
                              "ray_query's triangle, aabb or after block",
                          s.loc};
    LocalScope::Frame caller = scope_.openFrame();
    std::vector<char> loops;
    std::swap(loops, breakable_);
    // A function sees no query of its caller (GLSL: it is another function)
    // unless it takes it (query: true: a rayQueryEXT parameter, the
    // caller's innermost query, read and decided as in the caller's block);
    // its return leaves only the function, but its traces would still run
    // inside the caller's candidate block.
    const bool candidates = candidate_block_, frame = candidate_frame_;
    if (!s.query_param) scope_.setQueryBlock(LocalScope::QueryBlock::None);
    candidate_frame_ = candidates || frame;
    candidate_block_ = false;
    std::optional<ProgramError> r;
    for (const auto& [name, type] : s.params)
      if (!r) r = declare(s, name, {type});
    if (!r) r = block(s.then_);
    scope_.setQueryBlock(query);
    candidate_block_ = candidates;
    candidate_frame_ = frame;
    std::swap(loops, breakable_);
    scope_.closeFrame(std::move(caller));
    return r;
  }

  std::optional<ProgramError> as(Expr& e, ValueType want, const std::string& what) {
    return checkExprAs(e, stage_, want, what, &scope_);
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
      if (isHitIdentityField(name) && !isBuiltin(value, builtinId(findBuiltin(name))) &&
          !isBuiltin(value, builtinId(findBuiltin(hitObjectGetterOf(name)))))
        return ProgramError{"per-ray field '" + name +
                                "' holds the built-in of that name: the judge reads it as the "
                                "hit itself. Record `" +
                                name + "` (or in raygen, closest-hit and miss its hit object's " +
                                hitObjectGetterOf(name) +
                                ") there, and other values in a free field (value, value1 .. "
                                "value11)",
                            value.loc};
      if (auto r = as(value, fieldValueType(*f), "record " + name)) return r;
    }
    return std::nullopt;
  }

  // payload / call_data fields (color, value, word<i>), and for `call` also
  // position, normal.
  enum class Data { Payload, CallData, Call };
  std::optional<ProgramError> dataFields(Stmt& s, Data data) {
    const bool call = data == Data::Call;
    for (auto& [name, value] : s.assigns) {
      ValueType want;
      if (name == "color")
        want = ValueType::Vec4;
      else if (name == "value" || payloadWordField(name))
        want = ValueType::Uint;
      else if (const auto sized = sizedMemberField(name))
        want = *sized;  // a sized member: its own type
      else if (call && (name == "position" || name == "normal"))
        want = ValueType::Vec3;
      else
        return ProgramError{"unknown field '" + name + "' (" +
                                (call ? "position, normal, color, value, word<i>, a sized member"
                                      : "color, value, word<i>, a sized member") +
                                ")",
                            value.loc};
      if (auto r = as(value, want, name)) return r;
    }
    return std::nullopt;
  }

  std::optional<ProgramError> trace(Stmt& s) {
    if (auto r = traceFields(s, "trace", 9)) return r;
    return dataFields(s, Data::Payload);  // the payload the trace starts with
  }

  // The first `slots` fields of a trace (origin .. miss), as `what` names them.
  // execute, record_miss, record_empty, record_hit, reorder.
  std::optional<ProgramError> hitObjectStatement(Stmt& s) {
    switch (s.kind) {
      case Stmt::Kind::ExecuteHitObject:
        if (auto r = notInCandidates(s, "execute")) return r;
        return dataFields(s, Data::Payload);  // the payload it starts with, as a trace's
      case Stmt::Kind::RecordMiss:            // origin .. tmax and miss, as a trace gives them
        return traceFields(s, "record_miss", 9);
      case Stmt::Kind::RecordHit:
        return recordHit(s);
      case Stmt::Kind::Reorder:
        for (auto& [name, value] : s.assigns)
          if (auto r = as(value, ValueType::Uint, "reorder " + name)) return r;
        return std::nullopt;
      default:  // record_empty
        return std::nullopt;
    }
  }

  // record_hit: the ids, hit kind and record index Uint, the attributes a
  // Vec2, the ray as a trace's (sbt_offset and sbt_stride among its fields).
  std::optional<ProgramError> recordHit(Stmt& s) {
    for (auto& [name, value] : s.assigns)
      if (auto r = as(value, name == "attributes" ? ValueType::Vec2 : ValueType::Uint,
                      "record_hit " + name))
        return r;
    return traceFields(s, "record_hit", 8);
  }

  std::optional<ProgramError> traceFields(Stmt& s, const std::string& what, size_t slots_used) {
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
    for (size_t k = 0; k < slots_used; ++k) {
      Slot& slot = slots[k];
      if (slot.exprs->size() > 1)
        return ProgramError{what + " " + slot.name + " given twice", s.loc};
      if (slot.exprs->empty() && stage_ != Stage::Raygen && (slot.type == ValueType::Vec3))
        return ProgramError{what + " outside raygen needs '" + slot.name + "'", s.loc};
      for (Expr& e : *slot.exprs)
        if (auto r = as(e, slot.type, what + " " + slot.name)) return r;
    }
    for (Expr& e : t.tlas_index)
      if (auto r = as(e, ValueType::Uint, what + " tlas")) return r;
    return std::nullopt;
  }

  Stage stage_;
  LocalScope scope_;
  std::vector<char> breakable_;   // 'L' a repeat, 'S' a switch, innermost last
  uint32_t query_depth_ = 0;      // ray_query statements around the one checked
  bool candidate_block_ = false;  // in a ray_query's triangle or aabb block
  bool candidate_frame_ = false;  // in a function invoked from one
  bool stepped_block_ = false;    // in a candidate block of a ray_queries query
  bool stepped_member_ = false;   // the ray_query checked next is one of ray_queries'

  const std::vector<std::string>& counters_;
  const std::vector<std::string>& fields_;
};

}  // namespace

std::optional<ProgramError> checkProgram(Program& p, Stage stage,
                                         const std::vector<std::string>& counters,
                                         const std::vector<std::string>& per_ray_fields,
                                         const std::vector<SpecConstant>& constants,
                                         const ShaderRecordLayout* record_layout,
                                         std::vector<InterfaceUse>* interface_uses) {
  std::optional<ProgramError> error =
      Checker(stage, counters, per_ray_fields, constants, record_layout, interface_uses).block(p);
  if (!error) error = checkBitCasts(p, stage);  // exactness claims: after typing
  if (!error) error = checkWideLiterals(p);     // a literal over 32 bits: in a 64-bit place
  return error;
}

}  // namespace rayspec
