// Faults of launches wider than 65536 ids in x (R-LAUNCH-3D, R-BUILTIN): a
// device that maps a launch onto compute workgroups and stops, or wraps the
// id, at 65536 (the smallest maxComputeWorkGroupCount[0] the spec allows,
// plus one).
#include "fault/fault_impl.h"
#include "fault/program_edit.h"
#include "program/builtins.h"
#include "program/ops.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

constexpr uint32_t kWrapIds = 65536;

}  // namespace

// R-LAUNCH-3D: raygen runs only for launch x below 65536; the ids beyond
// run nothing.
std::string wideLaunchTruncated(Case& c, ModelOptions&) {
  if (c.rays.launchSize()[0] <= kWrapIds) return "";
  Stmt stop;
  stop.kind = Stmt::Kind::If;
  stop.loc = c.rays.defaults_loc;
  stop.cond = opExpr(Op::Ge, {builtinExpr(kBiLaunchX, stop.loc), uintLiteral(kWrapIds, stop.loc)},
                     ValueType::Bool, stop.loc);
  Stmt end;
  end.kind = Stmt::Kind::Return;
  end.loc = stop.loc;
  stop.then_.push_back(end);
  c.pipeline.raygen.insert(c.pipeline.raygen.begin(), stop);
  return describeCount(c.rays.launchSize()[0] - kWrapIds,
                       "launch ids in x from 65536 on that run no raygen");
}

// R-BUILTIN: every stage reads gl_LaunchIDEXT.x modulo 65536.
std::string launchIdXWrapped(Case& c, ModelOptions&) {
  if (c.rays.launchSize()[0] <= kWrapIds) return "";
  // The reads first, then the edits: an edited read holds a read of its own.
  std::vector<Expr*> reads;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    editExpressions(p, [&](Expr& e) {
      if (isBuiltin(e, kBiLaunchX)) reads.push_back(&e);
    });
  });
  for (Expr* e : reads) {
    *e = opExpr(Op::Mod, {*e, uintLiteral(kWrapIds, e->loc)}, ValueType::Uint, e->loc);
  }
  return describeCount(reads.size(), "reads of gl_LaunchIDEXT.x that wrap at 65536");
}

}  // namespace rayspec
