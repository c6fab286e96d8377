// The parts of compareResults, one file each (internal to compare/).
#pragma once

#include <map>
#include <optional>
#include <set>

#include "compare/compare_results.h"
#include "compare/trace_shape.h"
#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {

// undefined_rays: how many rays the model found undefined (R-UB); the counters
// they may have moved (counter_modes.h) are then informational. The model's
// ambiguous rays give each counter the slack their legal answers allow; a
// counter that follows a stage's run count (trace_shape.h) must also agree
// with the device's own per-ray records.
// R-STAGE-INTERFACE: every shader the case expects the compiler to reject
// (the model names them) was rejected on the device side (compare_rejections.cpp).
void compareRejections(const Case& c, const Results& device, const Results& model, Verdict& v);

void compareCounters(const Case& c, const Plan& plan, const Results& device, const Results& model,
                     size_t undefined_rays, Verdict& v);
// `undefined`: rays left out (R-UB), as in compareAnyHitRuns.
void compareRecords(const Case& c, const Plan& plan, const Results& device, const Results& model,
                    const std::set<uint32_t>& undefined, Verdict& v);
// R-AHIT-CLOSEST: with every geometry triangles, a clear ray ran any-hit at
// least as often as the model, which runs it for exactly the candidates every
// device must show it. R-AHIT-DUP: with every geometry NO_DUPLICATE_ANY_HIT (triangles), a ray on
// which the model committed no hit ran any-hit once on every primitive it
// crosses: the device may run it at most that often on the ray.
void compareAnyHitRuns(const Case& c, const Results& device, const Results& model,
                       const std::set<uint32_t>& undefined, Verdict& v);
// masked: the pixels of ambiguous and of undefined rays, left out.
void compareImages(const Plan& plan, const Results& device, const Results& model,
                   const std::set<uint32_t>& masked, Verdict& v);
// Each image pixel of an ambiguous ray (left out of compareImages) against
// the device's own record of the field it shows, where the record has it: a
// device whose image and records disagree lost one of them.
void compareImagesToRecords(const Results& device, const std::set<uint32_t>& rays, Verdict& v);
// Images a case declares equal (`equal_to`): texel for texel in the model
// (else CaseError: the case claims an identity its own reference does not
// have, and the device is not judged on them) and on the device (else Fail).
void compareEqualImages(const Plan& plan, const Results& device, const Results& model, Verdict& v);

// Words of one per-ray record (record_words.cpp).
float asFloat(uint32_t w);
uint32_t fieldWord(const uint32_t* rec, const char* name);
// The record's hit is the legal (or leak) answer k: k is a hit, and every
// identity field the record wrote (primitive, instance, geometry) is k's.
bool hitFits(const uint32_t* rec, const Candidate& k);
// The model's wider t bound of a ray (TBound), 0 when none.
float tBound(const std::map<uint32_t, float>& t_bounds, uint32_t ray);
// What the model widens one ray's tolerances to (Results::t_bounds,
// object_origin_bounds, position_bounds); 0: the field's own tolerance.
struct RayBounds {
  float t = 0;              // hit_t and ray_tmax
  float object_origin = 0;  // object_ray_origin
  float position = 0;       // hit_position: t's bound carried through the direction
  // A free float field (color, color2, color3): the widest of the three
  // where the case carries a bounded built-in into other fields
  // (carriesBoundedBuiltins: a colour of hit_position and hit_t).
  float carried = 0;
};
// Whether some program reads hit_t, ray_tmax, object_ray_origin or
// hit_position other than straight into its own record field: a colour
// (`vec4: [{x: hit_position}, ..., hit_t]`, a payload's colour) then holds
// what the model knows only to the ray's bound (carried_bounds.cpp).
bool carriesBoundedBuiltins(const Case& c);
// The widest of a ray's bounds (RayBounds::carried).
float carriedBound(const RayBounds& b);
// Every ray's bounds as the model gives them (Results::t_bounds,
// object_origin_bounds, position_bounds; the carried one where the case
// carries bounded built-ins), looked up by ray.
class ModelRayBounds {
 public:
  ModelRayBounds(const Case& c, const Results& model);
  RayBounds of(uint32_t ray) const;

 private:
  std::map<uint32_t, float> t_, origin_, position_;
  bool carries_;
};
// Which of a ray's bounds widens a field's tolerance (fieldTolerance): its
// FieldBound's (hit_t and ray_tmax: t, object_ray_origin: the origin's,
// hit_position: the position's), the carried one for a free field (which
// no other bound widens), none for the rest. The C export embeds each
// ray's bounds in this order (export/expectations_section.cpp).
enum class RayBoundSlot { None, T, ObjectOrigin, Position, Carried };
RayBoundSlot boundSlotOf(const RecordField& f);
// The bound of `bounds` in slot s; 0 for None.
float boundIn(const RayBounds& bounds, RayBoundSlot s);
// A float field's tolerance on one ray: its own, its abs widened to the
// ray's bound in the field's slot.
Tolerance fieldTolerance(const RecordField& f, const RayBounds& bounds);
// One field of one ray as the model has it: written alike, and equal (floats
// within the field's tolerance, widened to the ray's bounds).
bool sameField(const RecordField& f, const uint32_t* d, const uint32_t* m, const RayBounds& bounds);

