#include "base/generated_part.h"

namespace rayspec {

Result<std::string> withGeneratedPart(const std::string& doc, const std::string& begin,
                                      const std::string& end, const std::string& part) {
  const size_t b = doc.find(begin);
  const size_t e = b == std::string::npos ? b : doc.find(end, b + begin.size());
  if (e == std::string::npos)
    return errorMessage("the document lacks the lines " + begin + " and " + end);
  std::string out = doc;
  const size_t from = b + begin.size();
  out.replace(from, e - from, "\n" + part);
  return out;
}

}  // namespace rayspec
