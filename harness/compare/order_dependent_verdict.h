// R-ORDER-UNSPEC: a case whose candidate programs leave different answers
// behind in different orders of more candidates than the model's exact tier
// enumerates (Results::order_dependent, model/candidate_orders.h) cannot be
// judged: the model cannot list its legal answers. Like any-hit repetition
// (any_hit_repeat_verdict.h) it is diagnosed, not judged: CaseError
// "order-dependent", naming each block and its file:line. (Up to the bound,
// order-dependent rays are ambiguous instead, with every order's answer.)
#pragma once

#include "case/case.h"
#include "compare/verdict.h"
#include "results/results.h"

namespace rayspec {

// Returns true when the comparison goes on.
bool judgeOrderDependence(const Results& model, Verdict& v);

}  // namespace rayspec
