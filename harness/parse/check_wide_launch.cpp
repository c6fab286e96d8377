// checkWideLaunch (parse_parts.h): a launch too wide for the model to trace
// id by id reads no launch id.
#include "parse/parse_parts.h"
#include "program/builtins.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

bool readsLaunchId(const Program& p) {
  bool reads = false;
  walkExpressions(p, [&](const Expr& e) {
    reads =
        reads || isBuiltin(e, kBiLaunchX) || isBuiltin(e, kBiLaunchY) || isBuiltin(e, kBiLaunchZ);
  });
  return reads;
}

bool anyReadsLaunchId(const Pipeline& p) {
  bool reads = readsLaunchId(p.raygen);
  for (const Program& g : p.other_raygens) reads = reads || readsLaunchId(g);
  for (const Program& m : p.miss) reads = reads || readsLaunchId(m);
  for (const HitGroup& g : p.hit_groups)
    for (const std::optional<Program>* s : {&g.closest_hit, &g.any_hit, &g.intersection})
      reads = reads || (*s && readsLaunchId(**s));
  for (const Program& k : p.callables) reads = reads || readsLaunchId(k);
  return reads;
}

}  // namespace

void checkWideLaunch(YamlReader& r, const Case& c) {
  if (!c.rays.same || c.rays.launchRays() <= kMaxTracedLaunchIds) return;
  if (!anyReadsLaunchId(c.pipeline)) return;
  SourceLoc at = c.rays.defaults_loc;
  at.field = "rays.launch";
  r.error(at, "a rays.same launch of " + std::to_string(c.rays.launchRays()) +
                  " ids (above 2^24) reads launch_id_x/_y/_z in a program: the model traces "
                  "one id for all ids of such a launch, so its programs may read the launch "
                  "size but not the id");
}

}  // namespace rayspec
