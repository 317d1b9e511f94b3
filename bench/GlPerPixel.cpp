#include "GlPerPixel.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/Units.hpp"
#include "host/render/gl/EglContext.hpp"
#include "host/render/gl/GlProgram.hpp"

namespace arp::bench {

namespace {

const char* kVertex = R"(#version 330 core
void main() {  // one triangle covering the viewport
  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

std::string fragment(int memories, int lines) {
  std::string s = "#version 330 core\n#define MEMORIES " + std::to_string(memories) + "\n#define LINES " +
                  std::to_string(lines) + "\n";
  s += R"(uniform samplerCube mem[MEMORIES];
layout(std140) uniform Lines { vec4 rows[3 * LINES]; };  // each line's orientation register, row by row
uniform float cx, half_w, half_h, tan_half, y0;
uniform vec4 k;             // scale(r) = k0 + k1 r^2 + k2 r^4 + k3 r^6
uniform vec4 background;
out vec4 color;
void main() {
  float py = gl_FragCoord.y - y0;  // this eye's line, + 1/2
  float nx = (gl_FragCoord.x - cx) / half_w, ny = (py - half_h) / half_w;
  float r2 = nx * nx + ny * ny;
  float s = (k.x + r2 * (k.y + r2 * (k.z + r2 * k.w))) * tan_half;
  vec3 d = vec3(nx * s, -ny * s, -1.0);
  int line = int(py);
  vec3 w = vec3(dot(rows[3 * line].xyz, d), dot(rows[3 * line + 1].xyz, d), dot(rows[3 * line + 2].xyz, d));
  vec4 best = texture(mem[0], w);
)";
  for (int m = 1; m < memories; ++m)
    s += "  { vec4 c = texture(mem[" + std::to_string(m) + "], w); if (c.a < best.a) best = c; }\n";
  s += "  color = best.a == 1.0 ? background : vec4(best.rgb, 1.0);\n}\n";
  return s;
}

}  // namespace

struct GlPerPixel::Gl {
  host::GlProgram program;
  GLuint vao = 0, ubo = 0, fbo = 0, rb = 0;
  std::vector<GLuint> cubes;  // [eye][memory]
  std::vector<float> rows;
  Gl(int memories, int lines) : program(kVertex, fragment(memories, lines), "per-pixel (time warp)") {}
  ~Gl() {
    glDeleteTextures(static_cast<GLsizei>(cubes.size()), cubes.data());
    glDeleteBuffers(1, &ubo);
    glDeleteVertexArrays(1, &vao);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &rb);
  }
};

GlPerPixel::GlPerPixel(const FunctionalModel& model, const dp::DisplayMemorySet& mem, const PerPixelSetup& setup)
    : model_(model), setup_(setup) {
  const dp::ArpConfig& cfg = model.config();
  const dp::MemoryFormat& fmt = mem.format();
  if (fmt.red_bits != 8 || fmt.green_bits != 8 || fmt.blue_bits != 8 || fmt.depth_bits != 16)
    throw std::invalid_argument("the per-pixel comparison needs 8-bit channels and 16-bit depth codes");
  if (setup.memories < 1 || setup.memories > mem.count()) throw std::invalid_argument("memories out of range");
  const int W = cfg.timing.h_active, H = cfg.timing.v_active, E = cfg.timing.eyes, S = fmt.face_size;
  gl_ = std::make_unique<Gl>(setup.memories, H);
  Gl& g = *gl_;
  glGenVertexArrays(1, &g.vao);
  glGenBuffers(1, &g.ubo);
  glBindBuffer(GL_UNIFORM_BUFFER, g.ubo);
  glBufferData(GL_UNIFORM_BUFFER, static_cast<GLsizeiptr>(sizeof(float) * 12 * static_cast<size_t>(H)), nullptr,
               GL_STREAM_DRAW);
  glUniformBlockBinding(g.program.id(), glGetUniformBlockIndex(g.program.id(), "Lines"), 0);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, g.ubo);
  g.rows.assign(12 * static_cast<size_t>(H), 0.0f);

  glGenFramebuffers(1, &g.fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
  glGenRenderbuffers(1, &g.rb);
  glBindRenderbuffer(GL_RENDERBUFFER, g.rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, W, H * E);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, g.rb);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw host::GlUnavailable("per-pixel framebuffer incomplete");

