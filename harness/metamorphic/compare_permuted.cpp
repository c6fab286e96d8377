#include "metamorphic/compare_permuted.h"

#include <bit>
#include <map>
#include <set>

#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {
namespace {

constexpr uint32_t kUnknown = ~0u;

// A ray's answer in the original's ids; a primitive led back through every
// geometry it could belong to (one when the record says which).
struct Answer {
  bool hit_known = false, hit = false;
  uint32_t instance = kUnknown, geometry = kUnknown;
  std::set<uint32_t> primitives;  // empty: not recorded
};

class Records {
 public:
  explicit Records(const Results& r) : r_(r), words_(recordWords()) {}
  bool has(uint32_t ray) const {
    return !r_.records.empty() && (ray + 1) * size_t{words_} <= r_.records.size();
  }
  const uint32_t* of(uint32_t ray) const { return r_.records.data() + size_t{ray} * words_; }
  bool written(uint32_t ray, const char* field) const {
    return rayspec::written(of(ray), recordFieldIndex(field));
  }
  uint32_t word(uint32_t ray, const char* field) const {
    return of(ray)[findRecordField(field)->offset];
  }

 private:
  const Results& r_;
  uint32_t words_;
};

Answer originalAnswer(const Records& rec, uint32_t ray) {
  Answer a;
  if ((a.hit_known = rec.written(ray, "hit"))) a.hit = rec.word(ray, "hit") != 0;
  if (rec.written(ray, "instance_id")) a.instance = rec.word(ray, "instance_id");
  if (rec.written(ray, "geometry_index")) a.geometry = rec.word(ray, "geometry_index");
  if (rec.written(ray, "primitive_id")) a.primitives.insert(rec.word(ray, "primitive_id"));
  return a;
}

Answer ledBack(const CasePermutation& p, const Records& rec, uint32_t ray) {
  Answer a;
  if ((a.hit_known = rec.written(ray, "hit"))) a.hit = rec.word(ray, "hit") != 0;
  uint32_t instance_new = kUnknown;
  if (rec.written(ray, "instance_id")) {
    instance_new = rec.word(ray, "instance_id");
    a.instance = instance_new < p.instance_of.size() ? p.instance_of[instance_new] : instance_new;
  }
  if (rec.written(ray, "geometry_index")) a.geometry = rec.word(ray, "geometry_index");
  if (!rec.written(ray, "primitive_id")) return a;
  const uint32_t primitive_new = rec.word(ray, "primitive_id");
  const std::vector<Instance>& instances = p.permuted.scene.instances;
  std::set<uint32_t> blases;
  if (instance_new < instances.size() && instances[instance_new].blas)
    blases.insert(*instances[instance_new].blas);
  if (instance_new == kUnknown)
    for (const Instance& i : instances)
      if (i.blas) blases.insert(*i.blas);
  for (uint32_t b : blases) {
    if (b >= p.primitive_of.size()) continue;
    for (uint32_t g = 0; g < p.primitive_of[b].size(); ++g) {
      if (a.geometry != kUnknown && g != a.geometry) continue;
      const std::vector<uint32_t>& old_of = p.primitive_of[b][g];
      a.primitives.insert(primitive_new < old_of.size() ? old_of[primitive_new] : primitive_new);
    }
  }
  return a;
}

bool legal(const Answer& a, const Candidate& k) {
  if (a.hit_known && a.hit != k.hit) return false;
  if (!k.hit) return !a.hit_known || !a.hit;
  if (a.instance != kUnknown && a.instance != k.instance) return false;
  if (a.geometry != kUnknown && a.geometry != k.geometry) return false;
  return a.primitives.empty() || a.primitives.count(k.primitive) != 0;
}

std::string describe(const Answer& a) {
  std::string s = !a.hit_known ? "hit ?" : a.hit ? "hit" : "miss";
  if (a.instance != kUnknown) s += " instance " + std::to_string(a.instance);
  if (a.geometry != kUnknown) s += " geometry " + std::to_string(a.geometry);
  if (!a.primitives.empty()) {
    s += " primitive";
    for (uint32_t p : a.primitives) s += " " + std::to_string(p);
  }
  return s;
}

// The first field of a clear ray's record that moved, or "".
std::string movedField(const CasePermutation& p, const Records& orig, const Records& perm,
                       uint32_t ray) {
  const uint32_t* a = orig.of(ray);
  const uint32_t* b = perm.of(ray);
  if (!sameWrittenMask(a, b)) return "the fields written";
  for (const RecordField& f : recordFields()) {
    const bool written = f.automatic || orig.written(ray, f.name);
    if (!written) continue;
    const std::string name = f.name;
    // Keyed by instance, geometry and primitive index, which the permutation renumbers.
    if (name == "any_hit_slots" || name == "any_hit_repeats") continue;
    if (name == "instance_id" || name == "primitive_id") {
      const Answer led = ledBack(p, perm, ray);
      const bool same = name == "instance_id" ? led.instance == a[f.offset]
                                              : led.primitives.count(a[f.offset]) != 0;
      if (!same) return name;
      continue;
    }
    for (uint32_t k = 0; k < f.words; ++k) {
      const uint32_t x = a[f.offset + k], y = b[f.offset + k];
      const bool same =
          f.type == FieldType::Float
              ? toleranceFor(name).matches(std::bit_cast<float>(y), std::bit_cast<float>(x))
              : x == y;
      if (!same) return name;
    }
  }
  return {};
}

}  // namespace

