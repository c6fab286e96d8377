// Callable data types by location (pipeline.callable_data) and the
// callables, each of which may name the location whose data type it takes:
//   callable_data: [{}, {words: 4, sized: [int16]}]  # location 0, location 1
//   callables: [[...], {call_data: 1, program: [...]}]
// A call names its location with `call: {location: k}` (parse_program.cpp).
#include "parse/parse_parts.h"

namespace rayspec {
namespace {

const WordTypes kCallDataTypes{"pipeline.callable_data", "callable data", kMaxCallDataLocations,
                               kMaxCallDataWords};

}  // namespace

void parseCallDataTypes(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  parseWordTypes(r, n, kCallDataTypes, p.call_data_words, p.call_data_sized);
}

void parseCallables(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  if (!r.expectSeq(n, "pipeline.callables")) return;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string f = "pipeline.callables[" + std::to_string(i) + "]";
    Program prog;
    uint32_t location = 0;
    if (n[i].IsMap() && YamlReader::has(n[i], "program")) {
      if (r.expectMap(n[i], f, {"program", "call_data"})) {
        parseProgram(r, YamlReader::get(n[i], "program"), f + ".program", prog);
        if (auto v = YamlReader::get(n[i], "call_data"); v.IsDefined())
          location =
              parseWordLocation(r, v, f + ".call_data", kCallDataTypes, p.call_data_words.size())
                  .value_or(0);
      }
    } else {
      parseProgram(r, n[i], f, prog);
    }
    p.callables.push_back(std::move(prog));
    p.callable_data.push_back(location);
  }
}

}  // namespace rayspec
