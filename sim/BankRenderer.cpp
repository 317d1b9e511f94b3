#include "BankRenderer.hpp"

#include <memory>

#include "common/InputError.hpp"
#include "host/render/gl/GlCubeRenderer.hpp"

namespace arp::sim {

namespace {
constexpr const char* kNoOpenGl = " (--renderer software needs no OpenGL)";
}  // namespace

void check_renderer(const MemoryContents& m, int depth_bits) {
  if (m.renderer != "software" && m.renderer != "gl")
    throw InputError("--renderer", m.renderer, std::string("expected ") + kRendererNames);
  if (m.renderer != "software" && m.scene.empty()) throw InputError("--renderer", m.renderer, "draws a scene: it needs --scene");
  if (!m.face_culling && m.scene.empty()) throw InputError("--no-face-culling", "", "culls a scene's objects: it needs --scene");
  if (m.renderer == "gl" && depth_bits > host::GlCubeRenderer::kMaxDepthBits)
    throw InputError("--renderer", m.renderer,
                     "codes depth in float, exact to " + std::to_string(host::GlCubeRenderer::kMaxDepthBits) +
                         " bits; memory.depth_bits is " + std::to_string(depth_bits) + " (--renderer software codes any width)");
}

host::HostSimulation::BankRenderer make_bank_renderer(const std::string& name, int threads, bool face_culling) {
  if (name == "software") {
    host::CubeFaceRenderer soft;
    soft.set_threads(threads);
    soft.set_face_culling(face_culling);
    return [r = soft](const host::Scene& s, const std::vector<size_t>& objs, double t,
                                          const glm::dvec3& eye, dp::DisplayMemoryBank& bank,
                                          std::vector<host::FaceImage>* visible) {
      return r.render(s, objs, t, eye, bank, visible);
    };
  }
  if (name != "gl") throw InputError("--renderer", name, std::string("expected ") + kRendererNames);
  std::shared_ptr<host::GlCubeRenderer> gl;
  try {
    gl = std::make_shared<host::GlCubeRenderer>();
  } catch (const host::GlUnavailable& e) {
    throw InputError("--renderer", "gl", std::string(e.what()) + kNoOpenGl);
  }
  gl->set_threads(threads);
  gl->set_face_culling(face_culling);
  return [gl](const host::Scene& s, const std::vector<size_t>& objs, double t, const glm::dvec3& eye,
              dp::DisplayMemoryBank& bank, std::vector<host::FaceImage>* visible) {
    try {
      return gl->render(s, objs, t, eye, bank, visible);
    } catch (const host::GlUnavailable& e) {  // e.g. a framebuffer this driver will not make at this face size
      throw InputError("--renderer", "gl", std::string(e.what()) + kNoOpenGl);
    }
  };
}

}  // namespace arp::sim
