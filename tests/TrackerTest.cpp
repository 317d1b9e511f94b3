#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <vector>

#include "TestSupport.hpp"
#include "common/InputError.hpp"
#include "common/ResourceUsage.hpp"
#include "tracker/DatasetImport.hpp"
#include "tracker/OculusReport.hpp"
#include "tracker/RiftProtocol.hpp"
#include "tracker/SyntheticMotion.hpp"
#include "tracker/TraceFile.hpp"

using namespace arp::tracker;

namespace {
// An encoder written independently of the decoder: three 21-bit two's
// complement fields at bits 63-43, 42-22, 21-1 of a big-endian 64-bit word.
void pack21(uint8_t* out, int32_t x, int32_t y, int32_t z) {
  const uint64_t m = 0x1FFFFF;
  const uint64_t v = ((static_cast<uint64_t>(x) & m) << 43) | ((static_cast<uint64_t>(y) & m) << 22) |
                     ((static_cast<uint64_t>(z) & m) << 1);
  for (int i = 0; i < 8; ++i) out[i] = static_cast<uint8_t>(v >> (56 - 8 * i));
}
void put16(uint8_t* p, int v) { p[0] = static_cast<uint8_t>(v & 0xFF); p[1] = static_cast<uint8_t>((v >> 8) & 0xFF); }
// A report that must decode, and the header fields both models carry.
void expect_decoded(RiftModel m, const uint8_t* r, size_t n, ImuReport& rep, int samples, uint32_t timestamp, int command_id,
                    int temperature) {
  std::string err;
  ASSERT_TRUE(decode_report(m, r, n, rep, err)) << err;
  EXPECT_EQ(rep.sample_count, samples);
  EXPECT_EQ(rep.timestamp, timestamp);
  EXPECT_EQ(rep.last_command_id, command_id);
  EXPECT_EQ(rep.temperature, temperature);
}
}  // namespace

TEST(OculusReport, TwentyOneBitFieldsAtTheirExtremes) {
  const int32_t lo = -(1 << 20), hi = (1 << 20) - 1;
  const int32_t cases[][3] = {{0, 0, 0}, {1, -1, 2}, {lo, hi, lo}, {hi, lo, hi}, {-1, -1, -1}, {123456, -654321, 1000}};
  for (const auto& c : cases) {
    uint8_t b[8];
    pack21(b, c[0], c[1], c[2]);
    const auto v = unpack_21bit_triplet(b);
    EXPECT_EQ(v[0], c[0]);
    EXPECT_EQ(v[1], c[1]);
    EXPECT_EQ(v[2], c[2]);
  }
  std::mt19937 rng(3);
  std::uniform_int_distribution<int32_t> d(lo, hi);
  for (int i = 0; i < 10000; ++i) {
    const int32_t x = d(rng), y = d(rng), z = d(rng);
    uint8_t b[8];
    pack21(b, x, y, z);
    const auto v = unpack_21bit_triplet(b);
    ASSERT_EQ(v, (std::array<int32_t, 3>{x, y, z}));
  }
}

TEST(OculusReport, Dk1ReportDecodesByteExactly) {
  uint8_t r[64] = {};
  r[0] = 1;
  r[1] = 3;
  put16(r + 2, 0xBEEF);
  put16(r + 4, 0x1234);
  put16(r + 6, -1234);
  for (int s = 0; s < 3; ++s) {
    pack21(r + 8 + 16 * s, 98066 + s, -s, 12 * s);   // about 9.81 m/s^2 on x
    pack21(r + 16 + 16 * s, -(1 << 20), (1 << 20) - 1, s);
  }
  put16(r + 56, -5);
  put16(r + 58, 0);
  put16(r + 60, 32767);
  ImuReport rep;
  ASSERT_NO_FATAL_FAILURE(expect_decoded(RiftModel::DK1, r, sizeof r, rep, 3, 0xBEEFu, 0x1234, -1234));
  for (int s = 0; s < 3; ++s) {
    EXPECT_EQ(rep.samples[s].accel[0], 98066 + s);
    EXPECT_EQ(rep.samples[s].accel[1], -s);
    EXPECT_EQ(rep.samples[s].gyro[0], -(1 << 20));
    EXPECT_EQ(rep.samples[s].gyro[1], (1 << 20) - 1);
  }
  EXPECT_NEAR(accel_m_s2(rep.samples[0].accel[0]), 9.8066, 1e-9);
  EXPECT_EQ(rep.magnetometer[0], -5);
  EXPECT_EQ(rep.magnetometer[2], 32767);
}

TEST(OculusReport, Dk2ReportDecodesByteExactly) {
  uint8_t r[64] = {};
  r[0] = 11;
  put16(r + 1, 0x0102);
  r[3] = 2;
  put16(r + 4, 60000);
  put16(r + 6, 3150);
  const uint32_t ts = 0xDEADBEEF;
  for (int i = 0; i < 4; ++i) r[8 + i] = static_cast<uint8_t>(ts >> (8 * i));
  pack21(r + 12, 1, 2, 3);
  pack21(r + 20, 4, 5, 6);
  pack21(r + 28, -7, -8, -9);
  pack21(r + 36, 10, 11, 12);
  put16(r + 44, 100);
  put16(r + 46, -200);
  put16(r + 48, 300);
  ImuReport rep;
  ASSERT_NO_FATAL_FAILURE(expect_decoded(RiftModel::DK2, r, sizeof r, rep, 2, 0xDEADBEEFu, 0x0102, 3150));
  EXPECT_EQ(rep.samples_since_start, 60000);
  EXPECT_EQ(rep.samples[0].accel, (std::array<int32_t, 3>{1, 2, 3}));
  EXPECT_EQ(rep.samples[0].gyro, (std::array<int32_t, 3>{4, 5, 6}));
  EXPECT_EQ(rep.samples[1].accel, (std::array<int32_t, 3>{-7, -8, -9}));
  EXPECT_EQ(rep.samples[1].gyro, (std::array<int32_t, 3>{10, 11, 12}));
  EXPECT_EQ(rep.magnetometer, (std::array<int16_t, 3>{100, -200, 300}));
}

TEST(OculusReport, MalformedReportsAreRejectedWithAReason) {
  uint8_t r[64] = {};
  ImuReport rep;
  std::string err;
  ReportFault fault = ReportFault::None;
  r[0] = 1;
  r[1] = 1;
  EXPECT_FALSE(decode_report(RiftModel::DK1, r, 61, rep, err, &fault));  // short: the magnetometer ends at byte 62
  EXPECT_NE(err.find("61 bytes"), std::string::npos) << err;
  EXPECT_EQ(fault, ReportFault::TooShort);
  EXPECT_FALSE(decode_report(RiftModel::DK2, r, 64, rep, err, &fault));  // wrong id
  EXPECT_NE(err.find("id 1"), std::string::npos) << err;
  EXPECT_EQ(fault, ReportFault::WrongId);
  r[0] = 11;
  EXPECT_FALSE(decode_report(RiftModel::DK2, r, 63, rep, err, &fault));  // a DK2 sends 64
  EXPECT_EQ(fault, ReportFault::TooShort);
  EXPECT_FALSE(decode_report(RiftModel::DK2, nullptr, 0, rep, err, &fault));
  EXPECT_EQ(fault, ReportFault::Empty);
  EXPECT_FALSE(decode_report(RiftModel::DK1, r, 0, rep, err));
  r[3] = 0;  // no samples is a valid report
  EXPECT_TRUE(decode_report(RiftModel::DK2, r, 64, rep, err, &fault));
  EXPECT_EQ(rep.sample_count, 0);
  EXPECT_EQ(fault, ReportFault::None);
}

