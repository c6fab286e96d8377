// The one list of the fields of a per-ray record. Everything else is generated
// from it: the record layout (results/record_layout.h: offsets, the written
// mask's width), each field's tolerance (results/tolerances.h), the rule a
// mismatch of it points at (compare/compare_records.cpp) and which fields the
// judge reads as the hit, as free data or as counts that depend on traversal
// order.
//
// X(name, type, words, written, kind, "rule", tolerance, widened by, "meaning"):
//   type, words: Uint or Float, 1..4 components;
//   written: Bit, a field a case writes (`record: {name: ...}`), whose index
//     is its bit in the written mask; Auto, a count the harness keeps in every
//     record, which has none. Every Bit row comes before the first Auto row;
//   kind: Plain; HitIdentity, what the judge reads as the hit itself (which
//     primitive of which geometry and instance, at which t: a case records
//     only the built-in of the same name there); Free, what a program
//     computes (no built-in fills it); Traversal, a count that depends on
//     traversal order and duplicate any-hit runs (never compared word for
//     word with the model's);
//   rule: the rule a mismatch of the field points at when no rule the case
//     claims is evidenced by it (compare/finding_rules.h);
//   tolerance: Exact (Uint), Field, Barycentric or Color (base/error_bounds.h);
//   widened by: the model's per-ray bound that widens the tolerance (NoBound,
//     TBound, OriginBound, PositionBound: results/results.h).
#pragma once

#define RAYSPEC_RECORD_FIELDS(X)                                                                   \
  X(hit, Uint, 1, Bit, Plain, "R-MISS-XOR-CHIT", Exact, NoBound, "1 where the ray hit, 0 a miss")  \
  X(instance_id, Uint, 1, Bit, HitIdentity, "R-BUILTIN", Exact, NoBound, "the hit's instance")     \
  X(instance_custom_index, Uint, 1, Bit, Plain, "R-BUILTIN", Exact, NoBound,                       \
    "the hit instance's custom index")                                                             \
  X(geometry_index, Uint, 1, Bit, HitIdentity, "R-BUILTIN", Exact, NoBound,                        \
    "the hit's geometry in its bottom level")                                                      \
  X(primitive_id, Uint, 1, Bit, HitIdentity, "R-BUILTIN", Exact, NoBound,                          \
    "the hit's primitive in its geometry")                                                         \
  X(hit_kind, Uint, 1, Bit, Plain, "R-HITKIND-TRI", Exact, NoBound,                                \
    "the hit's kind (a triangle's face, or an intersection's report)")                             \
  X(hit_t, Float, 1, Bit, HitIdentity, "R-PREC", Field, TBound, "the hit's t")                     \
  X(barycentrics, Float, 2, Bit, Plain, "R-BUILTIN", Barycentric, NoBound,                         \
    "the hit's barycentrics on its triangle")                                                      \
  X(ray_tmin, Float, 1, Bit, Plain, "R-TMAX-VIEW", Field, NoBound, "the ray's tmin")               \
  X(ray_tmax, Float, 1, Bit, Plain, "R-TMAX-VIEW", Field, TBound,                                  \
    "the ray's tmax as the stage sees it")                                                         \
  X(incoming_ray_flags, Uint, 1, Bit, Plain, "R-BUILTIN", Exact, NoBound, "the ray's flags")       \
  X(world_ray_origin, Float, 3, Bit, Plain, "R-BUILTIN", Field, NoBound,                           \
    "the ray's origin in world space")                                                             \
  X(world_ray_direction, Float, 3, Bit, Plain, "R-BUILTIN", Field, NoBound,                        \
    "the ray's direction in world space")                                                          \
  X(object_ray_origin, Float, 3, Bit, Plain, "R-BUILTIN", Field, OriginBound,                      \
    "the ray's origin in the hit instance's space")                                                \
  X(object_ray_direction, Float, 3, Bit, Plain, "R-BUILTIN", Field, NoBound,                       \
    "the ray's direction in the hit instance's space")                                             \
  X(hit_position, Float, 3, Bit, Plain, "R-BUILTIN", Field, PositionBound,                         \
    "the hit's position (a triangle's, fetched or computed)")                                      \
  X(depth, Uint, 1, Bit, Plain, "R-RECURSION", Exact, NoBound, "the trace's recursion depth")      \
  X(value, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "a number the program computes")       \
  X(color, Float, 4, Bit, Free, "R-PAYLOAD", Color, NoBound, "a colour the program computes")      \
  X(color2, Float, 4, Bit, Free, "R-PAYLOAD", Color, NoBound, "a second colour")                   \
  X(value1, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "a second number")                    \
  X(value2, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "a third number")                     \
  X(value3, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "a fourth number")                    \
  X(value4, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "a fifth number")                     \
  X(value5, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "a sixth number")                     \
  X(value6, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "a seventh number")                   \
  X(value7, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "an eighth number")                   \
  /* Free fields beyond value7 and color2 (issue 43: loops folded their                         */ \
  /* results into single numbers).                                                              */ \
  X(value8, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "a ninth number")                     \
  X(value9, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "a tenth number")                     \
  X(value10, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "an eleventh number")                \
  X(value11, Uint, 1, Bit, Free, "R-PAYLOAD", Exact, NoBound, "a twelfth number")                  \
  /* color3 keeps the field tolerance color and color2 do not (as it was)                       */ \
  X(color3, Float, 4, Bit, Free, "R-PAYLOAD", Field, NoBound, "a third colour")                    \
  X(raygen_runs, Uint, 1, Auto, Plain, "R-BUILTIN", Exact, NoBound, "raygen runs for the ray")     \
  X(miss_runs, Uint, 1, Auto, Plain, "R-MISS-XOR-CHIT", Exact, NoBound, "miss runs for the ray")   \
  X(closest_hit_runs, Uint, 1, Auto, Plain, "R-MISS-XOR-CHIT", Exact, NoBound,                     \
    "closest-hit runs for the ray")                                                                \
  X(any_hit_runs, Uint, 1, Auto, Traversal, "R-BUILTIN", Exact, NoBound,                           \
    "any-hit runs for the ray")                                                                    \
  X(intersection_runs, Uint, 1, Auto, Traversal, "R-BUILTIN", Exact, NoBound,                      \
    "intersection runs for the ray")                                                               \
  X(callable_runs, Uint, 1, Auto, Plain, "R-CALLABLE", Exact, NoBound,                             \
    "callable runs for the ray")                                                                   \
  X(any_hit_slots, Uint, 1, Auto, Traversal, "R-BUILTIN", Exact, NoBound,                          \
    "bit anyHitSlot(instance, geometry, primitive) of each primitive any-hit ran on")              \
  X(any_hit_repeats, Uint, 1, Auto, Traversal, "R-BUILTIN", Exact, NoBound,                        \
    "those bits again where any-hit ran on the primitive twice (R-AHIT-DUP)")
