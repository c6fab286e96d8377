// rayspec shared GLSL: rayQueryGetIntersectionTriangleVertexPositionsEXT (the
// candidate.vertex_position<i> and committed.vertex_position<i> getters, and
// vertex_position<i> of a hit stage run inlined), VK_KHR_ray_tracing_position_fetch.
// glslang 12 (Debian 12) has no GL_EXT_ray_tracing_position_fetch, so the
// instruction is declared through GL_EXT_spirv_intrinsics (enabled by the
// stage): OpRayQueryGetIntersectionTriangleVertexPositionsKHR (5340) with the
// capability RayQueryPositionFetchKHR (5391), giving the three vertices in
// object space. `intersection` must be a constant: 0u the candidate, 1u the
// committed intersection, and only a triangle's.
// Model counterpart: ModelBuiltins::queryVertexPosition (harness/model).

spirv_instruction(extensions = ["SPV_KHR_ray_tracing_position_fetch"], capabilities = [5391],
                  id = 5340)
vec3[3] rs_query_positions(spirv_by_reference rayQueryEXT query, uint intersection);
