// Recorded head motion from real datasets (issue 17): conventions as data
// (columns, axes, quaternion order, Euler angles), the summary and warnings
// for what a human head does not do, and the edits for low-rate logs. The
// expectations are geometry: in arpsim's frame (x right, y up, looking down
// -z) a head turned right by 30 degrees looks along (sin 30, 0, -cos 30) and
// pitched up by 20 along (0, sin 20, -cos 20), whatever the dataset's
// convention was.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "TestSupport.hpp"
#include "common/InputError.hpp"
#include "tracker/DatasetImport.hpp"
#include "tracker/MotionSummary.hpp"
#include "tracker/TraceEdit.hpp"
#include "tracker/TraceFile.hpp"

using namespace arp::tracker;
using arp::test::run_command;
using arp::test::TempDir;

namespace {

const double kDeg = 3.14159265358979323846 / 180.0;

// What a head looks at and which way is its up, in arpsim's frame.
struct Look {
  glm::dvec3 forward, up;
};
const Look kLevel{{0, 0, -1}, {0, 1, 0}};
const Look kRight30{{std::sin(30 * kDeg), 0, -std::cos(30 * kDeg)}, {0, 1, 0}};
const Look kUp20{{0, std::sin(20 * kDeg), -std::cos(20 * kDeg)}, {0, std::cos(20 * kDeg), std::sin(20 * kDeg)}};
// Turned right 30, then (in the head's own frame) pitched up 20.
const Look kRightThenUp{{std::sin(30 * kDeg) * std::cos(20 * kDeg), std::sin(20 * kDeg), -std::cos(30 * kDeg) * std::cos(20 * kDeg)},
                        {-std::sin(30 * kDeg) * std::sin(20 * kDeg), std::cos(20 * kDeg), std::cos(30 * kDeg) * std::sin(20 * kDeg)}};

void expect_look(const PoseSample& s, const Look& want, const std::string& what) {
  const glm::dvec3 f = s.orientation * glm::dvec3(0, 0, -1), u = s.orientation * glm::dvec3(0, 1, 0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(f[i], want.forward[i], 2e-6) << what << " forward[" << i << "]";
    EXPECT_NEAR(u[i], want.up[i], 2e-6) << what << " up[" << i << "]";
  }
}

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.9f", v);
  return b;
}

struct LayoutCase {
  std::string name, text, axes, columns, euler;
  DatasetLayout::AngleUnit unit = DatasetLayout::AngleUnit::Degrees;
  std::vector<Look> looks;
};

}  // namespace

