#include "AccuracyHarness.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <random>

#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"
#include "reference/golden/GoldenReference.hpp"
#include "common/Units.hpp"

namespace arp::accuracy {

using namespace arp::dp;

void Stats::merge(const Stats& o) {
  samples += o.samples;
  exact += o.exact;
  face_mismatch += o.face_mismatch;
  max_error = std::max(max_error, o.max_error);
  sum_error += o.sum_error;
  ties += o.ties;
  face_ties += o.face_ties;
  tie_low += o.tie_low;
  tie_high += o.tie_high;
  tie_rule_face += o.tie_rule_face;
  tie_other_face += o.tie_other_face;
  tie_off += o.tie_off;
  nontie_exact += o.nontie_exact;
  arith_errors += o.arith_errors;
}

__extension__ typedef __int128 i128;  // S * (ma + sc): up to 2^14 * 2^61

void exact_product(const Mat3q& m, const Vec3q& v, int64_t p[3]) {
  // |entries| < 2^29 at the widest widths: three products below 2^58 each fit 64 bits.
  for (int r = 0; r < 3; ++r)
    p[r] = int64_t{m.m[3 * r]} * v.x + int64_t{m.m[3 * r + 1]} * v.y + int64_t{m.m[3 * r + 2]} * v.z;
}

namespace {

// sc, tc, ma of the OpenGL cube-map table (the golden reference's face_coords), on exact integers.
void exact_face_coords(const int64_t p[3], int face, int64_t& sc, int64_t& tc, int64_t& ma) {
  const int64_t x = p[0], y = p[1], z = p[2];
  switch (face) {
    case 0: sc = -z; tc = -y; ma = x; break;
    case 1: sc = z; tc = -y; ma = -x; break;
    case 2: sc = x; tc = z; ma = y; break;
    case 3: sc = x; tc = -z; ma = -y; break;
    case 4: sc = x; tc = -y; ma = z; break;
    default: sc = -x; tc = -y; ma = -z; break;
  }
}

// One texel coordinate S (1 + c/ma) / 2 = S (ma + c) / (2 ma), ma > 0 and
// |c| <= ma so it is in [0, S]: its floor and whether it is an integer.
struct ExactCoord {
  int64_t floor;
  bool integer;
};
ExactCoord exact_coord(int64_t c, int64_t ma, int S) {
  const i128 num = static_cast<i128>(S) * (static_cast<i128>(ma) + c);
  const i128 den = static_cast<i128>(2) * ma;
  return {static_cast<int64_t>(num / den), num % den == 0};
}

int clamp_texel(int64_t k, int S) { return static_cast<int>(std::clamp<int64_t>(k, 0, S - 1)); }

// Texel t is right on an axis whose exact coordinate is c: floor(c), or at an
// integer k either neighbour k - 1 or k (each clamped to the face).
bool coord_right(const ExactCoord& c, int t, int S) {
  return t == clamp_texel(c.floor, S) || (c.integer && t == clamp_texel(c.floor - 1, S));
}

}  // namespace

ExactAddress exact_address(const int64_t p[3], int S) {
  ExactAddress e;
  const int64_t a[3] = {p[0] < 0 ? -p[0] : p[0], p[1] < 0 ? -p[1] : p[1], p[2] < 0 ? -p[2] : p[2]};
  const int64_t top = std::max({a[0], a[1], a[2]});
  if (top == 0) {  // a zero vector (degenerate widths only): the datapath reads the face centre of +X
    e.x = e.y = clamp_texel(S / 2, S);
    e.tied_faces = 1u;
    return e;
  }
  e.face = -1;
  for (int axis = 0; axis < 3; ++axis) {
    if (a[axis] != top) continue;
    const int f = 2 * axis + (p[axis] >= 0 ? 0 : 1);
    e.tied_faces |= 1u << f;
    if (e.face < 0) e.face = f;  // the first axis in X, Y, Z order wins
  }
  e.face_tie = (e.tied_faces & (e.tied_faces - 1)) != 0;
  int64_t sc, tc, ma;
  exact_face_coords(p, e.face, sc, tc, ma);
  const ExactCoord u = exact_coord(sc, ma, S), v = exact_coord(tc, ma, S);
  e.u_tie = u.integer && u.floor > 0 && u.floor < S;
  e.v_tie = v.integer && v.floor > 0 && v.floor < S;
  e.x = clamp_texel(u.floor, S);
  e.y = clamp_texel(v.floor, S);
  return e;
}

bool texel_right(const int64_t p[3], int S, int face, int x, int y) {
  const ExactAddress e = exact_address(p, S);
  if (face < 0 || face > 5 || !(e.tied_faces & (1u << face))) return false;
  if (!(p[0] | p[1] | p[2])) return x == e.x && y == e.y;
  int64_t sc, tc, ma;
  exact_face_coords(p, face, sc, tc, ma);
  return coord_right(exact_coord(sc, ma, S), x, S) && coord_right(exact_coord(tc, ma, S), y, S);
}

namespace {

struct Orientation {
  glm::dquat g;
  Mat3q m;
  glm::dmat3 R;
};

Orientation make_orientation(const glm::dquat& q, int mat_frac) {
  const glm::dquat n = glm::normalize(q);
  return {n, quantise_rotation(Quat{n.w, n.x, n.y, n.z}, mat_frac), golden::rotation(n)};
}

class Evaluator {
 public:
  Evaluator(const FunctionalModel& model, int keep) : model_(model), keep_(keep) {
    S_ = model.config().memory.face_size;
    scale_ = std::ldexp(1.0, -model.config().widths.texel_frac);
  }
  // One sample: exact head-frame direction d (golden input) and its datapath code dq.
  void eval(const char* set, const glm::dvec3& d, const Vec3q& dq, const Orientation& o, Stats& st,
            std::vector<WorstCase>& worst) const {
    const CubeAddress a = generate_address(rotate(o.m, dq, model_.rotate_params()), model_.address_params());
    const glm::dvec3 w = o.R * d;
    const golden::Address g = golden::address(w, S_);
    count_exact(o.m, dq, a, g, st);
    const double du = static_cast<double>(a.u) * scale_, dv = static_cast<double>(a.v) * scale_;
    double err;
    if (a.face == g.face) {
      err = std::hypot(du - g.u, dv - g.v);
    } else {
      double pu, pv;
      err = golden::project_onto_face(w, a.face, S_, pu, pv) ? std::hypot(du - pu, dv - pv) : 2.0 * S_;
      ++st.face_mismatch;
    }
    ++st.samples;
    st.exact += (a.face == g.face && a.x == g.x && a.y == g.y) ? 1 : 0;
    st.max_error = std::max(st.max_error, err);
    st.sum_error += err;
    const bool duplicate = !worst.empty() && std::any_of(worst.begin(), worst.end(), [&](const WorstCase& c) {
      return c.error == err && c.dir[0] == d.x && c.dir[1] == d.y && c.dir[2] == d.z;
    });
    if (keep_ > 0 && !duplicate && (worst.size() < static_cast<size_t>(keep_) || err > worst.back().error)) {
      WorstCase wc;
      wc.set = set;
      wc.error = err;
      wc.dir[0] = d.x; wc.dir[1] = d.y; wc.dir[2] = d.z;
      wc.quat[0] = o.g.w; wc.quat[1] = o.g.x; wc.quat[2] = o.g.y; wc.quat[3] = o.g.z;
      wc.golden_face = g.face; wc.datapath_face = a.face;
      wc.golden_uv[0] = g.u; wc.golden_uv[1] = g.v;
      wc.datapath_uv[0] = du; wc.datapath_uv[1] = dv;
      worst.push_back(wc);
      std::sort(worst.begin(), worst.end(), [](const WorstCase& x, const WorstCase& y) { return x.error > y.error; });
      if (worst.size() > static_cast<size_t>(keep_)) worst.pop_back();
    }
  }

