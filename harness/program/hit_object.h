// What uses a stage's hit object (GL_NV_shader_invocation_reorder's
// hitObjectNV, VK_NV_ray_tracing_invocation_reorder): a trace into it, the
// statements that execute, record or reorder by it, and its getters
// (hit_object.*). A stage that uses it declares one, empty at its start.
#pragma once

#include <string>

#include "program/program.h"

namespace rayspec {

// The statement itself (not the statements nested in it) uses the hit object.
bool isHitObjectStatement(const Stmt& s);
// hit_object_record_uint / _float: a read of the hit object's shader record
// (hitObjectGetShaderRecordBufferHandleNV).
bool isHitObjectRecordRead(const Expr& e);
// The program (nested statements and every expression included) uses it.
bool usesHitObject(const Program& p);
// The hit object getter that reads a hit stage's built-in `name` of the
// hit it holds ("hit_t": "hit_object.t", "primitive_id":
// "hit_object.primitive_id"): a record field of the hit's identity may hold
// either.
std::string hitObjectGetterOf(const std::string& name);

}  // namespace rayspec
