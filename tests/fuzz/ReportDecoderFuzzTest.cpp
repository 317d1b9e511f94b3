// The fuzz target run briefly in the ordinary tests: 200 000 inputs from a
// fixed seed -- random bytes of every length around a report's, and valid
// DK1/DK2 reports with bytes flipped -- every one decoded or refused without
// reading past its end (ASan build) and round-tripping when accepted.
#include <gtest/gtest.h>

#include <random>

#include "ReportDecoderFuzz.hpp"
#include "tracker/RiftProtocol.hpp"

TEST(ReportDecoderFuzz, RandomAndMutatedReports) {
  std::mt19937_64 rng(20261122);
  std::vector<uint8_t> buf;
  int64_t runs = 0;
  for (int i = 0; i < 100000; ++i) {
    buf.resize(1 + rng() % 80);
    for (auto& b : buf) b = static_cast<uint8_t>(rng());
    if (buf.size() > 1 && rng() % 2) buf[1] = (buf[0] & 1) ? 11 : 1;  // the right report id half the time
    arp::fuzz::report_decoder_one_input(buf.data(), buf.size());
    ++runs;
  }
  for (int i = 0; i < 100000; ++i) {
    arp::tracker::ImuReport r;
    r.model = (i & 1) ? arp::tracker::RiftModel::DK2 : arp::tracker::RiftModel::DK1;
    r.sample_count = static_cast<int>(rng() % (r.model == arp::tracker::RiftModel::DK1 ? 4 : 3));
    r.timestamp = static_cast<uint32_t>(rng()) & (r.model == arp::tracker::RiftModel::DK1 ? 0xffffu : 0xffffffffu);
    for (int s = 0; s < r.sample_count; ++s)
      for (int a = 0; a < 3; ++a) {
        r.samples[static_cast<size_t>(s)].accel[static_cast<size_t>(a)] = static_cast<int32_t>(rng() % (1 << 21)) - (1 << 20);
        r.samples[static_cast<size_t>(s)].gyro[static_cast<size_t>(a)] = static_cast<int32_t>(rng() % (1 << 21)) - (1 << 20);
      }
    const auto rep = arp::tracker::encode_report(r);
    buf.assign(1, static_cast<uint8_t>(i & 1));
    buf.insert(buf.end(), rep.begin(), rep.end());
    for (int f = static_cast<int>(rng() % 4); f > 0; --f) buf[1 + rng() % rep.size()] ^= static_cast<uint8_t>(1u << (rng() % 8));
    if (rng() % 8 == 0) buf.resize(1 + rng() % buf.size());  // cut short
    arp::fuzz::report_decoder_one_input(buf.data(), buf.size());
    ++runs;
  }
  EXPECT_EQ(runs, 200000);
}
