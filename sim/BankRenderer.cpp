#include "BankRenderer.hpp"

#include <memory>

#include "common/InputError.hpp"
#include "host/render/gl/GlCubeRenderer.hpp"

namespace arp::sim {

void check_renderer(const MemoryContents& m) {
  if (m.renderer != "software" && m.renderer != "gl")
    throw InputError("--renderer", m.renderer, std::string("expected ") + kRendererNames);
  if (m.renderer != "software" && m.scene.empty()) throw InputError("--renderer", m.renderer, "draws a scene: it needs --scene");
}

host::HostSimulation::BankRenderer make_bank_renderer(const std::string& name) {
  if (name == "software") {
    return [r = host::CubeFaceRenderer{}](const host::Scene& s, const std::vector<size_t>& objs, double t,
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
    throw InputError("--renderer", "gl", std::string(e.what()) + " (--renderer software needs no OpenGL)");
  }
  return [gl](const host::Scene& s, const std::vector<size_t>& objs, double t, const glm::dvec3& eye,
              dp::DisplayMemoryBank& bank, std::vector<host::FaceImage>* visible) {
    return gl->render(s, objs, t, eye, bank, visible);
  };
}

}  // namespace arp::sim
