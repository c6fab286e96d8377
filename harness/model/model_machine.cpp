// The stage-program interpreter of the model (the meaning of every statement,
// built-in and op; program/program.h, builtins.h, ops.h).
#include "model/model_machine.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "model/model_shading.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

uint32_t fbits(float f) { uint32_t u; std::memcpy(&u, &f, 4); return u; }
float bitsf(uint32_t u) { float f; std::memcpy(&f, &u, 4); return f; }

Val fromVec3(const Vec3& v) { Val r; r.f = {v[0], v[1], v[2], 0}; return r; }
Val fromVec4(const std::array<float, 4>& v) { Val r; r.f = v; return r; }
Val fromUint(uint32_t u) { Val r; r.u = u; return r; }
Val fromFloat(float f) { Val r; r.f[0] = f; return r; }

bool isVec(ValueType t) { return t == ValueType::Vec2 || t == ValueType::Vec3 || t == ValueType::Vec4; }

std::vector<SbtRecord> defaults(size_t n) {
  std::vector<SbtRecord> v(n);
  for (size_t i = 0; i < n; ++i) v[i].group = static_cast<uint32_t>(i);
  return v;
}

}  // namespace

Machine::Machine(const ModelShared& shared, uint32_t* records) : sh_(shared), records_(records) {
  counters.assign(sh_.plan->counters.size(), 0);
  const Pipeline& p = sh_.c->pipeline;
  default_miss_ = p.sbt_miss.empty() ? defaults(p.miss.size()) : p.sbt_miss;
  default_hit_ = p.sbt_hit.empty() ? defaults(p.hit_groups.size()) : p.sbt_hit;
  default_callable_ = p.sbt_callable.empty() ? defaults(p.callables.size()) : p.sbt_callable;
  const char* runs[6] = {"raygen_runs", "miss_runs", "closest_hit_runs", "any_hit_runs",
                         "intersection_runs", "callable_runs"};
  for (int k = 0; k < 6; ++k) runs_offset_[k] = findRecordField(runs[k])->offset;
}

void Machine::bumpRuns(int which) {
  if (rec_) rec_[runs_offset_[which]] += 1;
}

namespace {
const char* const kBuiltinNames[] = {
    "launch_id_x", "launch_id_y", "launch_size_x", "launch_size_y", "primitive_id", "instance_id",
    "instance_custom_index", "geometry_index", "hit_kind", "hit_t", "hit", "barycentrics",
    "aabb_min", "aabb_max", "object_ray_origin", "object_ray_direction", "ray_tmin", "ray_tmax",
    "incoming_ray_flags", "world_ray_origin", "world_ray_direction", "hit_position",
    "payload.color", "payload.value", "depth", "child.color", "child.value", "call.position",
    "call.normal", "call.color", "call.value", "callee.color", "callee.value"};
enum IdKind { kIdBuiltin = 1, kIdField = 2, kIdCounter = 3 };
}  // namespace

// Names resolved once per address (the case outlives the run), so the
// interpreter compares no strings on the hot path.
int Machine::cachedId(const std::string* key, int kind) {
  IdSlot& slot = id_cache_[(reinterpret_cast<uintptr_t>(key) >> 3) & (id_cache_.size() - 1)];
  if (slot.key == key && slot.kind == kind) return slot.id;
  int id = -1;
  if (kind == kIdBuiltin) {
    for (size_t i = 0; i < sizeof(kBuiltinNames) / sizeof(kBuiltinNames[0]); ++i)
      if (*key == kBuiltinNames[i]) id = static_cast<int>(i);
  } else if (kind == kIdField) {
    id = recordFieldIndex(*key);
  } else {
    const auto& names = sh_.plan->counters;
    const auto it = std::find(names.begin(), names.end(), *key);
    if (it != names.end()) id = static_cast<int>(it - names.begin());
  }
  slot = {key, kind, id};
  return id;
}

void Machine::record(const std::string& field, const Val& v, ValueType t) {
  if (!rec_) return;
  const int idx = cachedId(&field, kIdField);
  if (idx < 0) return;
  const RecordField& f = recordFields()[idx];
  if (f.automatic) return;
  if (f.type == FieldType::Uint) {
    rec_[f.offset] = t == ValueType::Float ? static_cast<uint32_t>(v.f[0]) : v.u;
  } else {
    for (uint32_t k = 0; k < f.words; ++k)
      rec_[f.offset + k] = fbits(t == ValueType::Uint && k == 0 ? static_cast<float>(v.u) : v.f[k]);
  }
  rec_[kRecordWrittenMaskWord] |= 1u << idx;
}

