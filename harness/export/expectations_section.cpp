#include <algorithm>
#include <cstdint>
#include <limits>
#include <set>

#include "compare/counter_modes.h"
#include "compare/finding_rules.h"
#include "export/c_text.h"
#include "export/export_sections.h"
#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {
namespace {

// The rule a field's mismatch names, as the judge names it (compare_records.cpp).
std::string fieldRule(const Case& c, const RecordField& f) {
  return findingRule(rulesEvidencedByField(f.name), c.rules, f.rule).rule;
}

std::string fieldsText(const Case& c, const Plan& plan) {
  std::string out = "static const rs_field rs_fields[] = {\n";
  for (const RecordField* f : comparedRecordFields(plan)) {
    const Tolerance tol = toleranceFor(f->name);
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, "%.17g, %.17g", tol.abs, tol.rel);
    out += "  {" + cString(f->name) + ", " + cString(fieldRule(c, *f)) + ", " +
           std::to_string(f->offset) + ", " + std::to_string(f->words) + ", " +
           (f->type == FieldType::Float ? "1" : "0") + ", " + (f->automatic ? "1" : "0") + ", " +
           std::to_string(f->index) + ", " + numbers + "},\n";
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

// The rule a counter's mismatch names, as the judge names it (compare_counters.cpp).
std::string counterRule(const Case& c, const std::string& name) {
  return findingRule(rulesEvidencedByCounter(c, name), c.rules, "counter").rule;
}

// How far the ambiguous rays' legal answers may move a counter from the
// model's count, together: each ray's replays' smallest and largest move
// (the model's own answer moves it by 0), summed over the rays.
std::pair<int64_t, int64_t> replayedMoves(const Results& model, const std::string& name) {
  int64_t down = 0, up = 0;
  for (const RayAmbiguity& a : model.ambiguous) {
    int64_t least = 0, most = 0;
    for (const LegalReplay& r : a.replays) {
      const auto move = r.counter_moves.find(name);
      const int64_t m = move == r.counter_moves.end() ? 0 : move->second;
      least = std::min(least, m);
      most = std::max(most, m);
    }
    down += least;
    up += most;
  }
  return {down, up};
}

// A counter's range: the model's count, moved as far as the legal answers
// move it, then opened below (at_least), above (at_most) or both
// (informational, or moved by a ray with undefined behaviour).
std::pair<uint64_t, uint64_t> counterRange(const Case& c, const Results& model,
                                           const std::string& name, CounterMode how) {
  const auto found = model.counters.find(name);
  const int64_t m = found == model.counters.end() ? 0 : static_cast<int64_t>(found->second);
  const auto [down, up] = replayedMoves(model, name);
  uint64_t lo = static_cast<uint64_t>(std::max<int64_t>(0, m + down));
  uint64_t hi = static_cast<uint64_t>(m + up);
  const bool undefined = !model.undefined.empty() && countersUndefinedRaysMayMove(c).count(name);
  if (how == CounterMode::AtMost || how == CounterMode::Informational || undefined) lo = 0;
  if (how == CounterMode::AtLeast || how == CounterMode::Informational || undefined)
    hi = std::numeric_limits<uint64_t>::max();
  return {lo, hi};
}

// Each counter with the range the judge allows.
std::string countersText(const Case& c, const Plan& plan, const Results& model) {
  const std::map<std::string, CounterMode> modes = counterModes(c);
  std::string table;
  for (const std::string& name : plan.counters) {
    const auto mode = modes.find(name);
    const CounterMode how = mode == modes.end() ? CounterMode::Exact : mode->second;
    const auto [lo, hi] = counterRange(c, model, name, how);
    table += "  {" + cString(name) + ", " + cString(counterRule(c, name)) + ", " +
             std::to_string(lo) + "ull, " + std::to_string(hi) + "ull},  /* " +
             counterModeName(how) + " */\n";
  }
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
         std::to_string(recordWords()) + "u\n" + cWordArray("rs_expected", records) +
         fieldsText(c, plan) + undefinedText(model, uint64_t(c.rays.width) * c.rays.height) +
         ambiguousText(model) + countersText(c, plan, model) + "\n";
}

}  // namespace rayspec
