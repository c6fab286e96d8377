// rayspec shared GLSL: the lights (`light: point|spot|directional` in a
// callable, and the ops light_point, light_spot, light_directional).
// P = call.position, N = call.normal, f(i) = float i of the shader record.
// Model counterpart: harness/model implements exactly these formulas; change
// both or neither. `precise` keeps operations unfused.

float rs_light_f(uint i) {
  return rs_shader_record_float(i);
}

// Point light at f0..f2 with intensity f3..f5, inverse-square falloff.
vec4 rs_light_point(vec3 P, vec3 N) {
  precise vec3 L = vec3(rs_light_f(0u), rs_light_f(1u), rs_light_f(2u)) - P;
  precise float d2 = dot(L, L);
  precise vec3 l = L / sqrt(d2);
  precise vec3 c = max(dot(N, l), 0.0) / d2 * vec3(rs_light_f(3u), rs_light_f(4u), rs_light_f(5u));
  return vec4(c, 1.0);
}

// Spot light at f0..f2 pointing along f3..f5, white, unit intensity,
// inverse-square falloff, and a smooth cone: full inside the cone of cosine
// f6, dark outside the cone of cosine f7 (f7 < f6), the cosine's linear ramp
// between.
vec4 rs_light_spot(vec3 P, vec3 N) {
  precise vec3 L = vec3(rs_light_f(0u), rs_light_f(1u), rs_light_f(2u)) - P;
  precise float d = length(L);
  precise vec3 l = L / d;
  precise float cosang = dot(-l, normalize(vec3(rs_light_f(3u), rs_light_f(4u), rs_light_f(5u))));
  precise float s = clamp((cosang - rs_light_f(7u)) / (rs_light_f(6u) - rs_light_f(7u)), 0.0, 1.0);
  precise float c = s * max(dot(N, l), 0.0) / (d * d);
  return vec4(c, c, c, 1.0);
}

// Directional light travelling along f0..f2 with intensity f3..f5.
vec4 rs_light_directional(vec3 P, vec3 N) {
  precise vec3 l = -normalize(vec3(rs_light_f(0u), rs_light_f(1u), rs_light_f(2u)));
  precise vec3 c = max(dot(N, l), 0.0) * vec3(rs_light_f(3u), rs_light_f(4u), rs_light_f(5u));
  return vec4(c, 1.0);
}
