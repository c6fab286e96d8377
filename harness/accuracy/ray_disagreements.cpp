#include "accuracy/ray_disagreements.h"

#include <bit>
#include <map>
#include <set>

#include "compare/shared_edge.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

struct Fields {
  uint32_t words = recordWords();
  int hit = recordFieldIndex("hit"), prim = recordFieldIndex("primitive_id"),
      inst = recordFieldIndex("instance_id"), geom = recordFieldIndex("geometry_index"),
      t = recordFieldIndex("hit_t");
  uint32_t chit = findRecordField("closest_hit_runs")->offset,
           ahit = findRecordField("any_hit_runs")->offset;
  uint32_t offset(int index) const { return recordFields()[index].offset; }
};

// Closest-hit ran, or any-hit saw a candidate, or the stages recorded hit = 1.
bool found(const Fields& f, const uint32_t* rec) {
  return rec[f.chit] > 0 || rec[f.ahit] > 0 || (written(rec, f.hit) && rec[f.offset(f.hit)] == 1);
}

bool hit(const Fields& f, const uint32_t* rec) {
  return rec[f.chit] > 0 || (written(rec, f.hit) && rec[f.offset(f.hit)] == 1);
}

// One id both records hold differs.
bool differentIds(const Fields& f, const uint32_t* a, const uint32_t* b) {
  for (int index : {f.prim, f.inst, f.geom})
    if (written(a, index) && written(b, index) && a[f.offset(index)] != b[f.offset(index)])
      return true;
  return false;
}

// The record's ids (those written) match one of the legal hits.
bool legalHit(const Fields& f, const uint32_t* rec, const RayAmbiguity& a) {
  for (const Candidate& k : a.candidates) {
    if (!k.hit) continue;
    if ((!written(rec, f.prim) || rec[f.offset(f.prim)] == k.primitive) &&
        (!written(rec, f.inst) || rec[f.offset(f.inst)] == k.instance) &&
        (!written(rec, f.geom) || rec[f.offset(f.geom)] == k.geometry))
      return true;
  }
  return false;
}

// A miss on this ambiguous ray leaks through a closed surface: it crosses
// an edge or vertex that triangles share, or no legal answer is a miss and
// (with the case at hand) the ray does not only cross the outer border of a
// mesh, where a miss is legal whatever the candidates say (as the case's own
// verdict judges it, compare/compare_records.cpp).
bool closedCrossing(const RayAmbiguity& a, const Case* c) {
  bool miss_legal = false;
  for (const Candidate& k : a.candidates) miss_legal = miss_legal || !k.hit;
  if (c) {
    if (crossesSharedEdge(*c, a) || sharedCrossing(*c, a).triangles >= 2) return true;
    return !miss_legal && !crossesBorderOnly(*c, a);
  }
  return !miss_legal || a.shared_triangles.size() >= 2;
}

}  // namespace

void Disagreements::add(const Disagreements& o) {
  rays += o.rays;
  disagreeing += o.disagreeing;
  leaks += o.leaks;
  double_hits += o.double_hits;
  other_primitive += o.other_primitive;
  extra_hits += o.extra_hits;
  t.add(o.t);
}

Disagreements countDisagreements(const Results& exact, const Results& other, const Case* c) {
  Disagreements d;
  const Fields f;
  if (exact.records.size() != other.records.size() || exact.width != other.width ||
      exact.height != other.height)
    return d;
  std::map<uint32_t, const RayAmbiguity*> ambiguous;
  for (const RayAmbiguity& a : exact.ambiguous) ambiguous[a.ray] = &a;
  std::set<uint32_t> undefined;
  for (const UndefinedRay& u : exact.undefined) undefined.insert(u.ray);
  const size_t rays = exact.records.size() / f.words;
  for (size_t i = 0; i < rays; ++i) {
    const uint32_t ray = static_cast<uint32_t>(i);
    if (undefined.count(ray)) continue;
    const uint32_t* e = &exact.records[i * f.words];
    const uint32_t* o = &other.records[i * f.words];
    const auto it = ambiguous.find(ray);
    const RayAmbiguity* a = it == ambiguous.end() ? nullptr : it->second;
    ++d.rays;
    bool disagrees = false;
    if (found(f, e) && !found(f, o) && (!a || closedCrossing(*a, c))) {
      ++d.leaks;
      disagrees = true;
    }
    if (!found(f, e) && found(f, o) && !a) {
      ++d.extra_hits;
      disagrees = true;
    }
    if (e[f.ahit] == 1 && o[f.ahit] > 1) {
      ++d.double_hits;
      disagrees = true;
    }
    if (hit(f, e) && hit(f, o)) {
      const bool different = differentIds(f, e, o);
      if (different && (!a || !legalHit(f, o, *a))) {
        ++d.other_primitive;
        disagrees = true;
      }
      // A hit within rounding of tmin (a ray that starts on a surface): its t
      // is that rounding itself, near 0, where a ULP of t_exact is no scale
      // for a device's error (one float step of the coordinates is millions
      // of them). Left out of the t errors; its answer is still checked above.
      const bool tmin_tie = a && a->reason == AmbiguityReason::TminTie;
      if (!different && !tmin_tie && written(e, f.t) && written(o, f.t))
        d.t.add(ulpError(std::bit_cast<float>(o[f.offset(f.t)]),
                         std::bit_cast<float>(e[f.offset(f.t)])));
    }
    d.disagreeing += disagrees;
  }
  return d;
}

}  // namespace rayspec