// Five layouts, each holding "forward and level", "turned right 30" and
// "pitched up 20" (two also the turn then the pitch) as its recorder wrote them.
TEST(DatasetImport, EveryLayoutReadsForwardAndLevelAsIdentity) {
  const double c15 = std::cos(15 * kDeg), s15 = std::sin(15 * kDeg), c10 = std::cos(10 * kDeg), s10 = std::sin(10 * kDeg);
  std::vector<LayoutCase> cases;
  // arpsim's own frame, w x y z: a right turn is -30 about +y, up is +20 about +x.
  cases.push_back({"gl wxyz",
                   "0 0 1 0 0 0\n0.01 1 " + num(c15) + " 0 " + num(-s15) + " 0\n0.02 2 " + num(c10) + " " + num(s10) + " 0 0\n",
                   "gl", "", "", DatasetLayout::AngleUnit::Degrees, {kLevel, kRight30, kUp20}});
  // Unity, x y z w: left-handed, +z forward; a right turn is +30 about +y, up is -20 about +x.
  cases.push_back({"unity xyzw",
                   "0,0,0,0,0,1\n0.01,1,0," + num(s15) + ",0," + num(c15) + "\n0.02,2," + num(-s10) + ",0,0," + num(c10) + "\n", "unity",
                   "t=1,frame=2,qx=3,qy=4,qz=5,qw=6", "", DatasetLayout::AngleUnit::Degrees, {kLevel, kRight30, kUp20}});
  // Corbillon et al.'s recorder: z up, looking down +x, y to the left; columns by header name.
  // A right turn is -30 about +z, up is -20 about +y (lifting +x toward +z).
  cases.push_back({"corbillon by name",
                   "timestamp frameId UnitQuaternion.w UnitQuaternion.x UnitQuaternion.y UnitQuaternion.z\n"
                   "10.0 7 1 0 0 0\n10.01 8 " + num(c15) + " 0 0 " + num(-s15) + "\n10.02 9 " + num(c10) + " 0 " + num(-s10) + " 0\n",
                   "corbillon", "t=timestamp,frame=frameid,qw=UnitQuaternion.w,qx=UnitQuaternion.x,qy=UnitQuaternion.y,qz=UnitQuaternion.z",
                   "", DatasetLayout::AngleUnit::Degrees, {kLevel, kRight30, kUp20}});
  // Unity Euler angles in degrees (yaw about y, then pitch about x, then roll about z; pitch down positive),
  // a CSV with position columns first and no frame id.
  cases.push_back({"unity euler by name",
                   "time,px,py,pz,pitch,yaw,roll\n0,1,1.6,2,0,0,0\n0.01,1,1.6,2,0,30,0\n0.02,1,1.6,2,-20,0,0\n0.03,1,1.6,2,-20,30,0\n",
                   "unity", "t=time,rx=pitch,ry=yaw,rz=roll", "yxz", DatasetLayout::AngleUnit::Degrees,
                   {kLevel, kRight30, kUp20, kRightThenUp}});
  // A z-up frame's Euler angles in radians, yaw about z, then pitch about y, then roll about x.
  cases.push_back({"z-up euler radians",
                   "0\t0\t0\t0\n0.01\t" + num(-30 * kDeg) + "\t0\t0\n0.02\t0\t" + num(-20 * kDeg) + "\t0\n0.03\t" + num(-30 * kDeg) + "\t" +
                       num(-20 * kDeg) + "\t0\n",
                   "-z,-x,+y", "t=1,rz=2,ry=3,rx=4", "zyx", DatasetLayout::AngleUnit::Radians, {kLevel, kRight30, kUp20, kRightThenUp}});
  TempDir d;
  for (const auto& c : cases) {
    {
      std::ofstream f(d.file("ds.txt"));
      f << "# " << c.name << "\n" << c.text;
    }
    DatasetLayout l;
    std::string why;
    ASSERT_TRUE(parse_axes(c.axes, l.axes, why)) << c.name << ": " << why;
    if (!c.columns.empty()) {
      ASSERT_TRUE(parse_columns(c.columns, l.columns, why)) << c.name << ": " << why;
    }
    if (!c.euler.empty()) {
      ASSERT_TRUE(parse_euler_order(c.euler, l.euler_order, why)) << c.name << ": " << why;
    }
    l.angle_unit = c.unit;
    const auto s = read_head_motion_dataset(d.file("ds.txt"), l);
    ASSERT_EQ(s.size(), c.looks.size()) << c.name;
    EXPECT_EQ(s[0].orientation, glm::dquat(1, 0, 0, 0)) << c.name;  // forward and level: the identity, exactly
    EXPECT_EQ(s[0].time_ps, 0) << c.name;
    EXPECT_EQ(s[1].time_ps, 10'000'000'000) << c.name;
    for (size_t i = 0; i < s.size(); ++i) expect_look(s[i], c.looks[i], c.name + " sample " + std::to_string(i));
  }
}

// The layout and its values are checked, each refusal naming what is wrong.
TEST(DatasetImport, BadLayoutsAndColumnsAreRefused) {
  glm::dmat3 m;
  std::string why;
  for (const char* bad : {"", "yup", "+x,+y", "+x,+x,+z", "+x,+y,+w", "x,y,--z"}) EXPECT_FALSE(parse_axes(bad, m, why)) << bad;
  EXPECT_TRUE(parse_axes("X,-Z,y", m, why)) << why;  // case and a missing '+' are fine
  EXPECT_EQ(m[1], glm::dvec3(0, 0, -1));
  DatasetLayout::Columns c;
  for (const char* bad : {"t", "t=", "=3", "t=1,t=2", "w=3"}) EXPECT_FALSE(parse_columns(bad, c, why)) << bad;
  std::string order;
  for (const char* bad : {"xy", "xxz", "xyw", "xyzx"}) EXPECT_FALSE(parse_euler_order(bad, order, why)) << bad;

  DatasetLayout mixed;
  ASSERT_TRUE(parse_columns("t=1,qw=2,qx=3,qy=4,qz=5,rx=6", mixed.columns, why));
  EXPECT_NE(layout_problem(mixed).find("not both"), std::string::npos);
  DatasetLayout upper;  // the reader uses the order as given: only lower-case x, y, z
  ASSERT_TRUE(parse_columns("t=1,rx=2,ry=3,rz=4", upper.columns, why));
  upper.euler_order = "YXZ";
  EXPECT_NE(layout_problem(upper).find("lower case"), std::string::npos);
  DatasetLayout partial;
  ASSERT_TRUE(parse_columns("t=1,rx=2,ry=3", partial.columns, why));
  EXPECT_NE(layout_problem(partial).find("all of"), std::string::npos);

  TempDir d;
  struct {
    std::string text, columns, says;
  } files[] = {
      {"0 1 0 0 0\n1 1 0 0 0\n", "t=1,qw=2,qx=3,qy=4,qz=9", "line 1: the qz column 9 is not one of the 5 columns"},
      {"0 1 0 0 0\n1 1 0 0 0\n", "t=time,qw=2,qx=3,qy=4,qz=5", "columns are named ('time') but the file has no header"},
      {"t w x y z\n0 1 0 0 0\n", "t=t,qw=w,qx=x,qy=y,qz=q", "the header has no column 'q' (the qz)"},
      {"0 1 0 0 0\n1 one 0 0 0\n", "t=1,qw=2,qx=3,qy=4,qz=5", "line 2: quaternion 'one' is not a finite number"},
      {"0 0 0 0\n1 0 nan 0\n", "t=1,rx=2,ry=3,rz=4", "line 2: angle 'nan' is not a finite number"},
      {"0 1 0 0 0\n1 1 0 0 0\n0.5 1 0 0 0\n", "t=1,qw=2,qx=3,qy=4,qz=5", "line 3: timestamp 0.5 goes back"},
      {"0 x 1 0 0 0\n1 0 1 0 0 0\n", "", "line 1: frame id 'x' is not a finite number"},  // a bad first line is data, not a header
      {"nan nan nan nan nan nan\n0 0 1 0 0 0\n1 1 1 0 0 0\n", "", "line 1: timestamp 'nan' is not a finite number"},  // not a header
      {"0 1 0 0 0\n0 1 0 0 0\n", "t=1,qw=2,qx=3,qy=4,qz=5", "every sample has the same timestamp"},
      {"t w w y z\n0 1 0 0 0\n1 1 0 0 0\n", "t=t,qw=w,qx=3,qy=y,qz=z", "the header names 'w' more than once"},
      {"0 1 0 0 0\n1 1 0 0 0\n", "t=1,qw=1,qx=3,qy=4,qz=5", "the time and the qw are the same column"},
  };
  for (const auto& f : files) {
    {
      std::ofstream o(d.file("bad.txt"));
      o << f.text;
    }
    DatasetLayout l;
    if (!f.columns.empty()) {
      ASSERT_TRUE(parse_columns(f.columns, l.columns, why)) << f.columns;
    }
    try {
      read_head_motion_dataset(d.file("bad.txt"), l);
      ADD_FAILURE() << "accepted: " << f.says;
    } catch (const arp::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(f.says), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("bad.txt"), std::string::npos) << e.what();
    }
  }
  // Equal timestamps are kept, as trace files allow them.
  {
    std::ofstream o(d.file("same.txt"));
    o << "0 0 1 0 0 0\n0 1 1 0 0 0\n0.01 2 1 0 0 0\n";
  }
  EXPECT_EQ(read_head_motion_dataset(d.file("same.txt"), DatasetLayout{}).size(), 3u);
}

