// The programs of a generated case: every stage's, drawn from the
// vocabulary as that stage may use it (fuzz/stage_vocabulary.h).
#include <map>
#include <mutex>

#include "fuzz/case_generator.h"
#include "fuzz/stage_vocabulary.h"

namespace rayspec {
namespace {

// The Uint built-ins `stage` reads in the skeleton, but those that need a
// device feature lavapipe lacks or a scene part the generator does not make
// (the cull mask built-in, vertex positions, box data), computed once.
const std::vector<std::string>& uintBuiltins(Stage stage) {
  static std::mutex mutex;
  static std::map<Stage, std::vector<std::string>> found;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = found.find(stage);
  if (it != found.end()) return it->second;
  using namespace builtin_needs;
  std::vector<std::string> names, skipped;
  for (const BuiltinInfo* b : readableBuiltins(stage, &skipped)) {
    if (b->type != ValueType::Uint || (b->needs & (CullMask | PositionFetch | BoxData))) continue;
    names.push_back(builtinSpelling(builtinId(b), 0));  // payload.word<i>: word 0
  }
  return found.emplace(stage, std::move(names)).first->second;
}

}  // namespace

std::string CaseGenerator::uintAtom(Stage stage) {
  const std::vector<std::string>& names = uintBuiltins(stage);
  // Constants from 1: no division by a constant zero.
  if (names.empty() || chance(0.3)) return std::to_string(1 + pick(15));
  return oneOf(names);
}

std::string CaseGenerator::uintExpr(Stage stage, int depth) {
  const std::vector<UintOperator>& operators = uintOperators(stage);
  if (depth <= 0 || operators.empty() || chance(0.35)) return uintAtom(stage);
  const UintOperator& op = oneOf(operators);
  const int arity = oneOf(op.arities);
  // A divisor with its low bit set is never zero: no division by zero
  // (undefined: the model would refuse the case).
  const bool divides = op.name == "div" || op.name == "mod";
  std::string text = "{" + op.name + ": [";
  for (int i = 0; i < arity; ++i) {
    const std::string arg = uintExpr(stage, depth - 1);
    text += (i ? ", " : "") + (divides && i == 1 ? "{bit_or: [" + arg + ", 1]}" : arg);
  }
  return text + "]}";
}

std::string CaseGenerator::condition(Stage stage) {
  if (chance(0.5)) return "{odd: " + uintExpr(stage, 1) + "}";
  return "{lt: [" + uintExpr(stage, 1) + ", " + std::to_string(pick(8)) + "]}";
}

std::string CaseGenerator::raygenProgram() {
  counters_.insert("rg");
  fields_.insert("value");
  std::string p = "[{count: rg}";
  if (chance(0.4)) {
    fields_.insert("value2");
    p += ", {record: {value2: " + uintExpr(Stage::Raygen, 2) + "}}";
  }
  p += ", {trace: {payload: {value: " + uintExpr(Stage::Raygen, 1) +
       "}}}, {record: {value: payload.value}}";
  if (callable_count_ && chance(0.8)) {
    fields_.insert("value3");
    p += ", {call: {index: " + std::to_string(pick(callable_count_)) +
         ", value: " + uintExpr(Stage::Raygen, 1) + "}}, {record: {value3: callee.value}}";
  }
  return p + "]";
}

std::string CaseGenerator::missProgram(Stage stage) {
  counters_.insert("miss");
  fields_.insert("hit");
  return "[{count: miss}, {record: {hit: 0}}, {payload: {value: " + uintExpr(stage, 2) + "}}]";
}

std::string CaseGenerator::closestHitProgram() {
  static const std::vector<std::string> kFields = {"instance_id",    "instance_custom_index",
                                                   "geometry_index", "primitive_id",
                                                   "hit_kind",       "hit_t"};
  counters_.insert("chit");
  fields_.insert("hit");
  std::string fields = "hit";
  for (const std::string& f : kFields)
    if (chance(0.6)) {
      fields += ", " + f;
      fields_.insert(f);
    }
  std::string p = "[{count: chit}, {record: [" + fields +
                  "]}, {payload: {value: " + uintExpr(Stage::ClosestHit, 2) + "}}";
  if (chance(0.5)) {
    fields_.insert("value1");
    p += ", {record: {value1: " + uintExpr(Stage::ClosestHit, 3) + "}}";
  }
  return p + "]";
}

std::string CaseGenerator::anyHitProgram() {
  counters_.insert("ahit");
  std::string p = "[{count: ahit}";
  if (chance(0.3)) {
    features_.insert("any-hit-payload");
    p += ", {payload: {value: {add: [payload.value, " + uintExpr(Stage::AnyHit, 1) + "]}}}";
  }
  const bool terminate = chance(0.35);
  features_.insert(terminate ? "any-hit-terminate" : "any-hit-ignore");
  p += ", {if: " + condition(Stage::AnyHit) + ", then: [" + (terminate ? "terminate" : "ignore") +
       "]}";
  return p + "]";
}

std::string CaseGenerator::intersectionProgram() {
  counters_.insert("isect");
  const auto report = [&] {
    return "{report: {t: " + num(eighths(0.25, 8)) + ", kind: " + std::to_string(pick(128)) + "}}";
  };
  std::string p = "[{count: isect}";
  if (chance(0.5)) {
    features_.insert("conditional-report");
    p += ", {if: " + condition(Stage::Intersection) + ", then: [" + report() + "], else: [" +
         report() + "]}";
  } else {
    p += ", " + report();
  }
  if (chance(0.3)) {
    features_.insert("two-reports");
    p += ", " + report();
  }
  return p + "]";
}

std::string CaseGenerator::callableProgram() {
  counters_.insert("callable");
  return "[{count: callable}, {call_data: {value: " + uintExpr(Stage::Callable, 2) + "}}]";
}

void CaseGenerator::hitGroups() {
  out_ += "  hit_groups:\n";
  for (size_t g = 0; g < hit_groups_; ++g) {
    std::string group;
    const auto add = [&](const std::string& key, const std::string& program) {
      group += (group.empty() ? "" : ", ") + key + ": " + program;
    };
    if (group_aabbs_[g]) add("intersection", intersectionProgram());
    if (chance(0.5)) add("any_hit", anyHitProgram());
    if (chance(0.85)) add("closest_hit", closestHitProgram());
    out_ += "    - {" + group + "}\n";
  }
}

void CaseGenerator::pipeline() {
  callable_count_ = chance(0.4) ? 1 + pick(2) : 0;
  // The payload and callable data types of the skeleton the vocabulary was
  // found in: every word a drawn built-in reads is there.
  out_ += "pipeline:\n  payloads: [{words: 3}]\n  callable_data: [{words: 2}]\n";
  if (callable_count_) features_.insert("callables");
  out_ += "  raygen: " + raygenProgram() + "\n  miss:\n";
  for (size_t m = 0; m < miss_count_; ++m) out_ += "    - " + missProgram(Stage::Miss) + "\n";
  hitGroups();
  if (callable_count_) {
    out_ += "  callables:\n";
    for (size_t k = 0; k < callable_count_; ++k) out_ += "    - " + callableProgram() + "\n";
  }
}

void CaseGenerator::outputs() {
  out_ += "outputs:\n  counters: [";
  bool first = true;
  for (const std::string& c : counters_) {
    out_ += (first ? "" : ", ") + c;
    first = false;
  }
  out_ += "]\n  per_ray: [";
  first = true;
  for (const std::string& f : fields_) {
    out_ += (first ? "" : ", ") + f;
    first = false;
  }
  out_ += "]\n";
}

}  // namespace rayspec
