// The words of the hit attribute (pipeline.hit_attribute.words): what a
// report writes and what any-hit and closest-hit read stay within them, and
// only hit groups with an intersection shader read them.
#include "parse/parse_parts.h"
#include "program/builtins.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

void reports(YamlReader& r, const Program& p, uint32_t words) {
  walkStatements(p, [&](const Stmt& s) {
    if (s.kind != Stmt::Kind::Report) return;
    for (const auto& [name, value] : s.assigns)
      if (auto i = payloadWordField(name); i && *i >= words)
        r.error(value.loc, "report " + name + ": the hit attribute has " + std::to_string(words) +
                               " word(s) (pipeline.hit_attribute.words)");
  });
}

void reads(YamlReader& r, const Program& p, uint32_t words, bool procedural) {
  bool reported = false;
  walkExpressions(p, [&](const Expr& e) {
    if (!isBuiltin(e, kBiAttributeWord) || reported) return;
    if (!procedural)
      r.error(e.loc, e.name +
                         ": a hit group without an intersection shader hits triangles, whose "
                         "attribute is the barycentrics alone");
    else if (e.word >= words)
      r.error(e.loc, e.name + ": the hit attribute has " + std::to_string(words) +
                         " word(s) (pipeline.hit_attribute.words)");
    else
      return;
    reported = true;
  });
}

}  // namespace

void checkAttributeWords(YamlReader& r, const Pipeline& p) {
  for (const HitGroup& g : p.hit_groups) {
    if (g.intersection) reports(r, *g.intersection, p.attribute_words);
    for (const auto* prog : {&g.any_hit, &g.closest_hit})
      if (*prog) reads(r, **prog, p.attribute_words, g.intersection.has_value());
  }
}

}  // namespace rayspec
