#include "reduce/operand_sites.h"

#include "program/ops.h"

namespace rayspec {
namespace {

// The operator's name when n is one ({name: operands}, a single key naming an op).
const OpInfo* operatorOf(const YAML::Node& n) {
  if (!n.IsMap() || n.size() != 1) return nullptr;
  const auto it = n.begin();
  if (!it->first.IsScalar() || it->second.IsMap() || it->second.IsNull()) return nullptr;
  return findOp(it->first.Scalar());
}

void collect(std::vector<OperandSite>& sites, const YAML::Node& root, const YamlPath& path) {
  const YAML::Node n = nodeAt(root, path);
  if (operatorOf(n)) {
    const YAML::Node args = n.begin()->second;
    sites.push_back({path, args.IsSequence() ? args.size() : 1});
  }
  if (n.IsSequence()) {
    for (size_t i = 0; i < n.size(); ++i) collect(sites, root, plus(path, i));
  } else if (n.IsMap()) {
    for (auto it = n.begin(); it != n.end(); ++it)
      if (it->first.IsScalar()) collect(sites, root, plus(path, it->first.Scalar()));
  }
}

}  // namespace

std::vector<OperandSite> operandSites(const YAML::Node& root) {
  std::vector<OperandSite> sites;
  collect(sites, root, {{false, 0, "pipeline"}});
  return sites;
}

YAML::Node operandOf(const YAML::Node& root, const OperandSite& site, size_t i) {
  const YAML::Node args = nodeAt(root, site.path).begin()->second;
  return args.IsSequence() ? args[i] : args;
}

}  // namespace rayspec