// Whether the device's record `d` is replay r's in every field of `fields`.
bool replayMatches(const LegalReplay& r, const uint32_t* d,
                   const std::vector<const RecordField*>& fields, const RayBounds& bounds);
// An ambiguous ray with its legal answers replayed (RayAmbiguity::replays,
// each with a record): nullptr where the device's record equals one of them
// in every field of `fields` (as sameField compares); else the first field
// in which the nearest of them (fewest fields differing) differs.
const RecordField* fieldNoReplayLeaves(const RayAmbiguity& a, const uint32_t* d,
                                       const std::vector<const RecordField*>& fields,
                                       const RayBounds& bounds);
// Whether the device's record `d` is one of the ray's leak replays
// (RayAmbiguity::leak_replays) in every field of `fields`.
bool leakReplayMatches(const RayAmbiguity& a, const uint32_t* d,
                       const std::vector<const RecordField*>& fields, const RayBounds& bounds);
// Whether the device's record `d` is one of the ray's double-hit replays
// (RayAmbiguity::double_replays) in every field of `fields`.
bool doubleReplayMatches(const RayAmbiguity& a, const uint32_t* d,
                         const std::vector<const RecordField*>& fields, const RayBounds& bounds);
// The exact counters whose slack the replays give (CounterSlack::replayed),
// each within its own range, judged together (counter_moves_together.cpp):
// `device_moves`, each one's device count less the model's, must be the sum
// of one replay's moves per ambiguous ray; a Fail where it is none (nothing
// where the sums are too many to follow).
// A ray whose device record is one of its replays moves the counters only
// as those replays do (the record tells which answer the device took); a
// ray whose record is none of them, or a device without records: nothing.
void checkMovesTogether(const Case& c, const Plan& plan, const Results& device,
                        const std::map<std::string, int64_t>& device_moves, const Results& model,
                        Verdict& v);
// Collects the rays breaking one rule into one finding.
struct FindingBuilder {
  Finding finding;
  void addRay(uint32_t ray) {
    ++finding.ray_count;
    if (finding.rays.size() < kFirstRays) finding.rays.push_back(ray);
  }
  void flush(Verdict& v) {
    if (finding.ray_count) v.add(finding);
  }
};

// What the judge makes of one ambiguous ray's record `d` alone, as
// compareRecords judges it among the case's rays (the C export asks it of
// each answer it embeds, export/expectations_section.cpp): status Pass where
// it breaks no rule, else the finding (a Fail, or R-WATERTIGHT's
// QualityWarning: a leak, a pass between triangles, a double hit) with the
// ray alone. `m`: the model's record of the ray.
class AmbiguousRecordJudge {
 public:
  AmbiguousRecordJudge(const Case& c, const Plan& plan);
  Finding judge(const RayAmbiguity& a, const uint32_t* d, const uint32_t* m,
                const RayBounds& bounds) const;

 private:
  const Case& c_;
  const TraceShape shape_;
  const std::optional<std::set<std::string>> query_reached_;
  const std::vector<const RecordField*> fields_;
};

// A double hit told by any-hit runs (R-WATERTIGHT, a "should";
// compareAnyHitRuns): on a ray through a shared edge or vertex whose
// candidates were all ignored (the model's record m ran no closest-hit nor
// intersection), in a scene of NO_DUPLICATE_ANY_HIT triangles only, the
// model ran any-hit once for each of the h triangles sharing it that it
// decided as hits (one where the mesh is closed); a watertight device runs
// it for one of them, so at most (model - (h - 1)) times in all: that most,
// or nullopt where the ray is not judged so (only where the triangles
// really share the edge, or close a fan around the vertex: on the outer
// border of a mesh hitting two is no rule's break).
std::optional<uint32_t> watertightAnyHitLimit(const Case& c, const RayAmbiguity& a,
                                              const uint32_t* m);
inline constexpr const char* kAnyHitDoubleHit =
    "double hit: any-hit ran for more than one of the triangles sharing an edge or vertex";

// What every legal answer of an ambiguous ray shares (trace_shape.h), each
// broken rule into `wrongs` by rule: raygen ran once; with one trace per ray
// whose answer is the ambiguous one (not a ray query's), one of miss and
// closest-hit (exactly one where each answer runs one), never a miss where no
// answer is one, the identity fields closest-hit records in every program
// never left unwritten; and where no ray query may write the record too, the
// model's own answer with the model's record (its fields, where no any-hit or
// intersection program writes anything); a hit through an edge, vertex or t
// tie at the model's t.
// `fields`: the record fields compared on clear rays.
void checkAmbiguousShared(const Case& c, const TraceShape& shape, const RayAmbiguity& a,
                          const uint32_t* d, const uint32_t* m,
                          const std::vector<const RecordField*>& fields, const RayBounds& bounds,
                          std::map<std::string, FindingBuilder>& wrongs);

}  // namespace rayspec
