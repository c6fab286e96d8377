// Faults of the pipeline interface's sized members (pipeline.payloads[].sized,
// callable_data[].sized, hit_attribute.sized): a driver that lays out or
// spills the narrow and wide members of a payload, callable data or hit
// attribute through slots half their width, so that each comes back with
// only the upper half of its bits.
#include "fault/fault_impl.h"
#include "fault/program_edit.h"
#include "program/payload_words.h"

namespace rayspec {
namespace {

// The statements of `kind` that write a sized member, and how many members.
size_t sizedWrites(Case& c, Stmt::Kind kind) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachStmt(p, [&](Stmt& s) {
      if (s.kind != kind) return;
      for (const auto& [name, value] : s.assigns) n += sizedMemberField(name).has_value();
    });
  });
  return n;
}

}  // namespace

std::string sizedPayloadHalved(Case& c, ModelOptions& o) {
  if (c.pipeline.allPayloadSized().empty()) return "";
  o.faults.sized_payload_halved = true;
  return describeCount(sizedWrites(c, Stmt::Kind::SetPayload) + sizedWrites(c, Stmt::Kind::Trace),
                       "sized payload member writes that come back from each trace with only the "
                       "upper half of their bits");
}

std::string sizedCallDataHalved(Case& c, ModelOptions& o) {
  if (c.pipeline.allCallDataSized().empty()) return "";
  o.faults.sized_call_data_halved = true;
  return describeCount(sizedWrites(c, Stmt::Kind::SetCall) + sizedWrites(c, Stmt::Kind::Call),
                       "sized callable data member writes that come back from each call with "
                       "only the upper half of their bits");
}

std::string sizedAttributeHalved(Case& c, ModelOptions& o) {
  if (c.pipeline.attribute_sized.empty()) return "";
  o.faults.sized_attribute_halved = true;
  return describeCount(sizedWrites(c, Stmt::Kind::Report),
                       "sized hit attribute members a report gives that reach the candidate "
                       "with only the upper half of their bits");
}

}  // namespace rayspec