std::vector<std::string> comparePermuted(const CasePermutation& p, const Results& original,
                                         const Results& permuted, size_t limit) {
  std::vector<std::string> out;
  auto note = [&](std::string line) {
    if (out.size() < limit) out.push_back(std::move(line));
  };
  const std::string seed = "seed " + std::to_string(p.seed) + ": ";
  if (!original.ok() || !permuted.ok()) {
    note(seed + "status " + original.statusText() + " / " + permuted.statusText());
    return out;
  }
  std::set<uint32_t> undefined_a, undefined_b;
  for (const UndefinedRay& u : original.undefined) undefined_a.insert(u.ray);
  for (const UndefinedRay& u : permuted.undefined) undefined_b.insert(u.ray);
  for (uint32_t ray : undefined_a)
    if (!undefined_b.count(ray))
      note(seed + "ray " + std::to_string(ray) + " undefined only in the original");
  for (uint32_t ray : undefined_b)
    if (!undefined_a.count(ray))
      note(seed + "ray " + std::to_string(ray) + " undefined only in the permutation");
  std::map<uint32_t, const RayAmbiguity*> ambiguous;
  for (const RayAmbiguity& a : original.ambiguous) ambiguous[a.ray] = &a;
  const Records orig(original), perm(permuted);
  const uint32_t rays = original.width * original.height;
  for (uint32_t ray = 0; ray < rays; ++ray) {
    if (undefined_a.count(ray) || !orig.has(ray) || !perm.has(ray)) continue;
    const std::string which = seed + "ray " + std::to_string(ray) + ": ";
    if (const auto it = ambiguous.find(ray); it != ambiguous.end()) {
      const Answer led = ledBack(p, perm, ray);
      bool ok = false;
      for (const Candidate& k : it->second->candidates) ok = ok || legal(led, k);
      if (!ok)
        note(which + "ambiguous (" + ambiguityReasonName(it->second->reason) +
             "), the permutation answers " + describe(led) + ", not a legal answer");
      continue;
    }
    if (const std::string field = movedField(p, orig, perm, ray); !field.empty())
      note(which + "clear, " + field + " moved: " + describe(originalAnswer(orig, ray)) +
           " became " + describe(ledBack(p, perm, ray)));
  }
  if (original.ambiguous.empty() && original.undefined.empty() &&
      original.counters != permuted.counters)
    note(seed + "the counters moved");
  return out;
}

}  // namespace rayspec
