// The pipeline of a generated case (fuzz/generate_case.h): every stage's
// program drawn from the vocabulary as that stage may use it
// (fuzz/stage_vocabulary.h), by the case's seeded sequence. The shapes:
// nested traces from closest-hit and miss within max_recursion (each
// guarded by the depth built-in), calls from every stage that may call,
// if/else, bounded loops, switches and functions, locals read after the
// traces and calls they live across, colours of float expressions that are
// exact in float32 whatever the algorithm and of float built-ins, any-hit
// programs that accumulate (commutative, so legal under duplicates and any
// order) and ignore or terminate on a condition, ray queries with
// confirm/generate/terminate and committed reads, and the traces inlined as
// ray queries (from raygen or a compute shader), and now and then typed live
// state (locals, a struct and an array of the sized types, across the traces,
// calls and reports: generate_typed_state.cpp).
#pragma once

#include <string>
#include <vector>

#include "fuzz/case_generator.h"

namespace rayspec {

class ProgramGenerator {
 public:
  explicit ProgramGenerator(CaseGenerator& g) : g_(g) {}

  // Writes the pipeline block (after the scene and the rays).
  void pipeline();

 private:
  // The stages (generate_programs.cpp).
  std::string raygenProgram();
  std::string missProgram();
  std::string closestHitProgram(bool aabbs);
  std::string anyHitProgram(bool aabbs);
  std::string intersectionProgram();
  std::string callableProgram(size_t index);
  std::string hitGroups();
  std::string functions();
  std::string header();
  bool mayTraceNested() const;

  // The parts (generate_program_parts.cpp): each a statement list without
  // its brackets, ready to join with ", ".
  std::string nestedTrace(Stage stage);
  std::string call(Stage stage, size_t first_callee);
  std::string rayQuery(Stage stage);
  std::string queryCrossing(double tmax);
  std::string queryAfter();
  std::string controlFlow(Stage stage);
  std::string liveLocal(Stage stage, const std::string& across);
  std::string anyHitDecision(bool aabbs);

  // Typed live state (generate_typed_state.cpp), drawn from a stream of its
  // own (CaseGenerator::swapStreams): `before` declares and sets it, `fold`
  // reads all of it back as one Uint; both empty where none is drawn.
  struct TypedState {
    std::string before, fold;
  };
  TypedState typedState(Stage stage);
  std::vector<ValueType> typedTypes() const;
  // The intersection program's reports (`crossing`) with typed state set
  // before them and a last report whose hit kind folds it.
  void typedReports(std::vector<std::string>& crossing);
  // The statement right after a nested trace (its payload folded in), up to
  // the local's name.
  static constexpr const char* kAfterNestedTrace = "{payload: {value: {add: [child.value, var.";

  // Expressions (generate_expressions.cpp).
  std::string floatAtom(Stage stage);
  std::string floatExpr(Stage stage, int depth);
  std::string exactColor(Stage stage);
  std::string vectorComponent(Stage stage, int i);
  std::string builtinColor(Stage stage);
  std::string hitCondition(bool aabbs);

  // Names: a fresh local, a free Uint field to record into.
  std::string local();
  std::string freeField();
  std::string colorField();
  void feature(const std::string& name) { g_.features_.insert(name); }

  CaseGenerator& g_;
  int max_recursion_ = 1;
  bool compute_ = false;  // raygen runs as a compute shader (no callables)
  bool inlined_ = false;  // traces as ray queries (pipeline.traces)
  size_t locals_ = 0, fields_ = 0;
  size_t nested_sites_ = 0;                       // traces in closest-hit and miss programs
  bool uses_fold_ = false, uses_decide_ = false;  // the functions invoked
  bool accumulates_ = false;                      // any-hit counts in payload.word0
  bool colors_ = false;                           // a program writes payload.color
  bool typed_kind_ = false;  // the hit group's intersection reports a kind of typed state
};

}  // namespace rayspec
