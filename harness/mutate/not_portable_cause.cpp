#include "mutate/not_portable_cause.h"

#include <algorithm>
#include <functional>
#include <map>

#include "base/error.h"
#include "base/visible_text.h"
#include "compare/compare_results.h"
#include "fault/program_edit.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

bool startsWith(const std::string& s, const char* prefix) {
  return s.rfind(prefix, 0) == 0;
}

// Every statement of a block, nested ones included.
void eachStmt(const std::vector<Stmt>& block, const std::function<void(const Stmt&)>& visit) {
  for (const Stmt& s : block) {
    visit(s);
    eachStmt(s.then_, visit);
    eachStmt(s.else_, visit);
  }
}

// The statements of every program that runs whose kind is one of `kinds`,
// in the order of the pipeline (forEachProgram) and of the programs.
std::vector<const Stmt*> statementsOf(const Case& c, std::initializer_list<Stmt::Kind> kinds) {
  std::vector<const Stmt*> out;
  forEachProgram(c.pipeline, [&](const Program& p, Stage) {
    eachStmt(p, [&](const Stmt& s) {
      if (std::find(kinds.begin(), kinds.end(), s.kind) != kinds.end()) out.push_back(&s);
    });
  });
  return out;
}

// The case file alone: a declaration no line is known for.
SourceLoc fileOf(const Case& c) {
  SourceLoc loc;
  loc.file = c.file;
  return loc;
}

// The first of `stmts` where written (the case file when there is none),
// and ", and N more" for the rest.
SourceLoc firstPlace(const Case& c, const std::vector<const Stmt*>& stmts, std::string* more) {
  if (stmts.size() > 1) *more = " (and " + std::to_string(stmts.size() - 1) + " more like it)";
  return stmts.empty() || stmts[0]->loc.file.empty() ? fileOf(c) : stmts[0]->loc;
}

// The first ray whose record the device changed from the model's own answers.
int64_t firstChangedRay(const Results& device, const Results& base) {
  const size_t words = recordWords();
  if (words == 0 || device.records.size() != base.records.size()) return -1;
  for (size_t ray = 0; ray * words < device.records.size(); ++ray)
    if (!std::equal(device.records.begin() + ray * words,
                    device.records.begin() + (ray + 1) * words, base.records.begin() + ray * words))
      return static_cast<int64_t>(ray);
  return -1;
}

// The verdict's first failing finding, "RULE: message", and its first ray.
std::string failingFinding(const Verdict& verdict, int64_t* ray) {
  for (const Finding& f : verdict.findings)
    if (isFailing(f.status)) {
      if (!f.rays.empty()) *ray = f.rays[0];
      return f.rule + ": " + f.message;
    }
  return verdict.headline();
}

uint64_t counterOf(const Results& r, const std::string& name) {
  const auto it = r.counters.find(name);
  return it == r.counters.end() ? 0 : it->second;
}

// The counters whose declared mode (exact, at_least, at_most) the device
// breaks: those it moves from the model's count, the way the mode forbids.
std::vector<std::string> brokenCounterModes(const Case& c, const Results& device,
                                            const Results& model) {
  std::vector<std::string> out;
  for (const auto& [name, mode] : c.outputs.counter_modes) {
    const uint64_t d = counterOf(device, name), m = counterOf(model, name);
    if ((mode == "exact" && d != m) || (mode == "at_least" && d < m) ||
        (mode == "at_most" && d > m))
      out.push_back(name);
  }
  return out;
}

// What to declare instead of a counter's mode that a legal device breaks.
// (The counts are the finding's: the change is the same for every device
// that moves the counter the same way.)
std::string counterChange(const Case& c, const std::string& name, uint64_t d, uint64_t m) {
  const std::string mode = c.outputs.counter_modes.at(name);
  const std::string moved = std::string("a device the specification allows counts it ") +
                            (d > m ? "more" : "less") + " often than the model";
  if (mode == "exact")
    return "counter '" + name + "' is declared `exact`, but " + moved + ": declare it a bound (`" +
           (d > m ? "at_least" : "at_most") +
           "`) or leave its mode undeclared (then it may move as the legal answers move it)";
  return "counter '" + name + "' is declared `" + mode + "`, but " + moved +
         ": leave its mode undeclared or declare it `informational`";
}