namespace {

// A head turning right about world up at `dps` degrees per second, sampled at `hz`.
std::vector<PoseSample> turning(double dps, double hz, double seconds) {
  std::vector<PoseSample> v;
  for (int i = 0; i <= static_cast<int>(std::lround(seconds * hz)); ++i) {
    PoseSample p;
    const double t = i / hz;
    p.time_ps = std::llround(t * 1e12);
    p.orientation = glm::angleAxis(-dps * t * kDeg, glm::dvec3(0, 1, 0));
    v.push_back(p);
  }
  return v;
}

bool mentions(const std::vector<std::string>& lines, const std::string& what) {
  for (const auto& l : lines)
    if (l.find(what) != std::string::npos) return true;
  return false;
}

}  // namespace

// A clean 1 kHz turn: the figures are the construction's, and nothing is flagged.
TEST(MotionSummary, ACleanTraceIsDescribedAndNotFlagged) {
  const auto s = summarize_motion(turning(100, 1000, 2.0));
  EXPECT_EQ(s.samples, 2001u);
  EXPECT_NEAR(s.span_s, 2.0, 1e-12);
  EXPECT_NEAR(s.rate_hz(), 1000.0, 1e-6);
  EXPECT_NEAR(s.peak_speed_dps, 100.0, 1e-3);
  EXPECT_NEAR(s.p99_speed_dps, 100.0, 1e-3);
  EXPECT_NEAR(s.max_tilt_deg, 0.0, 1e-6);
  EXPECT_EQ(s.gaps + s.bursts + s.same_time + s.repeats + s.fast_steps, 0u);
  EXPECT_TRUE(motion_warnings(s).empty()) << motion_warnings(s).front();
  EXPECT_NE(describe(s)[0].find("2001 samples over 2.000 s, 1000.0 Hz"), std::string::npos) << describe(s)[0];
}

