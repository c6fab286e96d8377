// The vocabulary as each stage may use it, found by asking the case parser:
// a skeleton case (a triangle and a box, every stage present) with one
// statement put in a stage's place parses or does not. The generator tests
// (tests/glsl_generator_test.cpp) compile every form found here, and
// `rayspec fuzz` (fuzz/generate_case.h) draws its programs from them.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "program/builtins.h"
#include "program/program.h"

namespace rayspec {

// A stage of the skeleton and the key its program stands in for.
struct StageSlot {
  Stage stage;
  const char* key;
};
const std::vector<StageSlot>& skeletonSlots();

// The skeleton case with each stage's program (flow YAML statements) in
// place ({count: c} where none is given).
std::string skeletonCase(const std::map<Stage, std::string>& programs);

// A statement that reads built-in b into local v<i> and folds it into local
// w<i> (so no compiler may drop the read).
std::string readStatement(const BuiltinInfo& b, size_t i);

// The built-ins `stage` may read that parse in the skeleton; those that need
// a case feature the skeleton lacks (payload words, ...) go to *skipped.
std::vector<const BuiltinInfo*> readableBuiltins(Stage stage, std::vector<std::string>* skipped);

// Every operator `stage` may use, with each argument list of one or two
// types (more arguments: one type repeated) that parses, as expression
// texts; operators that parse in no form go to *skipped.
std::vector<std::string> operatorForms(Stage stage, std::vector<std::string>* skipped);

// An operator whose arguments may all be Uint and whose value is a Uint
// (it parses as `record: {value: ...}`), with the argument counts that do.
struct UintOperator {
  std::string name;
  std::vector<int> arities;
};
// Those of `stage`, computed once per stage.
const std::vector<UintOperator>& uintOperators(Stage stage);

}  // namespace rayspec