Val Machine::builtin(const std::string& n, StageEnv& env) {
  static const HitView kNone;
  static const TraceRay kNoRay;
  static const Payload kNoPayload;
  static const CallData kNoCall;
  const HitView* hv = env.hit ? env.hit : &kNone;
  const TraceRay* r = env.ray ? env.ray : &kNoRay;
  const Payload* pl = env.payload ? env.payload : &kNoPayload;
  const CallData* cd = env.call ? env.call : &kNoCall;
  switch (cachedId(&n, kIdBuiltin)) {
    case 0: return fromUint(x_);
    case 1: return fromUint(y_);
    case 2: return fromUint(sh_.c->rays.width);
    case 3: return fromUint(sh_.c->rays.height);
    case 4: return fromUint(hv->primitive);
    case 5: return fromUint(hv->instance);
    case 6: return fromUint(hv->custom_index);
    case 7: return fromUint(hv->geometry);
    case 8: return fromUint(hv->hit_kind);
    case 9: return fromFloat(hv->t);
    case 10: return fromUint(env.stage == Stage::ClosestHit ? 1u : 0u);
    case 11: { Val v; v.f = {hv->b1, hv->b2, 0, 0}; return v; }
    case 12: return fromVec3(hv->aabb_min);
    case 13: return fromVec3(hv->aabb_max);
    case 14: return fromVec3(hv->object_origin);
    case 15: return fromVec3(hv->object_direction);
    case 16: return fromFloat(r->tmin);
    case 17: return fromFloat(env.tmax_view);
    case 18: return fromUint(r->flags);
    case 19: return fromVec3(r->origin);
    case 20: return fromVec3(r->direction);
    case 21: {
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = r->origin[k] + hv->t * r->direction[k];
      return fromVec3(p);
    }
    case 22: return fromVec4(pl->color);
    case 23: return fromUint(pl->value);
    case 24: return fromUint(env.depth);
    case 25: return fromVec4(env.child.color);
    case 26: return fromUint(env.child.value);
    case 27: return fromVec3(cd->position);
    case 28: return fromVec3(cd->normal);
    case 29: return fromVec4(cd->color);
    case 30: return fromUint(cd->value);
    case 31: return fromVec4(env.callee.color);
    case 32: return fromUint(env.callee.value);
    default: break;
  }
  if (error.empty()) error = "model: unknown built-in '" + n + "'";
  return Val{};
}

Val Machine::eval(const Expr& e, StageEnv& env) {
  switch (e.kind) {
    case Expr::Kind::Literal: {
      Val v;
      if (e.type == ValueType::Uint) v.u = static_cast<uint32_t>(e.literal.empty() ? 0 : e.literal[0]);
      else if (e.type == ValueType::Bool) v.b = !e.literal.empty() && e.literal[0] != 0;
      else
        for (size_t k = 0; k < e.literal.size() && k < 4; ++k) v.f[k] = static_cast<float>(e.literal[k]);
      return v;
    }
    case Expr::Kind::Builtin: return builtin(e.name, env);
    case Expr::Kind::Op: return op(e, env);
  }
  return Val{};
}

