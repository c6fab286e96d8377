// The words and sized members of the hit attribute (pipeline.hit_attribute): what a
// report writes and what any-hit and closest-hit read stay within them, and
// only hit groups with an intersection shader read them.
#include "parse/parse_parts.h"
#include "program/builtins.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

std::string noMember(ValueType t) {
  return std::string(": the hit attribute has no ") + valueTypeSpelling(t) +
         " member (pipeline.hit_attribute.sized)";
}

void reports(YamlReader& r, const Program& p, const Pipeline& pipe) {
  const uint32_t words = pipe.attribute_words;
  walkStatements(p, [&](const Stmt& s) {
    if (s.kind != Stmt::Kind::Report) return;
    for (const auto& [name, value] : s.assigns) {
      if (auto i = payloadWordField(name); i && *i >= words)
        r.error(value.loc, "report " + name + ": the hit attribute has " + std::to_string(words) +
                               " word(s) (pipeline.hit_attribute.words)");
      if (auto t = sizedMemberField(name); t && !holdsSized(pipe.attribute_sized, *t))
        r.error(value.loc, "report " + name + noMember(*t));
    }
  });
}

bool attributeRead(const Expr& e) {
  return isBuiltin(e, kBiAttributeWord) || isBuiltin(e, kBiAttributeSized);
}

void reads(YamlReader& r, const Program& p, const Pipeline& pipe, bool procedural) {
  bool reported = false;
  walkExpressions(p, [&](const Expr& e) {
    if (!attributeRead(e) || reported) return;
    const bool sized = isBuiltin(e, kBiAttributeSized);
    if (!procedural)
      r.error(e.loc, e.name +
                         ": a hit group without an intersection shader hits triangles, whose "
                         "attribute is the barycentrics alone");
    else if (!sized && e.word >= pipe.attribute_words)
      r.error(e.loc, e.name + ": the hit attribute has " + std::to_string(pipe.attribute_words) +
                         " word(s) (pipeline.hit_attribute.words)");
    else if (sized && !holdsSized(pipe.attribute_sized, static_cast<ValueType>(e.word)))
      r.error(e.loc, e.name + noMember(static_cast<ValueType>(e.word)));
    else
      return;
    reported = true;
  });
}

}  // namespace

void checkAttributeWords(YamlReader& r, const Pipeline& p) {
  for (const HitGroup& g : p.hit_groups) {
    if (g.intersection) reports(r, *g.intersection, p);
    for (const auto* prog : {&g.any_hit, &g.closest_hit})
      if (*prog) reads(r, **prog, p, g.intersection.has_value());
  }
}

}  // namespace rayspec