 private:
  // Ties and errors against the exact address of the datapath's own inputs,
  // axis by axis on the face the datapath read: a tied coordinate (an integer,
  // the face's border included) is right on either texel beside it, an untied
  // one only on its floor.
  void count_exact(const Mat3q& m, const Vec3q& v, const CubeAddress& a, const golden::Address& g, Stats& st) const {
    int64_t p[3];
    exact_product(m, v, p);
    const ExactAddress e = exact_address(p, S_);
    const bool on_tied_face = (e.tied_faces >> a.face) & 1u;
    bool tied_off = e.face_tie && !on_tied_face;     // a tie resolved to no texel beside its boundary
    bool untied_off = !e.face_tie && !on_tied_face;  // the datapath's own rounding
    uint64_t low = 0, high = 0;
    if (on_tied_face && (p[0] | p[1] | p[2])) {
      int64_t sc, tc, ma;
      exact_face_coords(p, a.face, sc, tc, ma);
      for (int axis = 0; axis < 2; ++axis) {
        const ExactCoord c = exact_coord(axis == 0 ? sc : tc, ma, S_);
        const int t = axis == 0 ? a.x : a.y;
        if (!c.integer) {
          untied_off = untied_off || t != clamp_texel(c.floor, S_);
        } else if (!coord_right(c, t, S_)) {
          tied_off = true;
        } else if (c.floor > 0 && c.floor < S_) {  // a texel boundary inside the face: k - 1 below, k above
          (t == c.floor ? high : low) += 1;
        }
      }
    }
    st.arith_errors += untied_off ? 1 : 0;
    if (!e.tie()) {
      st.nontie_exact += (a.face == g.face && a.x == g.x && a.y == g.y) ? 1 : 0;
      return;
    }
    ++st.ties;
    st.tie_off += tied_off ? 1 : 0;
    st.tie_low += low;
    st.tie_high += high;
    if (e.face_tie) {
      ++st.face_ties;
      st.tie_rule_face += a.face == e.face ? 1 : 0;
      st.tie_other_face += (a.face != e.face && on_tied_face) ? 1 : 0;
    }
  }

