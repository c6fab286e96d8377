// The model's meaning of every built-in (program/builtins.h), read from the
// stage's frame (StageEnv) and the launch ray now (LaunchState: its launch
// index). Reads only; an unknown built-in is the launch's case error.
#pragma once

#include <cstdint>

#include "model/launch_state.h"
#include "model/model_shared.h"
#include "model/model_stage_env.h"

namespace rayspec {

class ModelBuiltins {
 public:
  ModelBuiltins(const ModelShared& shared, LaunchState& state) : sh_(shared), st_(state) {}
  Val read(const CExpr& e, StageEnv& env) const;
  // Word index % words of a data array indexed by a value (payload_word ..
  // callee_word, store: payload.words / call.words); null where the stage has
  // no such data or the type no words.
  static uint32_t* dataWord(WordArray which, uint32_t words, uint32_t index, StageEnv& env);

 private:
  Val rayBuiltin(const CExpr& e, const StageEnv& env) const;
  Val hitBuiltin(const CExpr& e, const StageEnv& env) const;
  Val dataBuiltin(const CExpr& e, StageEnv& env) const;
  Val vertexPosition(const HitView& hv, int i) const;
  Val transformBuiltin(const HitView& hv, int k) const;
  // candidate.*, committed.*, query.* of the innermost query (model_builtins_query.cpp).
  Val queryBuiltin(const CExpr& e, const StageEnv& env) const;
  Val queryHit(int row, const HitView& hv) const;
  Val queryVertexPosition(const HitView& hv, int i) const;
  // hit_object.* of the stage's hit object (model_builtins_hit_object.cpp).
  Val hitObjectBuiltin(const CExpr& e, const StageEnv& env) const;
  Val hitObjectOwn(const CExpr& e, const HitObjectState& h) const;
  void unknown(const CExpr& e) const;
  // Widens this ray's object_ray_origin tolerance where hv's world-to-object
  // terms of the world origin are large beside the result (R-PREC).
  void noteObjectOriginBound(const HitView& hv, const Vec3& world_origin) const;

  const ModelShared& sh_;
  LaunchState& st_;  // read: the launch index; written: the case error
};

}  // namespace rayspec
