// The any-hit / intersection protocol (hit_protocol.h).
#include "model/hit_protocol.h"

#include <cmath>

#include "case/flag_names.h"
#include "model/sphere_error.h"
#include "model/stage_interpreter.h"
#include "model/traversal.h"

namespace rayspec {

using namespace trace_detail;

namespace {

// The flags of the geometry a candidate belongs to.
uint32_t geometryFlags(const ModelScene& scene, const ModelCandidate& c) {
  return scene.blases[scene.instances[c.instance].blas].geometries[c.geometry].flags;
}

bool isSphereRootExpr(const CExpr& e) {
  return e.kind == Expr::Kind::Op && (e.op == Op::SphereNear || e.op == Op::SphereFar);
}

// The sphere root a report's t is: sphere_near or sphere_far itself, or the
// max or min of one and an exact operand (a literal or ray_tmin), which moves
// by no more than the root does (the generator's {max: [sphere_near,
// ray_tmin]}); nullptr for any other t.
const CExpr* sphereRootOf(const CExpr& t) {
  if (isSphereRootExpr(t)) return &t;
  if (t.kind != Expr::Kind::Op || (t.op != Op::Max && t.op != Op::Min) || t.args.size() != 2)
    return nullptr;
  const auto exact = [](const CExpr& e) {
    return e.kind == Expr::Kind::Literal || (e.kind == Expr::Kind::Builtin && e.builtin == kBiTmin);
  };
  for (size_t k = 0; k < 2; ++k)
    if (isSphereRootExpr(t.args[k]) && exact(t.args[1 - k])) return &t.args[k];
  return nullptr;
}

// A report at a bare root (whose t may round across an interval end on a
// device; a max or min clamps it), or at one within a max or min (whose t a
// device's rounding of the root moves as far, and no farther).
bool reportsSphereRoot(const CStmt& s, const StageEnv& env) {
  return isSphereRoot(s) && env.hit && env.ray;
}
bool reportsBoundedRoot(const CStmt& s, const StageEnv& env) {
  return sphereRootOf(s.t) && env.hit && env.ray;
}

}  // namespace

void HitProtocol::runIntersection(Traversal& tr, const ModelCandidate& cand, size_t k, bool opaque,
                                  const SbtRecord* rec, const CHitGroup* grp) {
  const TraceRay& r = tr.ray;
  HitView hv = viewOf(*sh_.scene, *sh_.c, r, cand.instance, cand.geometry, cand.primitive);
  tr.cur = &cand;
  tr.cur_index = k;
  tr.cur_opaque = opaque;
  if (tr.reports) tr.reports->push_back({k, NAN});  // it ran (the exact tier's tie check)
  tr.sphere_ord = 0;
  tr.report_ord = 0;
  tr.cur_rec = rec;
  tr.cur_group = grp;
  st_.bumpRuns(kRunsIntersection);
  StageEnv env = hitStage(Stage::Intersection, rec->data, nullptr, r, hv,
                          static_cast<float>(tr.reportTmax()), tr.depth);
  env.traversal = &tr;
  interp_.exec(*grp->intersection, env);
  tr.cur = nullptr;
}

Flow HitProtocol::runAnyHit(const CProgram& p, StageEnv& a, const HitView& hv,
                            uint32_t geometry_flags) {
  if (!sh_.fault_seam.ignoreDiscardsWrites()) return runAnyHitRepeated(p, a, hv, geometry_flags);
  // Planted: an ignoring invocation's writes are lost.
  const LaunchState::Saved before = st_.save();
  const Flow f = runAnyHitRepeated(p, a, hv, geometry_flags);
  if (f == Flow::Ignore) st_.restore(before);
  return f;
}

Flow HitProtocol::runAnyHitRepeated(const CProgram& p, StageEnv& a, const HitView& hv,
                                    uint32_t geometry_flags) {
  st_.markAnyHit(hv);
  const Flow first = interp_.exec(p, a);
  const AnyHitRepeat repeat = sh_.any_hit_repeat;
  if (first == Flow::Terminate || repeat == AnyHitRepeat::None ||
      (geometry_flags & kGeometryNoDuplicateAnyHit) ||
      (repeat == AnyHitRepeat::First && st_.repeated_any_hit))
    return first;
  st_.repeated_any_hit = true;
  st_.markAnyHit(hv);
  return interp_.exec(p, a);
}

double HitProtocol::sphereRootError(const CStmt& s, const HitView& h, const TraceRay& ray) const {
  const ModelInstance& mi = sh_.scene->instances[h.instance];
  const SphereError se = sphereError(h.aabb_min, h.aabb_max, h.object_origin, h.object_direction,
                                     objectRayError(mi.inverse_f, ray.origin, ray.direction));
  return sphereRootOf(s.t)->op == Op::SphereNear ? se.near_err : se.far_err;
}

bool HitProtocol::reportInside(const CStmt& s, StageEnv& env, Traversal& tr, float t) {
  // R-ISECT-REPORT, R-CAND-AABB-CLOSED: tmin <= t <= current tmax.
  const double tmax = tr.reportTmax();
  bool inside = t >= tr.ray.tmin && static_cast<double>(t) <= tmax;
  if (sh_.fault_seam.openAabbInterval()) inside = t > tr.ray.tmin && static_cast<double>(t) < tmax;
  if (tr.reports && t >= tr.ray.tmin && t <= tr.ray.tmax + tr.tol(t))
    tr.reports->push_back({tr.cur_index, t});
  if (tr.exact) {
    // R-PREC: a sphere root within its error bound of an interval end may
    // fall on either side on a device; the current tmax is a committed t
    // (a root) of its own error. Against the current candidate's own
    // committed report, only past it: the device orders its own roots as
    // the model does, but they coincide where its discriminant rounds to 0
    // (then sphere_far = sphere_near, at tmax: inside; fuzz seed 111014 on
    // NVIDIA reported its far root so).
    const uint32_t ord = tr.report_ord++;
    if (const ShaderDecision* f = tr.forced(1, ord)) {
      inside = f->value;
    } else if (tr.shader_unsure && reportsSphereRoot(s, env)) {
      const HitView& h = *env.hit;
      const double et = sphereRootError(s, h, *env.ray) + tr.tol(t);
      const double committed_err = tr.best.valid ? tr.best.t_err : 0.0;
      const bool own = tr.best.valid && tr.best.instance == h.instance &&
                       tr.best.geometry == h.geometry && tr.best.primitive == h.primitive;
      const bool near_end = std::fabs(double(t) - tr.ray.tmin) <= et ||
                            ((!own || double(t) > tr.tmax_cur) &&
                             std::fabs(double(t) - tr.tmax_cur) <= et + committed_err);
      if (near_end) tr.shader_unsure->push_back({tr.cur_index, 1, ord, inside});
    }
  }
  // What-if run of another order (R-TIE), as for a triangle: a report at the
  // committed t dropped before its any-hit (Keep: the device's t a step past
  // its tmax), or confirmed, its any-hit run (R-CAND-AABB-CLOSED: t = tmax is
  // inside), then replacing the committed hit or dropped (report).
  if (tr.exact && tr.tie != TieRule::Model && t >= tr.ray.tmin && tr.ties(t))
    inside = tr.tie != TieRule::Keep;
  // What-if run preferring one candidate (R-TIE): it wins every tie, and a
  // committed preferred hit loses none.
  if (tr.prefer >= 0 && t >= tr.ray.tmin && tr.ties(t)) {
    if (tr.cur_index == static_cast<size_t>(tr.prefer))
      inside = true;
    else if (tr.isPreferred(tr.best.instance, tr.best.geometry, tr.best.primitive))
      inside = false;
  }
  return inside;
}

void HitProtocol::commitReport(const CStmt& s, StageEnv& env, Traversal& tr, const HitView& hv,
                               float t, uint32_t kind) {
  tr.best = {true, static_cast<double>(t), hv.instance, hv.geometry, hv.primitive, kind, hv.b1,
             hv.b2};
  tr.best.words = hv.words;
  tr.best.sized = hv.sized;
  // R-PREC: how far a device's root may lie from this one.
  if (tr.exact && reportsBoundedRoot(s, env)) tr.best.t_err = sphereRootError(s, hv, *env.ray);
  if (!tr.inlined.commit_keeps_interval) tr.tmax_cur = t;
  env.tmax_view = t;
}

// A legal device's conservative AABB test: a report or generate for a box
// the model's own ray misses (mutate/not_portable_cause.cpp names it).
void HitProtocol::noteMissedBox(const CStmt& s, const Traversal& tr) const {
  if (!tr.cur || !tr.cur->missed || !s.src) return;
  if (sh_.fault_seam.aabbNeighboursRun() || sh_.fault_seam.nearBoxesOffered())
    st_.missedBoxReport(s.src->loc);
}

// Exact tier: the t of a box's leading report, wherever it lies (the
// counter floors' any-hit of it, counter_floors.cpp).
void HitProtocol::noteLeadReport(const CStmt& s, const StageEnv& env, Traversal& tr,
                                 float t) const {
  if (!tr.lead_reports || !tr.cur_group || &s != tr.cur_group->leading_report) return;
  const double err = reportsBoundedRoot(s, env) ? sphereRootError(s, *env.hit, *env.ray) : 0.0;
  tr.lead_reports->push_back({tr.cur_index, static_cast<double>(t), err});
}

// What a report gives the hit attribute: its words and sized members (the
// planted fault sized_attribute_halved: each member with half its bits).
void HitProtocol::reportedAttribute(const CStmt& s, StageEnv& env, HitView& hv) {
  for (const CAssign& a : s.assigns) {
    const Val v = interp_.eval(a.value, env);
    if (a.slot == Slot::Sized)
      hv.sized.write(static_cast<ValueType>(a.word), v);
    else
      hv.words[a.word % kMaxAttributeWords] = v.u;
  }
  if (sh_.fault_seam.sizedAttributeHalvedToCandidate()) halveMembers(hv.sized);
}

Flow HitProtocol::report(const CStmt& s, StageEnv& env) {
  Traversal* tr = env.traversal;
  if (!tr || !tr->cur) return Flow::Continue;
  const Val tv = interp_.eval(s.t, env);
  const float t = s.t.type == ValueType::Uint ? static_cast<float>(tv.u) : tv.f[0];
  const uint32_t kind = interp_.eval(s.hit_kind, env).u;
  noteLeadReport(s, env, *tr, t);
  Val attr;
  if (s.has_attribute) attr = interp_.eval(s.attribute, env);
  bool accepted = false;
  if (reportInside(s, env, *tr, t)) {
    noteMissedBox(s, *tr);
    HitView hv = *env.hit;
    setHit(hv, t, kind, attr.f[0], attr.f[1]);
    reportedAttribute(s, env, hv);
    Flow ah = Flow::Continue;
    if (!tr->cur_opaque && tr->cur_group && tr->cur_group->any_hit) {
      // R-TMAX-VIEW: any-hit sees the candidate's t.
      st_.checkPayloadType(*tr->payload, tr->cur_group->payload, "pipeline.hit_groups",
                           *tr->cur_rec->group, ".any_hit");
      StageEnv a =
          hitStage(Stage::AnyHit, tr->cur_rec->data, tr->payload, tr->ray, hv, t, tr->depth);
      ah = runAnyHit(*tr->cur_group->any_hit, a, hv, geometryFlags(*sh_.scene, *tr->cur));
    }
    if (ah != Flow::Ignore) {
      accepted = true;
      // Planted, inlined: the loop's generate commits nothing, its report
      // still true; so a what-if run's confirmed report at the committed t
      // it drops (R-TIE, Traversal::confirmDrops).
      if (!tr->inlined.generate_ignored && !tr->confirmDrops(t))
        commitReport(s, env, *tr, hv, t, kind);
      if (ah == Flow::Terminate || (tr->flags & kRayTerminateOnFirstHit)) {
        tr->stop = !tr->inlined.terminate_ignored;
        return Flow::Terminate;  // R-TERMINATE: the intersection program stops too
      }
    }
  }
  return interp_.exec(accepted ? s.then_ : s.else_, env);
}

bool HitProtocol::sphereHitDecision(Traversal& tr, const HitView& h, bool model_value, float disc) {
  if (!tr.exact || !tr.cur) return model_value;
  const uint32_t ord = tr.sphere_ord++;
  if (const ShaderDecision* f = tr.forced(0, ord)) return f->value;
  if (tr.shader_unsure) {
    const ModelInstance& mi = sh_.scene->instances[h.instance];
    const SphereError se =
        sphereError(h.aabb_min, h.aabb_max, h.object_origin, h.object_direction,
                    objectRayError(mi.inverse_f, tr.ray.origin, tr.ray.direction));
    if (std::fabs(double(disc)) <= se.disc_err)
      tr.shader_unsure->push_back({tr.cur_index, 0, ord, model_value});
  }
  return model_value;
}

}  // namespace rayspec