// As the devices send them: a DK1 report may be 62 bytes; a count above what
// a report holds is clamped (the open drivers do the same), the rest lost.
TEST(OculusReport, Dk1ReportsOf62BytesAndLargeCountsAreTaken) {
  ImuReport in;
  in.model = RiftModel::DK1;
  in.sample_count = 3;
  in.reported_sample_count = 7;  // the device took 7 since its last report; 3 fit
  in.timestamp = 0xBEEF;
  for (int s = 0; s < 3; ++s) in.samples[static_cast<size_t>(s)] = {{{s, -s, 100 + s}}, {{-1000 * s, 5, 6}}};
  in.magnetometer = {1, -2, 3};
  const auto bytes = encode_report(in);
  EXPECT_EQ(bytes[1], 7);
  std::vector<uint8_t> short62(bytes.begin(), bytes.begin() + 62);  // exactly 62 bytes on the heap: ASan sees an overread
  ImuReport out;
  std::string err;
  ASSERT_TRUE(decode_report(RiftModel::DK1, short62.data(), short62.size(), out, err)) << err;
  EXPECT_EQ(out.sample_count, 3);
  EXPECT_EQ(out.reported_sample_count, 7);
  EXPECT_EQ(out.timestamp, 0xBEEFu);
  EXPECT_EQ(out.samples[2].accel, (std::array<int32_t, 3>{2, -2, 102}));
  EXPECT_EQ(out.magnetometer, (std::array<int16_t, 3>{1, -2, 3}));
  // A DK2 count of 3 keeps 2.
  uint8_t dk2[64] = {11};
  dk2[3] = 3;
  ASSERT_TRUE(decode_report(RiftModel::DK2, dk2, 64, out, err)) << err;
  EXPECT_EQ(out.sample_count, 2);
  EXPECT_EQ(out.reported_sample_count, 3);
}

TEST(OculusReport, RandomBytesNeverReadPastTheReport) {
  // Each buffer is exactly `len` bytes on the heap, so ASan sees any overread.
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int> byte(0, 255), length(0, 80);
  int accepted = 0;
  for (int i = 0; i < 20000; ++i) {
    const size_t len = static_cast<size_t>(length(rng));
    std::vector<uint8_t> buf(len);
    for (auto& b : buf) b = static_cast<uint8_t>(byte(rng));
    const RiftModel m = i % 2 ? RiftModel::DK1 : RiftModel::DK2;
    if (len > 0 && i % 3 != 0) buf[0] = m == RiftModel::DK1 ? 1 : 11;
    ImuReport rep;
    std::string err;
    if (decode_report(m, len ? buf.data() : nullptr, len, rep, err)) {
      ++accepted;
      ASSERT_LE(rep.sample_count, m == RiftModel::DK1 ? 3 : 2);
      ASSERT_GE(len, m == RiftModel::DK1 ? 62u : 64u);
    } else {
      ASSERT_FALSE(err.empty());
    }
  }
  EXPECT_GT(accepted, 0);
}

TEST(TraceFile, RoundTripsWithAndWithoutPositions) {
  arp::test::TempDir d;
  SamplingSpec s;
  s.duration_s = 0.05;
  s.noise_deg = 0.5;
  auto a = head_shake(glm::dvec3(0, 1, 0), 300.0, 2.0, s);
  write_trace_csv(d.file("a.csv"), a);
  const auto back = read_trace_csv(d.file("a.csv"));
  ASSERT_EQ(back.size(), a.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(back[i].time_ps, a[i].time_ps);
    EXPECT_NEAR(back[i].orientation.w, a[i].orientation.w, 1e-15);
    EXPECT_NEAR(back[i].orientation.y, a[i].orientation.y, 1e-15);
    EXPECT_FALSE(back[i].has_position);
  }
  for (auto& p : a) {
    p.has_position = true;
    p.position = glm::dvec3(1.5, 1.7, -2.25);
  }
  write_trace_csv(d.file("b.csv"), a);
  const auto withpos = read_trace_csv(d.file("b.csv"));
  EXPECT_TRUE(withpos.front().has_position);
  EXPECT_DOUBLE_EQ(withpos.back().position.z, -2.25);
}

TEST(TraceFile, BadTracesNameTheFileLineAndReason) {
  arp::test::TempDir d;
  auto error_of = [&](const std::string& body) -> std::string {
    std::ofstream(d.file("t.csv")) << body;
    try {
      read_trace_csv(d.file("t.csv"));
    } catch (const arp::InputError& e) {
      EXPECT_EQ(e.source(), d.file("t.csv"));
      return e.place() + ": " + e.reason();
    }
    return "no error";
  };
  const std::string h = "time_s,qw,qx,qy,qz\n";
  EXPECT_NE(error_of("").find("no header"), std::string::npos);
  EXPECT_NE(error_of("# only a comment\n").find("no header"), std::string::npos);
  EXPECT_NE(error_of(h).find("no samples"), std::string::npos);
  EXPECT_NE(error_of("time,qw,qx,qy,qz\n0,1,0,0,0\n").find("line 1: header column 1"), std::string::npos);
  EXPECT_NE(error_of(h + "0,1,0,0\n").find("line 2: 4 columns"), std::string::npos);
  EXPECT_NE(error_of(h + "0,1,0,0,0\n0.1,one,0,0,0\n").find("line 3: qw 'one' is not a number"), std::string::npos);
  EXPECT_NE(error_of(h + "0,1,0,0,nan\n").find("not a finite number"), std::string::npos);
  EXPECT_NE(error_of(h + "0,0,0,0,0\n").find("length 0"), std::string::npos);
  EXPECT_NE(error_of(h + "0,2,0,0,0\n").find("unit quaternion"), std::string::npos);
  EXPECT_NE(error_of(h + "1,1,0,0,0\n0.5,1,0,0,0\n").find("line 3: time 0.5 s is earlier"), std::string::npos);
  EXPECT_NE(error_of(h + "1e300,1,0,0,0\n").find("outside"), std::string::npos);
  EXPECT_NE(error_of(h + "0,1,0,0,0,\n").find("6 columns"), std::string::npos);
  EXPECT_EQ(error_of("# a comment\n\n" + h + "  0 , 1 ,0,0,0\n0,1,0,0,0\n"), "no error");  // spaces, equal times
  // A spreadsheet's byte-order mark before the header is read past; lines ending in CR alone are named as such.
  EXPECT_EQ(error_of("\xEF\xBB\xBF" + h + "0,1,0,0,0\n"), "no error");
  EXPECT_NE(error_of(h + "0x1,1,0,0,0\n").find("time_s '0x1' is not a decimal number"), std::string::npos);
  EXPECT_NE(error_of("time_s,qw,qx,qy,qz,px,py,pz\n0,1,0,0,0,1e300,0,0\n").find("px 1e300 is outside +-1000000 m"),
            std::string::npos);
  EXPECT_NE(error_of("time_s,qw,qx,qy,qz\r0,1,0,0,0\r").find("line 1: lines end in a carriage return alone"), std::string::npos);
  try {
    read_trace_csv(d.file("missing.csv"));
    FAIL();
  } catch (const arp::InputError& e) {
    EXPECT_NE(e.reason().find("cannot open"), std::string::npos);
  }
  EXPECT_THROW(write_trace_csv(d.file("no/folder/t.csv"), {PoseSample{}}), arp::InputError);
}

