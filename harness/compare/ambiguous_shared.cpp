#include <algorithm>
#include <cmath>
#include <set>

#include "compare/compare_parts.h"
#include "program/builtins.h"
#include "program/walk_program.h"
#include "results/tolerances.h"

namespace rayspec {
namespace {

void addWrong(std::map<std::string, FindingBuilder>& wrongs, const std::string& key,
              const std::string& rule, const std::string& message, uint32_t ray) {
  FindingBuilder& b = wrongs[key];
  if (b.finding.rule.empty()) b.finding = {Status::Fail, rule, message};
  b.addRay(ray);
}

// Any-hit or intersection programs write nothing a record can show: then an
// answer (which candidate, or a miss) decides the whole record.
bool answerDecidesRecord(const Case& c) {
  bool writes = false;
  for (const HitGroup& g : c.pipeline.hit_groups)
    for (const auto* p : {&g.any_hit, &g.intersection})
      if (*p)
        walkStatements(**p, [&](const Stmt& s) {
          writes = writes || s.kind == Stmt::Kind::Record || s.kind == Stmt::Kind::SetPayload;
        });
  return !writes;
}

// Every closest-hit program records the field at its top level.
bool everyClosestHitRecords(const Case& c, const std::string& field) {
  bool all = !c.pipeline.hit_groups.empty();
  for (const HitGroup& g : c.pipeline.hit_groups) {
    bool top = false;
    if (g.closest_hit)
      for (const Stmt& s : *g.closest_hit)
        if (s.kind == Stmt::Kind::Record)
          for (const auto& [name, value] : s.assigns) top = top || name == field;
    all = all && top;
  }
  return all;
}

// Every write of the field is in a closest-hit or miss program, and every
// closest-hit writes the same literal (or `hit`), and so does every miss:
// then every hit writes the same, and every miss.
bool sameForEveryAnswer(const Case& c, const std::string& field) {
  bool invariant = true;
  std::set<std::string> hit_values, miss_values;
  auto visit = [&](const Program& p, std::set<std::string>* values) {
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind != Stmt::Kind::Record) return;
      for (const auto& [name, value] : s.assigns) {
        if (name != field) continue;
        if (!values || (value.kind != Expr::Kind::Literal && !isBuiltin(value, kBiHit))) {
          invariant = false;
          continue;
        }
        std::string text = value.name;
        for (double x : value.literal) text += " " + std::to_string(x);
        values->insert(text);
      }
    });
  };
  const Pipeline& pipe = c.pipeline;
  visit(pipe.raygen, nullptr);
  for (const Program& p : pipe.miss) visit(p, &miss_values);
  for (const Program& p : pipe.callables) visit(p, nullptr);
  for (const HitGroup& g : pipe.hit_groups) {
    if (g.closest_hit) visit(*g.closest_hit, &hit_values);
    if (g.any_hit) visit(*g.any_hit, nullptr);
    if (g.intersection) visit(*g.intersection, nullptr);
  }
  return invariant && hit_values.size() + miss_values.size() > 0 && hit_values.size() <= 1 &&
         miss_values.size() <= 1;
}

bool sameIdentity(const uint32_t* d, const uint32_t* m) {
  bool any = false;
  for (const char* f : {"primitive_id", "instance_id", "geometry_index"}) {
    const int i = recordFieldIndex(f);
    if (!written(d, i)) continue;
    if (!written(m, i) || fieldWord(d, f) != fieldWord(m, f)) return false;
    any = true;
  }
  return any;
}

// Ambiguities whose legal answers' t the model knows to the device's
// rounding: triangles through an edge or vertex, ties, interval ends; and to
// the ray's t bound, a triangle the ray runs in the plane of (hit anywhere
// across it).
bool legalTKnown(AmbiguityReason r) {
  return r == AmbiguityReason::Edge || r == AmbiguityReason::Vertex || r == AmbiguityReason::TTie ||
         r == AmbiguityReason::TmaxTie || r == AmbiguityReason::TminTie ||
         r == AmbiguityReason::InPlane;
}

// The device's hit_t is the t of a legal hit (or of a hit behind a shared
// edge) that fits its identity fields where written; true where some such
// answer's t is unknown (a bundle saved without it).
bool tOfALegalHit(const RayAmbiguity& a, const uint32_t* d, float t_bound) {
  Tolerance tol = toleranceFor("hit_t");
  tol.abs = std::max(tol.abs, static_cast<double>(t_bound));
  const float t = asFloat(d[findRecordField("hit_t")->offset]);
  for (const auto* list : {&a.candidates, &a.leak_answers})
    for (const Candidate& k : *list)
      if (hitFits(d, k) && (!std::isfinite(k.t) || tol.matches(t, static_cast<float>(k.t))))
        return true;
  return false;
}

}  // namespace

