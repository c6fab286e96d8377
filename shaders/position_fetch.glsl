// rayspec shared GLSL: gl_HitTriangleVertexPositionsEXT (the vertex_position<i>
// built-ins), VK_KHR_ray_tracing_position_fetch. glslang 12 (Debian 12) has no
// GL_EXT_ray_tracing_position_fetch, so the input is declared through
// GL_EXT_spirv_intrinsics (enabled by the stage): the same SPIR-V the
// extension gives, an Input array of three vec3 decorated BuiltIn (11)
// HitTriangleVertexPositionsKHR (5335), with the capability
// RayTracingPositionFetchKHR (5336) and SPV_KHR_ray_tracing_position_fetch.
// Only any-hit and closest-hit of triangle hits read it.
// Model counterpart: HitView::vertices (harness/model).

spirv_decorate(extensions = ["SPV_KHR_ray_tracing_position_fetch"], capabilities = [5336], 11, 5335)
spirv_storage_class(1) vec3 rs_hit_positions[3];
