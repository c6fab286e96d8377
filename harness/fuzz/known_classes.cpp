#include "fuzz/known_classes.h"

#include <algorithm>
#include <sstream>

#include "base/whole_file.h"
#include "fuzz/content_features.h"

namespace rayspec {
namespace {

std::string featureList() {
  std::string list;
  for (const std::string& f : contentFeatureNames()) list += (list.empty() ? "" : ", ") + f;
  return list;
}

}  // namespace

Result<std::vector<KnownClass>> loadKnownClasses(const std::string& path) {
  const Result<std::string> text = readWholeFile(path, uint64_t(1) << 20);
  if (!text) return text.error();
  std::vector<KnownClass> known;
  std::istringstream lines(*text);
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n) {
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    const size_t end = line.find_first_of(" \t", start);
    KnownClass k{line.substr(start, end - start), ""};
    if (end != std::string::npos) {
      const size_t reason = line.find_first_not_of(" \t", end);
      if (reason != std::string::npos) k.reason = line.substr(reason);
    }
    const std::vector<std::string>& features = contentFeatureNames();
    if (std::find(features.begin(), features.end(), k.feature) == features.end())
      return Error{{path, n, int(start) + 1, "feature"},
                   "'" + k.feature + "' is no feature a case's text shows (" + featureList() +
                       ": fuzz/content_features.h)"};
    if (k.reason.empty())
      return Error{{path, n, int(start) + 1, "reason"},
                   "a known class needs its reason after the feature"};
    known.push_back(std::move(k));
  }
  return known;
}

const KnownClass* knownClassOf(const std::vector<KnownClass>& known,
                               const std::set<std::string>& features) {
  for (const KnownClass& k : known)
    if (features.count(k.feature)) return &k;
  return nullptr;
}

}  // namespace rayspec