Val Machine::op(const Expr& e, StageEnv& env) {
  const std::string& n = e.name;
  if (n == "sphere_hit" || n == "sphere_near" || n == "sphere_far") {
    static const HitView kNone;
    const HitView* hv = env.hit ? env.hit : &kNone;
    SphereRoots s = sphereRoots(hv->aabb_min, hv->aabb_max, hv->object_origin, hv->object_direction);
    Val v;
    if (n == "sphere_hit") v.b = s.hit;
    else v.f[0] = n == "sphere_near" ? s.t_near : s.t_far;
    return v;
  }
  if (n == "shader_record_uint" || n == "shader_record_float") {
    const uint32_t i = e.args.empty() ? 0 : static_cast<uint32_t>(e.args[0].literal.empty() ? 0 : e.args[0].literal[0]);
    const uint32_t w = env.record_data && i < env.record_data->size() ? (*env.record_data)[i] : 0u;
    return n == "shader_record_uint" ? fromUint(w) : fromFloat(bitsf(w));
  }
  if (n == "and" || n == "or") {
    const bool isAnd = n == "and";
    for (const Expr& a : e.args) {
      const bool b = eval(a, env).b;
      if (isAnd && !b) { Val r; r.b = false; return r; }
      if (!isAnd && b) { Val r; r.b = true; return r; }
    }
    Val r; r.b = isAnd; return r;
  }
  std::vector<Val> a;
  a.reserve(e.args.size());
  for (const Expr& x : e.args) a.push_back(eval(x, env));
  auto type = [&](size_t i) { return e.args[i].type; };
  Val r;
  if (n == "not") { r.b = !a[0].b; return r; }
  if (n == "odd") { r.b = (a[0].u & 1u) != 0; return r; }
  if (n == "even") { r.b = (a[0].u & 1u) == 0; return r; }
  if (n == "float") return fromFloat(static_cast<float>(a[0].u));
  if (n == "uint") {
    const float f = a[0].f[0];
    return fromUint(f <= 0 || std::isnan(f) ? 0u : f >= 4294967295.0f ? 0xFFFFFFFFu : static_cast<uint32_t>(f));
  }
  if (n == "vec2" || n == "vec3" || n == "vec4") {
    const int cnt = n == "vec2" ? 2 : n == "vec3" ? 3 : 4;
    for (int k = 0; k < cnt; ++k) r.f[k] = a.size() == 1 ? a[0].f[0] : (k < static_cast<int>(a.size()) ? a[k].f[0] : 0.0f);
    return r;
  }
  if (n == "x") return fromFloat(a[0].f[0]);
  if (n == "y") return fromFloat(a[0].f[1]);
  if (n == "z") return fromFloat(a[0].f[2]);
  if (n == "w") return fromFloat(a[0].f[3]);
  if (n == "dot" || n == "length" || n == "normalize") {
    const int cnt = componentCount(type(0));
    float d = 0;
    const Val& b = n == "dot" ? a[1] : a[0];
    for (int k = 0; k < cnt; ++k) d = k == 0 ? a[0].f[0] * b.f[0] : d + a[0].f[k] * b.f[k];
    if (n == "dot") return fromFloat(d);
    const float len = std::sqrt(d);
    if (n == "length") return fromFloat(len);
    for (int k = 0; k < cnt; ++k) r.f[k] = a[0].f[k] / len;
    return r;
  }
  if (n == "eq" || n == "ne" || n == "lt" || n == "le" || n == "gt" || n == "ge") {
    const bool u = type(0) == ValueType::Uint && type(1) == ValueType::Uint;
    const double x = u ? a[0].u : static_cast<double>(type(0) == ValueType::Uint ? a[0].u : a[0].f[0]);
    const double y = u ? a[1].u : static_cast<double>(type(1) == ValueType::Uint ? a[1].u : a[1].f[0]);
    if (n == "eq") r.b = x == y;
    else if (n == "ne") r.b = x != y;
    else if (n == "lt") r.b = x < y;
    else if (n == "le") r.b = x <= y;
    else if (n == "gt") r.b = x > y;
    else r.b = x >= y;
    return r;
  }
  if (n == "mod") { r.u = a[1].u == 0 ? 0 : a[0].u % a[1].u; return r; }
  // add sub mul div min max: Uint x Uint, or float-wise with scalar broadcast.
  if (e.type == ValueType::Uint) {
    const uint32_t x = a[0].u, y = a[1].u;
    if (n == "add") r.u = x + y;
    else if (n == "sub") r.u = x - y;
    else if (n == "mul") r.u = x * y;
    else if (n == "div") r.u = y == 0 ? 0xFFFFFFFFu : x / y;
    else if (n == "min") r.u = std::min(x, y);
    else if (n == "max") r.u = std::max(x, y);
    return r;
  }
  const int cnt = componentCount(e.type);
  auto comp = [&](size_t i, int k) {
    if (type(i) == ValueType::Uint) return static_cast<float>(a[i].u);
    return isVec(type(i)) ? a[i].f[k] : a[i].f[0];
  };
  for (int k = 0; k < cnt; ++k) {
    const float x = comp(0, k), y = comp(1, k);
    if (n == "add") r.f[k] = x + y;
    else if (n == "sub") r.f[k] = x - y;
    else if (n == "mul") r.f[k] = x * y;
    else if (n == "div") r.f[k] = x / y;
    else if (n == "min") r.f[k] = std::fmin(x, y);
    else if (n == "max") r.f[k] = std::fmax(x, y);
  }
  return r;
}

Flow Machine::exec(const Program& p, StageEnv& env) {
  for (const Stmt& s : p) {
    const Flow f = execStmt(s, env);
    if (f != Flow::Continue) return f;
  }
  return Flow::Continue;
}