  const FunctionalModel& model_;
  int keep_;
  int S_;
  double scale_;
};

void merge_worst(std::vector<WorstCase>& into, const std::vector<WorstCase>& from, int keep) {
  for (const WorstCase& w : from) {  // both eyes share directions: one entry per input
    const bool seen = std::any_of(into.begin(), into.end(), [&](const WorstCase& c) {
      return c.error == w.error && c.dir[0] == w.dir[0] && c.dir[1] == w.dir[1] && c.dir[2] == w.dir[2];
    });
    if (!seen) into.push_back(w);
  }
  std::sort(into.begin(), into.end(), [](const WorstCase& x, const WorstCase& y) { return x.error > y.error; });
  if (into.size() > static_cast<size_t>(keep)) into.resize(static_cast<size_t>(keep));
}

glm::dquat random_quat(std::mt19937_64& rng) {  // uniform over rotations (Shoemake)
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double u1 = U(rng), u2 = U(rng), u3 = U(rng);
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  return glm::dquat(b * std::cos(2 * kPi * u3), a * std::sin(2 * kPi * u2), a * std::cos(2 * kPi * u2),
                    b * std::sin(2 * kPi * u3));
}

Vec3q quantise_dir(const glm::dvec3& d, int frac) {
  return {static_cast<int32_t>(quantise_real(d.x, frac, frac + 2)), static_cast<int32_t>(quantise_real(d.y, frac, frac + 2)),
          static_cast<int32_t>(quantise_real(d.z, frac, frac + 2))};
}

std::vector<glm::dquat> directed_rotations() {
  const glm::dvec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  std::vector<glm::dquat> r{glm::dquat(1, 0, 0, 0)};
  for (const glm::dvec3& ax : {X, Y, Z})
    for (double deg : {90.0, -90.0, 180.0}) r.push_back(glm::angleAxis(glm::radians(deg), ax));
  r.push_back(glm::angleAxis(glm::radians(180.0), glm::normalize(glm::dvec3(1, 1, 0))));
  r.push_back(glm::angleAxis(glm::radians(180.0), glm::normalize(glm::dvec3(1, 1, 1))));
  r.push_back(glm::angleAxis(glm::radians(120.0), glm::normalize(glm::dvec3(1, 1, 1))));
  r.push_back(glm::angleAxis(glm::radians(240.0), glm::normalize(glm::dvec3(1, 1, 1))));
  r.push_back(glm::angleAxis(glm::radians(37.0), glm::normalize(glm::dvec3(0.3, 0.5, 0.8))));
  return r;
}

std::vector<glm::dvec3> directed_directions() {
  std::vector<glm::dvec3> d;
  for (int axis = 0; axis < 3; ++axis)
    for (double s : {1.0, -1.0}) { glm::dvec3 v(0.0); v[axis] = s; d.push_back(v); }  // major = 1
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b)
      for (double sa : {1.0, -1.0})
        for (double sb : {1.0, -1.0}) {  // cube edges: two-way ties
          glm::dvec3 v(0.0); v[a] = sa; v[b] = sb; d.push_back(glm::normalize(v));
          for (int k : {4, 8, 12, 16, 20, 30}) {  // just off the edge, both sides
            glm::dvec3 w = v; w[b] *= 1.0 - std::ldexp(1.0, -k); d.push_back(glm::normalize(w));
            w = v; w[a] *= 1.0 - std::ldexp(1.0, -k); d.push_back(glm::normalize(w));
          }
        }
  for (double sx : {1.0, -1.0})
    for (double sy : {1.0, -1.0})
      for (double sz : {1.0, -1.0}) d.push_back(glm::normalize(glm::dvec3(sx, sy, sz)));  // corners: major 1/sqrt3
  d.push_back(glm::dvec3(1.0, -0.0, 0.0));  // signed zeros
  d.push_back(glm::dvec3(-0.0, 1.0, -0.0));
  d.push_back(glm::dvec3(0.0, -0.0, -1.0));
  d.push_back(glm::normalize(glm::dvec3(1.0, 1e-12, -1e-12)));  // tiny components
  d.push_back(glm::normalize(glm::dvec3(1e-300, 1.0, -1e-300)));
  d.push_back(glm::normalize(glm::dvec3(-1e-9, 1e-9, -1.0)));
  return d;
}

// Every pixel of every row_step-th display line of each eye at one view; the
// golden directions from configuration gc (whose lens `table` quantises).
Stats eval_frame(const Evaluator& ev, const char* set, const ArpConfig& gc, const LensVectorTable& table,
                 const Orientation& o, int row_step, int keep, std::vector<WorstCase>& worst) {
  const int W = table.width(), H = table.height(), E = table.eyes();
  const int rows = (H + row_step - 1) / row_step;
  Stats total;
#pragma omp parallel
  {
    Stats st;
    std::vector<WorstCase> wl;
#pragma omp for schedule(dynamic, 8)
    for (int line = 0; line < E * rows; ++line) {
      const int e = line / rows, y = line % rows * row_step;
      for (int x = 0; x < W; ++x) ev.eval(set, golden::lens_direction(gc, e, x, y), table.at(e, x, y), o, st, wl);
    }
#pragma omp critical
    {
      total.merge(st);
      merge_worst(worst, wl, keep);
    }
  }
  return total;
}

void fill_color_test_memories(DisplayMemorySet& mem) {
  const auto& fmt = mem.format();
  const int S = fmt.face_size;
  host::load_into_memories(mem, 0, host::make_calibration_pattern(S), host::far_depth(fmt));
  // Nearer squares in memory 1 and, overlapping at the same depth, memory 2:
  // object edges between memories and the composition tie rule.
  const uint32_t near = fmt.empty_depth() / 2;
  for (int e = 0; e < mem.eyes(); ++e) {
    for (int m = 1; m < std::min(3, mem.count()); ++m) {
      auto& bank = mem.bank(e, m);
      bank.clear_back();
      for (int f = 0; f < 6; ++f)
        for (int y = 0; y < S; ++y)
          for (int x = 0; x < S; ++x) {
            const bool in1 = (x / std::max(1, S / 8) + y / std::max(1, S / 8)) % 3 == 0;
            const bool in2 = (x / std::max(1, S / 5)) % 2 == 0 && (y / std::max(1, S / 5)) % 2 == 0;
            if (m == 1 && in1) bank.write(f, x, y, fmt.pack_rgb8(250, 250, 250), near);
            if (m == 2 && in2) bank.write(f, x, y, fmt.pack_rgb8(20, 20, 120), near);
          }
      bank.commit();
      bank.vblank();
    }
  }
}

}  // namespace