TEST(SyntheticMotion, ConstantRotationAtExtremeRates) {
  SamplingSpec s;
  s.duration_s = 0.1;
  const auto fast = constant_rotation(glm::dvec3(0, 1, 0), 1000.0, s);  // 1000 deg/s at 1 kHz: 1 deg a sample
  ASSERT_EQ(fast.size(), 101u);
  for (size_t i = 1; i < fast.size(); ++i) {
    const double step = glm::degrees(2.0 * std::acos(std::min(1.0, std::abs(glm::dot(fast[i].orientation, fast[i - 1].orientation)))));
    ASSERT_NEAR(step, 1.0, 1e-9);
    ASSERT_EQ(fast[i].time_ps - fast[i - 1].time_ps, 1'000'000'000);
  }
  EXPECT_NEAR(glm::length(fast[5].angular_velocity), glm::radians(1000.0), 1e-12);
  const auto still = constant_rotation(glm::dvec3(1, 0, 0), 0.0, s);
  for (const auto& p : still) ASSERT_DOUBLE_EQ(p.orientation.w, 1.0);
  EXPECT_THROW(constant_rotation(glm::dvec3(0, 0, 0), 10.0, s), std::invalid_argument);
  // An axis is a direction however it is scaled: components whose squares overflow (the length was infinite and
  // the normalised axis zero: a still head, exit 0) or underflow turn the head as the unit axis does.
  for (const glm::dvec3 axis : {glm::dvec3(1e200, 0, 0), glm::dvec3(1e308, 1e308, 0), glm::dvec3(1e-320, 0, 0)}) {
    const glm::dvec3 unit = axis.y != 0 ? glm::normalize(glm::dvec3(1, 1, 0)) : glm::dvec3(1, 0, 0);
    const auto scaled = constant_rotation(axis, 1000.0, s), plain = constant_rotation(unit, 1000.0, s);
    ASSERT_EQ(scaled.size(), plain.size());
    for (size_t i = 0; i < plain.size(); ++i)
      ASSERT_NEAR(glm::dot(scaled[i].orientation, plain[i].orientation), 1.0, 1e-12) << axis.x << " sample " << i;
  }
  EXPECT_EQ(parse_axis("1e200,0,0"), glm::dvec3(1e200, 0, 0));
  EXPECT_THROW(parse_axis("1e400,0,0"), arp::InputError);
  EXPECT_THROW(parse_axis("0,0,0"), arp::InputError);
  EXPECT_THROW(constant_rotation(glm::dvec3(1e308, 0, std::numeric_limits<double>::infinity()), 10.0, s), std::invalid_argument);
  s.rate_hz = 0.0;
  EXPECT_THROW(constant_rotation(glm::dvec3(0, 1, 0), 10.0, s), std::invalid_argument);
}

TEST(SyntheticMotion, HeadShakeReachesItsPeakVelocityAndPendulumItsAmplitude) {
  SamplingSpec s;
  s.duration_s = 1.0;
  const auto shake = head_shake(glm::dvec3(0, 1, 0), 370.0, 1.5, s);  // the peak of real heads
  double peak = 0.0;
  for (size_t i = 1; i < shake.size(); ++i) {
    const double d = 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(shake[i].orientation, shake[i - 1].orientation))));
    peak = std::max(peak, glm::degrees(d) * s.rate_hz);
  }
  EXPECT_NEAR(peak, 370.0, 370.0 * 0.005);
  const auto swing = pendulum(glm::dvec3(0, 0, 1), 30.0, 2.0, s);
  EXPECT_NEAR(glm::degrees(glm::angle(swing.front().orientation)), 30.0, 1e-9);
  EXPECT_NEAR(glm::degrees(glm::angle(swing[1000].orientation)), 30.0, 1e-6);  // half a period on: the other extreme
}

TEST(SyntheticMotion, NoiseIsSeeded) {
  SamplingSpec s;
  s.duration_s = 0.01;
  s.noise_deg = 1.0;
  const auto a = constant_rotation(glm::dvec3(0, 1, 0), 50.0, s), b = constant_rotation(glm::dvec3(0, 1, 0), 50.0, s);
  s.seed = 2;
  const auto c = constant_rotation(glm::dvec3(0, 1, 0), 50.0, s);
  EXPECT_EQ(a[5].orientation, b[5].orientation);
  EXPECT_NE(a[5].orientation, c[5].orientation);
}

#include "tracker/DriftScenario.hpp"
#include "tracker/Fusion.hpp"
#include "tracker/SyntheticImu.hpp"

TEST(Fusion, NoiselessGyroIntegrationFollowsTheTruth) {
  SamplingSpec s;
  s.duration_s = 2.0;
  const auto truth = constant_rotation(glm::normalize(glm::dvec3(1, 2, 3)), 1000.0, s);
  const auto imu = synthesize_imu(truth, ImuNoise{});
  FusionParams p;
  p.correct_tilt = p.estimate_bias = false;
  Fusion f(p, truth.front().orientation);
  for (size_t i = 1; i < imu.size(); ++i) f.update(imu[i].gyro, imu[i].accel, 1e-3);
  EXPECT_LT(angle_between_deg(f.orientation(), truth.back().orientation), 1e-6);
  f.update(glm::dvec3(1, 0, 0), glm::dvec3(0, 9.8, 0), 0.0);  // a repeated timestamp changes nothing
  f.update(glm::dvec3(1, 0, 0), glm::dvec3(0, 9.8, 0), -1e-3);
  EXPECT_LT(angle_between_deg(f.orientation(), truth.back().orientation), 1e-6);
}

TEST(Fusion, TiltCorrectionAndBiasEstimationBoundTheDrift) {
  FusionParams raw;
  raw.correct_tilt = raw.estimate_bias = false;
  FusionParams tilt;
  tilt.estimate_bias = false;
  const DriftResult r = run_drift(raw, 30.0), t = run_drift(tilt, 30.0);
  EXPECT_GT(r.total_deg, 15.0);     // 0.71 deg/s of bias over 30 s, uncorrected
  EXPECT_LT(t.tilt_deg, 3.0);       // gravity holds the tilt ...
  EXPECT_GT(t.total_deg, 5.0);      // ... but not the yaw
  // Learning the bias (slowly: a time constant of two minutes) stops the yaw drift once it has learned:
  // over 10 minutes the yaw of the tilt-only fusion drifts well past 100 deg, the full one's far less.
  const DriftResult t10 = run_drift(tilt, 600.0), f10 = run_drift(FusionParams{}, 600.0);
  EXPECT_GT(t10.total_deg, 100.0);
  EXPECT_LT(f10.total_deg * 2.0, t10.total_deg);
  EXPECT_LT(f10.bias_error_deg_s, 0.1);
}

