#include "fault/record_edit.h"

#include <algorithm>
#include <cstring>

#include "plan/walk_program.h"
#include "results/record_layout.h"

namespace rayspec {

uint32_t RecordEdit::rays() const { return static_cast<uint32_t>(r.records.size() / recordWords()); }

bool RecordEdit::written(uint32_t ray, const std::string& field) const {
  const RecordField* f = findRecordField(field);
  if (!f) return false;
  if (f->automatic) return true;
  return (r.records[ray * recordWords() + kRecordWrittenMaskWord] >> recordFieldIndex(field)) & 1u;
}

uint32_t RecordEdit::get(uint32_t ray, const std::string& field) const {
  return r.records[ray * recordWords() + findRecordField(field)->offset];
}

float RecordEdit::getFloat(uint32_t ray, const std::string& field) const {
  const uint32_t w = get(ray, field);
  float f;
  std::memcpy(&f, &w, 4);
  return f;
}

void RecordEdit::set(uint32_t ray, const std::string& field, uint32_t value) {
  const RecordField* f = findRecordField(field);
  uint32_t* rec = &r.records[ray * recordWords()];
  rec[f->offset] = value;
  if (!f->automatic) rec[kRecordWrittenMaskWord] |= 1u << recordFieldIndex(field);
  for (Image& im : r.images) {
    if (im.field != field || ray >= static_cast<size_t>(im.width) * im.height) continue;
    im.texels[static_cast<size_t>(ray) * im.channels] = value;
  }
}

void RecordEdit::setFloat(uint32_t ray, const std::string& field, float value) {
  uint32_t w;
  std::memcpy(&w, &value, 4);
  set(ray, field, w);
}

void RecordEdit::copyRay(uint32_t ray, const Results& from) {
  const size_t words = recordWords();
  std::copy_n(from.records.begin() + ray * words, words, r.records.begin() + ray * words);
  for (Image& im : r.images)
    for (const Image& src : from.images) {
      if (src.name != im.name || src.channels != im.channels || src.texels.size() != im.texels.size()) continue;
      const size_t at = static_cast<size_t>(ray) * im.channels;
      if (at + im.channels <= im.texels.size())
        std::copy_n(src.texels.begin() + at, im.channels, im.texels.begin() + at);
    }
}

std::string RecordEdit::bumpCounter(const std::vector<std::string>& names, int delta) {
  for (const std::string& n : names) {
    auto it = r.counters.find(n);
    if (it == r.counters.end() || (delta < 0 && it->second == 0)) continue;
    it->second = static_cast<uint64_t>(static_cast<int64_t>(it->second) + delta);
    return n;
  }
  return {};
}

std::vector<std::string> countersIn(const Case& c,
                                    const std::function<void(std::function<void(const Program&)>)>& each) {
  std::set<std::string> named;
  each([&](const Program& p) {
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::Count) named.insert(s.counter);
    });
  });
  std::vector<std::string> out;
  for (const std::string& n : c.outputs.counters)
    if (named.count(n)) out.push_back(n);
  return out;
}

std::vector<std::string> missCounters(const Case& c) {
  return countersIn(c, [&](auto visit) {
    for (const Program& p : c.pipeline.miss) visit(p);
  });
}

std::vector<std::string> closestHitCounters(const Case& c) {
  return countersIn(c, [&](auto visit) {
    for (const HitGroup& g : c.pipeline.hit_groups)
      if (g.closest_hit) visit(*g.closest_hit);
  });
}

std::vector<std::string> anyHitCounters(const Case& c) {
  return countersIn(c, [&](auto visit) {
    for (const HitGroup& g : c.pipeline.hit_groups)
      if (g.any_hit) visit(*g.any_hit);
  });
}

std::set<uint32_t> ambiguousRays(const Results& model) {
  std::set<uint32_t> s;
  for (const RayAmbiguity& a : model.ambiguous) s.insert(a.ray);
  return s;
}

}  // namespace rayspec
