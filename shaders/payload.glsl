// rayspec shared GLSL: the ray payload and the callable data.
// Model counterpart: harness/model (the same fields, the same start values).

// Payload of every trace (location 0 in raygen and as the incoming payload;
// location 1 for a nested trace). A trace starts with the color and value its
// statement gives (`trace: {payload: ...}`, 0 where not given) and depth = 1
// from raygen, the caller's depth + 1 from a nested trace.
struct RsPayload {
  vec4 color;
  uint value;
  uint depth;
};

// Callable data of location L (pipeline.callable_data; declared at L in
// raygen / closest-hit / miss, at L + 1 inside a callable, whose incoming data
// is at location 0), RsCallDataW<N> when the type has N more words
// (harness/glsl/emit_call_data.cpp). Fields a `call` does not give are zero.
struct RsCallData {
  vec4 color;
  vec3 position;
  uint value;
  vec3 normal;
  uint pad;
};