// A steady slow turn looks like a gyro bias to gyro and accelerometer. With
// the bias learned below 0.02 rad/s and a time constant of tau = 120 s, a
// turn at w held for T = 10 s loses about w T^2 / (2 tau) (0.21 deg at
// 0.5 deg/s, 0.42 at 1 deg/s), plus what the noise leaves; a turn at 3 deg/s
// is above the learning rate and loses only the noise's share.
TEST(Fusion, SlowTurnsAreNotTakenForBias) {
  const FusionParams p;
  ASSERT_EQ(p.bias_time_constant, 120.0);
  auto loss = [](double deg_per_s) { return deg_per_s * 10.0 * 10.0 / (2.0 * 120.0); };
  const double e05 = run_slow_turn(p, 0.5, 10), e1 = run_slow_turn(p, 1, 10), e3 = run_slow_turn(p, 3, 10);
  EXPECT_LT(e3, 0.5);
  EXPECT_LT(e1, loss(1) + 0.2);
  EXPECT_LT(e05, loss(0.5) + 0.2);
  EXPECT_GT(e1, e3);  // the slower turn, inside the learning band, loses more
  // The old model (bias learned in 2 s from anything below 0.1 rad/s) lost most of a slow turn.
  FusionParams fast = p;
  fast.bias_time_constant = 2.0;
  fast.bias_still_rate = 0.1;
  EXPECT_GT(run_slow_turn(fast, 3, 10), 10.0);
}

// A real bias within the bound (0.87 deg/s < max_bias = 1.15 deg/s) is learned
// like a first-order filter: within 2 % after 4 tau (8 minutes); one above the
// bound never looks still and is not learned; the estimate never exceeds it.
TEST(Fusion, ABiasWithinTheBoundIsLearnedInEightMinutes) {
  const FusionParams p;
  const glm::dvec3 small = glm::radians(glm::dvec3(0.5));  // 0.87 deg/s
  EXPECT_NEAR(run_bias_learning(p, small, 120), std::exp(-1.0), 0.03);  // one tau
  EXPECT_LT(run_bias_learning(p, small, 480), 0.02);
  const glm::dvec3 large = glm::radians(glm::dvec3(2.0, 0.0, 0.0));  // 2 deg/s
  EXPECT_GT(run_bias_learning(p, large, 480), 0.95);
  // Bounded: with max_bias below the learning band, a still head read with a bias inside the band (but
  // above max_bias) for 10 time constants learns max_bias, no more.
  FusionParams capped = p;
  capped.max_bias = 0.01;
  Fusion f(capped);
  for (int i = 0; i < 120000; ++i) f.update(glm::dvec3(0.0195, 0.0, 0.0), glm::dvec3(0, kStandardGravity, 0), 1e-2);
  EXPECT_NEAR(glm::length(f.bias()), 0.01, 1e-12);
  FusionParams bad;
  bad.bias_time_constant = 0;
  EXPECT_THROW(Fusion{bad}, std::invalid_argument);
}

// An hour of the drift scenario (3.6 million samples, streamed): the tilt
// stays below 1 deg, the bias is learned to the noise's level, the yaw error
// is what accumulated while learning and stops growing, and memory stays flat.
TEST(Fusion, AnHourOfNoisyBiasedShakingKeepsTiltAndMemory) {
  const double rss0 = static_cast<double>(arp::peak_resident_bytes());
  const DriftResult half = run_drift(FusionParams{}, 1800.0), hour = run_drift(FusionParams{}, 3600.0);
  EXPECT_LT(hour.tilt_deg, 1.0);
  EXPECT_LT(hour.bias_error_deg_s, 0.01);
  EXPECT_LT(std::abs(hour.total_deg - half.total_deg), 1.0);  // < 1 deg in the second half hour: < 0.04 deg/min
  EXPECT_LT(static_cast<double>(arp::peak_resident_bytes()) - rss0, 16e6);
}

// Yaw from the magnetometer, against the closed form of a proportional
// correction: a still, level head whose gyroscope reads a constant bias w about
// the vertical (bias learning off) drifts in yaw at w without the magnetometer
// (w t after t seconds); with it, the error obeys de/dt = w - k e and settles
// at w / k (k = yaw_gain), whatever the time. A field whose strength is off by
// more than mag_tolerance is refused, and the drift is then the gyroscope's.
TEST(Fusion, TheMagnetometerHoldsYawAtBiasOverGain) {
  const double w = glm::radians(0.5), k = 0.5, dt = 1e-3, seconds = 60.0;
  const glm::dvec3 field = ImuNoise{}.mag_field;
  auto run = [&](double gain, double field_scale_after_first) {
    FusionParams p;
    p.estimate_bias = false;
    p.yaw_gain = gain;
    Fusion f(p);
    for (int i = 0; i < static_cast<int>(seconds / dt); ++i)
      f.update(glm::dvec3(0, w, 0), glm::dvec3(0, kStandardGravity, 0), field * (i == 0 ? 1.0 : field_scale_after_first), dt);
    return f;
  };
  const Fusion without = run(0.0, 1.0), with = run(k, 1.0), disturbed = run(k, 1.5);
  EXPECT_NEAR(angle_between_deg(without.orientation(), glm::dquat(1, 0, 0, 0)), 0.5 * seconds, 1e-6);
  EXPECT_NEAR(angle_between_deg(with.orientation(), glm::dquat(1, 0, 0, 0)), glm::degrees(w / k), 0.01 * glm::degrees(w / k));
  EXPECT_EQ(with.mag_used(), static_cast<int64_t>(seconds / dt) - 1);
  EXPECT_EQ(disturbed.mag_refused(), static_cast<int64_t>(seconds / dt) - 1);
  EXPECT_NEAR(angle_between_deg(disturbed.orientation(), glm::dquat(1, 0, 0, 0)), 0.5 * seconds, 1e-6);
  FusionParams bad;
  bad.yaw_gain = -1;
  EXPECT_THROW(Fusion{bad}, std::invalid_argument);
}

// The drift scenario (shaking bursts, an IMU with bias and noise, a
// magnetometer with 2 milligauss of noise) with the magnetometer: the yaw no
// longer accumulates what the bias learning has not yet removed.
TEST(Fusion, TheMagnetometerBoundsTheDriftScenariosYaw) {
  FusionParams mag;
  mag.yaw_gain = 0.1;
  const DriftResult without = run_drift(FusionParams{}, 600.0), with = run_drift(mag, 600.0);
  EXPECT_GT(without.total_deg, 30.0);
  EXPECT_LT(with.total_deg, 1.0);
  EXPECT_LT(with.tilt_deg, 1.0);
}

TEST(SyntheticImu, AtRestTheAccelerometerReadsGravityUp) {
  SamplingSpec s;
  s.duration_s = 0.0;
  auto still = constant_rotation(glm::dvec3(0, 1, 0), 0.0, s);
  auto imu = synthesize_imu(still, ImuNoise{});
  ASSERT_EQ(imu.size(), 1u);
  EXPECT_DOUBLE_EQ(imu[0].accel.y, kStandardGravity);
  still[0].orientation = glm::angleAxis(glm::radians(90.0), glm::dvec3(1, 0, 0));  // looking straight up
  imu = synthesize_imu(still, ImuNoise{});
  EXPECT_NEAR(imu[0].accel.z, -kStandardGravity, 1e-12);  // world up is where the face points: the head's -z
  // The magnetometer reads the field in the head frame: looking straight up, north (world -z, 0.22 gauss)
  // is toward the chin (the head's -y), and the field's downward part (0.42 gauss) leaves through the back
  // of the head (+z).
  EXPECT_NEAR(imu[0].mag.x, 0.0, 1e-12);
  EXPECT_NEAR(imu[0].mag.y, -0.22, 1e-12);
  EXPECT_NEAR(imu[0].mag.z, 0.42, 1e-12);
  ImuNoise noisy;
  noisy.mag_noise = 0.01;
  noisy.gyro_noise = 0.01;
  ImuNoise quiet_mag = noisy;
  quiet_mag.mag_noise = 0;
  const auto a = synthesize_imu(still, noisy), b = synthesize_imu(still, quiet_mag);
  EXPECT_EQ(a[0].gyro, b[0].gyro) << "the magnetometer's noise is its own stream";
  EXPECT_NE(a[0].mag, b[0].mag);
  still[0].has_angular_velocity = false;
  EXPECT_THROW(synthesize_imu(still, ImuNoise{}), std::invalid_argument);
}

