// A fault of a pipeline made with an empty pipeline layout
// (pipeline.layout: empty, R-EMPTY-LAYOUT): its shaders reach the case's
// buffers through device addresses only.
#include "fault/fault_impl.h"
#include "fault/program_edit.h"

namespace rayspec {

// R-EMPTY-LAYOUT: what the shaders other than raygen write through their
// device addresses is lost (their counts and records dropped), as on a
// driver that gives only raygen the addresses it needs.
std::string addressWritesLost(Case& c, ModelOptions&) {
  if (!c.pipeline.empty_layout) return "";
  size_t dropped = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage s) {
    if (s == Stage::Raygen) return;
    dropped += removeStmts(p, [](const Stmt& st) {
      return st.kind == Stmt::Kind::Count || st.kind == Stmt::Kind::Record;
    });
  });
  return describeCount(dropped, "counts and records of non-raygen stages dropped");
}

}  // namespace rayspec
