#include <algorithm>
#include <array>
#include <cstdint>

#include "compare/counter_modes.h"
#include "export/c_text.h"
#include "export/expected_values.h"
#include "export/export_sections.h"
#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {
namespace {

std::string fieldsText(const Case& c, const Plan& plan) {
  std::string out = "static const rs_field rs_fields[] = {\n";
  for (const RecordField* f : comparedRecordFields(plan)) {
    const Tolerance tol = toleranceFor(f->name);
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, "%.17g, %.17g", tol.abs, tol.rel);
    out += "  {" + cString(f->name) + ", " + cString(expectedFieldRule(c, *f)) + ", " +
           std::to_string(f->offset) + ", " + std::to_string(f->words) + ", " +
           (f->type == FieldType::Float ? "1" : "0") + ", " + (f->automatic ? "1" : "0") + ", " +
           std::to_string(f->index) + ", " + std::to_string(static_cast<int>(f->bound)) + ", " +
           numbers + "},\n";
  }
  return out + "};\n#define RS_FIELD_COUNT (sizeof rs_fields / sizeof rs_fields[0])\n";
}

// The ambiguous rays, each with its legal answers' records (the replays).
std::string ambiguousText(const Results& model) {
  std::vector<uint32_t> replays;
  std::string table;
  for (const RayAmbiguity& a : model.ambiguous) {
    const uint32_t first = static_cast<uint32_t>(replays.size() / recordWords());
    for (const LegalReplay& r : a.replays)
      replays.insert(replays.end(), r.record.begin(), r.record.end());
    table += "  {" + std::to_string(a.ray) + ", " + std::to_string(first) + ", " +
             std::to_string(a.replays.size()) + ", " + cString(ambiguityReasonName(a.reason)) +
             ", " + cString(ruleForAmbiguity(a.reason)) + "},\n";
  }
  if (table.empty()) table = "  {0, 0, 0, \"\", \"\"},\n";
  return "/* Numerically ambiguous rays: the record must be one of the legal answers' records,\n"
         "   each replayed by the model through the launch ray. */\n" +
         cWordArray("rs_replays", replays) + "static const rs_ambiguous rs_ambiguous_rays[] = {\n" +
         table + "};\n#define RS_AMBIGUOUS_COUNT " + std::to_string(model.ambiguous.size()) + "u\n";
}

std::string undefinedText(const Results& model, uint64_t rays) {
  std::vector<uint8_t> undefined(rays, 0);
  for (const UndefinedRay& u : model.undefined)
    if (u.ray < rays) undefined[u.ray] = 1;
  return "/* Rays whose behaviour is undefined (R-UB): not judged. */\n" +
         cByteArray("rs_undefined", undefined);
}

// R-PREC: the rays the model bounds more widely than the fields' tolerances
// (t, the object-space origin, the hit position), each with its bounds in
// FieldBound's order.
std::string boundsText(const Results& model) {
  std::map<uint32_t, std::array<float, 4>> by_ray;
  const std::pair<const std::vector<TBound>*, FieldBound> lists[] = {
      {&model.t_bounds, FieldBound::TBound},
      {&model.object_origin_bounds, FieldBound::OriginBound},
      {&model.position_bounds, FieldBound::PositionBound}};
  for (const auto& [list, kind] : lists)
    for (const TBound& b : *list) by_ray[b.ray][static_cast<size_t>(kind)] = b.bound;
  std::string table;
  for (const auto& [ray, by] : by_ray)
    table += "  {" + std::to_string(ray) + ", {0, " + cFloat(by[1]) + ", " + cFloat(by[2]) + ", " +
             cFloat(by[3]) + "}},\n";
  if (table.empty()) table = "  {0, {0, 0, 0, 0}},\n";
  return "/* Rays whose t, object-space origin or hit position the model bounds more widely\n"
         "   than the field's tolerance (R-PREC): the bound widens the field's abs. */\n"
         "static const rs_bound rs_bounds[] = {\n" +
         table + "};\n#define RS_BOUND_COUNT " + std::to_string(by_ray.size()) + "u\n";
}

// R-AHIT-DUP: the rays whose fields a repeated any-hit may change, and those fields.
std::string repeatText(const Results& model) {
  std::string table;
  for (const RepeatDependentRay& r : model.repeat_dependent)
    table += "  {" + std::to_string(r.ray) + ", " + std::to_string(r.fields) + "ull},\n";
  if (table.empty()) table = "  {0, 0},\n";
  return "/* Rays a device that runs any-hit more than once for a primitive may change\n"
         "   (R-AHIT-DUP), with the fields it may change: those not judged (an ambiguous one\n"
         "   not at all). */\n"
         "static const rs_repeat rs_repeat_rays[] = {\n" +
         table + "};\n#define RS_REPEAT_COUNT " + std::to_string(model.repeat_dependent.size()) +
         "u\n";
}

// Each counter with the range the judge allows.
std::string countersText(const Case& c, const Plan& plan, const Results& model) {
  std::string table;
  for (const ExpectedCounter& e : expectedCounters(c, plan, model))
    table += "  {" + cString(e.name) + ", " + cString(e.rule) + ", " + std::to_string(e.lo) +
             "ull, " + std::to_string(e.hi) + "ull},  /* " + counterModeName(e.how) + " */\n";
  if (table.empty()) table = "  {\"\", \"\", 0, 0},\n";
  return "/* Counters, in the order the shaders count them, with the range the judge allows\n"
         "   (the model's count, as far as the legal answers of ambiguous rays move it). */\n"
         "static const rs_counter rs_counters[] = {\n" +
         table + "};\n#define RS_COUNTER_COUNT " + std::to_string(plan.counters.size()) + "u\n";
}

}  // namespace

std::string expectationsSection(const Case& c, const Plan& plan, const Results& model) {
  const std::vector<uint32_t> records(model.records.begin(), model.records.end());
  return "/* What rayspec's reference model (exact tier) expects: each ray's record, " +
         std::to_string(recordWords()) +
         " words (a written mask, the fields, the stage run counts), the fields compared. */\n"
         "#define RS_RECORD_WORDS " +
         std::to_string(recordWords()) + "u\n#define RS_RECORDS_JUDGED " +
         (plan.records ? "1" : "0 /* a case of counters only */") + "\n" +
         cWordArray("rs_expected", records) + fieldsText(c, plan) +
         undefinedText(model, uint64_t(c.rays.width) * c.rays.height) + ambiguousText(model) +
         repeatText(model) + boundsText(model) + countersText(c, plan, model) + "\n";
}

}  // namespace rayspec
