#include "results/step_cost.h"

namespace rayspec {

double StepCosts::total() const {
  double t = 0;
  for (double s : seconds) t += s;
  return t;
}

StepCosts& StepCosts::operator+=(const StepCosts& other) {
  for (size_t i = 0; i < kCostSteps; ++i) seconds[i] += other.seconds[i];
  return *this;
}

double CaseCost::total() const {
  double t = 0;
  for (const StepCosts& s : sides) t += s.total();
  return t;
}

CaseCost& CaseCost::operator+=(const CaseCost& other) {
  for (size_t i = 0; i < kCostSides; ++i) sides[i] += other.sides[i];
  return *this;
}

double StepTimer::stop() {
  if (!costs_) return 0;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  costs_->add(step_, s);
  costs_ = nullptr;
  return s;
}

}  // namespace rayspec