double edge_fov_deg(int W) {
  if (W < 2) return 90.0;  // one column: its centre is the lens centre, never on an edge
  // The column's centre is (W - 1) / W half-widths from the lens centre; at
  // tan(fov/2) = W / (W - 1) its direction has |x| = |z|.
  return 2.0 * rad_to_deg(std::atan(static_cast<double>(W) / (W - 1)));
}

std::vector<View> aligned_views(const ArpConfig& cfg) {
  std::vector<View> v;
  auto add = [&](const char* name, double yaw, double pitch, double roll) {
    v.push_back({name, from_yaw_pitch_roll_deg(yaw, pitch, roll), cfg.lens});
  };
  add("ahead", 0, 0, 0);
  add("yaw 90", 90, 0, 0);
  add("yaw 180", 180, 0, 0);
  add("yaw 270", 270, 0, 0);
  add("pitch +90", 0, 90, 0);
  add("pitch -90", 0, -90, 0);
  add("roll 90", 0, 0, 90);
  // Straight ahead through an undistorted, centred lens whose first and last
  // columns sit on the cube edges between -Z and -X / +X: face ties.
  LensConfig edge;
  edge.fov_deg = edge_fov_deg(cfg.timing.h_active);
  char name[64];
  std::snprintf(name, sizeof name, "ahead fov %.4f", edge.fov_deg);
  v.push_back({name, Quat{1, 0, 0, 0}, edge});
  return v;
}

int worst_view(const Report& r, bool aligned) {
  int w = -1;
  for (size_t i = 0; i < r.views.size(); ++i) {
    if (r.views[i].aligned != aligned) continue;
    if (w < 0) {
      w = static_cast<int>(i);
      continue;
    }
    const Stats& a = r.views[i].stats;
    const Stats& b = r.views[static_cast<size_t>(w)].stats;
    const double ea = a.exact_share_nontie(), eb = b.exact_share_nontie();
    if (ea < eb || (ea == eb && a.max_error > b.max_error)) w = static_cast<int>(i);
  }
  return w;
}

