#include "GlCubeRenderer.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <omp.h>

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "GlProgram.hpp"
#include "host/render/FaceFrustum.hpp"

namespace arp::host {

namespace {

// Lighting per vertex and interpolated (Gouraud; a flat mesh's three vertices
// share the triangle's normal), as the software renderer shades.
const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
uniform mat4 model_rel;   // model frame -> world relative to the eye
uniform mat3 normal_mat;
uniform mat4 face_clip;   // eye-relative world -> the face's clip space
uniform vec3 color;
uniform vec3 light_dir;
uniform float ambient, diffuse;
out vec3 rel;
out vec3 shade;
out vec2 tex;
void main() {
  vec4 r = model_rel * vec4(position, 1.0);
  rel = r.xyz;
  shade = color * (ambient + diffuse * abs(dot(normalize(normal_mat * normal), light_dir)));
  tex = uv;
  gl_Position = face_clip * r;
}
)";

// Colour and, in an integer target, the depth code of the radial distance
// (DepthCode's logarithmic scale) and the object; the z-buffer decides
// visibility, so early depth testing stays on (no gl_FragDepth).
const char* kFragment = R"(#version 330 core
in vec3 rel;
in vec3 shade;
in vec2 tex;
uniform bool textured;
uniform sampler2D image;
uniform uint object_id;
uniform float near_m, log_range, max_code;
layout(location = 0) out vec4 out_color;
layout(location = 1) out uvec2 out_code;
void main() {
  vec3 c = shade;
  if (textured) c *= texture(image, vec2(tex.x, 1.0 - tex.y)).rgb;
  out_color = vec4(c, 1.0);
  float t = log(max(length(rel), near_m) / near_m) / log_range;
  out_code = uvec2(uint(round(min(t, 1.0) * max_code)), object_id);
}
)";

constexpr GLuint kNoCode = 0xFFFFFFFFu;

// The shaders' uniforms: their names, and the index of each location in Gl::u.
enum Uniform { kModelRel, kNormalMat, kFaceClip, kColor, kLightDir, kAmbient, kDiffuse, kTextured, kImage, kObjectId, kNearM, kLogRange, kMaxCode, kUniforms };
constexpr const char* kUniformName[kUniforms] = {"model_rel", "normal_mat", "face_clip", "color", "light_dir", "ambient", "diffuse",
                                                 "textured", "image", "object_id", "near_m", "log_range", "max_code"};

struct MeshBuffers {
  std::shared_ptr<const Mesh> keep;  // the cache is keyed by address: the mesh must outlive its entry
  GLuint vao = 0, vbo = 0, ebo = 0;
  GLsizei count = 0;  // indices (smooth) or vertices (flat)
  bool indexed = false;
};

}  // namespace

struct GlCubeRenderer::Gl {
  EglContext ctx;
  GlProgram program;
  int u[kUniforms];  // locations, by Uniform
  GLuint query[6] = {};
  // One framebuffer per face: all six are drawn before any is read back, so
  // llvmpipe rasterises a face while the next one is being bound.
  GLuint fbo[6] = {}, rb[18] = {};
  int size = 0;
  std::map<std::pair<const Mesh*, bool>, MeshBuffers> meshes;
  std::map<const RgbImage*, std::pair<std::shared_ptr<const RgbImage>, GLuint>> textures;
  std::vector<uint8_t> color[6];   // RGBA8 per texel, row 0 = memory row 0
  std::vector<uint32_t> code[6];   // depth code (kNoCode: nothing drawn) and object per texel
  bool drawn[6] = {};

  explicit Gl(const EglOptions& o)
      : ctx(o),
        program(kVertex, kFragment, "cube-face renderer") {
    for (int i = 0; i < kUniforms; ++i) u[i] = program.uniform(kUniformName[i]);
    glGenQueries(6, query);
  }

  ~Gl() {
    for (auto& [k, m] : meshes) {
      glDeleteVertexArrays(1, &m.vao);
      glDeleteBuffers(1, &m.vbo);
      if (m.ebo) glDeleteBuffers(1, &m.ebo);
    }
    for (auto& [k, t] : textures) glDeleteTextures(1, &t.second);
    glDeleteQueries(6, query);
    release_targets();
  }

