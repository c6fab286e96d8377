#include "base/error.h"

#include "base/visible_text.h"

namespace rayspec {

std::string Error::format() const {
  if (loc.file.empty()) return visibleText(message);
  std::string s = visibleText(loc.file) + ":" + std::to_string(loc.line) + ":" +
                  std::to_string(loc.column) + ": ";
  if (!loc.field.empty()) s += visibleText(loc.field) + ": ";
  return s + visibleText(message);
}

Error withContext(const std::string& context, const Error& e) {
  Error out = e;
  out.loc = {};
  out.message = context + (e.loc.file.empty() ? e.message : e.format());
  return out;
}

}  // namespace rayspec