Flow Machine::execStmt(const Stmt& s, StageEnv& env) {
  switch (s.kind) {
    case Stmt::Kind::Count: {
      const int k = cachedId(&s.counter, kIdCounter);
      if (k >= 0) counters[k] += 1;
      return Flow::Continue;
    }
    case Stmt::Kind::Record:
      for (const auto& [field, expr] : s.assigns) record(field, eval(expr, env), expr.type);
      return Flow::Continue;
    case Stmt::Kind::SetPayload:
    case Stmt::Kind::SetCall:
      for (const auto& [field, expr] : s.assigns) {
        const Val v = eval(expr, env);
        if (s.kind == Stmt::Kind::SetPayload && env.payload) {
          if (field == "color") env.payload->color = v.f;
          else if (field == "value") env.payload->value = v.u;
        } else if (s.kind == Stmt::Kind::SetCall && env.call) {
          if (field == "color") env.call->color = v.f;
          else if (field == "value") env.call->value = v.u;
        }
      }
      return Flow::Continue;
    case Stmt::Kind::Ignore: return Flow::Ignore;
    case Stmt::Kind::Terminate: return Flow::Terminate;
    case Stmt::Kind::If: return exec(eval(s.cond, env).b ? s.then_ : s.else_, env);
    case Stmt::Kind::Light: {
      if (!env.call) return Flow::Continue;
      static const std::vector<uint32_t> kEmpty;
      const F3 P = env.call->position, N = env.call->normal;
      env.call->color = lightColor(s.light, P, N, env.record_data ? *env.record_data : kEmpty);
      return Flow::Continue;
    }
    case Stmt::Kind::Call: {
      CallData d;
      for (const auto& [field, expr] : s.assigns) {
        const Val v = eval(expr, env);
        if (field == "color") d.color = v.f;
        else if (field == "value") d.value = v.u;
        else if (field == "position") d.position = {v.f[0], v.f[1], v.f[2]};
        else if (field == "normal") d.normal = {v.f[0], v.f[1], v.f[2]};
      }
      callCallable(eval(s.call_index, env).u, d, env.depth);
      env.callee = d;
      return Flow::Continue;
    }
    case Stmt::Kind::Trace: {
      const TraceArgs& t = s.trace;
      const bool fromLaunch = env.stage == Stage::Raygen;
      TraceRay r;
      const Ray& base = fromLaunch ? sh_.c->rays.rays[index_] : sh_.c->rays.defaults;
      r.origin = base.origin;
      r.direction = base.direction;
      r.tmin = base.tmin;
      r.tmax = base.tmax;
      r.flags = base.flags;
      r.cull_mask = base.cull_mask;
      r.sbt_offset = base.sbt_offset;
      r.sbt_stride = base.sbt_stride;
      r.miss = base.miss;
      auto v3 = [&](const std::vector<Expr>& x, Vec3& out) {
        if (!x.empty()) { const Val v = eval(x[0], env); out = {v.f[0], v.f[1], v.f[2]}; }
      };
      auto f1 = [&](const std::vector<Expr>& x, float& out) {
        if (!x.empty()) { const Val v = eval(x[0], env); out = x[0].type == ValueType::Uint ? static_cast<float>(v.u) : v.f[0]; }
      };
      auto u1 = [&](const std::vector<Expr>& x, uint32_t& out) {
        if (!x.empty()) out = eval(x[0], env).u;
      };
      v3(t.origin, r.origin);
      v3(t.direction, r.direction);
      f1(t.tmin, r.tmin);
      f1(t.tmax, r.tmax);
      u1(t.flags, r.flags);
      u1(t.cull_mask, r.cull_mask);
      u1(t.sbt_offset, r.sbt_offset);
      u1(t.sbt_stride, r.sbt_stride);
      u1(t.miss, r.miss);
      const uint32_t depth = env.stage == Stage::Raygen ? 1 : env.depth + 1;
      if (depth > std::max<uint32_t>(sh_.c->pipeline.max_recursion, 1)) {
        if (error.empty())
          error = "Crash: trace at depth " + std::to_string(depth) + " exceeds max_recursion " +
                  std::to_string(sh_.c->pipeline.max_recursion) + " (undefined behaviour on a device)";
        return Flow::Continue;
      }
      Payload p = trace(r, depth);
      if (env.stage == Stage::Raygen && env.payload) *env.payload = p;
      else env.child = p;
      return Flow::Continue;
    }
    case Stmt::Kind::Report:
      return report(s, env);
  }
  return Flow::Continue;
}

void Machine::callCallable(uint32_t index, CallData& data, uint32_t depth) {
  if (index >= default_callable_.size()) return;
  const SbtRecord& rec = default_callable_[index];
  if (!rec.group || *rec.group >= sh_.c->pipeline.callables.size()) return;  // R-SBT-ZERO
  bumpRuns(kRunsCallable);
  StageEnv env;
  env.stage = Stage::Callable;
  env.record_data = &rec.data;
  env.call = &data;
  env.depth = depth;
  exec(sh_.c->pipeline.callables[*rec.group], env);
}

void Machine::runRay(uint32_t index) {
  index_ = index;
  x_ = index % sh_.c->rays.width;
  y_ = index / sh_.c->rays.width;
  rec_ = records_ ? records_ + static_cast<size_t>(index) * recordWords() : nullptr;
  ray_ambiguous_ = false;
  bumpRuns(kRunsRaygen);
  StageEnv env;
  env.stage = Stage::Raygen;
  env.record_data = &sh_.c->pipeline.raygen_data;
  Payload last;
  env.payload = &last;
  exec(sh_.c->pipeline.raygen, env);
}

}  // namespace rayspec
