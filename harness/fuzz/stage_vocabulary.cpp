#include "fuzz/stage_vocabulary.h"

#include <algorithm>
#include <mutex>

#include "parse/parse_case.h"
#include "program/ops.h"

namespace rayspec {
namespace {

// A triangle (hit group 0: any-hit, closest-hit) and a box (hit group 1:
// intersection, any-hit, closest-hit); raygen traces and calls callable 0.
// The programs stand where the keys are.
const char* kSkeleton = R"(rules: [R-BUILTIN]
description: generated
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
        flags: []
    ball:
      - aabbs: [[-1, -1, -1, 1, 1, 1]]
        flags: []
  instances:
    - {blas: tri}
    - {blas: ball, transform: {translate: [10, 0, 0]}, sbt_offset: 1}
rays:
  list:
    - {origin: [0, 0, 3], direction: [0, 0, -1]}
pipeline:
  payloads: [{words: 3}]
  callable_data: [{words: 2}]
  raygen: [RAYGEN, {trace: {}}, {call: {index: 0}}]
  miss:
    - [MISS]
  hit_groups:
    - any_hit: [ANY_HIT]
      closest_hit: [CLOSEST_HIT]
    - intersection: [INTERSECTION, {report: {t: 1.5, kind: 1}}]
      any_hit: [ANY_HIT]
      closest_hit: [CLOSEST_HIT]
  callables:
    - [CALLABLE]
outputs:
  counters: [c]
)";

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

bool parses(Stage stage, const std::string& statement) {
  return parseCaseText(skeletonCase({{stage, statement}}), "gen/probe.yaml", "gen/probe")
      .value.has_value();
}

// One expression of each value type, readable in every stage.
const std::pair<ValueType, const char*> kTypedArgs[] = {
    {ValueType::Uint, "{add: [launch_id_x, 3]}"},
    {ValueType::Float, "{float: launch_id_y}"},
    {ValueType::Vec2, "{vec2: [{float: launch_id_x}, 0.5]}"},
    {ValueType::Vec3, "{vec3: [1.0, {float: launch_id_x}, 2.0]}"},
    {ValueType::Vec4, "{vec4: [1.0, 2.0, {float: launch_size_x}, 4.0]}"},
    {ValueType::Bool, "{lt: [launch_id_x, 2]}"},
};

std::string formText(const OpInfo& op, const std::vector<const char*>& args) {
  if (args.empty()) return op.name;
  std::string text = "{" + std::string(op.name) + ": [";
  for (size_t i = 0; i < args.size(); ++i) text += (i ? ", " : "") + std::string(args[i]);
  return text + "]}";
}

// The argument lists of op to try: none, then one or two types (more
// arguments: one type repeated).
std::vector<std::vector<const char*>> argumentLists(const OpInfo& op) {
  std::vector<std::vector<const char*>> lists;
  if (op.min_args == 0) lists.push_back({});
  for (const auto& a : kTypedArgs)
    for (int n = std::max(op.min_args, 1); n <= std::min(op.max_args, 4); ++n) {
      if (n == 2) {
        for (const auto& b : kTypedArgs) lists.push_back({a.second, b.second});
        continue;
      }
      lists.push_back(std::vector<const char*>(static_cast<size_t>(n), a.second));
    }
  return lists;
}

std::vector<UintOperator> findUintOperators(Stage stage) {
  std::vector<UintOperator> out;
  const char* uint_arg = kTypedArgs[0].second;
  for (const OpInfo& op : ops()) {
    if (!(op.stages & stageBit(stage))) continue;
    UintOperator u{op.name, {}};
    for (int n = std::max(op.min_args, 1); n <= std::min(op.max_args, 3); ++n) {
      const std::string form = formText(op, std::vector<const char*>(size_t(n), uint_arg));
      // A bit operation with a Uint built-in parses only where the value is a Uint.
      if (parses(stage, "{let: {v0: " + form + "}}, {let: {w0: {bit_xor: [var.v0, launch_id_x]}}}"))
        u.arities.push_back(n);
    }
    if (!u.arities.empty()) out.push_back(std::move(u));
  }
  return out;
}

}  // namespace

const std::vector<StageSlot>& skeletonSlots() {
  static const std::vector<StageSlot> slots = {{Stage::Raygen, "RAYGEN"},
                                               {Stage::Miss, "MISS"},
                                               {Stage::AnyHit, "ANY_HIT"},
                                               {Stage::ClosestHit, "CLOSEST_HIT"},
                                               {Stage::Intersection, "INTERSECTION"},
                                               {Stage::Callable, "CALLABLE"}};
  return slots;
}

std::string skeletonCase(const std::map<Stage, std::string>& programs) {
  std::string text = kSkeleton;
  for (const StageSlot& s : skeletonSlots()) {
    const auto it = programs.find(s.stage);
    text = replaceAll(text, s.key, it == programs.end() ? "{count: c}" : it->second);
  }
  return text;
}

std::string readStatement(const BuiltinInfo& b, size_t i) {
  const std::string v = "v" + std::to_string(i);
  const std::string name = builtinSpelling(builtinId(&b), 0);  // payload.word<i>: word 0
  std::string folded;
  switch (b.type) {
    case ValueType::Uint:
      folded = "{add: [var." + v + ", 1]}";
      break;
    case ValueType::Float:
      folded = "{add: [var." + v + ", 1.0]}";
      break;
    case ValueType::Vec2:
      folded = "{x: var." + v + "}";
      break;
    default:  // vec3, vec4
      folded = "{y: var." + v + "}";
      break;
  }
  return "{let: {" + v + ": " + name + "}}, {let: {w" + std::to_string(i) + ": " + folded + "}}";
}

std::vector<const BuiltinInfo*> readableBuiltins(Stage stage, std::vector<std::string>* skipped) {
  std::vector<const BuiltinInfo*> out;
  for (const BuiltinInfo& b : builtins()) {
    if (!(b.stages & stageBit(stage))) continue;
    if (parses(stage, readStatement(b, 0)))
      out.push_back(&b);
    else
      skipped->push_back(std::string(b.name));
  }
  return out;
}

std::vector<std::string> operatorForms(Stage stage, std::vector<std::string>* skipped) {
  std::vector<std::string> out;
  for (const OpInfo& op : ops()) {
    if (!(op.stages & stageBit(stage))) continue;
    size_t found = 0;
    for (const auto& args : argumentLists(op)) {
      const std::string text = formText(op, args);
      if (parses(stage, "{let: {v0: " + text + "}}")) {
        out.push_back(text);
        ++found;
      }
    }
    if (!found) skipped->push_back(op.name);
  }
  return out;
}

const std::vector<UintOperator>& uintOperators(Stage stage) {
  static std::mutex mutex;
  static std::map<Stage, std::vector<UintOperator>> found;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = found.find(stage);
  if (it == found.end()) it = found.emplace(stage, findUintOperators(stage)).first;
  return it->second;
}

}  // namespace rayspec
