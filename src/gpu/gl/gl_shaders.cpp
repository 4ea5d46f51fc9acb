// GLSL 3.30 sources of the OpenGL renderer. The draw program mirrors software_renderer_pixel.h
// and the software rasterizers rule for rule, in integer arithmetic: at scale 1 every fragment
// is one native pixel and the results are the software renderer's; at scale N a fragment is the
// sub-pixel whose top-left corner is the sample point (x / N, y / N), so the sub-pixel at (0, 0)
// of each N x N block is exactly the native sample. Records are drawn as clipped boxes (triangles
// as grown triangles); coverage (the top-left fill rule, the line stepping) is decided per
// fragment.
#include "gpu/gl/gl_shaders.h"

#include <cstdio>
#include <vector>

namespace psx::gpu::gl {

namespace {

// Records are drawn as their clipped boxes, except triangles: those are drawn as the triangle
// grown by one native pixel on every side (so every sample the exact rule covers is rasterized,
// whatever the host's own fill rule), unless a sharp corner would make that larger than the box.
const char* kDrawVertex = R"(#version 330 core
layout(location = 0) in ivec4 i_bbox;
layout(location = 1) in ivec4 i_state;
layout(location = 2) in ivec4 i_ab;
layout(location = 3) in ivec4 i_c;
layout(location = 4) in ivec4 i_base;
layout(location = 5) in ivec4 i_g0;
layout(location = 6) in ivec4 i_g1;
layout(location = 7) in ivec4 i_g2;
flat out ivec4 v_bbox, v_state, v_ab, v_c, v_base, v_g0, v_g1, v_g2;

vec2 outward(vec2 from, vec2 to, float orient) {
  vec2 e = normalize(to - from);
  return orient * vec2(e.y, -e.x);
}

void main() {
  ivec2 corner = ivec2(gl_VertexID & 1, gl_VertexID >> 1);
  vec2 pos = vec2(mix(i_bbox.xy, i_bbox.zw, corner));
  if ((i_state.x & 7) == 0) {
    vec2 p[3] = vec2[3](vec2(i_ab.xy), vec2(i_ab.zw), vec2(i_c.xy));
    vec2 e1 = p[1] - p[0], e2 = p[2] - p[0];
    float orient = sign(e1.x * e2.y - e1.y * e2.x);
    vec2 grown[3];
    float worst = 0.0;
    for (int i = 0; i < 3; ++i) {
      vec2 n1 = outward(p[(i + 2) % 3], p[i], orient), n2 = outward(p[i], p[(i + 1) % 3], orient);
      float k = 1.0 + dot(n1, n2);  // 2 cos^2(half the corner's angle)
      worst = max(worst, 1.0 / max(k, 1e-6));
      grown[i] = p[i] + (n1 + n2) / max(k, 1e-6);
    }
    if (worst < 16.0) pos = grown[min(gl_VertexID, 2)];
  }
  gl_Position = vec4(pos / vec2(512.0, 256.0) - 1.0, 0.0, 1.0);
  v_bbox = i_bbox; v_state = i_state; v_ab = i_ab; v_c = i_c; v_base = i_base; v_g0 = i_g0; v_g1 = i_g1; v_g2 = i_g2;
}
)";

// Compiled once per variant: KIND, TEX, RAW, SEMI, CHECK and the renderer's SCALE are #defined
// in front (see draw_variant), so each program is straight-line code for one kind of record; llvmpipe runs
// every branch of a shader for every fragment, which made one program for all kinds slow.
const char* kDrawFragment = R"(
uniform usampler2D u_vram;     // the snapshot of scaled VRAM that reads see
uniform usampler2D u_staging;  // native 1024x512, CPU->VRAM rows
uniform usampler2D u_palette;  // 256x1, the CLUT cache
const int u_scale = SCALE;     // a constant: divisions by it become multiplications
flat in ivec4 v_bbox, v_state, v_ab, v_c, v_base, v_g0, v_g1, v_g2;
out uint o_pixel;

const int kDither[16] = int[16](-4, 0, -3, 1, 2, -2, 3, -1, -3, 1, -4, 0, 3, -1, 2, -2);

uint native_at(int x, int y) {
  return texelFetch(u_vram, ivec2((x & 1023) * u_scale, (y & 511) * u_scale), 0).r;
}

uint fetch_texel(int mode, int u, int v) {
  int win = v_state.w;
  u = (u & (win & 255)) | ((win >> 8) & 255);
  v = (v & ((win >> 16) & 255)) | ((win >> 24) & 255);
  int px = v_state.y & 0xFFFF, py = v_state.y >> 16;
  int row = py + v;
  if (mode == 1) {
    int index = int(native_at(px + (u >> 2), row) >> uint((u & 3) * 4)) & 15;
    return texelFetch(u_palette, ivec2(index, 0), 0).r;
  }
  if (mode == 2) {
    int index = int(native_at(px + (u >> 1), row) >> uint((u & 1) * 8)) & 255;
    return texelFetch(u_palette, ivec2(index, 0), 0).r;
  }
  return native_at(px + u, row);
}

int sat5(int c8, int d) { return clamp(c8 + d, 0, 255) >> 3; }

uint colour_pixel(ivec3 c, int d) { return uint(sat5(c.r, d) | (sat5(c.g, d) << 5) | (sat5(c.b, d) << 10)); }

uint modulate(uint t, ivec3 c, int d) {
  int texel = int(t);
  int r = ((texel & 31) * c.r) >> 4, g = (((texel >> 5) & 31) * c.g) >> 4, b = (((texel >> 10) & 31) * c.b) >> 4;
  return uint(sat5(r, d) | (sat5(g, d) << 5) | (sat5(b, d) << 10) | (texel & 0x8000));
}

uint blend(uint back, uint front, int mode) {
  int bk = int(back), fr = int(front), outp = 0;
  for (int shift = 0; shift < 15; shift += 5) {
    int b = (bk >> shift) & 31, f = (fr >> shift) & 31, c;
    if (mode == 0) c = (b + f) >> 1;
    else if (mode == 1) c = min(31, b + f);
    else if (mode == 2) c = max(0, b - f);
    else c = min(31, b + (f >> 2));
    outp |= c << shift;
  }
  return uint(outp | (fr & 0x8000));
}

// Inside the half-plane of edge e0->e1 (e1.y > e0.y) at sub-pixel s: x >= edge (left) or x < edge.
bool edge_test(ivec2 e0, ivec2 e1, ivec2 s, bool left) {
  int lhs = (s.x - e0.x * u_scale) * (e1.y - e0.y), rhs = (s.y - e0.y * u_scale) * (e1.x - e0.x);
  return left ? lhs >= rhs : lhs < rhs;
}

// A 12-bit fixed-point attribute at native offset dn and sub-pixel offset f from the top vertex.
int interpolate(int base, int gdx, int gdy, ivec2 dn, ivec2 f) {
  int v = base + gdx * dn.x + gdy * dn.y;
  if (u_scale > 1) v += int(floor((float(gdx) * float(f.x) + float(gdy) * float(f.y)) / float(u_scale) + 0.5));
  return v;
}

// Line coordinate after i steps: start + |delta| * i / steps, halves toward the end point
// (bias = steps) or toward the start (bias = steps - 1), as the software renderer's LineAxis.
int line_axis(int start, int delta, int steps, int i, int bias) {
  if (steps == 0) return start;
  int n = (bias + 2 * abs(delta) * i) / (2 * steps);
  return delta < 0 ? start - n : start + n;
}

void main() {
  ivec2 s = ivec2(gl_FragCoord.xy);
  ivec2 p = s / u_scale;
  ivec2 f = s - p * u_scale;
  if (KIND == 0 && (any(lessThan(p, v_bbox.xy)) || any(greaterThanEqual(p, v_bbox.zw)))) discard;
  int flags = v_state.x;
  const int kind = KIND;
  const int tex = TEX;
  const bool semi = SEMI != 0;
  uint mask_or = (flags & (1 << 11)) != 0 ? 0x8000u : 0u;
  int skip = (flags >> 12) & 3;
  if (skip != 0 && (p.y & 1) == skip - 1) discard;
  const bool check = CHECK != 0;
  uint dst = (check || semi) ? texelFetch(u_vram, s, 0).r : 0u;
  if (check && (dst & 0x8000u) != 0u) discard;

  if (kind == 3) {
    ivec2 src = (v_ab.xy + ((p - v_ab.zw) & ivec2(1023, 511))) & ivec2(1023, 511);
    o_pixel = texelFetch(u_vram, src * u_scale + f, 0).r | mask_or;
    return;
  }
  if (kind == 4) { o_pixel = texelFetch(u_staging, p, 0).r | mask_or; return; }

  ivec3 colour;
  int u = 0, v = 0, d = 0;
  bool dither = (flags & (1 << 9)) != 0;
  if (dither) d = kDither[(p.y & 3) * 4 + (p.x & 3)];
  if (kind == 0) {
    ivec2 a = v_ab.xy, b = v_ab.zw, c = v_c.xy;
    bool long_left = (flags & (1 << 14)) != 0;
    if (s.y < a.y * u_scale || s.y >= c.y * u_scale) discard;
    if (!edge_test(a, c, s, long_left)) discard;
    bool upper = s.y < b.y * u_scale;
    if (!edge_test(upper ? a : b, upper ? b : c, s, !long_left)) discard;
    ivec2 dn = p - a;
    colour = ivec3(interpolate(v_base.x, v_g0.y, v_g0.z, dn, f), interpolate(v_base.y, v_g0.w, v_g1.x, dn, f),
                   interpolate(v_base.z, v_g1.y, v_g1.z, dn, f));
    colour = clamp(colour >> 12, 0, 255);
    u = (interpolate(v_base.w, v_g1.w, v_g2.x, dn, f) >> 12) & 255;
    v = (interpolate(v_g0.x, v_g2.y, v_g2.z, dn, f) >> 12) & 255;
  } else if (kind == 1) {
    colour = v_base.xyz;
    u = (v_base.w + v_c.z * (p.x - v_ab.x)) & 255;
    v = (v_g0.x + v_c.w * (p.y - v_ab.y)) & 255;
  } else {
    ivec2 p0 = v_ab.xy, delta = v_ab.zw - v_ab.xy;
    int steps = v_c.x;
    int i = abs(delta.x) >= abs(delta.y) ? abs(p.x - p0.x) : abs(p.y - p0.y);
    if (i > steps) discard;
    // p0 is the left end point: x halves round toward it, y halves toward the right end point.
    if (p.x != line_axis(p0.x, delta.x, steps, i, steps - 1) || p.y != line_axis(p0.y, delta.y, steps, i, steps))
      discard;
    colour = (v_base.xyz + ivec3(v_g0.y, v_g0.w, v_g1.y) * i) >> 12;
  }

  uint outp;
  bool translucent = semi;
  if (tex != 0) {
    uint texel = fetch_texel(tex, u, v);
    if (texel == 0u) discard;
    translucent = semi && (texel & 0x8000u) != 0u;
    outp = RAW != 0 ? texel : modulate(texel, colour, d);
  } else {
    outp = colour_pixel(colour, d);
  }
  if (translucent) outp = blend(dst, outp, (flags >> 7) & 3);
  o_pixel = outp | mask_or;
}
)";

