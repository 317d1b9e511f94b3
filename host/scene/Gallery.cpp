#include "Gallery.hpp"

#include <filesystem>

#include "ModelImport.hpp"
#include "host/cubemap/BitmapFont.hpp"
#include <cmath>
#include "Primitives.hpp"
#include "common/InputError.hpp"

namespace arp::host {

namespace {
constexpr double kRoom = 8.0, kHeight = 3.0, kWall = 0.2, kDoor = 1.6;
constexpr int kRoomsX = 3, kRoomsZ = 2;

std::shared_ptr<const Mesh> box(const glm::dvec3& s) { return std::make_shared<Mesh>(make_box(s)); }

Material mat(const glm::dvec3& color, bool smooth, std::shared_ptr<const RgbImage> texture = nullptr) {
  Material m;
  m.color = color;
  m.smooth = smooth;
  m.texture = std::move(texture);
  return m;
}

// The pictures' canvases, drawn in code so the gallery needs no image files:
// rings, stripes, a checkerboard, a sunset, a lettering and a Mondrian.
std::shared_ptr<const RgbImage> painting(int kind) {
  auto img = std::make_shared<RgbImage>(160, 104);
  for (int y = 0; y < img->height; ++y)
    for (int x = 0; x < img->width; ++x) {
      uint8_t* p = img->px(x, y);
      const double u = (x + 0.5) / img->width, v = (y + 0.5) / img->height;
      glm::dvec3 c{0.9, 0.9, 0.85};
      switch (kind % 6) {
        case 0: c = std::fmod(std::hypot(u - 0.5, (v - 0.5) * 0.65) * 14, 1.0) < 0.5 ? glm::dvec3(0.8, 0.15, 0.1) : glm::dvec3(0.95, 0.85, 0.3); break;
        case 1: c = std::fmod((u + v) * 8, 1.0) < 0.5 ? glm::dvec3(0.1, 0.3, 0.7) : glm::dvec3(0.9, 0.9, 0.95); break;
        case 2: c = ((x / 20) + (y / 13)) % 2 ? glm::dvec3(0.05, 0.05, 0.05) : glm::dvec3(0.95, 0.95, 0.9); break;
        case 3: c = std::hypot(u - 0.5, v - 0.55) < 0.15 ? glm::dvec3(1, 0.85, 0.3) : glm::dvec3(0.9 - 0.5 * v, 0.35 + 0.2 * v, 0.3 + 0.5 * v); break;
        case 4: c = glm::dvec3(0.15, 0.45, 0.25); break;
        default: c = u < 0.3 ? (v < 0.6 ? glm::dvec3(0.85, 0.1, 0.1) : glm::dvec3(0.95, 0.95, 0.9))
                             : (v < 0.35 ? glm::dvec3(0.95, 0.95, 0.9) : (u > 0.75 ? glm::dvec3(0.1, 0.2, 0.7) : glm::dvec3(0.95, 0.85, 0.1)));
          if (std::abs(u - 0.3) < 0.015 || std::abs(v - 0.35) < 0.02 || std::abs(u - 0.75) < 0.015) c = glm::dvec3(0.05);
      }
      p[0] = static_cast<uint8_t>(c.r * 255);
      p[1] = static_cast<uint8_t>(c.g * 255);
      p[2] = static_cast<uint8_t>(c.b * 255);
    }
  if (kind % 6 == 4)
    draw_text("ARP", 30, 28, 7, [&](int x, int y) {
      if (x >= 0 && y >= 0 && x < img->width && y < img->height) {
        uint8_t* q = img->px(x, y);
        q[0] = 240, q[1] = 230, q[2] = 180;
      }
    });
  return img;
}

// A wall from a to b (on the floor plane, y = 0) with an optional centred doorway.
void add_wall(Scene& s, const std::string& name, glm::dvec2 a, glm::dvec2 b, bool door, const Material& m) {
  const glm::dvec2 d = b - a;
  const double len = glm::length(d);
  const bool along_x = std::abs(d.x) > std::abs(d.y);
  auto segment = [&](double t0, double t1, double y0, double y1, const std::string& part) {
    const glm::dvec2 c = a + d * ((t0 + t1) / 2 / len);
    const double l = t1 - t0;
    const glm::dvec3 size = along_x ? glm::dvec3(l, y1 - y0, kWall) : glm::dvec3(kWall, y1 - y0, l);
    add_object(s, name + part, box(size), {c.x, (y0 + y1) / 2, c.y}, m);
  };
  if (!door) {
    segment(0, len, 0, kHeight, "");
    return;
  }
  const double h = (len - kDoor) / 2;
  segment(0, h, 0, kHeight, " left");
  segment(len - h, len, 0, kHeight, " right");
  segment(h, len - h, 2.2, kHeight, " lintel");
}

struct Exhibit {
  const char* name;
  const char* relative;  // below a model root
  double size;           // bounding diameter, metres
  glm::dvec3 color;
  double spin;           // deg/s
};
}  // namespace

Scene make_gallery(const std::vector<std::string>& model_roots) {
  Scene s;
  s.name = "gallery";
  s.extent_min = {-kRoom / 2 - 1, -1, -kRoom * (kRoomsZ - 0.5) - 1};
  s.extent_max = {kRoom * (kRoomsX - 0.5) + 1, kHeight + 1, kRoom / 2 + 1};
  const Material wall = mat({0.85, 0.82, 0.75}, false), floor = mat({0.45, 0.35, 0.25}, false),
                 ceiling = mat({0.95, 0.95, 0.95}, false);
  const Material pillar = mat({0.7, 0.7, 0.72}, true), plinth = mat({0.3, 0.3, 0.32}, false),
                 frame = mat({0.55, 0.4, 0.15}, false);
  const double x0 = -kRoom / 2, x1 = kRoom * (kRoomsX - 0.5), z0 = kRoom / 2, z1 = -kRoom * (kRoomsZ - 0.5);
  add_object(s, "floor", box({x1 - x0, 0.1, z0 - z1}), {(x0 + x1) / 2, -0.05, (z0 + z1) / 2}, floor);
  add_object(s, "ceiling", box({x1 - x0, 0.1, z0 - z1}), {(x0 + x1) / 2, kHeight + 0.05, (z0 + z1) / 2}, ceiling);
  // Outer walls, then the partitions between rooms (each with a doorway).
  add_wall(s, "outer wall south", {x0, z0}, {x1, z0}, false, wall);
  add_wall(s, "outer wall north", {x0, z1}, {x1, z1}, false, wall);
  add_wall(s, "outer wall west", {x0, z0}, {x0, z1}, false, wall);
  add_wall(s, "outer wall east", {x1, z0}, {x1, z1}, false, wall);
  for (int i = 1; i < kRoomsX; ++i)
    for (int k = 0; k < kRoomsZ; ++k) {
      const double x = kRoom * (i - 0.5), za = kRoom * (0.5 - k), zb = kRoom * (-0.5 - k);
      add_wall(s, "partition x" + std::to_string(i) + " room " + std::to_string(k), {x, za}, {x, zb}, true, wall);
    }
  for (int i = 0; i < kRoomsX; ++i) {
    const double xa = kRoom * (i - 0.5), xb = kRoom * (i + 0.5), z = -kRoom / 2;
    add_wall(s, "partition z room " + std::to_string(i), {xa, z}, {xb, z}, true, wall);
  }
  auto pillar_mesh = std::make_shared<Mesh>(make_cylinder(0.25, kHeight, 24));
  auto plinth_mesh = box({0.8, 1.0, 0.8});
  auto frame_mesh = box({1.6, 1.1, 0.06});
  const glm::dvec3 picture_colors[] = {{0.8, 0.2, 0.2}, {0.2, 0.5, 0.8}, {0.2, 0.7, 0.3}, {0.9, 0.8, 0.2}, {0.6, 0.3, 0.7}, {0.9, 0.5, 0.2}};
  int picture = 0;
  for (int i = 0; i < kRoomsX; ++i)
    for (int k = 0; k < kRoomsZ; ++k) {
      const glm::dvec3 c{kRoom * i, 0, -kRoom * k};
      const std::string room = "room " + std::to_string(i) + "," + std::to_string(k);
      for (double dx : {-2.5, 2.5})
        add_object(s, room + " pillar", pillar_mesh, c + glm::dvec3(dx, kHeight / 2, 2.5), pillar);
      // Two framed pictures on the room's outer-facing walls.
      const double zwall = k == 0 ? kRoom / 2 - kWall / 2 - 0.04 : -kRoom / 2 + kWall / 2 + 0.04;
      for (double dx : {-1.8, 1.8}) {
        const glm::dvec3 p = c + glm::dvec3(dx, 1.7, k == 0 ? zwall : zwall);
        add_object(s, room + " frame", frame_mesh, p, frame);
        auto canvas = std::make_shared<Mesh>(make_quad(1.4, 0.9));
        (void)picture_colors;
        SceneObject& o = add_object(s, room + " picture", canvas, p + glm::dvec3(0, 0, k == 0 ? -0.035 : 0.035),
                                    mat({1, 1, 1}, false, painting(picture++)));
        o.rotation_deg.x = k == 0 ? 180 : 0;  // facing into the room
      }
      add_object(s, room + " plinth", plinth_mesh, c + glm::dvec3(0, 0.5, -1.5), plinth);
    }
  // Exhibits: real models where the packages are installed.
  const std::vector<std::string> roots =
      model_roots.empty() ? std::vector<std::string>{"/usr/share/glmark2/models", "/usr/share/assimp/models"} : model_roots;
  const Exhibit exhibits[] = {
      {"bunny", "bunny.obj", 0.9, {0.85, 0.8, 0.7}, 20},
      {"horse", "horse.3ds", 0.9, {0.5, 0.35, 0.2}, 0},
      {"cat", "cat.3ds", 0.8, {0.6, 0.6, 0.65}, -15},
      {"duck", "Collada/duck.dae", 0.7, {0.95, 0.8, 0.1}, 0},
      {"Wuson", "PLY/Wuson.ply", 0.8, {0.8, 0.5, 0.4}, 30},
      {"spider", "OBJ/spider.obj", 0.9, {0.3, 0.3, 0.3}, 0},
  };
  int n = 0;
  for (const Exhibit& e : exhibits) {
    const int i = n % kRoomsX, k = n / kRoomsX;
    ++n;
    const glm::dvec3 top{kRoom * i, 1.0, -kRoom * k - 1.5};
    std::shared_ptr<const Mesh> mesh;
    std::string found;
    bool refused = false;
    for (const auto& r : roots) {
      const std::string p = (std::filesystem::path(r) / e.relative).string();
      if (std::filesystem::exists(p)) {
        try {
          Mesh m = import_model(p);
          const Sphere b = bounding_sphere(m);
          for (auto& v : m.positions) v -= b.center;  // spin about its own centre
          mesh = std::make_shared<Mesh>(std::move(m));
          found = p;
        } catch (const InputError& err) {
          s.notes.push_back(std::string("exhibit ") + e.name + ": " + err.what());
          refused = true;
        }
        break;
      }
    }
    if (!mesh) {
      mesh = std::make_shared<Mesh>(make_sphere(0.5, 32));
      s.notes.push_back(std::string("exhibit ") + e.name + ": " + e.relative +
                        (refused ? " refused" : " not found (Debian packages glmark2-data, assimp-testmodels)") +
                        "; a sphere stands in");
    }
    SceneObject& o = add_object(s, std::string("exhibit ") + e.name, mesh, top, mat(e.color, true));
    const double scale = o.model_bound.radius > 0 ? e.size / (2 * o.model_bound.radius) : 1.0;
    o.scale = glm::dvec3(scale);
    // Stand it on the plinth: its bound's lowest point at the plinth top.
    o.position = top - glm::dvec3(o.model_bound.center * scale) + glm::dvec3(0, o.model_bound.radius * scale, 0);
    o.animation.spin_deg_per_s = e.spin;
    (void)found;
  }
  return s;
}

std::vector<glm::dvec3> gallery_walk() {
  const double y = 1.6;
  return {{0, y, 1.5},  {kRoom, y, 1.5},  {2 * kRoom, y, 1.5},  {2 * kRoom, y, -kRoom},
          {kRoom, y, -kRoom}, {0, y, -kRoom}, {0, y, 1.5}};
}

}  // namespace arp::host
