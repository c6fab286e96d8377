// pipeline.sbt.record_layout: the shader record block's members, read as
// shader_record.NAME in every stage:
//   record_layout: {layout: scalar, members: {a: uint, b: vec2, c: vec3}}
// layout std430 (default) or scalar; 1 to 8 members of uint, float, vec2,
// vec3 or vec4, in the order written; the block must fit the record's data
// bytes (pipeline.sbt.record_data, read first).
#include "parse/parse_parts.h"
#include "program/locals.h"
#include "program/shader_record_layout.h"

namespace rayspec {
namespace {

constexpr size_t kMaxRecordMembers = 8;

std::optional<ValueType> memberType(const std::string& s) {
  const auto t = valueTypeNamed(s);  // bool and the sized scalars are no member
  return t == ValueType::Bool || (t && isSized(*t)) ? std::nullopt : t;
}

void parseMembers(YamlReader& r, const YAML::Node& n, const std::string& f,
                  ShaderRecordLayout& out) {
  if (!n.IsMap() || n.size() == 0 || n.size() > kMaxRecordMembers) {
    r.error(n, f, "expected a map of 1 to 8 members, name: type (uint, float, vec2, vec3, vec4)");
    return;
  }
  for (auto it = n.begin(); it != n.end(); ++it) {
    RecordMember m;
    m.name = it->first.IsScalar() ? it->first.Scalar() : "?";
    m.loc = r.loc(it->first, f + "." + m.name);
    if (!isLocalName(m.name) || out.find(m.name)) {
      r.error(it->first, f + "." + m.name,
              "a member's name is a lower-case letter, then letters, digits or _, each once");
      continue;
    }
    const auto type = it->second.IsScalar() ? memberType(it->second.Scalar()) : std::nullopt;
    if (!type) {
      r.error(it->second, f + "." + m.name, "a member is uint, float, vec2, vec3 or vec4");
      continue;
    }
    m.type = *type;
    out.members.push_back(std::move(m));
  }
}

}  // namespace

void parseRecordLayout(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  const std::string f = "pipeline.sbt.record_layout";
  if (!r.expectMap(n, f, {"layout", "members"}) || !r.require(n, f, "members")) return;
  ShaderRecordLayout layout;
  if (auto v = YamlReader::get(n, "layout"); v.IsDefined()) {
    const auto name = r.string(v, f + ".layout");
    if (name && *name != "std430" && *name != "scalar")
      r.error(v, f + ".layout", "'" + *name + "': std430 or scalar");
    layout.scalar = name && *name == "scalar";
  }
  parseMembers(r, YamlReader::get(n, "members"), f + ".members", layout);
  layOutShaderRecord(layout);
  if (layout.bytes > p.sbt_record_data) {
    r.error(n, f,
            "the members take " + std::to_string(layout.bytes) + " bytes (" +
                (layout.scalar ? "scalar" : "std430") +
                "), more than the record's data bytes (pipeline.sbt.record_data " +
                std::to_string(p.sbt_record_data) + ")");
    return;
  }
  p.record_layout = std::move(layout);
}

}  // namespace rayspec