  void release_targets() {
    if (!fbo[0]) return;
    glDeleteFramebuffers(6, fbo);
    glDeleteRenderbuffers(18, rb);
    fbo[0] = 0;
  }

  void targets(int S) {
    if (fbo[0] && size == S) return;
    release_targets();
    size = S;
    glGenFramebuffers(6, fbo);
    glGenRenderbuffers(18, rb);
    const GLenum formats[3] = {GL_RGBA8, GL_RG32UI, GL_DEPTH_COMPONENT32F};
    const GLenum points[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_DEPTH_ATTACHMENT};
    const GLenum draw[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    for (int f = 0; f < 6; ++f) {
      glBindFramebuffer(GL_FRAMEBUFFER, fbo[f]);
      for (int i = 0; i < 3; ++i) {
        glBindRenderbuffer(GL_RENDERBUFFER, rb[3 * f + i]);
        glRenderbufferStorage(GL_RENDERBUFFER, formats[i], S, S);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, points[i], GL_RENDERBUFFER, rb[3 * f + i]);
      }
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        release_targets();  // not kept as if made: the next draw tries again
        throw GlUnavailable("OpenGL: the cube-face framebuffer (RGBA8, RG32UI, depth 32F) is not complete");
      }
      glDrawBuffers(2, draw);
    }
    for (int f = 0; f < 6; ++f) {
      color[f].resize(static_cast<size_t>(S) * static_cast<size_t>(S) * 4);
      code[f].resize(static_cast<size_t>(S) * static_cast<size_t>(S) * 2);
    }
  }

  const MeshBuffers& mesh(const std::shared_ptr<const Mesh>& keep, bool smooth) {
    auto [it, fresh] = meshes.try_emplace({keep.get(), smooth});
    MeshBuffers& b = it->second;
    if (!fresh) return b;
    b.keep = keep;
    const Mesh& m = *keep;
    // position, normal, uv: 8 floats per vertex.
    std::vector<float> v;
    auto put = [&](size_t k, const glm::dvec3& n) {
      const glm::dvec3& p = m.positions[k];
      const glm::dvec2 t = m.uvs.empty() ? glm::dvec2(0.0) : m.uvs[k];
      for (double x : {p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y}) v.push_back(static_cast<float>(x));
    };
    if (smooth) {
      for (size_t k = 0; k < m.positions.size(); ++k) put(k, m.normals[k]);
      b.count = static_cast<GLsizei>(m.indices.size());
      b.indexed = true;
    } else {
      for (size_t t3 = 0; t3 + 2 < m.indices.size(); t3 += 3) {
        const glm::dvec3 &a = m.positions[m.indices[t3]], &p1 = m.positions[m.indices[t3 + 1]],
                         &p2 = m.positions[m.indices[t3 + 2]];
        const glm::dvec3 n = glm::cross(p1 - a, p2 - a);  // normalised after the transform
        for (int j = 0; j < 3; ++j) put(m.indices[t3 + static_cast<size_t>(j)], n);
      }
      b.count = static_cast<GLsizei>(v.size() / 8);
    }
    glGenVertexArrays(1, &b.vao);
    glBindVertexArray(b.vao);
    glGenBuffers(1, &b.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
    if (b.indexed) {
      glGenBuffers(1, &b.ebo);
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.ebo);
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.indices.size() * sizeof(uint32_t)),
                   m.indices.data(), GL_STATIC_DRAW);
    }
    const GLsizei stride = 8 * sizeof(float);
    for (GLuint a = 0; a < 3; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(a, a == 2 ? 2 : 3, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<const void*>(static_cast<uintptr_t>(a * 3 * sizeof(float))));
    }
    check_gl("uploading a mesh");
    return b;
  }

  GLuint texture(const std::shared_ptr<const RgbImage>& keep) {
    auto [it, fresh] = textures.try_emplace(keep.get(), keep, 0);
    GLuint& id = it->second.second;
    if (!fresh) return id;
    const RgbImage& img = *keep;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Row 0 (the image's top) at t = 0: the shader samples t = 1 - v.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, img.width, img.height, 0, GL_RGB, GL_UNSIGNED_BYTE, img.rgb.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    check_gl("uploading a texture");
    return id;
  }
};

