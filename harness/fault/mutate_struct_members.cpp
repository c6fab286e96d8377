// A fault of struct locals (R-LIVE-STATE): a device that spills a struct
// across a call short by its last member.
#include "fault/fault_impl.h"
#include "fault/program_edit.h"
#include "program/locals.h"
#include "program/ops.h"

namespace rayspec {
namespace {

// A struct in scope: its last member's local (STRUCT.MEMBER) and type.
struct LastMember {
  std::string local;
  ValueType type = ValueType::Uint;
};

Expr read(const LastMember& m, const SourceLoc& loc) {
  Expr e;
  e.kind = Expr::Kind::Local;
  e.name = m.local;
  e.type = m.type;
  e.loc = loc;
  return e;
}

// set: {STRUCT.LAST: LAST - LAST} for each struct in `visible`: zero in any
// member type (exact: x - x of a finite value).
Stmt loseLastMembers(const std::vector<LastMember>& visible, const SourceLoc& loc) {
  Stmt set;
  set.kind = Stmt::Kind::Set;
  set.loc = loc;
  for (const LastMember& m : visible)
    set.assigns.emplace_back(m.local, opExpr(Op::Sub, {read(m, loc), read(m, loc)}, m.type, loc));
  return set;
}

bool isCall(const Stmt& s) {
  return s.kind == Stmt::Kind::Trace || s.kind == Stmt::Kind::Call || s.kind == Stmt::Kind::Report;
}

// After each trace, call and report of `block` and the blocks in it, the
// structs declared before it in scope lose their last member. A function's
// body sees none of its caller's structs.
void loseAfterCalls(std::vector<Stmt>& block, std::vector<LastMember> visible, size_t& n) {
  for (size_t i = 0; i < block.size(); ++i) {
    Stmt& s = block[i];
    if (s.kind == Stmt::Kind::Struct && !s.params.empty())
      visible.push_back({memberLocal(s.local, s.params.back().first), s.params.back().second});
    loseAfterCalls(s.then_, s.kind == Stmt::Kind::Invoke ? std::vector<LastMember>{} : visible, n);
    loseAfterCalls(s.else_, visible, n);
    if (!isCall(s) || visible.empty()) continue;
    const SourceLoc loc = s.loc;
    block.insert(block.begin() + static_cast<std::ptrdiff_t>(i) + 1, loseLastMembers(visible, loc));
    ++i;
    ++n;
  }
}

}  // namespace

// The structs' last members read zero after each trace, call and report.
std::string structMemberLost(Case& c, ModelOptions&) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) { loseAfterCalls(p, {}, n); });
  return describeCount(n,
                       "traces, calls and reports after which each struct local's last member "
                       "reads zero");
}

}  // namespace rayspec
