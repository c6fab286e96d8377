// Whether candidate programs may depend on the order (order_dependence.h).
#include "model/order_dependence.h"

#include <cstring>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "program/builtins.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// What a candidate program reads and writes across candidates: a local of
// the query's frame (by slot), the payload (as a whole), a record field.
enum class Place : uint8_t { Local, Payload, Record };
using Where = std::pair<Place, int>;

struct Write {
  bool varies = false;  // not one and the same constant every time
  Val value;            // the constant, while it does not vary
  const CStmt* at = nullptr;
};

bool sameConstant(const Val& a, const Val& b) {
  return a.u == b.u && a.b == b.b && std::memcmp(a.f.data(), b.f.data(), sizeof a.f) == 0;
}

class Scan {
 public:
  // query: the blocks of a ray_query (their frame's locals outlive a
  // candidate); otherwise a stage program of its own (any-hit, intersection).
  Scan(bool query, Stage stage) : query_(query), stage_(stage) {}

  void program(const CProgram& p) {
    for (const CStmt& s : p) stmt(s);
  }

  // Where a place is written (null: nowhere), and read.
  const CStmt* writes(const Where& w) const {
    const auto it = writes_.find(w);
    return it == writes_.end() ? nullptr : it->second.at;
  }
  const CStmt* reads(const Where& w) const {
    const auto it = reads_.find(w);
    return it == reads_.end() ? nullptr : it->second;
  }
  const std::map<Where, Write>& written() const { return writes_; }
  static std::string name(const Where& w) {
    switch (w.first) {
      case Place::Local:
        return "a local (slot " + std::to_string(w.second) + ")";
      case Place::Payload:
        return "the payload";
      case Place::Record:
        return "record field " + std::string(recordFields()[static_cast<size_t>(w.second)].name);
    }
    return "";
  }

  // The first reason found, or none.
  OrderDependence result() const {
    if (found_.yes) return found_;
    for (const auto& [where, w] : writes_) {
      if (w.varies) return {true, "writes " + name(where) + " with values an order decides", w.at};
      if (const auto r = reads_.find(where); r != reads_.end())
        return {true, "reads " + name(where) + ", which a candidate writes", r->second};
    }
    return tie_;
  }

 private:
  void dependsBecause(std::string why, const CStmt& s) {
    if (!found_.yes) found_ = {true, std::move(why), &s};
  }

  void write(Where where, const CExpr* value, const CStmt& s) {
    if (where.first == Place::Local && (!query_ || function_ > 0 || declared_.count(where.second)))
      return;  // a local of this candidate's own run
    auto [it, fresh] = writes_.try_emplace(where);
    Write& w = it->second;
    if (fresh) w.at = &s;
    const bool constant = value && value->kind == Expr::Kind::Literal;
    if (!constant || (!fresh && !sameConstant(w.value, value->literal))) {
      if (!w.varies) w.at = &s;
      w.varies = true;
    } else {
      w.value = value->literal;
    }
  }

  void read(Where where, const CStmt& s) {
    if (where.first == Place::Local && (!query_ || function_ > 0 || declared_.count(where.second)))
      return;
    reads_.try_emplace(where, &s);
  }

  void expr(const CExpr& e, const CStmt& s) {
    if (e.kind == Expr::Kind::Local) read({Place::Local, static_cast<int>(e.index)}, s);
    if (e.kind == Expr::Kind::Builtin) {
      const int b = e.builtin;
      if (query_ && b >= kBiQCommittedT && b <= kBiQCommittedType)
        dependsBecause(std::string("reads ") + builtins()[b].name, s);
      if (stage_ == Stage::Intersection && b == kBiTmax)
        dependsBecause("reads ray_tmax (the committed t)", s);
      if (b == kBiPayloadColor || b == kBiPayloadValue || b == kBiPayloadWord)
        read({Place::Payload, 0}, s);
    }
    if (e.kind == Expr::Kind::Op && wordArrayOf(e.op)) read({Place::Payload, 0}, s);
    for (const CExpr& a : e.args) expr(a, s);
  }

  // Whether a reported t comes from the box's own geometry (a hit built-in
  // or a sphere root), not only from the interval or constants.
  static bool ownT(const CExpr& e) {
    if (e.kind == Expr::Kind::Builtin && e.builtin != kBiTmin && e.builtin != kBiTmax) return true;
    if (e.kind == Expr::Kind::Op && (e.op == Op::SphereNear || e.op == Op::SphereFar)) return true;
    for (const CExpr& a : e.args)
      if (ownT(a)) return true;
    return false;
  }