GlCubeRenderer::GlCubeRenderer(DepthCode depth, LightModel light, const EglOptions& egl)
    : depth_(depth), light_(light), gl_(std::make_unique<Gl>(egl)) {}

GlCubeRenderer::~GlCubeRenderer() = default;

const EglContext& GlCubeRenderer::context() const { return gl_->ctx; }

RenderStats GlCubeRenderer::draw(const Scene& scene, const std::vector<size_t>& objects, double t,
                                 const glm::dvec3& eye, int S, int depth_bits) {
  if (depth_bits > kMaxDepthBits)
    throw std::invalid_argument("GlCubeRenderer: " + std::to_string(depth_bits) + "-bit depth codes (at most " +
                                std::to_string(kMaxDepthBits) + ")");
  DepthCode dc = depth_;
  dc.bits = depth_bits;
  Gl& g = *gl_;
  g.targets(S);
  RenderStats st;
  const FaceLists lists = cull_to_faces(scene, objects, t, eye, dc.near_m, cull_faces_);
  const auto& per_face = lists.per_face;
  const auto& model = lists.model;
  st.objects = lists.objects;

  g.program.use();
  glViewport(0, 0, S, S);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);  // the first drawn keeps an exact tie, as in the software renderer
  glDisable(GL_CULL_FACE);  // both windings are drawn
  glUniform3f(g.u[kLightDir], static_cast<float>(light_.direction.x), static_cast<float>(light_.direction.y),
              static_cast<float>(light_.direction.z));
  glUniform1f(g.u[kAmbient], static_cast<float>(light_.ambient));
  glUniform1f(g.u[kDiffuse], static_cast<float>(light_.diffuse));
  glUniform1f(g.u[kNearM], static_cast<float>(dc.near_m));
  glUniform1f(g.u[kLogRange], static_cast<float>(std::log(dc.far_m / dc.near_m)));
  glUniform1f(g.u[kMaxCode], static_cast<float>(dc.max_code()));
  glUniform1i(g.u[kImage], 0);
  // The z-buffer's far plane lies far beyond any depth code (codes saturate at far_m, objects still draw).
  const double n = dc.near_m, far = std::max(dc.far_m, 1.0) * 1e4;
  const double A = (far + n) / (far - n), B = -2.0 * far * n / (far - n);

  for (int f = 0; f < 6; ++f) {
    const auto& objs = per_face[static_cast<size_t>(f)];
    g.drawn[f] = !objs.empty();
    if (objs.empty()) continue;  // nothing reaches the face: nothing drawn, nothing read
    ++st.faces_rendered;
    const FaceFrame& F = face_frames()[static_cast<size_t>(f)];
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g.fbo[f]);
    glm::mat4 clip(0.0f);  // rows: u = rel.a, v = rel.b, z = A w + B, w = rel.fwd (column-major storage)
    for (int c = 0; c < 3; ++c) {
      clip[c][0] = static_cast<float>(F.a[c]);
      clip[c][1] = static_cast<float>(F.b[c]);
      clip[c][2] = static_cast<float>(A * F.fwd[c]);
      clip[c][3] = static_cast<float>(F.fwd[c]);
    }
    clip[3][2] = static_cast<float>(B);
    glUniformMatrix4fv(g.u[kFaceClip], 1, GL_FALSE, glm::value_ptr(clip));
    const GLfloat black[4] = {0, 0, 0, 0};
    const GLuint none[4] = {kNoCode, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, black);
    glClearBufferuiv(GL_COLOR, 1, none);
    const GLfloat far_depth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    glBeginQuery(GL_SAMPLES_PASSED, g.query[f]);  // fragments that passed the depth test: texels filled
    for (size_t i : objs) {
      const SceneObject& o = scene.objects[i];
      const Mesh& m = *o.mesh;
      st.triangles += static_cast<int64_t>(m.triangles());
      const bool smooth = o.material.smooth && !m.normals.empty();
      const MeshBuffers& b = g.mesh(o.mesh, smooth);
      glm::dmat4 rel = model[i];
      rel[3] = glm::dvec4(glm::dvec3(rel[3]) - eye, 1.0);
      const glm::mat4 relf(rel);
      const glm::mat3 nm(glm::inverseTranspose(glm::dmat3(model[i])));
      glUniformMatrix4fv(g.u[kModelRel], 1, GL_FALSE, glm::value_ptr(relf));
      glUniformMatrix3fv(g.u[kNormalMat], 1, GL_FALSE, glm::value_ptr(nm));
      glUniform3f(g.u[kColor], static_cast<float>(o.material.color.r), static_cast<float>(o.material.color.g),
                  static_cast<float>(o.material.color.b));
      const bool textured = o.material.texture && !m.uvs.empty();
      glUniform1i(g.u[kTextured], textured ? 1 : 0);
      if (textured) {
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, g.texture(o.material.texture));
      }
      glUniform1ui(g.u[kObjectId], static_cast<GLuint>(i + 1));
      glBindVertexArray(b.vao);
      if (b.indexed)
        glDrawElements(GL_TRIANGLES, b.count, GL_UNSIGNED_INT, nullptr);
      else
        glDrawArrays(GL_TRIANGLES, 0, b.count);
    }
    glEndQuery(GL_SAMPLES_PASSED);
  }
  for (int f = 0; f < 6; ++f) {
    if (per_face[static_cast<size_t>(f)].empty()) continue;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, g.fbo[f]);
    GLuint64 passed = 0;
    glGetQueryObjectui64v(g.query[f], GL_QUERY_RESULT, &passed);
    st.texels_filled += static_cast<int64_t>(passed);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, S, S, GL_RGBA, GL_UNSIGNED_BYTE, g.color[f].data());
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glReadPixels(0, 0, S, S, GL_RG_INTEGER, GL_UNSIGNED_INT, g.code[f].data());
    check_gl("rendering a cube face");
  }
  return st;
}

