#include "report/case_cost.h"

#include <algorithm>
#include <cstdio>

#include "base/whole_file.h"
#include "bundle/step_cost_json.h"
#include "report/json_text.h"

namespace rayspec {
namespace {

constexpr CostSide kSides[] = {CostSide::Parent, CostSide::Model, CostSide::Device};

double wallSeconds(const std::vector<CaseOutcome>& outcomes) {
  double s = 0;
  for (const CaseOutcome& o : outcomes) s += o.seconds;
  return s;
}

}  // namespace

nlohmann::json caseCostJson(const CaseCost& cost) {
  nlohmann::json j = nlohmann::json::object();
  for (CostSide side : kSides) j[costSideName(side)] = costJson(cost[side]);
  return j;
}

Result<CaseCost> caseCostFromJson(const nlohmann::json& j) {
  CaseCost cost;
  for (const auto& item : j.items()) {
    const std::string name = item.key();  // not a structured binding: clang 14 cannot capture one
    const auto side = std::find_if(std::begin(kSides), std::end(kSides),
                                   [&name](CostSide s) { return name == costSideName(s); });
    if (side == std::end(kSides)) return errorMessage("cost: unknown side '" + name + "'");
    RAYSPEC_TRY(cost[*side], costFromJson(item.value()));
  }
  return cost;
}

Result<void> writeCaseCost(const CaseOutcome& o, const std::string& path) {
  nlohmann::json j = caseCostJson(o.cost);
  j["case"] = o.name;
  j["seconds"] = o.seconds;
  j["accounted"] = o.cost.total();
  RAYSPEC_TRY(const std::string text, jsonText(j, 1));
  return writeWholeFile(path, text + '\n');
}

CaseCost runCost(const std::vector<CaseOutcome>& outcomes) {
  CaseCost sum;
  for (const CaseOutcome& o : outcomes) sum += o.cost;
  return sum;
}

nlohmann::json runCostJson(const std::vector<CaseOutcome>& outcomes) {
  const CaseCost sum = runCost(outcomes);
  nlohmann::json j = caseCostJson(sum);
  StepCosts by_step;
  for (const StepCosts& s : sum.sides) by_step += s;
  j["by_step"] = costJson(by_step);
  j["seconds"] = wallSeconds(outcomes);
  j["accounted"] = sum.total();
  return j;
}

std::string runCostText(const std::vector<CaseOutcome>& outcomes) {
  const CaseCost sum = runCost(outcomes);
  struct Line {
    CostSide side;
    CostStep step;
    double seconds;
  };
  std::vector<Line> lines;
  for (CostSide side : kSides)
    for (size_t i = 0; i < kCostSteps; ++i)
      if (sum[side].seconds[i] > 0)
        lines.push_back({side, static_cast<CostStep>(i), sum[side].seconds[i]});
  std::sort(lines.begin(), lines.end(),
            [](const Line& a, const Line& b) { return a.seconds > b.seconds; });
  const double wall = wallSeconds(outcomes);
  std::string text;
  char row[160];
  std::snprintf(row, sizeof row,
                "Where the time went: %.2f s of cases' wall time, %.2f s accounted for by steps\n",
                wall, sum.total());
  text += row;
  for (const Line& l : lines) {
    std::snprintf(row, sizeof row, "  %-7s %-18s %10.3f s %5.1f%%\n", costSideName(l.side),
                  costStepName(l.step), l.seconds, wall > 0 ? 100.0 * l.seconds / wall : 0.0);
    text += row;
  }
  return text;
}

}  // namespace rayspec
