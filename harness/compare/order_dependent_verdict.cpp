#include "compare/order_dependent_verdict.h"

namespace rayspec {

bool judgeOrderDependence(const Results& model, Verdict& v) {
  if (model.order_dependent.empty()) return true;
  std::string what;
  for (const std::string& o : model.order_dependent) what += (what.empty() ? "" : "; ") + o;
  v.add({Status::CaseError,
         "R-ORDER-UNSPEC",
         "order-dependent: " + what +
             "; a case must not depend on the order candidates arrive in: make the blocks "
             "decide alike in every order, or give the ray fewer candidates",
         {},
         0});
  return false;
}

}  // namespace rayspec
