// The EXPECT lines of an exported Amber script: what the judge compares,
// as rayspec's model expects it (export_amber.h).
#include <cstring>
#include <limits>
#include <set>

#include "compare/compare_parts.h"
#include "export/amber_sections.h"
#include "export/expected_values.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

std::string byteIndex(size_t word) {
  return std::to_string(4 * word);
}

// The ray's comment line: the fields compared and the rule each checks.
std::string rayComment(const Case& c, uint32_t ray, const std::vector<const RecordField*>& fields) {
  std::string out = "# ray " + std::to_string(ray) + ": written mask";
  for (const RecordField* f : fields)
    out += ", " + std::string(f->name) + " (" + expectedFieldRule(c, *f) + ")";
  return out + "\n";
}

// One field of one ray: integers EQ word for word; each float word EQ
// within the field's tolerance on the ray, read from the float copy.
std::string fieldLines(const RecordField& f, const uint32_t* m, size_t base,
                       const RayBounds& bounds) {
  if (f.type == FieldType::Uint) {
    std::string out = "EXPECT records IDX " + byteIndex(base + f.offset) + " EQ";
    for (uint32_t k = 0; k < f.words; ++k) out += " " + std::to_string(m[f.offset + k]);
    return out + "\n";
  }
  const Tolerance tol = fieldTolerance(f, bounds);
  std::string out;
  for (uint32_t k = 0; k < f.words; ++k) {
    float v;
    std::memcpy(&v, &m[f.offset + k], 4);
    out += "EXPECT records_as_float IDX " + byteIndex(base + f.offset + k) + " TOLERANCE " +
           amberFloat(tol.allowance(v)) + " EQ " + amberFloat(v) + "\n";
  }
  return out;
}

// Every judged ray: its written mask, then each compared field the model's
// record holds (written, or automatic); R-UB rays left out.
std::string recordLines(const Case& c, const Plan& plan, const Results& model) {
  const std::vector<const RecordField*> fields = comparedRecordFields(plan);
  std::set<uint32_t> undefined;
  for (const UndefinedRay& u : model.undefined) undefined.insert(u.ray);
  const ModelRayBounds bounds(c, model);
  const size_t words = recordWords(), rays = model.records.size() / words;
  std::string out = "COPY records TO records_as_float\n\n";
  for (uint32_t ray = 0; ray < rays; ++ray) {
    if (undefined.count(ray)) {
      out += "# ray " + std::to_string(ray) + ": undefined behaviour (R-UB), not judged\n";
      continue;
    }
    const uint32_t* m = &model.records[ray * words];
    out += rayComment(c, ray, fields) + "EXPECT records IDX " + byteIndex(ray * words) + " EQ " +
           std::to_string(m[kRecordWrittenMaskWord]) + "\n";
    for (const RecordField* f : fields)
      if (f->automatic || written(m, static_cast<int>(f->index)))
        out += fieldLines(*f, m, ray * words, bounds.of(ray));
  }
  return out + "\n";
}

// Each counter EQ its count, or GE and LE its range (neither: not judged).
std::string counterLines(const Case& c, const Plan& plan, const Results& model) {
  std::string out;
  const std::vector<ExpectedCounter> counters = expectedCounters(c, plan, model);
  for (size_t i = 0; i < counters.size(); ++i) {
    const ExpectedCounter& e = counters[i];
    const std::string at = "EXPECT counters IDX " + byteIndex(i);
    out += "# counter " + e.name + " (" + e.rule + "): " + counterModeName(e.how) + "\n";
    if (e.lo == e.hi) {
      out += at + " EQ " + std::to_string(e.lo) + "\n";
      continue;
    }
    if (e.lo > 0) out += at + " GE " + std::to_string(e.lo) + "\n";
    if (e.hi <= std::numeric_limits<uint32_t>::max())
      out += at + " LE " + std::to_string(e.hi) + "\n";
  }
  return out;
}

}  // namespace

std::string amberExpectations(const Case& c, const Plan& plan, const Results& model) {
  return "# What rayspec's reference model (exact tier) expects.\n" +
         (plan.records ? recordLines(c, plan, model) : std::string()) +
         counterLines(c, plan, model);
}

}  // namespace rayspec
