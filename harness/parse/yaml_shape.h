// The shape every YAML document rayspec reads is held to before a reader
// walks it: how many nodes it expands to, following its aliases, and how
// deep it nests. An alias is the very node of its anchor, so an anchor that
// holds an alias of itself nests without end, and a few lines of aliases can
// expand to 2^40 nodes; both are found here, in bounded time and without
// recursion, and reported where they start.
#pragma once

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <optional>
#include <string>

namespace rayspec {

// The case files of this repository expand to at most a few thousand nodes
// and nest 18 deep.
constexpr size_t kMaxYamlNodes = 1'000'000;
constexpr size_t kMaxYamlDepth = 100;

struct YamlShapeProblem {
  std::string message;
  YAML::Mark mark;  // where the walk stopped (line/column of the node, 0-based)
};

// nullopt when the document is within kMaxYamlNodes and kMaxYamlDepth.
std::optional<YamlShapeProblem> yamlShapeProblem(const YAML::Node& root);

// The message for yaml-cpp's own nesting limit (YAML::DeepRecursion, which
// yaml-cpp 0.7 words as "bad file").
std::string yamlTooDeepMessage();

}  // namespace rayspec
