#include "model/model_program.h"

#include <algorithm>

#include "model/order_dependence.h"
#include "program/builtins.h"
#include "program/hit_object.h"
#include "program/locals.h"
#include "program/payload_words.h"
#include "program/sized_values.h"
#include "program/walk_program.h"
#include "results/record_layout.h"

namespace rayspec {

namespace {

// A sized scalar's literal (the checker held it to its type's values; one
// over 32 bits, an int64's or uint64's, exactly as written: Expr::wide).
Val sizedLiteral(const Expr& e) {
  const double v = e.literal.empty() ? 0 : e.literal[0];
  if (isSizedFloat(e.type)) return fromSizedDouble(e.type, v);
  return fromSized(e.type, wrapToType(e.type, e.wide ? e.wide : static_cast<uint64_t>(v)));
}

// The built-ins a hit on a triangle the ray runs in the plane of leaves free
// (CPipeline::reads_in_plane_free): the hit's t and what follows from it,
// where on the triangle, which face.
bool isInPlaneFree(Builtin b) {
  switch (b) {
    case kBiHitT:
    case kBiTmax:
    case kBiHitPosition:
    case kBiBarycentrics:
    case kBiHitKind:
    case kBiQCandT:
    case kBiQCommittedT:
    case kBiQCandBarycentrics:
    case kBiQCommittedBarycentrics:
    case kBiQCandFrontFace:
    case kBiQCommittedFrontFace:
    case kBiHoT:
    case kBiHoAttributes:
    case kBiHoHitKind:
      return true;
    default:
      return false;
  }
}

// The built-ins a sphere root's rounding moves (CPipeline::reads_root_t_free):
// the hit's t and what follows from it, no more.
bool isRootTFree(Builtin b) {
  switch (b) {
    case kBiHitT:
    case kBiTmax:
    case kBiHitPosition:
    case kBiQCandT:
    case kBiQCommittedT:
    case kBiHoT:
      return true;
    default:
      return false;
  }
}

// `record: {field: e}` with e the built-in of the field's own name, a field
// the comparison widens by the ray's t bound (hit_t, ray_tmax, hit_position).
bool isOwnBoundedField(const std::string& field, const Expr& e) {
  const int index = recordFieldIndex(field);
  if (index < 0 || e.kind != Expr::Kind::Builtin || e.builtin == kBiUnknown) return false;
  const FieldBound bound = recordFields()[index].bound;
  return (bound == FieldBound::TBound || bound == FieldBound::PositionBound) &&
         field == builtins()[e.builtin].name;
}

struct Compiler {
  const Plan& plan;
  CPipeline& out;
  const Pipeline& pipeline;
  LocalScope scope;             // the locals visible where the compiler is (their slots)
  std::string shader;           // the shader compiled (its name picks pipeline.specialize's values)
  Stage stage = Stage::Raygen;  // the stage compiled
  uint32_t incoming_location = 0;   // its incoming payload's or callable data's location
  bool into_bounded_field = false;  // compiling isOwnBoundedField's e

  // Starts a shader: its name, stage and incoming data location.
  void begin(Stage s, size_t index, uint32_t location) {
    shader = Pipeline::shaderName(s, index);
    stage = s;
    incoming_location = location;
  }

  // The words an indexed read or store of `which` ranges over in this stage.
  uint32_t indexedWords(WordArray which) const {
    return pipeline.indexedWords(which, stage, incoming_location);
  }

  // const.NAME: a literal of the value this shader takes.
  void constant(const Expr& e, CExpr& r) const {
    r.kind = Expr::Kind::Literal;
    for (size_t k = 0; k < pipeline.constants.size(); ++k) {
      if (pipeline.constants[k].name != e.name) continue;
      const double v = pipeline.constantIn(shader, k);
      if (e.type == ValueType::Float)
        r.literal.f[0] = static_cast<float>(v);
      else if (e.type == ValueType::Bool)
        r.literal.b = v != 0;
      else
        r.literal.u = static_cast<uint32_t>(v);
    }
  }

