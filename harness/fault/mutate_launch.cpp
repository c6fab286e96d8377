// Faults of launches wider than 65536 ids in x or deeper than 4096 in y or z
// (R-LAUNCH-3D, R-BUILTIN): a device that maps a launch onto compute
// workgroups and stops, or wraps the id, at 65536 (the smallest
// maxComputeWorkGroupCount[0] the spec allows, plus one), or packs y and z
// into 12 bits each.
#include "fault/fault_impl.h"
#include "fault/program_edit.h"
#include "program/builtins.h"
#include "program/ops.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

constexpr uint32_t kWrapIds = 65536;
constexpr uint32_t kWrapDeepIds = 4096;

// Every read of the given launch id builtins becomes the read modulo `wrap`;
// how many were edited.
size_t wrapLaunchIdReads(Case& c, std::initializer_list<Builtin> builtins, uint32_t wrap) {
  // The reads first, then the edits: an edited read holds a read of its own.
  std::vector<Expr*> reads;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    editExpressions(p, [&](Expr& e) {
      for (Builtin b : builtins)
        if (isBuiltin(e, b)) reads.push_back(&e);
    });
  });
  for (Expr* e : reads) {
    *e = opExpr(Op::Mod, {*e, uintLiteral(wrap, e->loc)}, ValueType::Uint, e->loc);
  }
  return reads.size();
}

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
  return describeCount(wrapLaunchIdReads(c, {kBiLaunchX}, kWrapIds),
                       "reads of gl_LaunchIDEXT.x that wrap at 65536");
}

// R-BUILTIN: every stage reads gl_LaunchIDEXT.y and .z modulo 4096 (a
// device that packs them into 12 bits each).
std::string launchIdYzWrapped(Case& c, ModelOptions&) {
  const auto size = c.rays.launchSize();
  if (size[1] <= kWrapDeepIds && size[2] <= kWrapDeepIds) return "";
  return describeCount(wrapLaunchIdReads(c, {kBiLaunchY, kBiLaunchZ}, kWrapDeepIds),
                       "reads of gl_LaunchIDEXT.y and .z that wrap at 4096");
}

}  // namespace rayspec