Report run(const ArpConfig& cfg, const Options& opt) {
  const FunctionalModel model(cfg);
  const auto& lens = model.lens();
  const int W = lens.width(), H = lens.height(), E = lens.eyes();
  const int mf = cfg.widths.mat_frac, vf = cfg.widths.vec_frac;
  const Evaluator ev(model, opt.worst_kept);
  Report rep;
  rep.widths = cfg.widths;
  rep.face_size = cfg.memory.face_size;
  std::vector<WorstCase> worst;
  std::mt19937_64 rng(opt.seed);
  // Work units, roughly proportional to time: a full frame of samples is one unit.
  const double frame_px = static_cast<double>(E) * W * H;
  const int row_step = std::max(1, opt.aligned_row_step);
  const double aligned_units = opt.aligned ? static_cast<double>(aligned_views(cfg).size()) / row_step : 0.0;
  const double total = opt.frame_orientations + aligned_units + opt.random_orientations * 2.0 * opt.random_pixels / frame_px +
                       (opt.directed ? 0.05 : 0.0) + opt.color_orientations * 3.0;
  double done = 0.0;
  auto progress = [&](const char* stage, double units) {
    done += units;
    if (opt.progress) opt.progress(stage, total > 0 ? std::min(1.0, done / total) : 1.0);
  };

  // (a) every display pixel of whole-frame views: generic ones (a fixed spread
  // of yaw, pitch, roll), then those aligned with the cube axes.
  for (int i = 0; i < opt.frame_orientations; ++i) {
    const double yaw = 360.0 * i / std::max(1, opt.frame_orientations) + 13.0;
    const double pitch = 40.0 * std::sin(i + 1.0), roll = 15.0 * std::cos(i * 2.0);
    const glm::dquat q = glm::angleAxis(glm::radians(yaw), glm::dvec3(0, 1, 0)) *
                         glm::angleAxis(glm::radians(pitch), glm::dvec3(1, 0, 0)) *
                         glm::angleAxis(glm::radians(roll), glm::dvec3(0, 0, 1));
    const Orientation o = make_orientation(q, mf);
    char name[64];
    std::snprintf(name, sizeof name, "y%.0f p%.0f r%.0f", yaw, pitch, roll);
    ViewStats vs{View{name, Quat{o.g.w, o.g.x, o.g.y, o.g.z}, cfg.lens}, false, {}};
    vs.stats = eval_frame(ev, "frame", cfg, lens, o, 1, opt.worst_kept, worst);
    rep.frames.merge(vs.stats);
    rep.views.push_back(vs);
    progress("frames", 1.0);
  }
  if (opt.aligned) {
    for (const View& v : aligned_views(cfg)) {
      ArpConfig vc = cfg;
      vc.lens = v.lens;
      const LensVectorTable table(vc.lens, vc.timing, vf);
      const Orientation o = make_orientation(glm::dquat(v.q.w, v.q.x, v.q.y, v.q.z), mf);
      const std::string set = "aligned " + v.name;
      ViewStats vs{v, true, {}};
      vs.stats = eval_frame(ev, set.c_str(), vc, table, o, row_step, opt.worst_kept, worst);
      rep.aligned.merge(vs.stats);
      rep.views.push_back(vs);
      progress("aligned", 1.0 / row_step);
    }
  }

  // (b) seeded random orientations: random display pixels and random sphere directions.
  {
    std::uniform_int_distribution<int> ex(0, E - 1), px(0, W - 1), py(0, H - 1);
    std::normal_distribution<double> N01;
    std::vector<WorstCase> wl;
    for (int i = 0; i < opt.random_orientations; ++i) {
      const Orientation o = make_orientation(random_quat(rng), mf);
      for (int k = 0; k < opt.random_pixels; ++k) {
        const int e = ex(rng), x = px(rng), y = py(rng);
        ev.eval("random-pixel", golden::lens_direction(cfg, e, x, y), lens.at(e, x, y), o, rep.random, wl);
        glm::dvec3 d(N01(rng), N01(rng), N01(rng));
        if (glm::length(d) < 1e-9) d = glm::dvec3(0, 0, -1);
        d = glm::normalize(d);
        ev.eval("random-direction", d, quantise_dir(d, vf), o, rep.random, wl);
      }
      progress("random", 2.0 * opt.random_pixels / frame_px);
    }
    merge_worst(worst, wl, opt.worst_kept);
  }

  // (c) directed extremes.
  if (opt.directed) {
    std::vector<WorstCase> wl;
    std::vector<std::pair<glm::dvec3, Vec3q>> inputs;
    for (const glm::dvec3& d : directed_directions()) inputs.emplace_back(d, quantise_dir(d, vf));
    for (int e = 0; e < E; ++e)  // the widest lens angles: corners and edge midpoints
      for (int y : {0, H / 2, H - 1})
        for (int x : {0, W / 2, W - 1}) inputs.emplace_back(golden::lens_direction(cfg, e, x, y), lens.at(e, x, y));
    for (const glm::dquat& q : directed_rotations()) {
      const Orientation o = make_orientation(q, mf);
      for (const auto& in : inputs) ev.eval("directed", in.first, in.second, o, rep.directed, wl);
    }
    merge_worst(worst, wl, opt.worst_kept);
    progress("directed", 0.05);
  }

  rep.overall = rep.frames;
  rep.overall.merge(rep.random);
  rep.overall.merge(rep.directed);
  rep.worst = worst;

  // Colour of whole bilinear frames against the golden frame.
  if (opt.color_orientations > 0) {
    ArpConfig bc = cfg;
    bc.pipeline.aa = AaMode::Bilinear;
    bc.memory.faces = MemoryConfig{}.faces;  // the test pattern on every texel: the datapath's colour, not a plan's storage
    bc.memory.tiles.clear();
    bc.memory.tile_pool.clear();
    const FunctionalModel bmodel(bc);
    DisplayMemorySet mem(bc.memory, E);
    fill_color_test_memories(mem);
    std::vector<double> errs;
    for (int i = 0; i < opt.color_orientations; ++i) {
      const glm::dquat q = glm::normalize(glm::angleAxis(glm::radians(29.0 + 71.0 * i), glm::dvec3(0, 1, 0)) *
                                          glm::angleAxis(glm::radians(-21.0 + 33.0 * i), glm::dvec3(1, 0, 0)));
      HmdFrame f;
      bmodel.render(mem, OrientationStream::constant(Quat{q.w, q.x, q.y, q.z}), 0, f);
      const auto gold = golden::frame(bc, mem, q);
      const Mat3q Mq = quantise_rotation(Quat{q.w, q.x, q.y, q.z}, mf);
      const glm::dmat3 R = golden::rotation(q);
      for (size_t p = 0; p < gold.size(); ++p) {
        const int e = static_cast<int>(p / (static_cast<size_t>(W) * H));
        const int y = static_cast<int>(p / static_cast<size_t>(W) % static_cast<size_t>(H));
        const int x = static_cast<int>(p % static_cast<size_t>(W));
        const int dface = generate_address(rotate(Mq, lens.at(e, x, y), bmodel.rotate_params()), bmodel.address_params()).face;
        const int gface = golden::address(R * golden::lens_direction(bc, e, x, y), bc.memory.face_size).face;
        double e_max = 0.0;
        bool exact = true;
        for (int c = 0; c < 3; ++c) {
          const double dpv = static_cast<double>((f.pixels[p] >> ((2 - c) * f.display_bits)) & ((1u << f.display_bits) - 1));
          e_max = std::max(e_max, std::abs(dpv - gold[p][c]));
          exact = exact && dpv == std::floor(gold[p][c] + 0.5);
        }
        if (dface != gface) {
          ++rep.color.edge_pixels;
          rep.color.edge_max_error = std::max(rep.color.edge_max_error, e_max);
          continue;
        }
        errs.push_back(e_max);
        rep.color.exact += exact ? 1 : 0;
      }
      progress("colour", 3.0);
    }
    rep.color.pixels = errs.size();
    if (!errs.empty()) {
      double sum = 0.0;
      for (double e : errs) sum += e;
      rep.color.mean_error = sum / static_cast<double>(errs.size());
      const size_t k = std::min(errs.size() - 1, static_cast<size_t>(0.999 * static_cast<double>(errs.size())));
      std::nth_element(errs.begin(), errs.begin() + static_cast<std::ptrdiff_t>(k), errs.end());
      rep.color.p999_error = errs[k];
      rep.color.max_error = *std::max_element(errs.begin(), errs.end());
    }
  }
  return rep;
}

