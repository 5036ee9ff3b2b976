//! The shaders of the cubic lattice's WebGL2 renderer.

pub(super) const MESH_VS: &str = "#version 300 es
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_offset;
layout(location = 3) in vec3 a_scale;
layout(location = 4) in vec4 a_color;
uniform mat4 u_vp;
uniform mat3 u_rot;
out vec3 v_normal;
out vec3 v_local;
out vec4 v_color;
void main() {
  vec3 world = a_offset + u_rot * (a_pos * a_scale);
  gl_Position = u_vp * vec4(world, 1.0);
  v_normal = u_rot * a_normal;
  v_local = a_pos;
  v_color = a_color;
}";

// Modes: 0 lit solid with dark edges, 1 translucent ghost with bright edges, 2 soft shadow,
// 3 emissive (the lamp).
pub(super) const MESH_FS: &str = "#version 300 es
precision highp float;
in vec3 v_normal;
in vec3 v_local;
in vec4 v_color;
uniform int u_mode;
uniform vec3 u_key;
uniform vec3 u_eye_dir;
uniform vec3 u_lamp;
uniform float u_lamp_on;
uniform float u_alpha;
uniform float u_fill;
uniform float u_edge;
out vec4 outColor;
void main() {
  vec3 n = normalize(v_normal);
  vec3 base = v_color.rgb;
  // Distance to the face's border, 0 at its centre and 1 on its edges.
  vec3 a = abs(v_local) * 2.0;
  vec3 inPlane = step(abs(n), vec3(0.5));
  float e = max(max(a.x * inPlane.x, a.y * inPlane.y), a.z * inPlane.z);
  float aa = max(fwidth(e), 1e-4);
  float edge = smoothstep(1.0 - u_edge - aa, 1.0 - u_edge + aa, e);
  if (u_mode == 2) {
    float r = max(a.x, a.y);
    outColor = vec4(0.0, 0.0, 0.0, u_alpha * v_color.a * (1.0 - smoothstep(0.45, 1.05, r)));
    return;
  }
  if (u_mode == 3) {
    outColor = vec4(base, v_color.a * u_alpha);
    return;
  }
  float hemi = 0.5 + 0.5 * n.z;
  float key = max(dot(n, u_key), 0.0);
  float head = max(dot(n, u_eye_dir), 0.0);
  float lamp = u_lamp_on * max(dot(n, u_lamp), 0.0);
  vec3 lit = base * (0.26 + 0.20 * hemi + 0.48 * key + 0.16 * head) + base * vec3(1.0, 0.86, 0.55) * 0.30 * lamp;
  if (u_mode == 1) {
    vec3 col = mix(base * (0.75 + 0.35 * key), vec3(1.0), 0.25 * edge);
    outColor = vec4(col, u_alpha * mix(u_fill, 0.85, edge));
    return;
  }
  lit = mix(lit, lit * 0.52, edge);
  outColor = vec4(lit, v_color.a * u_alpha);
}";

pub(super) const PLANE_VS: &str = "#version 300 es
layout(location = 0) in vec2 a_uv;
uniform mat4 u_vp;
uniform vec2 u_min;
uniform vec2 u_max;
uniform float u_z;
out vec2 v_xy;
void main() {
  v_xy = mix(u_min, u_max, a_uv);
  gl_Position = u_vp * vec4(v_xy, u_z, 1.0);
}";

pub(super) const PLANE_FS: &str = "#version 300 es
precision highp float;
in vec2 v_xy;
uniform vec4 u_fill;
uniform vec4 u_line;
uniform vec2 u_centre;
uniform float u_fade;
out vec4 outColor;
void main() {
  vec2 g = abs(fract(v_xy) - 0.5);
  vec2 w = fwidth(v_xy);
  vec2 l = 1.0 - smoothstep(vec2(0.0), w * 1.2, 0.5 - g);
  float line = max(l.x, l.y);
  float fade = u_fade > 0.0 ? 1.0 - smoothstep(u_fade * 0.45, u_fade, length(v_xy - u_centre)) : 1.0;
  vec3 col = mix(u_fill.rgb, u_line.rgb, line * u_line.a);
  float alpha = max(u_fill.a, line * u_line.a) * fade;
  if (alpha <= 0.003) discard;
  outColor = vec4(col, alpha);
}";

pub(super) const LINE_VS: &str = "#version 300 es
layout(location = 0) in vec3 a_pos;
uniform mat4 u_vp;
void main() { gl_Position = u_vp * vec4(a_pos, 1.0); }";

pub(super) const LINE_FS: &str = "#version 300 es
precision mediump float;
uniform vec4 u_color;
out vec4 outColor;
void main() { outColor = u_color; }";