void checkAmbiguousShared(const Case& c, const TraceShape& shape, const RayAmbiguity& a,
                          const uint32_t* d, const uint32_t* m,
                          const std::vector<const RecordField*>& fields, const RayBounds& bounds,
                          std::map<std::string, FindingBuilder>& wrongs) {
  const std::string why =
      " on a numerically ambiguous ray (" + std::string(ambiguityReasonName(a.reason)) + ")";
  if (fieldWord(d, "raygen_runs") != fieldWord(m, "raygen_runs"))
    addWrong(wrongs, "raygen_runs", "R-BUILTIN", "raygen did not run once per launch ray" + why,
             a.ray);
  if (shape.calls_fixed && fieldWord(d, "callable_runs") != fieldWord(m, "callable_runs"))
    addWrong(wrongs, "callable_runs", "R-CALLABLE",
             "callables ran other than raygen's calls, which no answer of the trace changes" + why,
             a.ray);
  // The rest reads the one trace's answer: of no use where the ambiguous
  // traversal is a ray query's (its legal answers run no shader).
  if (!shape.single_trace || a.from_query) return;
  const uint32_t d_miss = fieldWord(d, "miss_runs"), d_chit = fieldWord(d, "closest_hit_runs");
  const uint32_t m_miss = fieldWord(m, "miss_runs"), m_chit = fieldWord(m, "closest_hit_runs");
  const bool miss_legal = std::any_of(a.candidates.begin(), a.candidates.end(),
                                      [](const Candidate& k) { return !k.hit; });
  const bool one_each = shape.hit_runs_closest_hit && shape.miss_runs_miss;
  if (one_each ? d_miss + d_chit != 1 : d_miss + d_chit > 1)
    addWrong(wrongs, "miss-xor-chit", "R-MISS-XOR-CHIT",
             std::string("the one trace ran ") + (one_each ? "not exactly one" : "more than one") +
                 " of miss and closest-hit" + why,
             a.ray);
  if (d_miss && !miss_legal && shape.miss_runs_miss && d_chit == 0)
    return;  // checkAmbiguous: a miss no answer allows
  if (d_chit && m_chit) {
    for (const char* f : {"primitive_id", "instance_id", "geometry_index"}) {
      const int i = recordFieldIndex(f);
      if (written(m, i) && !written(d, i) && everyClosestHitRecords(c, f))
        addWrong(wrongs, std::string("unwritten ") + f, "R-BUILTIN",
                 std::string("closest-hit ran but left '") + f +
                     "' unwritten, which every closest-hit records" + why,
                 a.ray);
    }
  }
  const bool same_kind = (d_chit && m_chit) || (d_miss && m_miss && !d_chit && !m_chit);
  for (const RecordField* f : fields)
    if (same_kind && !f->automatic && written(d, recordFieldIndex(f->name)) &&
        written(m, recordFieldIndex(f->name)) && sameForEveryAnswer(c, f->name) &&
        !sameField(*f, d, m, bounds))
      addWrong(wrongs, std::string("every answer ") + f->name, "R-BUILTIN",
               std::string("per-ray field '") + f->name +
                   "' differs from the model's, though every answer of the kind taken (hit or "
                   "miss) writes it alike" +
                   why,
               a.ray);
  // A ray query's answer too may differ where the trace's is the model's,
  // and reach any field: then only the trace's own fields are read.
  const bool same_answer =
      (d_chit && m_chit && sameIdentity(d, m)) || (d_miss && m_miss && !d_chit && !m_chit);
  if (shape.ray_queries > 0) return;
  if (same_answer && answerDecidesRecord(c)) {
    for (const RecordField* f : fields)
      if (!sameField(*f, d, m, bounds))
        addWrong(wrongs, std::string("same answer ") + f->name, "R-PREC",
                 std::string("per-ray field '") + f->name +
                     "' differs from the model's where the device took the model's own answer" +
                     why,
                 a.ray);
    return;
  }
  // The model's own answer on a ray in a triangle's plane is a miss: its
  // legal hit's t is known all the same.
  const bool model_t = (d_chit && m_chit && written(m, recordFieldIndex("hit_t"))) ||
                       (d_chit && a.reason == AmbiguityReason::InPlane);
  if (model_t && legalTKnown(a.reason) && written(d, recordFieldIndex("hit_t")) &&
      !tOfALegalHit(a, d, bounds.t))
    addWrong(wrongs, "legal hit_t", "R-PREC",
             "hit_t is the t of no legal hit that fits the recorded identity" + why, a.ray);
}

}  // namespace rayspec