namespace {
nlohmann::json stats_json(const Stats& s) {
  return {{"samples", s.samples},
          {"exact_texel_share", s.exact_share()},
          {"face_mismatches", s.face_mismatch},
          {"max_texel_error", s.max_error},
          {"mean_texel_error", s.mean_error()},
          {"ties", s.ties},
          {"face_ties", s.face_ties},
          {"ties_low_texel", s.tie_low},
          {"ties_high_texel", s.tie_high},
          {"face_ties_rule_face", s.tie_rule_face},
          {"face_ties_other_face", s.tie_other_face},
          {"ties_off_boundary", s.tie_off},
          {"nontie_errors", s.nontie_errors()},
          {"exact_texel_share_nontie", s.exact_share_nontie()},
          {"nontie_arith_errors", s.arith_errors}};
}
std::string tie_line(const std::string& name, const Stats& s) {
  char b[300];
  std::snprintf(b, sizeof b, "  %-20s %9llu %7llu %6llu %7llu/%-7llu %6llu/%-4llu %4llu  %9.4f%% %7llu %6llu  %9.5f %10.6f\n",
                name.c_str(), static_cast<unsigned long long>(s.samples), static_cast<unsigned long long>(s.ties),
                static_cast<unsigned long long>(s.face_ties), static_cast<unsigned long long>(s.tie_low),
                static_cast<unsigned long long>(s.tie_high), static_cast<unsigned long long>(s.tie_rule_face),
                static_cast<unsigned long long>(s.tie_other_face), static_cast<unsigned long long>(s.tie_off),
                100.0 * s.exact_share_nontie(), static_cast<unsigned long long>(s.nontie_errors()),
                static_cast<unsigned long long>(s.arith_errors), s.max_error, s.mean_error());
  return b;
}
std::string tie_header(const char* first) {
  char b[300];
  std::snprintf(b, sizeof b, "  %-20s %9s %7s %6s %15s %11s %4s  %10s %7s %6s  %9s %10s\n", first, "samples", "ties",
                "faces", "tie low/high", "rule/other", "off", "non-tie-ex", "errors", "arith", "max-error",
                "mean-error");
  return b;
}
std::string worst_view_line(const Report& r, bool aligned) {
  const int w = worst_view(r, aligned);
  if (w < 0) return "";
  const ViewStats& v = r.views[static_cast<size_t>(w)];
  char b[200];
  std::snprintf(b, sizeof b, "  worst %s view: %s (non-tie exact %.4f%%, max error %.5f)\n",
                aligned ? "aligned" : "generic", v.view.name.c_str(), 100.0 * v.stats.exact_share_nontie(),
                v.stats.max_error);
  return b;
}
std::string line(const char* name, const Stats& s) {
  char b[200];
  std::snprintf(b, sizeof b, "  %-9s %10llu  %8.4f%%  %8llu  %10.5f  %10.6f\n", name,
                static_cast<unsigned long long>(s.samples), 100.0 * s.exact_share(),
                static_cast<unsigned long long>(s.face_mismatch), s.max_error, s.mean_error());
  return b;
}
}  // namespace