  void assigns(const CStmt& s) {
    for (const CAssign& a : s.assigns) {
      expr(a.value, s);
      switch (s.kind) {
        case Stmt::Kind::Record:
          if (a.field >= 0) write({Place::Record, a.field}, &a.value, s);
          break;
        case Stmt::Kind::SetPayload:
          write({Place::Payload, 0}, nullptr, s);
          break;
        case Stmt::Kind::Let:
          declared_.insert(a.field);
          break;
        case Stmt::Kind::Set:
          write({Place::Local, a.field}, &a.value, s);
          break;
        default:
          break;
      }
    }
  }

  void stmt(const CStmt& s) {
    assigns(s);
    for (const CExpr* e : {&s.cond, &s.t, &s.hit_kind, &s.call_index, &s.count, &s.from, &s.index})
      expr(*e, s);
    for (size_t k = 0; k < s.args.size(); ++k)
      if (s.has[k]) expr(s.args[k], s);
    if (s.has_attribute) expr(s.attribute, s);
    switch (s.kind) {
      case Stmt::Kind::Report:
        if (stage_ == Stage::Intersection && !ownT(s.t) && !tie_.yes)
          tie_ = {true, "reports a t that is not its box's own (reports there tie)", &s, true};
        break;
      case Stmt::Kind::Terminate:
      case Stmt::Kind::TerminateQuery:
        dependsBecause("ends traversal", s);
        break;
      case Stmt::Kind::RestartQuery:
        // Which candidate restarts it, and what the candidates before it
        // left behind, is the order's.
        dependsBecause("restarts the query", s);
        break;
      case Stmt::Kind::Array:
      case Stmt::Kind::Repeat:
        if (s.slot >= 0) declared_.insert(s.slot);
        break;
      case Stmt::Kind::Struct:
        for (uint32_t k = 0; s.slot >= 0 && k < s.size; ++k)
          declared_.insert(s.slot + static_cast<int>(k));
        break;
      case Stmt::Kind::Store:
        if (s.words && *s.words == WordArray::Payload)
          write({Place::Payload, 0}, nullptr, s);
        else if (!s.words && s.slot >= 0)
          write({Place::Local, s.slot}, nullptr, s);
        break;
      default:
        break;
    }
    const bool function = s.kind == Stmt::Kind::Invoke;  // a frame of its own
    function_ += function;
    program(s.then_);
    program(s.else_);
    function_ -= function;
  }

  bool query_;
  Stage stage_;
  int function_ = 0;
  std::set<int> declared_;  // locals declared in the candidate programs
  std::map<Where, Write> writes_;
  std::map<Where, const CStmt*> reads_;
  OrderDependence found_;
  OrderDependence tie_;  // reports at a t not the box's own: ties only
};

}  // namespace

OrderDependence queryOrderDependence(const CStmt& query) {
  if (query.src && query.src->size == 1)
    return {true, "its ray_query says order_dependent", nullptr};
  Scan scan(true, Stage::Raygen);
  for (const CStmt& block : query.then_) scan.program(block.then_);
  return scan.result();
}

OrderDependence steppedQueriesShare(const CStmt& stepped) {
  std::vector<Scan> scans;
  for (const CStmt& q : stepped.then_) {
    scans.emplace_back(true, Stage::Raygen);
    for (const CStmt& block : q.then_) scans.back().program(block.then_);
  }
  for (size_t i = 0; i < scans.size(); ++i)
    for (const auto& [where, w] : scans[i].written())
      for (size_t j = 0; j < scans.size(); ++j) {
        if (j == i) continue;
        const CStmt* other = scans[j].reads(where);
        const char* how = "reads";
        if (!other) {
          other = scans[j].writes(where);
          how = "writes";
        }
        if (!other) continue;
        return {true,
                "query " + std::to_string(i) + "'s block writes " + Scan::name(where) + " at " +
                    statementPlace(w.at) + ", which query " + std::to_string(j) + "'s " + how +
                    " at " + statementPlace(other),
                w.at};
      }
  return {};
}

OrderDependence pipelineOrderDependence(const CPipeline& p) {
  // Each stage program apart (its locals are its own), the payload and the
  // record across them all.
  OrderDependence out;
  Scan shared(false, Stage::AnyHit);
  for (const CHitGroup& g : p.groups) {
    if (g.any_hit) shared.program(*g.any_hit);
    if (g.intersection) {
      Scan own(false, Stage::Intersection);
      own.program(*g.intersection);
      if (const OrderDependence d = own.result(); d.yes && (!out.yes || out.ties_only)) out = d;
      shared.program(*g.intersection);
    }
  }
  const OrderDependence d = shared.result();
  return out.yes && !(out.ties_only && d.yes && !d.ties_only) ? out : d;
}

std::string statementPlace(const CStmt* s) {
  if (!s || !s->src) return "";
  const SourceLoc& l = s->src->loc;
  std::string out = l.file;
  if (l.line > 0) out += ":" + std::to_string(l.line);
  if (!l.field.empty()) out += (out.empty() ? "" : " ") + l.field;
  return out;
}

}  // namespace rayspec