TEST(Prediction, ExactForConstantRotationAndGrowingWithHorizonOtherwise) {
  SamplingSpec s;
  s.duration_s = 1.0;
  const auto spin = constant_rotation(glm::normalize(glm::dvec3(0, 1, 1)), 370.0, s);
  for (int h : {0, 1, 16, 100})
    EXPECT_LT(angle_between_deg(predict(spin[10].orientation, spin[10].angular_velocity, h * 1e-3),
                                spin[10 + static_cast<size_t>(h)].orientation), 1e-9);
  const auto shake = head_shake(glm::dvec3(0, 1, 0), 200.0, 1.0, s);
  double prev = -1.0;
  for (int h : {0, 10, 50, 100}) {
    double worst = 0.0;
    for (size_t i = 0; i + static_cast<size_t>(h) < shake.size(); ++i)
      worst = std::max(worst, angle_between_deg(predict(shake[i].orientation, shake[i].angular_velocity, h * 1e-3),
                                                shake[i + static_cast<size_t>(h)].orientation));
    EXPECT_GT(worst, prev);
    prev = worst;
  }
  EXPECT_THROW(predict(glm::dquat(1, 0, 0, 0), glm::dvec3(0), -0.001), std::invalid_argument);
}

#include "tracker/DeviceClock.hpp"