  // The memories' front buffers as cube textures, face f = GL face f, row y first (the memory follows the GL table).
  g.cubes.resize(static_cast<size_t>(E * setup.memories));
  glGenTextures(static_cast<GLsizei>(g.cubes.size()), g.cubes.data());
  std::vector<uint8_t> t8;
  std::vector<uint16_t> t16;
  const GLint filter = setup.bilinear ? GL_LINEAR : GL_NEAREST;
  for (int e = 0; e < E; ++e)
    for (int m = 0; m < setup.memories; ++m) {
      glBindTexture(GL_TEXTURE_CUBE_MAP, g.cubes[static_cast<size_t>(e * setup.memories + m)]);
      const dp::DisplayMemoryBank& bank = mem.bank(e, m);
      for (int f = 0; f < 6; ++f) {
        t8.clear();
        t16.clear();
        for (int y = 0; y < S; ++y)
          for (int x = 0; x < S; ++x) {
            const uint64_t word = bank.read(f, x, y);
            const uint32_t c = dp::texel_color(word), d = dp::texel_depth(word);
            const uint32_t rgb[3] = {(c >> 16) & 0xFF, (c >> 8) & 0xFF, c & 0xFF};
            if (setup.wide_texel) {
              for (uint32_t v : rgb) t16.push_back(static_cast<uint16_t>(v * 257));
              t16.push_back(static_cast<uint16_t>(d));
            } else {
              for (uint32_t v : rgb) t8.push_back(static_cast<uint8_t>(v));
              t8.push_back(static_cast<uint8_t>(d >> 8));
            }
          }
        const GLenum target = static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f);
        if (setup.wide_texel)
          glTexImage2D(target, 0, GL_RGBA16, S, S, 0, GL_RGBA, GL_UNSIGNED_SHORT, t16.data());
        else
          glTexImage2D(target, 0, GL_RGBA8, S, S, 0, GL_RGBA, GL_UNSIGNED_BYTE, t8.data());
      }
      glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, filter);
      glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, filter);
      glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
  g.program.use();
  for (int m = 0; m < setup.memories; ++m)
    glUniform1i(g.program.uniform(("mem[" + std::to_string(m) + "]").c_str()), m);
  const dp::LensConfig& lens = cfg.lens;
  glUniform1f(g.program.uniform("half_w"), static_cast<float>(W / 2.0));
  glUniform1f(g.program.uniform("half_h"), static_cast<float>(H / 2.0));
  glUniform1f(g.program.uniform("tan_half"), static_cast<float>(std::tan(deg_to_rad(lens.fov_deg) / 2.0)));
  glUniform4f(g.program.uniform("k"), static_cast<float>(lens.k[0]), static_cast<float>(lens.k[1]),
              static_cast<float>(lens.k[2]), static_cast<float>(lens.k[3]));
  const auto& bg = cfg.memory.background;
  glUniform4f(g.program.uniform("background"), static_cast<float>(bg[0] / 255.0), static_cast<float>(bg[1] / 255.0),
              static_cast<float>(bg[2] / 255.0), 1.0f);
  host::check_gl("setting up the per-pixel pass");
}

GlPerPixel::~GlPerPixel() = default;

void GlPerPixel::render(const dp::OrientationStream& orientation, int64_t frame, std::vector<uint32_t>& rgba) {
  const dp::ArpConfig& cfg = model_.config();
  const int W = cfg.timing.h_active, H = cfg.timing.v_active, E = cfg.timing.eyes;
  Gl& g = *gl_;
  // Each line's register value: the sample the model's latch rule picks, quantised as the tracker interface writes it.
  const float scale = 1.0f / static_cast<float>(int64_t{1} << cfg.widths.mat_frac);
  size_t last = static_cast<size_t>(-1);
  dp::Mat3q M{};
  for (int y = 0; y < H; ++y) {
    const size_t s = model_.latch_rule().sample(orientation, frame, 0, 0, y);
    if (s != last) M = dp::quantise_rotation(orientation[s].q, cfg.widths.mat_frac);
    last = s;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) g.rows[static_cast<size_t>(12 * y + 4 * r + c)] = static_cast<float>(M.m[3 * r + c]) * scale;
  }
  g.program.use();
  glBindBuffer(GL_UNIFORM_BUFFER, g.ubo);
  glBufferSubData(GL_UNIFORM_BUFFER, 0, static_cast<GLsizeiptr>(g.rows.size() * sizeof(float)), g.rows.data());
  glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
  glBindVertexArray(g.vao);
  glDisable(GL_DEPTH_TEST);
  for (int e = 0; e < E; ++e) {
    for (int m = 0; m < setup_.memories; ++m) {
      glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + m));
      glBindTexture(GL_TEXTURE_CUBE_MAP, g.cubes[static_cast<size_t>(e * setup_.memories + m)]);
    }
    glViewport(0, e * H, W, H);
    glUniform1f(g.program.uniform("y0"), static_cast<float>(e * H));
    glUniform1f(g.program.uniform("cx"), static_cast<float>(dp::LensVectorTable::lens_center_x(cfg.lens, cfg.timing, e)));
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  rgba.resize(static_cast<size_t>(W) * static_cast<size_t>(H) * static_cast<size_t>(E));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, W, H * E, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  host::check_gl("the per-pixel pass");
}

}  // namespace arp::bench
