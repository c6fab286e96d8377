#include "fault/record_edit.h"

#include <bit>

#include "fault/program_edit.h"
#include "plan/walk_program.h"
#include "results/record_layout.h"

namespace rayspec {

uint32_t RecordView::rays() const {
  return static_cast<uint32_t>(r.records.size() / recordWords());
}

bool RecordView::written(uint32_t ray, const std::string& field) const {
  const RecordField* f = findRecordField(field);
  if (!f) return false;
  if (f->automatic) return true;
  return rayspec::written(&r.records[ray * recordWords()], recordFieldIndex(field));
}

uint32_t RecordView::get(uint32_t ray, const std::string& field, uint32_t word) const {
  return r.records[ray * recordWords() + findRecordField(field)->offset + word];
}

float RecordView::getFloat(uint32_t ray, const std::string& field, uint32_t word) const {
  return std::bit_cast<float>(get(ray, field, word));
}

void RecordEdit::set(uint32_t ray, const std::string& field, uint32_t value, uint32_t word) {
  const RecordField* f = findRecordField(field);
  uint32_t* rec = &w.records[ray * recordWords()];
  rec[f->offset + word] = value;
  if (!f->automatic) markWritten(rec, f->index);
  for (Image& im : w.images) {
    if (im.field != field || ray >= static_cast<size_t>(im.width) * im.height ||
        word >= im.channels)
      continue;
    im.texels[static_cast<size_t>(ray) * im.channels + word] = value;
  }
}

void RecordEdit::setFloat(uint32_t ray, const std::string& field, float value, uint32_t word) {
  set(ray, field, std::bit_cast<uint32_t>(value), word);
}

std::string RecordEdit::bumpCounter(const std::vector<std::string>& names, int delta) {
  for (const std::string& n : names) {
    auto it = w.counters.find(n);
    if (it == w.counters.end() || (delta < 0 && it->second == 0)) continue;
    it->second = static_cast<uint64_t>(static_cast<int64_t>(it->second) + delta);
    return n;
  }
  return {};
}

std::vector<std::string> countersIn(
    const Case& c, const std::function<void(std::function<void(const Program&)>)>& each) {
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

std::vector<FieldWrite> fieldWrites(const Case& c) {
  std::vector<FieldWrite> out;
  forEachProgram(c.pipeline, [&](const Program& p, Stage stage) {
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind != Stmt::Kind::Record) return;
      for (const auto& [field, value] : s.assigns) out.push_back({stage, field, &value});
    });
  });
  return out;
}

}  // namespace rayspec