// The declared counter modes the device breaks, one cause each, when
// leaving them out makes the device pass; *rest: the verdict without them.
std::vector<NotPortable> counterCauses(const Case& c, const Plan& plan, const Results& model,
                                       const LegalVariant& v, Verdict* rest) {
  const std::vector<std::string> names = brokenCounterModes(c, v.device, model);
  if (names.empty()) return {};
  Case relaxed = c;
  for (const std::string& n : names) relaxed.outputs.counter_modes.erase(n);
  *rest = compareResults(relaxed, plan, v.device, model);
  std::vector<NotPortable> out;
  for (const std::string& n : names) {
    NotPortable p;
    p.finding = "counter '" + n + "' (" + c.outputs.counter_modes.at(n) + "): device " +
                std::to_string(counterOf(v.device, n)) + ", model " +
                std::to_string(counterOf(model, n));
    const auto loc = c.outputs.counter_mode_locs.find(n);
    p.declaration = loc == c.outputs.counter_mode_locs.end() ? fileOf(c) : loc->second;
    p.change = counterChange(c, n, counterOf(v.device, n), counterOf(model, n));
    out.push_back(std::move(p));
  }
  return out;
}

// aabb-neighbours, aabb-near: the statement that reported (or generated)
// for a box the model's own ray misses, as the device's run noted it
// (Results::missed_box_reports); else the first report or generate of the
// pipeline.
void boxReports(const Case& c, const Results& device, NotPortable& p) {
  std::string more;
  const std::vector<SourceLoc>& made = device.missed_box_reports;
  if (!made.empty()) {
    p.declaration = made.front();
    if (made.size() > 1) more = " (and " + std::to_string(made.size() - 1) + " more like it)";
  } else {
    p.declaration =
        firstPlace(c, statementsOf(c, {Stmt::Kind::Report, Stmt::Kind::Generate}), &more);
  }
  p.change =
      "this report" + more +
      " is made without testing that the ray crosses its box, and a device with a conservative "
      "AABB test (R-AABB-CONS) runs the program for boxes the ray misses: report only where "
      "the ray crosses the box (compare object_ray_origin and object_ray_direction with the "
      "box's bounds)";
}

// Another candidate order: the ray queries' blocks, else the hit groups'
// any-hit and intersection programs.
void orderDependentBlocks(const Case& c, NotPortable& p) {
  std::string more;
  const std::vector<const Stmt*> queries = statementsOf(c, {Stmt::Kind::RayQuery});
  if (!queries.empty()) {
    p.declaration = firstPlace(c, queries, &more);
    p.change = "the candidate blocks of this ray_query" + more +
               " decide by the order their candidates come in, which is unspecified "
               "(R-ORDER-UNSPEC): make them independent of it (mark candidates in a bit mask, "
               "confirm the closest only, or one by identity) or declare `order_dependent: true` "
               "so that every order's answer is legal";
    return;
  }
  p.declaration = fileOf(c);
  for (const HitGroup& g : c.pipeline.hit_groups)
    if ((g.any_hit || g.intersection) && !g.loc.file.empty()) {
      p.declaration = g.loc;
      break;
    }
  p.change =
      "the any-hit or intersection programs of this hit group decide by the order candidates "
      "come in, which is unspecified (R-ORDER-UNSPEC): make what they leave behind independent "
      "of it (write one constant, mark candidates in a bit mask)";
}