TEST(DeviceClock, Dk1MillisecondCounterUnwrapsAcrossItsWrap) {
  DeviceClock c(16, 1'000'000'000);  // 16-bit ms
  int64_t last = -1;
  int wraps = 0;
  for (int64_t ms = 65000; ms < 67000; ++ms) {  // crosses 65536
    const auto m = c.map(static_cast<uint64_t>(ms) & 0xFFFF, (ms - 65000) * 1'000'000'000 + 300'000'000);
    ASSERT_FALSE(m.backwards);
    ASSERT_GT(m.time_ps, last);
    wraps += m.wrapped;
    last = m.time_ps;
  }
  EXPECT_EQ(wraps, 1);
  EXPECT_EQ(c.unwrapped_ticks(), 1999);
  EXPECT_EQ(last, 300'000'000 + int64_t{1999} * 1'000'000'000);  // anchored at the first arrival
}

TEST(DeviceClock, BackwardStepsAreFlaggedAndHeld) {
  DeviceClock c(32, 1'000'000);  // 32-bit us
  c.map(1000, 0);
  const auto a = c.map(2000, 1'000'000'000);
  const auto b = c.map(1995, 1'000'000'000);  // 5 us back
  EXPECT_TRUE(b.backwards);
  EXPECT_EQ(b.time_ps, a.time_ps);
  const auto d = c.map(3000, 2'000'000'000);
  EXPECT_FALSE(d.backwards);
  EXPECT_EQ(d.time_ps, a.time_ps + 1'000'000'000);
  EXPECT_THROW(DeviceClock(1, 1), std::invalid_argument);
  EXPECT_THROW(DeviceClock(16, 0), std::invalid_argument);
}

namespace {
constexpr int64_t kMs = 1'000'000'000;  // ps
}

// A DK1 that restarts (its counter back to 0 after 30 s) carries on from the
// report's arrival: no freeze (the old clock took 32 s of reports as stale).
TEST(DeviceClock, ARestartedDeviceReanchorsToTheHostClock) {
  DeviceClock c(16, kMs);
  for (int64_t k = 0; k <= 30000; ++k) ASSERT_FALSE(c.map(static_cast<uint64_t>(k), k * kMs).reanchored);
  const auto r = c.map(0, 30001 * kMs);  // restarted
  EXPECT_TRUE(r.reanchored);
  EXPECT_FALSE(r.backwards);
  EXPECT_EQ(r.jump_ps, -30000 * kMs);
  EXPECT_EQ(r.time_ps, 30001 * kMs);  // the arrival
  const auto n = c.map(1, 30002 * kMs);
  EXPECT_FALSE(n.reanchored);
  EXPECT_EQ(n.time_ps, 30002 * kMs);
  EXPECT_EQ(c.reanchors(), 1);
}

// The counter leaps 10 s ahead while reports keep arriving 1 ms apart: the
// device's time would lead its arrival, which cannot be, so time carries on
// from the arrival.
TEST(DeviceClock, AForwardJumpReanchorsAndTimeStaysMonotonic) {
  DeviceClock c(32, 1'000'000);  // DK2: us
  for (int64_t k = 0; k < 100; ++k) c.map(static_cast<uint64_t>(k * 1000), k * kMs);
  const auto j = c.map(99'000 + 10'000'000, 100 * kMs);
  EXPECT_TRUE(j.reanchored);
  EXPECT_EQ(j.time_ps, 100 * kMs);
  EXPECT_EQ(j.jump_ps, 9'999 * kMs);  // the counter stepped 10 s, the arrival 1 ms
  const auto n = c.map(99'000 + 10'001'000, 101 * kMs);
  EXPECT_FALSE(n.reanchored);
  EXPECT_EQ(n.time_ps, 101 * kMs);
  // A lead within the tolerance is no jump: the anchor's arrival was late by that much (or the counter
  // glitched by it); the lower envelope takes the report's arrival as the bound, so time follows it.
  const auto e = c.map(99'000 + 10'002'000 + 200'000, 102 * kMs);
  EXPECT_FALSE(e.reanchored);
  EXPECT_EQ(e.time_ps, 102 * kMs);
  EXPECT_EQ(c.envelope_offset_ps(), -200.0 * kMs);
  const auto f = c.map(99'000 + 10'003'000 + 200'000, 103 * kMs);
  EXPECT_EQ(f.time_ps, 103 * kMs);
}

// The report the clock was anchored at arrived 400 ms late (a busy host, a
// burst of queued reports): the device's time then leads every later arrival.
// One re-anchor; the reports until the new segment passes the last time are
// held 1 ps apart (their samples kept), then time follows the arrivals.
TEST(DeviceClock, ALateAnchorIsCorrectedOnceWithoutGoingBack) {
  DeviceClock c(16, kMs);
  c.map(0, 400 * kMs);
  int held = 0;
  int64_t last = 400 * kMs;
  for (int64_t k = 1; k <= 1000; ++k) {
    const auto m = c.map(static_cast<uint64_t>(k), k * kMs);
    ASSERT_GT(m.time_ps, last) << k;
    last = m.time_ps;
    held += m.held;
    if (k > 400) {
      ASSERT_EQ(m.time_ps, k * kMs) << k;
    }
  }
  EXPECT_EQ(held, 400);
  EXPECT_EQ(c.reanchors(), 1);
}

// The lower envelope: reports reach the host 1-2 ms after the device sampled
// them (the transport's least latency, 1 ms, cannot be seen from the host),
// every 50th report the host is busy for 20 ms and those behind it arrive in
// a burst, and the very first report (the anchor) arrives 20 ms late. Times
// are shed to the soonest arrival seen: within a second every sample's time
// is within 0.1 ms of the device's plus the least latency (anchoring at the
// first arrival kept the 20 ms for the session), the timeline never goes
// back, and only reports being held can be given a time after their arrival.
// With the host's clock 100 ppm fast the skew is found and the envelope
// follows the skewed line (within 0.1 ms after two minutes); the hull stays a
// few vertices.
TEST(DeviceClock, TheLowerEnvelopeOfArrivalsShedsTheAnchorsLatency) {
  for (const double ppm : {0.0, 100.0}) {
    SCOPED_TRACE(ppm);
    DeviceClock c(16, kMs);
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<int64_t> latency(kMs, 2 * kMs);
    int64_t last = -1, arrival = 0;
    size_t widest_hull = 0;
    int held = 0;
    for (int64_t k = 0; k <= 120'000; ++k) {
      const int64_t host_of_sample = static_cast<int64_t>(static_cast<double>(k * kMs) * (1.0 + ppm * 1e-6));
      // The host stamps reports in the order they come: a report never arrives before the one ahead of it.
      arrival = std::max(arrival, host_of_sample + (k == 0 || k % 50 == 0 ? 20 * kMs : latency(rng)));
      const auto m = c.map(static_cast<uint64_t>(k) & 0xFFFF, arrival);
      ASSERT_FALSE(m.reanchored) << k;
      ASSERT_GT(m.time_ps, last) << k;
      if (!m.held) {
        ASSERT_LE(m.time_ps, arrival) << k;
      }
      held += m.held;
      last = m.time_ps;
      widest_hull = std::max(widest_hull, c.hull_size());
      if (k >= 1000 && (ppm == 0.0 || k >= 120'000)) {
        ASSERT_NEAR(static_cast<double>(m.time_ps - host_of_sample), 1.0 * kMs, 0.1 * kMs) << k;
      }
    }
    EXPECT_NEAR(c.skew_ppm(), ppm, 2.0);
    EXPECT_LT(widest_hull, 40u);
    EXPECT_GT(held, 0);    // the anchor's 20 ms were shed by holding, not by going back
    EXPECT_LT(held, 40);
  }
}

// A counter that stops while reports keep coming: held for max_held_reports
// reports, then re-anchored, so the pose freezes 50 ms at most.
TEST(DeviceClock, AStuckCounterReanchorsAfterTheHeldLimit) {
  DeviceClockLimits lim;
  lim.max_held_reports = 50;
  DeviceClock c(16, kMs, lim);
  c.map(7, 0);
  int held = 0;
  DeviceClock::Mapped m{};
  for (int64_t k = 1; k <= 50; ++k) {
    m = c.map(7, k * kMs);
    held += m.backwards;
  }
  EXPECT_EQ(held, 49);
  EXPECT_TRUE(m.reanchored);
  EXPECT_EQ(m.time_ps, 50 * kMs);
  // A stale report a few ticks back (within 20 ms) is held, not a restart; 30 ticks back is one.
  c.map(40, 52 * kMs);
  const auto stale = c.map(25, 53 * kMs);
  EXPECT_TRUE(stale.backwards);
  EXPECT_FALSE(stale.reanchored);
  const auto restart = c.map(10, 54 * kMs);
  EXPECT_TRUE(restart.reanchored);
  EXPECT_EQ(restart.jump_ps, -30 * kMs);
  EXPECT_THROW(DeviceClock(16, kMs, DeviceClockLimits{10.0, 0.0, 0.25, 50}), std::invalid_argument);
  EXPECT_THROW(DeviceClock(16, kMs, DeviceClockLimits{10.0, 0.02, 0.0, 50}), std::invalid_argument);
  EXPECT_THROW(DeviceClock(16, kMs, DeviceClockLimits{10.0, 0.02, 0.25, 0}), std::invalid_argument);
}

// Over 75 minutes of a DK2 (its 32-bit microsecond counter wraps at 71.6 min)
// whose crystal runs 80 ppm fast, with up to 2 ms of transfer latency: no
// re-anchor, one wrap, and time within 2 ms of arrival at the end.
TEST(DeviceClock, AnHourAndAQuarterOfDk2CountsNoJumpAndTracksTheHost) {
  DeviceClock c(32, 1'000'000);
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int64_t> latency(0, 2 * kMs);
  const int64_t reports = 75 * 60 * 100;  // every 10 ms
  int wraps = 0;
  int64_t last = -1;
  DeviceClock::Mapped m{};
  int64_t arrival = 0;
  for (int64_t k = 0; k < reports; ++k) {
    const int64_t device_us = k * 10'000;
    arrival = static_cast<int64_t>(static_cast<double>(device_us) * 1e6 / (1 + 80e-6)) + latency(rng);
    m = c.map(static_cast<uint64_t>(device_us) + 4'000'000'000u, arrival);  // starts near the wrap
    ASSERT_FALSE(m.reanchored) << k;
    ASSERT_GT(m.time_ps, last) << k;
    wraps += m.wrapped;
    last = m.time_ps;
  }
  EXPECT_EQ(wraps, 1);
  EXPECT_NEAR(c.skew_ppm(), -80.0, 1.0);
  EXPECT_LT(std::llabs(m.time_ps - arrival), 2 * kMs);
}

TEST(DeviceClock, SkewIsEstimatedFromArrivalsWithJitter) {
  // The host runs 100 ppm faster than the device; arrivals jitter by 0-1 ms.
  DeviceClock c(32, 1'000'000, DeviceClockLimits{10.0, 0.02, 0.25, 50});
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int64_t> jitter(0, 1'000'000'000);
  DeviceClock::Mapped m{};
  for (int64_t ms = 0; ms <= 120'000; ++ms) {  // two minutes of 1 kHz reports
    const int64_t device_ps = ms * 1'000'000'000;
    const int64_t arrival = static_cast<int64_t>(static_cast<double>(device_ps) * (1.0 + 100e-6)) + jitter(rng);
    m = c.map(static_cast<uint64_t>(ms * 1000) & 0xFFFFFFFF, arrival);
  }
  EXPECT_NEAR(c.skew_ppm(), 100.0, 1.0);
  // Two minutes of device time map onto the host's two minutes and 12 ms, within the jitter.
  const double host_end = 120.0 * (1.0 + 100e-6);
  EXPECT_NEAR(static_cast<double>(m.time_ps) * 1e-12, host_end, 1.5e-3);
}

TEST(DeviceClock, Dk2MicrosecondCounterOverTwoHours) {
  DeviceClock c(32, 1'000'000);  // wraps every 71.6 min
  int64_t last = -1;
  int wraps = 0;
  for (int64_t ms = 0; ms <= 2 * 3600 * 1000; ms += 100) {  // 10 Hz for two hours
    const auto m = c.map(static_cast<uint64_t>(ms * 1000) & 0xFFFFFFFF, ms * 1'000'000'000);
    ASSERT_FALSE(m.backwards);
    ASSERT_GT(m.time_ps, last);
    wraps += m.wrapped;
    last = m.time_ps;
  }
  EXPECT_EQ(wraps, 1);
  EXPECT_NEAR(static_cast<double>(last) * 1e-12, 7200.0, 1e-6);
  EXPECT_NEAR(c.skew_ppm(), 0.0, 1e-6);
}

// A dataset in the 'timestamp frameId w x y z' layout: units, header,
// handedness (a Unity turn to the right stays a turn to the right) and bad lines.
TEST(DatasetImport, UnitsAxesAndBadLines) {
  arp::test::TempDir d;
  const double h = std::sqrt(0.5);
  {
    std::ofstream f(d.file("unity.txt"));
    f << "timestamp frameId qw qx qy qz\n"
      << "1000 0 1 0 0 0\n"
      << "1016.5 1 " << std::cos(0.25) << " 0 " << std::sin(0.25) << " 0\n"  // Unity: 0.5 rad about +y (a turn right)
      << "# a comment\n"
      << "1033,2," << h << ",0," << h << ",0\n";
  }
  DatasetLayout unity;
  unity.time_unit = DatasetLayout::TimeUnit::Milliseconds;
  std::string why;
  ASSERT_TRUE(parse_axes("unity", unity.axes, why)) << why;
  const auto s = read_head_motion_dataset(d.file("unity.txt"), unity);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].time_ps, 0);
  EXPECT_EQ(s[1].time_ps, 16'500'000'000);
  EXPECT_EQ(s[2].time_ps, 33'000'000'000);
  // Our head looks down -z; after the turn right it looks toward +x.
  const glm::dvec3 ahead = s[2].orientation * glm::dvec3(0, 0, -1);
  EXPECT_NEAR(ahead.x, 1.0, 1e-9);
  EXPECT_NEAR(ahead.z, 0.0, 1e-9);
  DatasetLayout gl;  // the same numbers read as right-handed: a turn left
  EXPECT_NEAR((read_head_motion_dataset(d.file("unity.txt"), gl)[2].orientation * glm::dvec3(0, 0, -1)).x, -1.0, 1e-9);
  // Scalar last.
  {
    std::ofstream f(d.file("xyzw.txt"));
    f << "0 0 0 0 0 1\n0.01 1 0 " << std::sin(0.25) << " 0 " << std::cos(0.25) << "\n";
  }
  DatasetLayout xyzw;
  ASSERT_TRUE(parse_columns("t=1,frame=2,qx=3,qy=4,qz=5,qw=6", xyzw.columns, why)) << why;
  EXPECT_NEAR(angle_between_deg(read_head_motion_dataset(d.file("xyzw.txt"), xyzw)[1].orientation,
                                glm::angleAxis(0.5, glm::dvec3(0, 1, 0))),
              0.0, 1e-3);  // six digits in the file
  // Bad lines: the file, the line and the reason.
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"0 0 1 0 0 0\n0.1 1 1 0 0\n", "line 2: expected 6 columns"},
      {"0 0 1 0 0 0\n0.1 1 one 0 0 0\n", "line 2: quaternion 'one' is not a finite number"},
      {"0 0 1 0 0 0\n0.1 1 0 0 0 0\n", "line 2: the quaternion is zero"},
      {"0 0 1 0 0 0\n0.1 1 2 0 0 0\n", "line 2: the quaternion is not unit length"},
      {"0.1 0 1 0 0 0\n0 1 1 0 0 0\n", "line 2: timestamp 0 goes back"},
      {"0 0 1 0 0 0\n0.1 1.5 1 0 0 0\n", "line 2: frame id '1.5' is not a non-negative integer"},
      {"0 0 1 0 0 0\n0.1 1 nan 0 0 0\n", "line 2: quaternion 'nan' is not a finite number"},
      {"0 0 1 0 0 0\n", "fewer than two samples"}};
  for (const auto& [text, want] : bad) {
    {
      std::ofstream f(d.file("bad.txt"));
      f << text;
    }
    try {
      read_head_motion_dataset(d.file("bad.txt"), gl);
      ADD_FAILURE() << "accepted: " << want;
    } catch (const arp::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("bad.txt"), std::string::npos) << e.what();
    }
  }
}

#include "tracker/PoseSource.hpp"

// Recorded sources hand over all their samples once; a USB source with no
// device says why it cannot open.
TEST(PoseSource, RecordedSourcesAndNoDevice) {
  arp::test::TempDir d;
  SamplingSpec spec;
  spec.duration_s = 0.5;
  const auto motion = head_shake({0, 1, 0}, 200, 1.0, spec);
  write_trace_csv(d.file("t.csv"), motion);
  std::vector<std::unique_ptr<PoseSource>> sources;
  sources.push_back(recorded_source(motion, "synthetic"));
  sources.push_back(trace_file_source(d.file("t.csv")));
  for (auto& src : sources) {
    EXPECT_FALSE(src->live());
    std::vector<PoseSample> got;
    src->poll(got, 0);
    ASSERT_EQ(got.size(), motion.size());
    EXPECT_NEAR(angle_between_deg(got.back().orientation, motion.back().orientation), 0.0, 1e-6);
    src->poll(got, 0);
    EXPECT_EQ(got.size(), motion.size());  // once
    EXPECT_TRUE(src->take_events().empty());
    StreamStats st;
    EXPECT_FALSE(src->usb_stats(st));
  }
  EXPECT_EQ(trace_file_source(d.file("t.csv"))->describe(), d.file("t.csv"));
  EXPECT_THROW(trace_file_source(d.file("missing.csv")), arp::InputError);
  std::string err;
  EXPECT_EQ(usb_source(err), nullptr);  // no tracker here (the USB tests emulate one)
  EXPECT_FALSE(err.empty());
}

// Synthetic motion taken in pieces (as a long run takes it, frame by frame)
// is exactly the motion taken at once -- noise included: one seeded
// generator in sample order -- and each piece ends on the first sample after
// the time asked for.
TEST(SyntheticMotion, PiecesAreTheWholeBitForBit) {
  arp::tracker::MotionSpec m;
  m.motion = "shake";
  m.noise = 0.5;
  m.seed = 7;
  const auto whole = m.make(-1.0, 2.5);
  ASSERT_EQ(whole.size(), 2501u);
  auto g = m.generator(-1.0, 2.5);
  std::vector<arp::tracker::PoseSample> pieces;
  for (int64_t t = -900'000'000'000; !g.done(); t += 16'666'666'667) {
    const size_t before = pieces.size();
    g.take_through(t, pieces);
    if (!g.done()) {
      ASSERT_GT(pieces.back().time_ps, t);
      if (pieces.size() - before > 1) {
        EXPECT_LE(pieces[pieces.size() - 2].time_ps, t);
      }
    }
  }
  ASSERT_EQ(pieces.size(), whole.size());
  for (size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(pieces[i].time_ps, whole[i].time_ps) << i;
    EXPECT_EQ(pieces[i].orientation, whole[i].orientation) << i;
    EXPECT_EQ(pieces[i].angular_velocity, whole[i].angular_velocity) << i;
  }
}

#include "tracker/UsbTrackers.hpp"

// Which tracker a reconnection takes (choose_again), whatever chose it first: by its serial number,
// wherever it now is; without one, at its old address, else the only serial-less tracker of its model
// (a replug moves the address, so --device BUS:ADDR is not held to the old one); never another model or
// one of several it cannot be told from.
TEST(UsbTrackers, AReconnectionTakesTheTrackerStreamedBefore) {
  auto tracker = [](RiftModel m, int address, std::string serial) {
    UsbTrackerInfo t;
    t.model = m;
    t.bus = 1;
    t.address = address;
    t.serial = std::move(serial);
    t.can_open = true;
    return t;
  };
  std::string why;
  // With a serial: found at its new address; another tracker at the old address is not taken.
  const UsbTrackerInfo first = tracker(RiftModel::DK1, 4, "FIRST");
  EXPECT_EQ(choose_again({tracker(RiftModel::DK1, 4, "OTHER"), tracker(RiftModel::DK1, 9, "FIRST")}, first, why), 1);
  EXPECT_EQ(choose_again({tracker(RiftModel::DK1, 4, "OTHER")}, first, why), -1);
  EXPECT_EQ(why, "waiting for the tracker streamed before (serial FIRST): attached: DK1 bus 001 address 004 serial OTHER");
  // Without one: the old address first, then the only serial-less tracker of the model.
  const UsbTrackerInfo unread = tracker(RiftModel::DK1, 4, "");
  EXPECT_EQ(choose_again({tracker(RiftModel::DK1, 7, ""), tracker(RiftModel::DK1, 4, "")}, unread, why), 1);
  EXPECT_EQ(choose_again({tracker(RiftModel::DK2, 5, ""), tracker(RiftModel::DK1, 6, "")}, unread, why), 1);
  EXPECT_EQ(choose_again({tracker(RiftModel::DK1, 6, ""), tracker(RiftModel::DK1, 4, "READ-NOW")}, unread, why), 1);  // its serial read now
  EXPECT_EQ(choose_again({tracker(RiftModel::DK2, 4, ""), tracker(RiftModel::DK1, 6, "SERIAL")}, unread, why), -1);
  EXPECT_NE(why.find("DK1 bus 001 address 004 (serial unread); without a serial number it is known by its model, and none of that model "
                     "without one is attached"),
            std::string::npos)
      << why;
  EXPECT_EQ(choose_again({tracker(RiftModel::DK1, 6, ""), tracker(RiftModel::DK1, 7, "")}, unread, why), -1);
  EXPECT_NE(why.find("2 of that model without one are attached and cannot be told apart"), std::string::npos) << why;
  EXPECT_EQ(choose_again({}, unread, why), -1);
}

#include "common/Units.hpp"
#include "tracker/MagCalibration.hpp"

namespace {
// A head turning at 60 deg/s while nodding +-40 deg every 5 s (looking around a room), 1 kHz, with its
// head-frame angular velocity.
std::vector<PoseSample> look_around(double seconds) {
  std::vector<PoseSample> v;
  const int n = static_cast<int>(seconds * 1000);
  auto at = [](double t) {
    return glm::angleAxis(glm::radians(60.0 * t), glm::dvec3(0, 1, 0)) *
           glm::angleAxis(glm::radians(40.0 * std::sin(2 * arp::kPi * t / 5.0)), glm::dvec3(1, 0, 0));
  };
  for (int i = 0; i <= n; ++i) {
    PoseSample p;
    p.time_ps = static_cast<int64_t>(i) * 1'000'000'000;
    p.orientation = at(i * 1e-3);
    p.has_angular_velocity = true;
    p.angular_velocity = rate_between(at(i * 1e-3 - 0.5e-3), at(i * 1e-3 + 0.5e-3), 1e-3);
    v.push_back(p);
  }
  return v;
}
}  // namespace

// The magnetometer's own field (hard iron, 0.15-0.25 gauss: as large as the earth's 0.47) added to every
// reading, a head looking around (60 deg/s, nodding +-40 deg, never still: the tilt is not corrected)
// with a 0.5 deg/s gyro bias, gain 0.5. The reference is the same fusion with a clean magnetometer: its
// heading error (fused minus true, about world up) stays within a few degrees of where it began. Taken
// as read, the hard iron pulls the heading by an amount that depends on where the head looks (it is
// lost). Learned (a sphere fit, trusted once the head has looked around: about 20 s here), the heading
// holds as well as the reference's from when the calibration was trusted (the gyro's drift before then
// is not recovered: the reference heading is taken then), and the offset is found within 2 milligauss.
TEST(Fusion, TheMagnetometersHardIronIsLearnedAsTheHeadLooksAround) {
  const auto truth = look_around(60.0);
  ImuNoise noise;
  noise.gyro_bias = glm::dvec3(0, glm::radians(0.5), 0);
  noise.mag_noise = 0.002;
  noise.mag_hard_iron = glm::dvec3(0.15, -0.2, 0.25);
  const auto imu = synthesize_imu(truth, noise);
  ImuNoise clean = noise;
  clean.mag_hard_iron = glm::dvec3(0.0);
  const auto imu_clean = synthesize_imu(truth, clean);
  auto heading_deg = [](const glm::dquat& q) {
    const glm::dvec3 f = q * glm::dvec3(0, 0, -1);
    return glm::degrees(std::atan2(-f.x, -f.z));
  };
  struct Result {
    double ready_s = -1;               // when the calibration was first trusted (0 without calibration)
    double drift_deg = 0;              // the largest |e - e(ready)| from 30 s on
    Fusion fusion;
  };
  auto run = [&](const std::vector<ImuReading>& readings, bool calibrate) {
    FusionParams p;
    p.estimate_bias = false;
    p.yaw_gain = 0.5;
    p.mag_calibrate = calibrate;
    Result r{calibrate ? -1.0 : 0.0, 0.0, Fusion(p, truth[0].orientation)};
    double e_ready = 0;
    for (size_t i = 1; i < readings.size(); ++i) {
      r.fusion.update(readings[i].gyro, readings[i].accel, readings[i].mag, 1e-3);
      double e = heading_deg(r.fusion.orientation()) - heading_deg(truth[i].orientation);
      e = std::remainder(e, 360.0);
      if (r.ready_s < 0 && r.fusion.calibration().ready()) {
        r.ready_s = static_cast<double>(i) * 1e-3;
        e_ready = e;
      }
      if (i >= 30'000) r.drift_deg = std::max(r.drift_deg, std::abs(std::remainder(e - e_ready, 360.0)));
    }
    return r;
  };
  const Result raw = run(imu, false), learned = run(imu, true), reference = run(imu_clean, false);
  std::printf("hard iron: heading held within %.2f deg taken as read, %.2f deg learned (trusted after %.1f s, %zu readings kept), "
              "%.2f deg with a clean magnetometer; offset found within %.4f G\n",
              raw.drift_deg, learned.drift_deg, learned.ready_s, learned.fusion.calibration().points(), reference.drift_deg,
              glm::length(learned.fusion.calibration().offset() - noise.mag_hard_iron));
  ASSERT_TRUE(learned.fusion.calibration().ready());
  EXPECT_LT(learned.ready_s, 30.0);
  EXPECT_LT(glm::length(learned.fusion.calibration().offset() - noise.mag_hard_iron), 0.002);
  EXPECT_NEAR(learned.fusion.calibration().radius(), glm::length(noise.mag_field), 0.002);
  EXPECT_LT(reference.drift_deg, 5.0);
  EXPECT_LT(learned.drift_deg, reference.drift_deg + 0.5);
  EXPECT_GT(raw.drift_deg, 30.0);
}

// A head that only turns about the vertical gives a circle of readings: the offset along the turning axis
// cannot be told, so no calibration is trusted (and no yaw correction made from it).
TEST(MagCalibration, ACircleOfReadingsIsNotEnough) {
  SamplingSpec s;
  s.rate_hz = 100;
  s.duration_s = 20;
  MagCalibration c;
  const glm::dvec3 field = ImuNoise{}.mag_field, hard(0.1, 0.1, 0.1);
  for (const auto& p : constant_rotation(glm::dvec3(0, 1, 0), 90.0, s)) c.add(glm::conjugate(p.orientation) * field + hard);
  EXPECT_GE(c.points(), 12u);
  EXPECT_FALSE(c.ready());
  EXPECT_EQ(c.offset(), glm::dvec3(0.0));
  MagCalibrationParams bad;
  bad.min_points = 3;
  EXPECT_THROW(MagCalibration{bad}, std::invalid_argument);
}
