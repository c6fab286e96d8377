#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <set>

#include "compare/compare_parts.h"
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
    const Tolerance tol = fieldTolerance(*f, RayBounds{});
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, "%.17g, %.17g", tol.abs, tol.rel);
    out += "  {" + cString(f->name) + ", " + cString(expectedFieldRule(c, *f)) + ", " +
           std::to_string(f->offset) + ", " + std::to_string(f->words) + ", " +
           (f->type == FieldType::Float ? "1" : "0") + ", " + (f->automatic ? "1" : "0") + ", " +
           std::to_string(f->index) + ", " + std::to_string(static_cast<int>(boundSlotOf(*f))) +
           ", " + numbers + "},\n";
  }
  return out + "};\n#define RS_FIELD_COUNT (sizeof rs_fields / sizeof rs_fields[0])\n";
}

// One ambiguous ray's answers as the player holds a record to them: the
// legal ones (the replays), then those the judge accepts with a warning
// (R-WATERTIGHT: the double-hit and leak replays it judges a
// QualityWarning), each with the judge's message. A double-hit or leak
// replay the judge fails is left out: the player fails it too.
struct EmbeddedAnswers {
  std::vector<const LegalReplay*> legal, warned;
  std::vector<std::string> notes;  // the judge's message of each warned one
};

EmbeddedAnswers embeddedAnswers(const AmbiguousRecordJudge& judge, const RayAmbiguity& a,
                                const uint32_t* m, const RayBounds& bounds) {
  EmbeddedAnswers out;
  for (const LegalReplay& r : a.replays) out.legal.push_back(&r);
  for (const auto* list : {&a.double_replays, &a.leak_replays})
    for (const LegalReplay& r : *list) {
      const Finding f = judge.judge(a, r.record.data(), m, bounds);
      if (f.status == Status::Pass) out.legal.push_back(&r);
      if (f.status != Status::QualityWarning) continue;
      out.warned.push_back(&r);
      out.notes.push_back(f.rule + ": " + f.message);
    }
  return out;
}

// The ambiguous rays, each with its answers' records (embeddedAnswers).
std::string ambiguousText(const Case& c, const Plan& plan, const Results& model) {
  const AmbiguousRecordJudge judge(c, plan);
  const ModelRayBounds bounds(c, model);
  std::vector<uint32_t> replays;
  std::string table, notes;
  size_t warnings = 0;
  for (const RayAmbiguity& a : model.ambiguous) {
    const uint32_t* m = &model.records[size_t(a.ray) * recordWords()];
    const EmbeddedAnswers e = embeddedAnswers(judge, a, m, bounds.of(a.ray));
    const std::optional<uint32_t> most = watertightAnyHitLimit(c, a, m);
    const uint32_t first = static_cast<uint32_t>(replays.size() / recordWords());
    for (const auto* list : {&e.legal, &e.warned})
      for (const LegalReplay* r : *list)
        replays.insert(replays.end(), r->record.begin(), r->record.end());
    table += "  {" + std::to_string(a.ray) + ", " + std::to_string(first) + ", " +
             std::to_string(e.legal.size()) + ", " + std::to_string(e.warned.size()) + ", " +
             std::to_string(warnings) + ", " + (most ? std::to_string(*most) + "u" : "RS_NONE") +
             ", " + cString(ambiguityReasonName(a.reason)) + ", " +
             cString(ruleForAmbiguity(a.reason)) + "},\n";
    for (const std::string& n : e.notes) notes += "  " + cString(n) + ",\n";
    warnings += e.warned.size();
  }
  if (table.empty()) table = "  {0, 0, 0, 0, 0, RS_NONE, \"\", \"\"},\n";
  if (notes.empty()) notes = "  \"\",\n";
  return "/* Numerically ambiguous rays: the record must be one of the legal answers' records,\n"
         "   each replayed by the model through the launch ray; or one of the answers the judge\n"
         "   accepts with a QualityWarning (R-WATERTIGHT, a \"should\": a double hit or a leak\n"
         "   at a shared edge or vertex), each with the judge's words (rs_warning_notes); and, "
         "where\n"
         "   the judge tells a double hit by any-hit runs, the most a watertight device runs. "
         "*/\n" +
         cWordArray("rs_replays", replays) + "static const rs_ambiguous rs_ambiguous_rays[] = {\n" +
         table + "};\n#define RS_AMBIGUOUS_COUNT " + std::to_string(model.ambiguous.size()) +
         "u\nstatic const char* const rs_warning_notes[] = {\n" + notes +
         "};\n/* A double hit told by any-hit runs (rs_ambiguous.ahit_limit): */\n"
         "#define RS_ANY_HIT_DOUBLE_HIT " +
         cString(std::string("R-WATERTIGHT: ") + kAnyHitDoubleHit) +
         "\n#define RS_ANY_HIT_RUNS_WORD " +
         std::to_string(findRecordField("any_hit_runs")->offset) + "u\n";
}

std::string undefinedText(const Results& model, uint64_t rays) {
  std::vector<uint8_t> undefined(rays, 0);
  for (const UndefinedRay& u : model.undefined)
    if (u.ray < rays) undefined[u.ray] = 1;
  return "/* Rays whose behaviour is undefined (R-UB): not judged. */\n" +
         cByteArray("rs_undefined", undefined);
}

// R-PREC: the rays the model bounds more widely than the fields' tolerances
// (t, the object-space origin, the hit position; and the widest of them
// where the case carries them into free fields), each with its bounds as
// the judge has them (ModelRayBounds), in RayBoundSlot's order.
std::string boundsText(const Case& c, const Results& model) {
  std::set<uint32_t> rays;
  for (const auto* list : {&model.t_bounds, &model.object_origin_bounds, &model.position_bounds})
    for (const TBound& b : *list) rays.insert(b.ray);
  const ModelRayBounds bounds(c, model);
  std::string table;
  for (const uint32_t ray : rays) {
    const RayBounds b = bounds.of(ray);
    table += "  {" + std::to_string(ray) + ", {0";
    for (const RayBoundSlot s : {RayBoundSlot::T, RayBoundSlot::ObjectOrigin,
                                 RayBoundSlot::Position, RayBoundSlot::Carried})
      table += ", " + cFloat(boundIn(b, s));
    table += "}},\n";
  }
  if (table.empty()) table = "  {0, {0, 0, 0, 0, 0}},\n";
  return "/* Rays whose t, object-space origin or hit position the model bounds more widely\n"
         "   than the field's tolerance (R-PREC), and the widest of them where the case carries\n"
         "   them into a free field (a colour of hit_t): the bound widens the field's abs. */\n"
         "static const rs_bound rs_bounds[] = {\n" +
         table + "};\n#define RS_BOUND_COUNT " + std::to_string(rays.size()) + "u\n";
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
         undefinedText(model, uint64_t(c.rays.width) * c.rays.height) +
         ambiguousText(c, plan, model) + repeatText(model) + boundsText(c, model) +
         countersText(c, plan, model) + "\n";
}

}  // namespace rayspec