// The widest trace the reader takes (+-9e6 s) is 1.8e19 ps long: more than int64_t holds. Its span and
// interval are the closed form's, not a wrapped (negative) figure.
TEST(MotionSummary, TheWidestAcceptedTraceHasItsOwnSpan) {
  std::vector<PoseSample> v(2);
  v[0].time_ps = -9'000'000'000'000'000'000;
  v[1].time_ps = 9'000'000'000'000'000'000;
  v[1].orientation = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 1, 0));
  const auto s = summarize_motion(v);
  EXPECT_NEAR(s.span_s, 1.8e7, 1e-3);
  EXPECT_NEAR(s.median_period_s, 1.8e7, 1e-3);
  EXPECT_NEAR(s.peak_speed_dps, 90.0 / 1.8e7, 1e-12);
  EXPECT_NE(describe(s)[0].find("2 samples over 18000000.000 s"), std::string::npos) << describe(s)[0];
}

// The quirks the issue found in real datasets, each built here and each flagged.
TEST(MotionSummary, FlagsWhatAHumanHeadDoesNot) {
  // Milliseconds read as seconds: a 60 Hz tracker looks like 60 kHz and 6000 deg/s.
  auto ms = turning(100, 60, 1.0);
  for (auto& p : ms) p.time_ps /= 1000;
  const auto s1 = summarize_motion(ms);
  EXPECT_NEAR(s1.rate_hz(), 60000.0, 5.0);  // intervals of 16666 or 16667 ps
  EXPECT_NEAR(s1.peak_speed_dps, 100000.0, 10.0);
  EXPECT_TRUE(mentions(motion_warnings(s1), "time unit")) << motion_warnings(s1).size();

  // A start-up jump of 176 degrees in 27 ms, then a still head at 100 Hz.
  std::vector<PoseSample> jump = turning(0, 100, 1.0);
  for (size_t i = 1; i < jump.size(); ++i) jump[i].time_ps += 27'000'000'000 - 10'000'000'000;
  for (size_t i = 1; i < jump.size(); ++i) jump[i].orientation = glm::angleAxis(176 * kDeg, glm::dvec3(0, 1, 0));
  for (size_t i = 1; i < jump.size(); ++i) jump[i].orientation *= glm::angleAxis(1e-3 * static_cast<double>(i) * kDeg, glm::dvec3(0, 1, 0));
  const auto s2 = summarize_motion(jump);
  EXPECT_NEAR(s2.peak_speed_dps, 176.0 / 0.027, 1.0);
  EXPECT_NEAR(s2.peak_speed_at_s, 0.027, 1e-12);
  EXPECT_EQ(s2.fast_steps, 1u);
  EXPECT_TRUE(mentions(motion_warnings(s2), "1 steps faster than a human head")) << motion_warnings(s2).size();

  // A z-up recording read as y-up: the head lies on its back (looking up) for the whole two seconds.
  auto lying = turning(10, 100, 2.0);
  for (auto& p : lying) p.orientation = glm::angleAxis(95 * kDeg, glm::dvec3(1, 0, 0)) * p.orientation;
  const auto s3 = summarize_motion(lying);
  EXPECT_NEAR(s3.max_tilt_deg, 95.0, 1e-6);
  EXPECT_NEAR(s3.longest_tilt_s, 2.0, 1e-9);
  EXPECT_TRUE(mentions(motion_warnings(s3), "axes")) << motion_warnings(s3).size();
  // ... but a 91-degree tilt held 0.5 s is a person looking up, not a convention.
  auto glance = turning(0, 100, 2.0);
  for (size_t i = 50; i <= 100; ++i) glance[i].orientation = glm::angleAxis(91 * kDeg, glm::dvec3(1, 0, 0));
  EXPECT_FALSE(mentions(motion_warnings(summarize_motion(glance)), "axes"));
  // At 5 Hz, tilted at 0.2 .. 1.0 s and upright again at 1.2 s: tilted for 1.0 s (until the upright sample).
  auto slow = turning(0, 5, 2.0);
  for (size_t i = 1; i <= 5; ++i) slow[i].orientation = glm::angleAxis(120 * kDeg, glm::dvec3(0, 0, 1));
  EXPECT_NEAR(summarize_motion(slow).longest_tilt_s, 1.0, 1e-9);
  EXPECT_TRUE(mentions(motion_warnings(summarize_motion(slow)), "axes"));

  // A 30 Hz tracker logged at 90 Hz: two of every three samples repeat; a 0.5 s hole; bursts 0.06 ms apart.
  auto log = turning(30, 90, 3.0);
  for (size_t i = 0; i < log.size(); ++i) log[i].orientation = log[i - i % 3].orientation;
  const auto s4 = summarize_motion(log);
  EXPECT_EQ(s4.repeats, 180u);  // 271 samples: every one not a multiple of 3
  EXPECT_TRUE(mentions(motion_warnings(s4), "--drop-repeats"));
  auto holey = turning(30, 100, 2.0);
  holey.erase(holey.begin() + 100, holey.begin() + 149);  // 1.00 .. 1.48 s missing: one 0.5 s interval
  holey.insert(holey.begin() + 10, holey[10]);
  holey[11].time_ps += 60'000'000;  // 0.06 ms after its twin
  const auto s5 = summarize_motion(holey);
  EXPECT_EQ(s5.gaps, 1u);
  EXPECT_NEAR(s5.longest_gap_s, 0.5, 1e-9);
  EXPECT_EQ(s5.bursts, 1u);
  EXPECT_EQ(s5.repeats, 1u);
}