const char* kFullscreenVertex = R"(#version 330 core
void main() {
  gl_Position = vec4(float(gl_VertexID & 1) * 2.0 - 1.0, float(gl_VertexID >> 1) * 2.0 - 1.0, 0.0, 1.0);
}
)";

// Each native pixel is the top-left sub-pixel of its block (the native sample point).
const char* kDownsampleFragment = R"(#version 330 core
uniform usampler2D u_vram;
uniform int u_scale;
out uint o_pixel;
void main() { o_pixel = texelFetch(u_vram, ivec2(gl_FragCoord.xy) * u_scale, 0).r; }
)";

GLuint compile(const GlFunctions& gl, GLenum type, const char* source, std::string& error) {
  GLuint shader = gl.CreateShader(type);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok) return shader;
  GLint length = 0;
  gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
  gl.GetShaderInfoLog(shader, length, nullptr, log.data());
  error = std::string("shader compilation failed: ") + log.data();
  gl.DeleteShader(shader);
  return 0;
}

GLuint link(const GlFunctions& gl, const char* vertex, const char* fragment, std::string& error) {
  GLuint vs = compile(gl, GL_VERTEX_SHADER, vertex, error);
  if (!vs) return 0;
  GLuint fs = compile(gl, GL_FRAGMENT_SHADER, fragment, error);
  if (!fs) {
    gl.DeleteShader(vs);
    return 0;
  }
  GLuint program = gl.CreateProgram();
  gl.AttachShader(program, vs);
  gl.AttachShader(program, fs);
  gl.LinkProgram(program);
  gl.DeleteShader(vs);
  gl.DeleteShader(fs);
  GLint ok = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok) return program;
  char log[2048] = {};
  gl.GetProgramInfoLog(program, sizeof(log), nullptr, log);
  error = std::string("shader link failed: ") + log;
  gl.DeleteProgram(program);
  return 0;
}

}  // namespace