// any-hit-runs-twice, intersection-runs-twice: the program run twice.
void repeatedProgram(const Case& c, const std::string& device, NotPortable& p) {
  const bool any_hit = startsWith(device, "any-hit");
  p.declaration = fileOf(c);
  for (const HitGroup& g : c.pipeline.hit_groups)
    if ((any_hit ? g.any_hit : g.intersection) && !g.loc.file.empty()) {
      p.declaration = g.loc;
      break;
    }
  p.change = any_hit ? "a device may run this any-hit more than once for a primitive "
                       "(R-AHIT-DUP): make what it writes the same however often it runs, or "
                       "give the geometries `flags: [no_duplicate_any_hit]`"
                     : "a device may run this intersection program more than once for a "
                       "primitive (R-ISECT-MULTI): make what it writes the same however often "
                       "it runs";
}

// Another legal answer of an ambiguous ray: where the ray is written.
void ambiguousRay(const Case& c, const Results& model, NotPortable& p) {
  p.declaration = c.rays.defaults_loc.file.empty() ? fileOf(c) : c.rays.defaults_loc;
  if (p.ray >= 0 && static_cast<size_t>(p.ray) < c.rays.list_locs.size())
    p.declaration = c.rays.list_locs[static_cast<size_t>(p.ray)];
  std::string reason = "ambiguous";
  for (const RayAmbiguity& a : model.ambiguous)
    if (static_cast<int64_t>(a.ray) == p.ray)
      reason += std::string(" (") + ambiguityReasonName(a.reason) + ")";
  p.change = "this ray is " + reason +
             ", and its legal answers differ in what the case compares: keep the rays off shared "
             "edges, vertices and ties, or compare only what every answer shares";
}

// What the device's kind says about the declaration to change.
void causeOfKind(const Case& c, const Results& model, const Results& device, NotPortable& p) {
  if (p.device == "aabb-neighbours" || p.device == "aabb-near") return boxReports(c, device, p);
  if (p.device == "reverse-order" || startsWith(p.device, "permuted-order-") ||
      startsWith(p.device, "last-"))
    return orderDependentBlocks(c, p);
  if (p.device == "any-hit-runs-twice" || p.device == "intersection-runs-twice")
    return repeatedProgram(c, p.device, p);
  if (startsWith(p.device, "answer-") || startsWith(p.device, "replay-") ||
      p.device == "pass-between-edges")
    return ambiguousRay(c, model, p);
  p.declaration = fileOf(c);
  if (p.device == "tolerance-bound") {
    p.change =
        "a value the case derives exactly from hit_t, hit_position or barycentrics changes "
        "within their tolerance: record the float itself, or derive nothing exact from it";
    return;
  }
  p.change =
      "the case relies on something this device, which the specification allows, "
      "does otherwise";
}

std::string alsoText(const std::vector<std::string>& also) {
  std::string out;
  for (const std::string& name : also) out += (out.empty() ? " (also " : ", ") + name;
  return out.empty() ? out : out + ")";
}

}  // namespace

std::vector<NotPortable> notPortableCauses(const Case& c, const Plan& plan, const Results& model,
                                           const Results& base, const LegalVariant& v,
                                           const Verdict& verdict) {
  Verdict rest = verdict;
  std::vector<NotPortable> out = counterCauses(c, plan, model, v, &rest);
  const int64_t changed = firstChangedRay(v.device, base);
  for (NotPortable& p : out) p.ray = changed;
  if (isFailing(rest.status)) {
    NotPortable p;
    p.finding = failingFinding(rest, &p.ray);
    if (p.ray < 0) p.ray = changed;
    p.device = v.name;
    causeOfKind(c, model, v.device, p);
    out.push_back(std::move(p));
  }
  for (NotPortable& p : out) {
    p.device = v.name;
    p.what = v.what;
  }
  return out;
}

std::string notPortableMessage(const NotPortable& p) {
  const std::string message =
      "not portable: a device the specification allows (" + p.device +
      (p.what.empty() ? "" : ": " + p.what) + ") would fail " +
      (p.ray >= 0 ? "ray " + std::to_string(p.ray) : std::string("the case")) + " because " +
      p.finding + "; " + p.change + alsoText(p.also);
  if (p.declaration.line > 0) return Error{p.declaration, message}.format();
  if (p.declaration.file.empty()) return visibleText(message);
  return visibleText(p.declaration.file) + ": " + visibleText(message);
}

}  // namespace rayspec