std::string to_text(const Report& r) {
  const auto& w = r.widths;
  std::string t;
  char b[400];
  std::snprintf(b, sizeof b,
                "widths: vectors Q1.%d, matrix Q1.%d, rotated Q1.%d (%s), divider %s (index %d bits, Q1.%d, %d "
                "Newton), quotient Q1.%d (%s), texel fraction %d bits (%s); faces %dx%d\n",
                w.vec_frac, w.mat_frac, w.rot_frac, to_string(w.rot_rounding).c_str(), to_string(w.divider).c_str(),
                w.recip_index_bits, w.recip_frac_bits, w.newton_steps, w.quot_frac, to_string(w.div_rounding).c_str(),
                w.texel_frac, to_string(w.texel_rounding).c_str(), r.face_size, r.face_size);
  t += b;
  t += "texel position error against golden (texels):\n";
  t += "  set          samples   exact-tex  face-mis   max-error  mean-error\n";
  t += line("frames", r.frames) + line("random", r.random) + line("directed", r.directed) + line("all", r.overall);
  if (r.aligned.samples) t += line("aligned", r.aligned) + "  (aligned: the axis-aligned views, not in all)\n";
  t += "exact ties: the exact product M*v of the quantised matrix and vector on a texel or face boundary,\n"
       "where either texel beside it is right (tie low/high: the datapath's texel below/above the boundary;\n"
       "rule/other: face ties on the tie rule's face or the other; off: beside no boundary). non-tie-ex and\n"
       "errors: non-ties whose nearest texel is (not) golden's; arith: off the exact texel of the quantised\n"
       "inputs on an untied axis (the datapath's rounding alone):\n";
  t += tie_header("set");
  t += tie_line("frames", r.frames) + tie_line("random", r.random) + tie_line("directed", r.directed) +
       tie_line("all", r.overall);
  if (r.aligned.samples) t += tie_line("aligned", r.aligned);
  if (!r.views.empty()) {
    t += "whole-frame views (generic, then aligned with the cube axes):\n";
    t += tie_header("view");
    for (const ViewStats& v : r.views) t += tie_line((v.aligned ? "A " : "G ") + v.view.name, v.stats);
    t += worst_view_line(r, false) + worst_view_line(r, true);
  }
  std::snprintf(b, sizeof b,
                "bilinear colour error (display LSB): max %.3f, 99.9%% %.3f, mean %.4f, exact %.3f%% of %llu pixels;\n"
                "  cube-edge pixels where the face differs: %llu (max %.3f)\n",
                r.color.max_error, r.color.p999_error, r.color.mean_error,
                r.color.pixels ? 100.0 * static_cast<double>(r.color.exact) / static_cast<double>(r.color.pixels) : 0.0,
                static_cast<unsigned long long>(r.color.pixels), static_cast<unsigned long long>(r.color.edge_pixels),
                r.color.edge_max_error);
  t += b;
  t += "worst inputs:\n";
  for (const auto& wc : r.worst) {
    std::snprintf(b, sizeof b,
                  "  %-16s err %.5f  dir (%.9g, %.9g, %.9g)  q (%.9g, %.9g, %.9g, %.9g)  golden %s (%.4f, %.4f)  "
                  "datapath %s (%.4f, %.4f)\n",
                  wc.set.c_str(), wc.error, wc.dir[0], wc.dir[1], wc.dir[2], wc.quat[0], wc.quat[1], wc.quat[2],
                  wc.quat[3], face_name(wc.golden_face), wc.golden_uv[0], wc.golden_uv[1], face_name(wc.datapath_face),
                  wc.datapath_uv[0], wc.datapath_uv[1]);
    t += b;
  }
  return t;
}

