// The features of generatorFeatures() (fuzz/generate_case.h) that a case's
// text shows, whoever wrote it: what the known bug classes
// (fuzz/known_classes.h) key on, so that a case is classified by what it
// holds, not by the seed it came from (a saved case judged by a build whose
// generator makes another text of that seed is still classified):
//   nan-vertex               a triangle that a NaN vertex X makes inactive
//   nan-box                  a box whose minimum X is NaN
//   inactive-instance        an instance with a null reference
//   first-vertex             geometries built with firstVertex (scene.build.first_vertex)
//   hit-builtin-after-trace  a closest-hit that reads a hit built-in the
//                            nested hit may overwrite (nestedHitBuiltin) after a trace
//   miss-world-ray-beside-empty-group  a hit group without shaders and a miss
//                            program that reads the world ray origin or direction
//   sized-values             a program computes with a value of a sized type
//                            (program/sized_types.h: int8 .. f64vec4, int32,
//                            uvec2 .. uvec4): a local, a struct member, an
//                            array element, a payload or callable data member
//   struct-local             a struct local (struct: {name, members})
// Read from the scene as built and as each update leaves it (case/inactive.h
// says which objects are inactive).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "case/case.h"
#include "program/builtins.h"

namespace rayspec {

// The names above, in generatorFeatures()'s order.
const std::vector<std::string>& contentFeatureNames();

// Those `c` holds.
std::set<std::string> contentFeatures(const Case& c);

// Those the case text `yaml` holds; none when it does not parse (the run
// refuses such a case anyway).
std::set<std::string> contentFeatures(const std::string& yaml);

// A hit built-in whose value lavapipe reads from the nested hit after a
// traceRayEXT that hits (references/driver-reports/lavapipe-builtins-after-nested-trace.md):
// instance_id, instance_custom_index, primitive_id, geometry_index, hit_kind
// and the instance matrices.
bool nestedHitBuiltin(Builtin b);

}  // namespace rayspec