// Dropping repeats keeps the first of each run; resampling a steady turn
// lands every new sample on the turn (slerp is exact about a fixed axis).
TEST(TraceEdit, DropRepeatsAndResample) {
  auto log = turning(30, 90, 3.0);
  for (size_t i = 0; i < log.size(); ++i) log[i].orientation = log[i - i % 3].orientation;
  auto kept = log;
  EXPECT_EQ(drop_repeats(kept), 180u);
  ASSERT_EQ(kept.size(), 91u);
  for (size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(kept[i].time_ps, log[3 * i].time_ps);

  auto slow = turning(90, 30, 3.0);  // 91 samples, 3 degrees apart, 270 degrees in all
  for (size_t i = 1; i < slow.size(); i += 2) slow[i].orientation = -slow[i].orientation;  // q and -q: the same pose
  const auto fine = resample(slow, 1000);
  ASSERT_EQ(fine.size(), 3001u);
  for (size_t i = 0; i < fine.size(); i += 7) {
    const double t = static_cast<double>(i) * 1e-3;
    EXPECT_EQ(fine[i].time_ps, std::llround(t * 1e12));
    const glm::dquat want = glm::angleAxis(-90 * t * kDeg, glm::dvec3(0, 1, 0));
    EXPECT_NEAR(std::abs(glm::dot(fine[i].orientation, want)), 1.0, 1e-12) << t;
  }
  EXPECT_THROW(resample(slow, 0), std::invalid_argument);
  EXPECT_THROW(resample(slow, 1e12), std::invalid_argument);  // 1e12 samples: refused, not allocated
}

// `arpsim tracker import` as a person uses it: the summary, a warning for the
// wrong axes, the edits, and refusals for bad layouts that write nothing.
TEST(DatasetImportCli, SummaryWarningsAndEdits) {
  const std::string& arpsim = arp::test::kArpsim;
  TempDir d;
  {
    // Corbillon's layout at 30 Hz logged at 90 Hz, the head looking ahead and level in its z-up frame
    // (the quaternion rotates about z: a turn to the right at 50 deg/s, 150 deg in all).
    std::ofstream f(d.file("corbillon.txt"));
    for (int i = 0; i < 271; ++i) {
      const double a = -50 * kDeg * static_cast<double>(i - i % 3) / 90.0 / 2.0;
      f << num(i / 90.0) << " " << i << " " << num(std::cos(a)) << " 0 0 " << num(std::sin(a)) << "\n";
    }
  }
  const auto ok = run_command(arpsim + " tracker import " + d.file("corbillon.txt") + " " + d.file("c.csv") +
                              " --axes corbillon --drop-repeats --resample 500");
  ASSERT_EQ(ok.status, 0) << ok.output;
  EXPECT_NE(ok.output.find("271 samples over 3.000 s, 90.0 Hz"), std::string::npos) << ok.output;
  EXPECT_NE(ok.output.find("180 repeated"), std::string::npos) << ok.output;
  EXPECT_NE(ok.output.find("--drop-repeats: 180 repeated samples dropped, 91 kept"), std::string::npos) << ok.output;
  EXPECT_NE(ok.output.find("--resample: 1501 samples at 500.0 Hz"), std::string::npos) << ok.output;
  const auto trace = read_trace_csv(d.file("c.csv"));
  ASSERT_EQ(trace.size(), 1501u);
  expect_look(trace.front(), kLevel, "first");
  // 3 s at 50 deg/s to the right, level.
  const Look right150{{std::sin(150 * kDeg), 0, -std::cos(150 * kDeg)}, {0, 1, 0}};
  expect_look(trace.back(), right150, "last");

  // A run on the 30 Hz trace says the latency it reports is mostly the trace's sample period (the
  // default pipeline latches per pixel: its own latency is far below 16.7 ms), and prints the
  // window's summary before simulating; the 500 Hz resampling's note gives its own period.
  ASSERT_EQ(run_command(arpsim + " tracker import " + d.file("corbillon.txt") + " " + d.file("r30.csv") + " --axes corbillon --drop-repeats")
                .status,
            0);
  const auto r30 = run_command(arpsim + " run -q --frames 2 --every 0 --trace " + d.file("r30.csv"));
  ASSERT_EQ(r30.status, 0) << r30.output;
  EXPECT_NE(r30.output.find("over the run's window: 3 samples over 0.067 s, 30.0 Hz"), std::string::npos) << r30.output;
  EXPECT_NE(r30.output.find("the trace's samples are 33.333 ms apart (30.0 Hz)"), std::string::npos) << r30.output;
  EXPECT_NE(r30.output.find("most of the median latency"), std::string::npos) << r30.output;
  const auto r500 = run_command(arpsim + " run -q --frames 2 --every 0 --trace " + d.file("c.csv"));
  ASSERT_EQ(r500.status, 0) << r500.output;
  EXPECT_NE(r500.output.find("the trace's samples are 2.000 ms apart (500.0 Hz)"), std::string::npos) << r500.output;

  // The same file read as y-up: the turn becomes a roll, over 90 degrees for the last 1.2 s; the import says so.
  const auto wrong = run_command(arpsim + " tracker import " + d.file("corbillon.txt") + " " + d.file("w.csv") + " --axes gl");
  EXPECT_EQ(wrong.status, 0) << wrong.output;
  EXPECT_NE(wrong.output.find("warning: the head is tilted more than 90 deg from upright"), std::string::npos) << wrong.output;

  arp::test::expect_refused(arpsim + " tracker import " + d.file("corbillon.txt") + " " + d.file("bad.csv") + " ",
                            {
                                {"--axes up", "--axes"},
                                {"--axes +x,+x,+z", "each of x, y and z must be used once"},
                                {"--columns t=1,w=2", "unknown role 'w'"},
                                {"--columns t=1,qw=3,qx=4,qy=5", "all of qw, qx, qy, qz"},
                                {"--scalar-last --columns t=1,qx=3,qy=4,qz=5,qw=6", "not both"},
                                {"--euler xyz", "needs --columns"},
                                {"--euler xyw --columns t=1,rx=2,ry=3,rz=4", "--euler"},
                                {"--angle-unit grad", "--angle-unit"},
                                {"--resample 0.5", "--resample"},
                                {"--resample nan", "--resample"},
                            },
                            "", d.file("bad.csv"));
  // A dataset shorter than one period of the resampling rate: refused, not a one-sample trace.
  std::ofstream(d.file("short.txt")) << "0 0 1 0 0 0\n0.0005 1 1 0 0 0\n";
  const auto one = run_command(arpsim + " tracker import " + d.file("short.txt") + " " + d.file("bad.csv") + " --resample 1000");
  EXPECT_EQ(one.status, 2) << one.output;
  EXPECT_NE(one.output.find("leaves fewer than two samples"), std::string::npos) << one.output;
  EXPECT_FALSE(std::filesystem::exists(d.file("bad.csv")));
  // Resampling a day-long span at 10 kHz would be a billion samples: refused before anything is made.
  std::ofstream(d.file("long.txt")) << "0 0 1 0 0 0\n100000 1 1 0 0 0\n";
  const auto big = run_command(arpsim + " tracker import " + d.file("long.txt") + " " + d.file("bad.csv") + " --resample 10000");
  EXPECT_EQ(big.status, 2) << big.output;
  EXPECT_NE(big.output.find("would make 1000000000 samples"), std::string::npos) << big.output;
  EXPECT_FALSE(std::filesystem::exists(d.file("bad.csv")));
}