std::string to_json(const Report& r) {
  const auto& w = r.widths;
  nlohmann::json j;
  j["widths"] = {{"vec_frac", w.vec_frac},         {"mat_frac", w.mat_frac},
                 {"rot_frac", w.rot_frac},         {"rot_rounding", to_string(w.rot_rounding)},
                 {"divider", to_string(w.divider)}, {"recip_index_bits", w.recip_index_bits},
                 {"recip_frac_bits", w.recip_frac_bits}, {"newton_steps", w.newton_steps},
                 {"quot_frac", w.quot_frac},       {"div_rounding", to_string(w.div_rounding)},
                 {"texel_frac", w.texel_frac},     {"texel_rounding", to_string(w.texel_rounding)},
                 {"face_size", r.face_size}};
  j["frames"] = stats_json(r.frames);
  j["random"] = stats_json(r.random);
  j["directed"] = stats_json(r.directed);
  j["all"] = stats_json(r.overall);
  j["aligned"] = stats_json(r.aligned);
  auto& views = j["views"] = nlohmann::json::array();
  for (const ViewStats& v : r.views) {
    nlohmann::json jv = stats_json(v.stats);
    jv["name"] = v.view.name;
    jv["set"] = v.aligned ? "aligned" : "generic";
    jv["quaternion_wxyz"] = {v.view.q.w, v.view.q.x, v.view.q.y, v.view.q.z};
    jv["lens_fov_deg"] = v.view.lens.fov_deg;
    views.push_back(jv);
  }
  for (bool aligned : {false, true}) {
    const int wv = worst_view(r, aligned);
    j["worst_view"][aligned ? "aligned" : "generic"] =
        wv < 0 ? nlohmann::json() : nlohmann::json(r.views[static_cast<size_t>(wv)].view.name);
  }
  j["bilinear_color"] = {{"pixels", r.color.pixels},
                         {"edge_pixels_face_differs", r.color.edge_pixels},
                         {"edge_max_lsb", r.color.edge_max_error},
                         {"max_lsb", r.color.max_error},
                         {"p999_lsb", r.color.p999_error},
                         {"mean_lsb", r.color.mean_error},
                         {"exact_pixels", r.color.exact}};
  auto& arr = j["worst"] = nlohmann::json::array();
  for (const auto& wc : r.worst)
    arr.push_back({{"set", wc.set},
                   {"texel_error", wc.error},
                   {"direction", {wc.dir[0], wc.dir[1], wc.dir[2]}},
                   {"quaternion_wxyz", {wc.quat[0], wc.quat[1], wc.quat[2], wc.quat[3]}},
                   {"golden", {{"face", face_name(wc.golden_face)}, {"u", wc.golden_uv[0]}, {"v", wc.golden_uv[1]}}},
                   {"datapath",
                    {{"face", face_name(wc.datapath_face)}, {"u", wc.datapath_uv[0]}, {"v", wc.datapath_uv[1]}}}});
  return j.dump(2);
}

}  // namespace arp::accuracy