RenderStats GlCubeRenderer::render(const Scene& scene, const std::vector<size_t>& objects, double t,
                                   const glm::dvec3& eye, dp::DisplayMemoryBank& bank, std::vector<FaceImage>* visible) {
  const dp::MemoryFormat& fmt = bank.format();
  const int S = fmt.face_size;
  RenderStats st = draw(scene, objects, t, eye, S, fmt.depth_bits);
  const Gl& g = *gl_;
  // As the software renderer stores: words per texel in parallel, the tiles reserved at once, the faces
  // copied into the bank in parallel.
  // Window row y is memory row y (the face's clip space maps texel rows upward).
  const size_t n = static_cast<size_t>(S) * static_cast<size_t>(S);
  words_.resize(6 * n);
  const uint64_t empty = fmt.empty_word();
  const dp::Rgb8Packer pack(fmt);
  const int threads = threads_ > 0 ? threads_ : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int f = 0; f < 6; ++f) {
    if (!g.drawn[f]) continue;
    uint64_t* out = words_.data() + static_cast<size_t>(f) * n;
    const uint32_t* code = g.code[f].data();
    const uint8_t* color = g.color[f].data();
    for (size_t k = 0; k < n; ++k)
      out[k] = code[2 * k] == kNoCode ? empty
                                      : (uint64_t{code[2 * k]} << 32) | pack(color[4 * k], color[4 * k + 1], color[4 * k + 2]);
  }
  bank.clear_back();
  std::array<const uint64_t*, 6> drawn{};
  for (int f = 0; f < 6; ++f)
    if (g.drawn[f]) drawn[static_cast<size_t>(f)] = words_.data() + static_cast<size_t>(f) * n;
  st.texels_written += bank.reserve_faces(drawn, empty);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int f = 0; f < 6; ++f)
    if (drawn[static_cast<size_t>(f)]) bank.store_face(f, drawn[static_cast<size_t>(f)], empty);
  if (visible) {
    visible->assign(6, FaceImage{});
    for (int f = 0; f < 6; ++f) {
      std::vector<uint32_t>& ids = (*visible)[static_cast<size_t>(f)].object;
      (*visible)[static_cast<size_t>(f)].size = S;
      if (!drawn[static_cast<size_t>(f)]) continue;
      ids.assign(n, 0);
      const uint64_t* in = drawn[static_cast<size_t>(f)];
      for (size_t k = 0; k < n; ++k) ids[k] = in[k] == empty ? 0u : g.code[f][2 * k + 1];
    }
  }
  bank.commit();
  return st;
}

}  // namespace arp::host
