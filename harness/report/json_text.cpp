#include "report/json_text.h"

namespace rayspec {

Result<std::string> jsonText(const nlohmann::json& j, int indent) {
  try {
    return j.dump(indent);
  } catch (const nlohmann::json::exception& e) {  // type_error 316: invalid UTF-8
    return errorOf(ErrorKind::Input, e.what());
  }
}

}  // namespace rayspec
