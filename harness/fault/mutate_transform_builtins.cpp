// R-BUILTIN broken for the instance matrices: a device whose
// gl_ObjectToWorldEXT and gl_WorldToObjectEXT (and their 3x4 forms) each give
// the other matrix (the model's test-only hook, model/model_faults.h).
#include "fault/fault_impl.h"
#include "fault/program_edit.h"
#include "program/builtins.h"
#include "program/walk_program.h"

namespace rayspec {

std::string transformBuiltinsSwapped(Case& c, ModelOptions& o) {
  size_t reads = 0;
  auto visit = [&](const Program& p) {
    walkExpressions(p, [&](const Expr& e) {
      reads += e.kind == Expr::Kind::Builtin && isInstanceTransform(e.builtin);
    });
  };
  forEachProgram(c.pipeline, [&](Program& p, Stage) { visit(p); });
  if (!reads) return "";
  o.faults.transform_builtins_swapped = true;
  return describeCount(reads, "reads of the instance matrices that get the other matrix");
}

}  // namespace rayspec
