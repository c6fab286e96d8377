// Moving a case rigidly by an exact motion.
#include "metamorphic/transform_case.h"

#include <algorithm>
#include <cmath>

#include "metamorphic/motion_spec.h"
#include "results/content_hash.h"

namespace rayspec {
namespace {

bool tracesOnlyTheLaunchRay(const Case& c) {
  const Program& rg = c.pipeline.raygen;
  if (rg.size() != 1 || rg[0].kind != Stmt::Kind::Trace) return false;
  auto traces = [](const Program& p) {
    return std::any_of(p.begin(), p.end(), [](const Stmt& s) {
      return s.kind == Stmt::Kind::Trace || !s.then_.empty() || !s.else_.empty();
    });
  };
  for (const Program& p : c.pipeline.miss)
    if (traces(p)) return false;
  for (const HitGroup& g : c.pipeline.hit_groups)
    for (const auto& p : {g.closest_hit, g.any_hit, g.intersection})
      if (p && traces(*p)) return false;
  return true;
}

// A trace or ray query anywhere that gives its own origin or direction:
// constants in them would not move with the case.
bool setsOwnRay(const Program& p) {
  return std::any_of(p.begin(), p.end(), [](const Stmt& s) {
    const bool traces = s.kind == Stmt::Kind::Trace || s.kind == Stmt::Kind::RayQuery ||
                        s.kind == Stmt::Kind::RestartQuery || s.kind == Stmt::Kind::RecordMiss ||
                        s.kind == Stmt::Kind::RecordHit;
    if (traces && (!s.trace.origin.empty() || !s.trace.direction.empty())) return true;
    return setsOwnRay(s.then_) || setsOwnRay(s.else_);
  });
}

bool anyTraceSetsItsOwnRay(const Case& c) {
  std::vector<const Program*> programs{&c.pipeline.raygen};
  for (const Program& p : c.pipeline.miss) programs.push_back(&p);
  for (const Program& p : c.pipeline.callables) programs.push_back(&p);
  for (const HitGroup& g : c.pipeline.hit_groups)
    for (const auto* p : {&g.closest_hit, &g.any_hit, &g.intersection})
      if (*p) programs.push_back(&**p);
  return std::any_of(programs.begin(), programs.end(),
                     [](const Program* p) { return setsOwnRay(*p); });
}

// a + b, false unless the sum is exact in double (TwoSum's error is zero:
// 1 + 2^60 rounds in double too) and that sum is a float. A NaN or an
// infinity stays what it is (an undefined ray stays undefined).
bool exactSum(float a, double b, float* out) {
  if (!std::isfinite(a)) {
    *out = a;
    return true;
  }
  const double s = double(a) + b;
  const double bb = s - double(a);
  const double error = (double(a) - (s - bb)) + (b - bb);
  *out = static_cast<float>(s);
  return error == 0 && double(*out) == s;
}

}  // namespace

Result<Case> moveCase(const Case& c, const RigidMotion& m, MoveScope scope) {
  std::array<int, 3> seen{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    if (m.axis[k] < 0 || m.axis[k] > 2 || (m.sign[k] != 1 && m.sign[k] != -1)) {
      return errorMessage("the motion is not a signed permutation of the axes");
    }
    ++seen[m.axis[k]];
  }
  if (seen != std::array<int, 3>{1, 1, 1}) {
    return errorMessage("the motion is not a signed permutation of the axes");
  }
  if (scope == MoveScope::SameGeometry && !tracesOnlyTheLaunchRay(c)) {
    return errorMessage(
        "a stage traces rays of its own (or branches): only the launch rays would move");
  }
  if (anyTraceSetsItsOwnRay(c)) {
    return errorMessage(
        "a trace or ray query gives its own origin or direction: only the launch rays would move");
  }
  Case out = c;
  for (Instance& inst : out.scene.instances) {
    const Transform& t = inst.transform;
    Transform n{};
    for (int k = 0; k < 3; ++k) {
      const int row = m.axis[k];
      for (int col = 0; col < 3; ++col) n[k * 4 + col] = m.sign[k] * t[row * 4 + col];
      if (!exactSum(m.sign[k] * t[row * 4 + 3], m.translate[k], &n[k * 4 + 3])) {
        return errorMessage("an instance translation plus the motion's is not exact in float");
      }
    }
    inst.transform = n;
  }
  for (Ray& r : out.rays.rays) {
    Ray n = r;
    for (int k = 0; k < 3; ++k) {
      n.direction[k] = m.sign[k] * r.direction[m.axis[k]];
      if (!exactSum(m.sign[k] * r.origin[m.axis[k]], m.translate[k], &n.origin[k])) {
        return errorMessage("a ray origin plus the motion's translation is not exact in float");
      }
    }
    r = n;
  }
  // A saved device bundle of the moved case is told from the unmoved one's.
  const std::string motion = "move " + motionSpecText(m);
  out.source_hash = contentHash(c.source_hash, motion.data(), motion.size());
  return out;
}

}  // namespace rayspec