  CExpr expr(const Expr& e) {
    CExpr r;
    r.kind = e.kind;
    r.type = e.type;
    r.src = &e;
    switch (e.kind) {
      case Expr::Kind::Constant:
        constant(e, r);
        break;
      case Expr::Kind::RecordMember:  // its first word in the record's data
        if (const RecordMember* m = pipeline.record_layout.find(e.name)) r.index = m->offset / 4;
        break;
      case Expr::Kind::Local:
        if (const LocalInfo* info = scope.find(e.name)) {
          r.index = info->slot;
          r.size = info->elements;
        }
        break;
      case Expr::Kind::Literal:
        if (isSized(e.type))
          r.literal = sizedLiteral(e);
        else if (e.type == ValueType::Uint)
          r.literal.u = static_cast<uint32_t>(e.literal.empty() ? 0 : e.literal[0]);
        else if (e.type == ValueType::Bool)
          r.literal.b = !e.literal.empty() && e.literal[0] != 0;
        else
          for (size_t k = 0; k < e.literal.size() && k < 4; ++k)
            r.literal.f[k] = static_cast<float>(e.literal[k]);
        break;
      case Expr::Kind::Builtin: {
        r.index = e.word;  // payload.word3: word<i>, index 3
        r.builtin = e.builtin;
        if (r.builtin != kBiUnknown) {
          out.read_bits.set(r.builtin);
          out.needs |= builtins()[r.builtin].needs;
          if (!into_bounded_field && isInPlaneFree(static_cast<Builtin>(r.builtin)))
            out.reads_in_plane_free = true;
          if (!into_bounded_field && isRootTFree(static_cast<Builtin>(r.builtin)))
            out.reads_root_t_free = true;
        }
        break;
      }
      case Expr::Kind::Op:
        r.op = e.op;
        if (r.op == Op::SphereHit || r.op == Op::SphereNear || r.op == Op::SphereFar)
          out.reads_sphere = true;
        if (const auto which = wordArrayOf(e.op)) {
          r.index = static_cast<uint32_t>(*which);
          r.size = indexedWords(*which);
        }
        if (r.op == Op::RecordUint || r.op == Op::RecordFloat || isHitObjectRecordRead(e))
          r.index =
              e.args.empty()
                  ? 0
                  : static_cast<uint32_t>(e.args[0].literal.empty() ? 0 : e.args[0].literal[0]);
        for (const Expr& a : e.args) r.args.push_back(expr(a));
        break;
    }
    return r;
  }

  static Slot slotOf(const std::string& f) {
    if (f == "color") return Slot::Color;
    if (f == "value") return Slot::Value;
    if (f == "position") return Slot::Position;
    if (f == "normal") return Slot::Normal;
    if (payloadWordField(f)) return Slot::Word;
    if (sizedMemberField(f)) return Slot::Sized;
    return Slot::None;
  }

  CProgram program(const Program& p) {
    CProgram r;
    r.reserve(p.size());
    scope.openBlock();
    for (const Stmt& s : p) r.push_back(stmt(s));
    scope.closeBlock();
    return r;
  }

  int slotOfLocal(const std::string& name) {
    const LocalInfo* info = scope.find(name);
    return info ? static_cast<int>(info->slot) : -1;
  }

  // let, set, array, store, repeat, switch, invoke: locals get their slots in
  // the order the checker declared them (program/locals.h).
  void controlFlow(const Stmt& s, CStmt& r) {
    for (const auto& [name, e] : s.assigns) {
      CAssign a;
      a.value = expr(e);
      if (s.kind == Stmt::Kind::Let) a.field = static_cast<int>(scope.declare(name, {e.type}).slot);
      if (s.kind == Stmt::Kind::Set) a.field = slotOfLocal(name);
      r.assigns.push_back(std::move(a));
    }
    if (s.kind == Stmt::Kind::Array) {
      r.slot = static_cast<int>(scope.declare(s.local, {s.local_type, s.size}).slot);
      r.size = s.size;
    } else if (s.kind == Stmt::Kind::Struct) {  // its members, one slot each, in order
      scope.declare(s.local, {ValueType::Uint, 0, true, true});
      for (const auto& [member, type] : s.params) {
        const int slot = static_cast<int>(scope.declare(memberLocal(s.local, member), {type}).slot);
        if (r.slot < 0) r.slot = slot;
      }
      r.size = static_cast<uint32_t>(s.params.size());
    } else if (const auto which =
                   s.kind == Stmt::Kind::Store ? wordArrayOfStore(s.local) : std::nullopt) {
      r.words = *which;
      r.size = indexedWords(*which);
      r.index = expr(s.index);
    } else if (s.kind == Stmt::Kind::Store) {
      const LocalInfo* info = scope.find(s.local);
      r.slot = info ? static_cast<int>(info->slot) : -1;
      r.size = info ? info->elements : 0;
      r.index = expr(s.index);
    } else if (s.kind == Stmt::Kind::Repeat) {
      r.count = expr(s.count);
      r.from = expr(s.from);
      scope.openBlock();
      if (!s.local.empty())
        r.slot = static_cast<int>(scope.declare(s.local, {ValueType::Uint, 0, true}).slot);
      r.then_ = program(s.then_);
      scope.closeBlock();
    } else if (s.kind == Stmt::Kind::Switch) {
      r.cond = expr(s.cond);
      r.then_ = program(s.then_);
      r.else_ = program(s.else_);
    } else if (s.kind == Stmt::Kind::Case) {
      r.size = s.size;
      r.then_ = program(s.then_);
    } else if (s.kind == Stmt::Kind::Invoke) {
      LocalScope::Frame caller = scope.openFrame();
      for (const auto& [name, type] : s.params) scope.declare(name, {type});
      r.then_ = program(s.then_);
      r.size = scope.frameSlots();
      scope.closeFrame(std::move(caller));
    }
  }