bool build_programs(const GlFunctions& gl, Programs& out, std::string& error) {
  out.downsample = link(gl, kFullscreenVertex, kDownsampleFragment, error);
  if (!out.downsample) return false;
  out.downsample_scale = gl.GetUniformLocation(out.downsample, "u_scale");
  gl.UseProgram(out.downsample);
  gl.Uniform1i(gl.GetUniformLocation(out.downsample, "u_vram"), 0);
  return true;
}

u32 variant_of(s32 flags) {
  const u32 f = static_cast<u32>(flags);
  return (f & 0x3F) | ((f & flag::kSemi) ? 0x40 : 0) | ((f & flag::kCheckMask) ? 0x80 : 0);
}

bool draw_variant(const GlFunctions& gl, u32 variant, u32 scale, DrawProgram& out, std::string& error) {
  char defines[192];
  std::snprintf(defines, sizeof defines, "#version 330 core\n#define KIND %u\n#define TEX %u\n#define RAW %u\n"
                "#define SEMI %u\n#define CHECK %u\n#define SCALE %u\n", variant & 7, (variant >> 3) & 3,
                (variant >> 5) & 1, (variant >> 6) & 1, (variant >> 7) & 1, scale);
  const std::string fragment = std::string(defines) + kDrawFragment;
  out.program = link(gl, kDrawVertex, fragment.c_str(), error);
  if (!out.program) return false;
  gl.UseProgram(out.program);
  gl.Uniform1i(gl.GetUniformLocation(out.program, "u_vram"), 0);
  gl.Uniform1i(gl.GetUniformLocation(out.program, "u_staging"), 1);
  gl.Uniform1i(gl.GetUniformLocation(out.program, "u_palette"), 2);
  return true;
}

}  // namespace psx::gpu::gl
