#include "parse/yaml_shape.h"

#include <utility>
#include <vector>

namespace rayspec {
namespace {

YAML::Mark markOf(const YAML::Node& n) {
  try {
    return n.Mark();
  } catch (const YAML::Exception&) {
    return YAML::Mark::null_mark();
  }
}

}  // namespace

std::optional<YamlShapeProblem> yamlShapeProblem(const YAML::Node& root) {
  std::vector<std::pair<YAML::Node, size_t>> stack{{root, 0}};
  size_t nodes = 0;
  while (!stack.empty()) {
    const auto [n, depth] = stack.back();
    stack.pop_back();
    if (++nodes > kMaxYamlNodes)
      return YamlShapeProblem{"the document expands to more than " + std::to_string(kMaxYamlNodes) +
                                  " nodes through its aliases (*name repeats the whole node "
                                  "of &name): write it out, or use a sweep",
                              markOf(n)};
    if (depth > kMaxYamlDepth)
      return YamlShapeProblem{"the document nests deeper than " + std::to_string(kMaxYamlDepth) +
                                  " levels (an alias inside its own anchor, *name within "
                                  "&name, nests without end)",
                              markOf(n)};
    if (n.IsSequence()) {
      for (auto it = n.begin(); it != n.end(); ++it) stack.emplace_back(*it, depth + 1);
    } else if (n.IsMap()) {
      for (auto it = n.begin(); it != n.end(); ++it) {
        stack.emplace_back(it->first, depth + 1);
        stack.emplace_back(it->second, depth + 1);
      }
    }
  }
  return std::nullopt;
}

std::string yamlTooDeepMessage() {
  return "the document nests deeper than the YAML reader allows (yaml-cpp stops at 500 levels "
         "of maps and lists; rayspec reads at most " +
         std::to_string(kMaxYamlDepth) + ")";
}

}  // namespace rayspec
