// Why a device the specification allows fails a case (a false alarm of the
// judge, mutate/legal_devices.h), as the declaration of the case to change:
//   a counter declared `exact` (or `at_least` / `at_most`) that the device
//                  moves: proved by judging the device again with that
//                  declaration left out, which must then pass;
//   aabb-neighbours, aabb-near  an intersection program (or a ray query's aabb block)
//                  that reports without testing its box: a conservative AABB
//                  test (R-AABB-CONS) runs it for boxes the ray misses;
//   another candidate order (reverse-order, permuted-order-<k>, last-<i>.<g>.<p>)
//                  a block that decides by the order its candidates come in
//                  (R-ORDER-UNSPEC) where the model saw no such dependence;
//   any-hit or an intersection program run twice (R-AHIT-DUP, R-ISECT-MULTI)
//                  a program whose writes depend on how often it runs;
//   another legal answer of an ambiguous ray (answer-<j>, replay-<j>,
//                  pass-between-edges)  the ray's declaration;
//   tolerance-bound  a value the case derives exactly from a float a device
//                  may round otherwise.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "case/case.h"
#include "compare/verdict.h"
#include "mutate/legal_devices.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

// One reason a legal device fails a case.
struct NotPortable {
  std::string device;             // the legal device (answer-1, aabb-neighbours, last-0.0.1, ...)
  std::string what;               // what that device does
  int64_t ray = -1;               // the first ray it fails (-1: none named, a counter)
  std::string finding;            // why the judge fails it: "RULE: message" of its failing finding
  SourceLoc declaration;          // the declaration to change (its file at least; line 0: unknown)
  std::string change;             // what is wrong with it and how to change it
  std::vector<std::string> also;  // other legal devices that fail for the same declaration
};

// The reasons `v` (a legal device the judge fails with `verdict`) fails `c`:
// the declared counter modes it breaks, if any, then what its kind of
// device says about the rest (none more when leaving those modes out makes
// it pass). `base`: the model's own answers as a device (perfectDevice).
std::vector<NotPortable> notPortableCauses(const Case& c, const Plan& plan, const Results& model,
                                           const Results& base, const LegalVariant& v,
                                           const Verdict& verdict);

// "FILE:LINE:COL: FIELD: not portable: a device the specification allows
// (NAME: WHAT) would fail ray R because FINDING; CHANGE" (FILE: ... when the
// line is unknown; "the case" when no ray is named; "(also A, B)" after
// CHANGE for the other devices), made visible (base/visible_text.h).
std::string notPortableMessage(const NotPortable& p);

}  // namespace rayspec
