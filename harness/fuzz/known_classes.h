// Known driver bug classes a fuzz finding may belong to, by what its case
// holds: a file of lines `FEATURE REASON` (a feature its text shows,
// contentFeatureNames() of fuzz/content_features.h, so that a saved case
// made by another generator is classified as well; the reason names the
// baseline entry or driver report), `#` comments. A finding whose case holds a known
// class's feature is counted apart, as probably that bug, and does not
// fail the fuzz run: a coarse match (another bug in such a case hides
// behind it), said so in fuzz.txt.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "base/result.h"

namespace rayspec {

struct KnownClass {
  std::string feature, reason;
};

// The classes of `path`; an error names the file, line and field.
Result<std::vector<KnownClass>> loadKnownClasses(const std::string& path);

// The first class whose feature the case holds (nullptr: none).
const KnownClass* knownClassOf(const std::vector<KnownClass>& known,
                               const std::set<std::string>& features);

}  // namespace rayspec