  static bool isControlFlow(Stmt::Kind k) { return k >= Stmt::Kind::Let; }

  CStmt stmt(const Stmt& s) {
    CStmt r;
    r.kind = s.kind;
    r.src = &s;
    if (isControlFlow(s.kind)) {
      controlFlow(s, r);
      return r;
    }
    if (s.kind == Stmt::Kind::Count) {
      const auto it = std::find(plan.counters.begin(), plan.counters.end(), s.counter);
      r.counter = it == plan.counters.end() ? -1 : static_cast<int>(it - plan.counters.begin());
    }
    for (const auto& [field, e] : s.assigns) {
      CAssign a;
      into_bounded_field = s.kind == Stmt::Kind::Record && isOwnBoundedField(field, e);
      a.value = expr(e);
      into_bounded_field = false;
      if (s.kind == Stmt::Kind::Record) {
        a.field = recordFieldIndex(field);
        if (a.field >= 0 && recordFields()[a.field].automatic) a.field = -1;
      } else {
        a.slot = slotOf(field);
        if (auto w = payloadWordField(field)) a.word = static_cast<uint8_t>(*w);
        if (auto t = sizedMemberField(field)) a.word = static_cast<uint8_t>(*t);
      }
      r.assigns.push_back(std::move(a));
    }
    if (s.kind == Stmt::Kind::If) r.cond = expr(s.cond);
    if (s.kind == Stmt::Kind::Report) {
      r.t = expr(s.t);
      r.hit_kind = expr(s.hit_kind);
      if (!s.attribute.empty()) {
        r.has_attribute = true;
        r.attribute = expr(s.attribute[0]);
      }
    }
    if (s.kind == Stmt::Kind::Call) r.call_index = expr(s.call_index);
    if (s.kind == Stmt::Kind::Light)
      r.light = s.light == "point"  ? LightKind::Point
                : s.light == "spot" ? LightKind::Spot
                                    : LightKind::Directional;
    if (s.kind == Stmt::Kind::Generate) r.t = expr(s.t);
    // A ray_query: size 1 when a candidate block may end its traversal
    // (terminate_query, or a break out of its loop).
    if (s.kind == Stmt::Kind::RayQuery) {
      walkStatements(s.then_, [&](const Stmt& x) {
        if (x.kind == Stmt::Kind::TerminateQuery) r.size = 1;
      });
      for (const Stmt& c : s.then_)
        if (leavesQueryLoop(c.then_)) r.size = 1;  // a break leaves its loop
    }
    if (s.kind == Stmt::Kind::Trace || s.kind == Stmt::Kind::RayQuery ||
        s.kind == Stmt::Kind::RestartQuery || s.kind == Stmt::Kind::RecordMiss ||
        s.kind == Stmt::Kind::RecordHit) {
      const std::vector<Expr>* a[CStmt::kTraceArgs] = {
          &s.trace.origin, &s.trace.direction, &s.trace.tmin,       &s.trace.tmax,
          &s.trace.flags,  &s.trace.cull_mask, &s.trace.sbt_offset, &s.trace.sbt_stride,
          &s.trace.miss,   &s.trace.tlas_index};
      for (int k = 0; k < CStmt::kTraceArgs; ++k)
        if (!a[k]->empty()) {
          r.has[k] = true;
          r.args[k] = expr(a[k]->front());
        }
    }
    r.then_ = program(s.then_);
    r.else_ = program(s.else_);
    if (s.kind == Stmt::Kind::RayQuery) r.order_dependent = queryOrderDependence(r).yes;
    // Stepped queries whose blocks share what they read or write: the
    // interleaving of their candidates would decide (order_dependence.h).
    if (s.kind == Stmt::Kind::RayQueries) r.order_dependent = steppedQueriesShare(r).yes;
    return r;
  }
};

}  // namespace

bool hasTerminate(const CProgram& p) {
  for (const CStmt& s : p)
    if (s.kind == Stmt::Kind::Terminate || hasTerminate(s.then_) || hasTerminate(s.else_))
      return true;
  return false;
}

CountsOnly countsOnly(const CProgram& p) {
  CountsOnly r;
  for (const CStmt& s : p)
    if (s.kind != Stmt::Kind::Count) return r;
  r.yes = true;
  for (const CStmt& s : p)
    if (s.counter >= 0) r.counters.push_back(s.counter);
  return r;
}

std::vector<int> leadingCounts(const CProgram& p) {
  std::vector<int> counters;
  for (const CStmt& s : p) {
    if (s.kind != Stmt::Kind::Count) break;
    if (s.counter >= 0) counters.push_back(s.counter);
  }
  return counters;
}

namespace {

bool readsTmax(const CExpr& e) {
  if (e.kind == Expr::Kind::Builtin && e.builtin == kBiTmax) return true;
  return std::any_of(e.args.begin(), e.args.end(), readsTmax);
}

bool mayEndQuery(const CProgram& p) {
  for (const CStmt& s : p) {
    switch (s.kind) {
      case Stmt::Kind::Break:
      case Stmt::Kind::Return:
      case Stmt::Kind::TerminateQuery:
      case Stmt::Kind::RestartQuery:
        return true;
      default:
        if (mayEndQuery(s.then_) || mayEndQuery(s.else_)) return true;
    }
  }
  return false;
}

}  // namespace

const CStmt* leadingReport(const CProgram& p) {
  for (const CStmt& s : p) {
    if (s.kind == Stmt::Kind::Count) continue;
    return s.kind == Stmt::Kind::Report && !readsTmax(s.t) ? &s : nullptr;
  }
  return nullptr;
}

bool queryBlocksMayEnd(const CStmt& query) {
  return mayEndQuery(query.then_);
}

CPipeline compilePipeline(const Case& c, const Plan& plan) {
  CPipeline out;
  const Pipeline& p = c.pipeline;
  Compiler k{plan, out, p};
  k.begin(Stage::Raygen, 0, 0);
  out.raygen = k.program(p.raygen);
  for (const Program& m : p.miss) {
    k.begin(Stage::Miss, out.miss.size(), p.missPayload(out.miss.size()));
    out.miss.push_back(k.program(m));
    out.miss_counts.push_back(countsOnly(out.miss.back()));
  }
  for (const Program& m : p.callables) {
    k.begin(Stage::Callable, out.callables.size(), p.callableData(out.callables.size()));
    out.callables.push_back(k.program(m));
  }
  out.hit_programs.reserve(p.hit_groups.size() * 3);  // stable addresses for the groups
  for (const HitGroup& g : p.hit_groups) {
    CHitGroup cg;
    auto add = [&](const std::optional<Program>& prog, Stage stage) -> const CProgram* {
      if (!prog) return nullptr;
      k.begin(stage, out.groups.size(), g.payload);
      out.hit_programs.push_back(k.program(*prog));
      return &out.hit_programs.back();
    };
    cg.closest_hit = add(g.closest_hit, Stage::ClosestHit);
    cg.any_hit = add(g.any_hit, Stage::AnyHit);
    cg.intersection = add(g.intersection, Stage::Intersection);
    if (cg.closest_hit) cg.closest_hit_counts = countsOnly(*cg.closest_hit);
    if (cg.any_hit) cg.any_hit_leading = leadingCounts(*cg.any_hit);
    if (cg.intersection) cg.intersection_leading = leadingCounts(*cg.intersection);
    if (cg.intersection) cg.leading_report = leadingReport(*cg.intersection);
    cg.any_hit_terminates = cg.any_hit && hasTerminate(*cg.any_hit);
    cg.payload = g.payload;
    out.any_hit_terminates = out.any_hit_terminates || cg.any_hit_terminates;
    out.groups.push_back(cg);
  }
  const OrderDependence order = pipelineOrderDependence(out);
  out.order_dependent = order.yes;
  out.order_ties_only = order.ties_only;
  return out;
}

}  // namespace rayspec
