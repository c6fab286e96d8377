// What a hit recorded by hand (record_hit, hitObjectRecordHitNV) needs of
// the case: a vec2 hit attribute, which is all it stores
// (hitObjectAttributeNV vec2), and one top level, whose instances its
// instance index names.
#include "parse/parse_parts.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

void checkProgram(YamlReader& r, const Case& c, const Program& p) {
  walkStatements(p, [&](const Stmt& s) {
    if (s.kind != Stmt::Kind::RecordHit) return;
    if (c.pipeline.attribute_words || !c.pipeline.attribute_sized.empty())
      r.error(s.loc,
              "record_hit stores a vec2 attribute, but the hit attribute has more "
              "(pipeline.hit_attribute words or sized members): the shaders it runs would read "
              "words never stored");
    if (c.scene.tlasCount() > 1)
      r.error(s.loc, "record_hit names an instance of the scene's one top level; this scene has " +
                         std::to_string(c.scene.tlasCount()));
  });
}

}  // namespace

void checkRecordHits(YamlReader& r, const Case& c) {
  const Pipeline& p = c.pipeline;
  checkProgram(r, c, p.raygen);
  for (const Program& g : p.other_raygens) checkProgram(r, c, g);
  for (const Program& m : p.miss) checkProgram(r, c, m);
  for (const HitGroup& g : p.hit_groups)
    if (g.closest_hit) checkProgram(r, c, *g.closest_hit);
}

}  // namespace rayspec
