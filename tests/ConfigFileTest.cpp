#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "TestSupport.hpp"
#include "sim/ConfigFile.hpp"
#include "common/InputError.hpp"

using namespace arp;
using nlohmann::json;

using arp::test::error_of;

namespace {
dp::ArpConfig parse(const std::string& text) { return config::from_json(json::parse(text), "test.json"); }
}  // namespace

TEST(ConfigFile, DefaultsAreTheBriefsAndRoundTrip) {
  const dp::ArpConfig d;
  EXPECT_TRUE(dp::validate(d).empty());
  EXPECT_EQ(d.timing.eyes, 2);
  EXPECT_EQ(d.timing.h_total(), 800);
  EXPECT_EQ(d.timing.v_total(), 525);
  EXPECT_EQ(d.timing.pixel_clock_hz, 25'175'000);
  EXPECT_EQ(d.memory.count, 4);
  EXPECT_EQ(d.memory.face_size, 512);
  EXPECT_EQ(d.memory.color_bits(), 24);
  EXPECT_EQ(d.memory.depth_bits, 16);
  EXPECT_EQ(d.widths.vec_frac, 14);
  EXPECT_EQ(d.widths.mat_frac, 14);
  EXPECT_EQ(d.pipeline.latch, dp::LatchPolicy::PerScanline);
  const json j = config::to_json(d);
  EXPECT_EQ(config::to_json(config::from_json(j, "round trip")), j);
}

TEST(ConfigFile, TheCommittedReferenceDocIsGeneratedFromTheParameterTable) {
  const std::string doc = test::read_text(std::string(ARPSIM_SOURCE_DIR) + "/docs/configuration.md");
  ASSERT_FALSE(doc.empty()) << "docs/configuration.md missing";
  EXPECT_EQ(config::update_reference_doc(doc), doc)
      << "docs/configuration.md is stale: build/apps/arpsim/arpsim config --update-doc docs/configuration.md";
  // Every key appears, once, in a generated table with its default.
  const json j = config::to_json(dp::ArpConfig{});
  for (auto s = j.begin(); s != j.end(); ++s)
    for (auto k = s.value().begin(); k != s.value().end(); ++k) {
      const std::string row = "| `" + s.key() + "." + k.key() + "` |";
      EXPECT_NE(doc.find(row), std::string::npos) << row;
      EXPECT_EQ(doc.find(row), doc.rfind(row)) << row;
    }
}

// A section of the table with no generated block in the doc is an error naming
// the doc and the section, not "current" with its keys left out.
TEST(ConfigFile, TheReferenceDocMustHaveATableForEverySection) {
  std::string doc = test::read_text(std::string(ARPSIM_SOURCE_DIR) + "/docs/configuration.md");
  const size_t b = doc.find("<!-- generated: host -->");
  ASSERT_NE(b, std::string::npos);
  doc.erase(b, doc.find("<!-- end generated -->", b) + 22 - b);
  const InputError e = error_of([&] { config::update_reference_doc(doc, "my.md"); });
  EXPECT_EQ(e.source(), "my.md");
  EXPECT_NE(e.reason().find("section 'host'"), std::string::npos) << e.what();
}

TEST(ConfigFile, EveryParameterIsDeclaredOnceWithADocAndItsDefaultInRange) {
  const auto& t = dp::arp_parameters();
  EXPECT_EQ(t.sections(), (std::vector<std::string>{"display", "lens", "datapath", "memory", "pipeline", "timed", "host", "plan"}));
  size_t n = 0;
  for (const auto& p : t.all()) {
    ++n;
    EXPECT_FALSE(p.doc.empty()) << p.key;
    EXPECT_EQ(p.range_error(p.get(dp::ArpConfig{})), "") << p.key;
  }
  EXPECT_EQ(n, 12u + 3 + 12 + 16 + 5 + 2 * dp::kStageCount + 4 + 3 + 3);  // display, lens, datapath, memory, pipeline, timed, host, plan
  // The table and the JSON writer agree: every key written is declared, and the other way round.
  const json j = config::to_json(dp::ArpConfig{});
  size_t written = 0;
  for (auto s = j.begin(); s != j.end(); ++s) written += s.value().size();
  EXPECT_EQ(written, n);
}

TEST(ConfigFile, StrictReadingRefusesRepeatsOverflowsAndDeepNesting) {
  test::TempDir d;
  auto file_error = [&](const std::string& text) {
    std::ofstream(d.file("c.json")) << text;
    return error_of([&] { config::load_file(d.file("c.json")); });
  };
  auto e = file_error(R"({"datapath": {"vec_frac": 12, "vec_frac": 13}})");
  EXPECT_EQ(e.place(), "datapath.vec_frac");
  EXPECT_NE(e.reason().find("twice"), std::string::npos);
  e = file_error("{\n \"lens\": {\"fov_deg\": 1e400}}");
  EXPECT_NE(e.place().find("line 2"), std::string::npos) << e.what();
  EXPECT_NE(e.reason().find("too large"), std::string::npos) << e.what();
  e = file_error(std::string(100000, '[') + std::string(100000, ']'));
  EXPECT_NE(e.reason().find("deeper"), std::string::npos) << e.what();
  e = file_error(R"({"memory": {"face_size": 18446744073709551615}})");
  EXPECT_NE(e.reason().find("18446744073709551615"), std::string::npos) << e.what();
  // One past uint64 is read as a real number: still too large, not "must be an integer".
  e = file_error(R"({"memory": {"face_size": 18446744073709551616}})");
  EXPECT_NE(e.reason().find("beyond any integer setting"), std::string::npos) << e.what();
  e = file_error(R"({"memory": {"face_size": -1e19}})");
  EXPECT_NE(e.reason().find("beyond any integer setting"), std::string::npos) << e.what();
  e = file_error(R"({"memory": {"background": [4294967296, 0, 0]}})");
  EXPECT_EQ(e.place(), "memory.background");
  EXPECT_NE(e.reason().find("element 0"), std::string::npos) << e.what();
  e = file_error(R"({"datapath": {"newton_steps": 3.9}})");
  EXPECT_NE(e.reason().find("integer"), std::string::npos);
  e = file_error(R"({"lens": {"k": [1e308, 0, 0, 0]}})");
  EXPECT_EQ(e.place(), "lens.k");
  e = file_error(R"({"lens": {"fov_deg": 1e-320}})");
  EXPECT_NE(e.reason().find("must be in"), std::string::npos) << e.what();
  // A long bad value is quoted, not echoed whole.
  e = file_error(R"({"pipeline": {"latch": ")" + std::string(100000, 'x') + "\"}}");
  EXPECT_LT(e.reason().size(), 200u);
  const InputError dev = error_of([] { config::load_file("/dev/zero"); });
  EXPECT_NE(dev.reason().find("regular file"), std::string::npos);
}

TEST(ConfigFile, PartialFilesOverrideOnlyTheirKeys) {
  const dp::ArpConfig c = parse(R"({"datapath": {"vec_frac": 12, "divider": "exact"}, "pipeline": {"latch": "pixel"}})");
  EXPECT_EQ(c.widths.vec_frac, 12);
  EXPECT_EQ(c.widths.divider, dp::DividerKind::Exact);
  EXPECT_EQ(c.pipeline.latch, dp::LatchPolicy::PerPixel);
  EXPECT_EQ(c.widths.mat_frac, 14);
}

TEST(ConfigFile, BadValuesNameTheKeyAndReason) {
  auto e = error_of([] { parse(R"({"display": {"h_activ": 640}})"); });
  EXPECT_EQ(e.source(), "test.json");
  EXPECT_EQ(e.place(), "display.h_activ");
  EXPECT_EQ(e.reason(), "unknown key");
  e = error_of([] { parse(R"({"displays": {}})"); });
  EXPECT_EQ(e.place(), "displays");
  e = error_of([] { parse(R"({"datapath": {"vec_frac": 0}})"); });
  EXPECT_EQ(e.place(), "datapath.vec_frac");
  EXPECT_NE(e.reason().find("[1, 28]"), std::string::npos);
  e = error_of([] { parse(R"({"datapath": {"mat_frac": 29}})"); });
  EXPECT_EQ(e.place(), "datapath.mat_frac");
  e = error_of([] { parse(R"({"datapath": {"vec_frac": "14"}})"); });
  EXPECT_NE(e.reason().find("integer"), std::string::npos);
  e = error_of([] { parse(R"({"datapath": {"vec_frac": 14.5}})"); });
  EXPECT_NE(e.reason().find("integer"), std::string::npos);
  e = error_of([] { parse(R"({"lens": {"fov_deg": 180}})"); });
  EXPECT_EQ(e.place(), "lens.fov_deg");
  e = error_of([] { parse(R"({"lens": {"fov_deg": 0}})"); });
  EXPECT_EQ(e.place(), "lens.fov_deg");
  e = error_of([] { parse(R"({"lens": {"fov_deg": -10}})"); });
  EXPECT_EQ(e.place(), "lens.fov_deg");
  e = error_of([] { parse(R"({"lens": {"k": [1, 0, 0]}})"); });
  EXPECT_EQ(e.place(), "lens.k");
  e = error_of([] { parse(R"({"lens": {"k": [1, -5, 0, 0]}})"); });
  EXPECT_NE(e.reason().find("not positive"), std::string::npos);
  e = error_of([] { parse(R"({"pipeline": {"latch": "line"}})"); });
  EXPECT_NE(e.reason().find("frame, field, scanline, pixel"), std::string::npos);
  e = error_of([] { parse(R"({"memory": {"red_bits": 16, "green_bits": 16, "blue_bits": 1}})"); });
  EXPECT_NE(e.reason().find("32"), std::string::npos);
  e = error_of([] { parse(R"({"memory": {"face_size": 99999999999}})"); });
  EXPECT_EQ(e.place(), "memory.face_size");
  e = error_of([] { parse(R"({"pipeline": {"texel_frac": 0}})"); });
  EXPECT_EQ(e.place(), "pipeline.texel_frac");
  EXPECT_EQ(e.reason(), "unknown key");
  e = error_of([] { parse(R"({"datapath": {"texel_frac": 0}})"); });
  EXPECT_NE(e.reason().find("bilinear"), std::string::npos);
  e = error_of([] { parse(R"([1, 2])"); });
  EXPECT_NE(e.reason().find("object"), std::string::npos);
  // A list of strings (memory.tiles): an array, of strings, of the stated characters, at most 16 of them.
  e = error_of([] { parse(R"({"memory": {"tiles": "512:*/*/*/*/*/*"}})"); });
  EXPECT_EQ(e.place(), "memory.tiles");
  EXPECT_NE(e.reason().find("must be an array of strings"), std::string::npos) << e.reason();
  e = error_of([] { parse(R"({"memory": {"count": 2, "tiles": ["512:*/*/*/*/*/*", 7]}})"); });
  EXPECT_NE(e.reason().find("element 1 must be a string"), std::string::npos) << e.reason();
  e = error_of([] { parse(R"({"memory": {"tiles": ["512:*/*/*/*/*/x"]}})"); });
  EXPECT_NE(e.reason().find("string 0 has \"x\" at character 14"), std::string::npos) << e.reason();
  e = error_of([] { parse(R"({"memory": {"tiles": ["", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", ""]}})"); });
  EXPECT_NE(e.reason().find("has 17 strings, at most 16 allowed"), std::string::npos) << e.reason();
  e = error_of([] { parse(R"({"memory": {"count": 2, "tiles": ["512:*/*/*/*/*/*"]}})"); });
  EXPECT_EQ(e.place(), "memory.tiles");
  EXPECT_NE(e.reason().find("has 1 strings and memory.count is 2"), std::string::npos) << e.reason();
  // Read back as written.
  const dp::ArpConfig c = parse(R"({"memory": {"count": 2, "tiles": ["512:*/*/*/*/*/*", "512:-/-/-/-/-/-"]}})");
  EXPECT_EQ(c.memory.tiles, (std::vector<std::string>{"512:*/*/*/*/*/*", "512:-/-/-/-/-/-"}));
  EXPECT_EQ(dp::arp_parameters().find("memory.tiles")->format(dp::arp_parameters().find("memory.tiles")->get(c)),
            "[\"512:*/*/*/*/*/*\", \"512:-/-/-/-/-/-\"]");
  // A list of numbers of any length (memory.tile_pool): an array, of integers, each in range, at most 16, and
  // one for each memory or none.
  e = error_of([] { parse(R"({"memory": {"tile_pool": 100}})"); });
  EXPECT_EQ(e.place(), "memory.tile_pool");
  EXPECT_NE(e.reason().find("must be an array of integers"), std::string::npos) << e.reason();
  e = error_of([] { parse(R"({"memory": {"count": 2, "tile_pool": [100, "a"]}})"); });
  EXPECT_NE(e.reason().find("element 1"), std::string::npos) << e.reason();
  e = error_of([] { parse(R"({"memory": {"count": 2, "tile_pool": [100, 1.5]}})"); });
  EXPECT_NE(e.reason().find("element 1"), std::string::npos) << e.reason();
  e = error_of([] { parse(R"({"memory": {"count": 2, "tile_pool": [100, -1]}})"); });
  EXPECT_NE(e.reason().find("element 1 is -1, must be in [0, 16777216]"), std::string::npos) << e.reason();
  e = error_of([] { parse(R"({"memory": {"tile_pool": [1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1]}})"); });
  EXPECT_NE(e.reason().find("has 17 numbers, at most 16 allowed"), std::string::npos) << e.reason();
  e = error_of([] { parse(R"({"memory": {"count": 2, "tile_pool": [100]}})"); });
  EXPECT_EQ(e.place(), "memory.tile_pool");
  EXPECT_NE(e.reason().find("has 1 numbers and memory.count is 2"), std::string::npos) << e.reason();
  const dp::ArpConfig pooled = parse(R"({"memory": {"count": 2, "tile_pool": [100, 0]}})");
  EXPECT_EQ(pooled.memory.tile_pool, (std::vector<int64_t>{100, 0}));
  EXPECT_EQ(pooled.memory.pool_slots(0), 100);
  EXPECT_EQ(pooled.memory.pool_slots(1), 0);
  EXPECT_EQ(dp::arp_parameters().find("memory.tile_pool")->format(dp::arp_parameters().find("memory.tile_pool")->get(pooled)), "[100, 0]");
  EXPECT_EQ(config::apply_overrides({}, {"memory.tile_pool=[7, 0, 0, 3]"}).memory.tile_pool, (std::vector<int64_t>{7, 0, 0, 3}));
  // memory.assignment: "name: m" or "name: a-b", a the faster (lower), both memories of this configuration, each
  // name once; any printable text for the name (it may hold colons: the last one ends it).
  const auto assignment_error = [](const std::string& entry) {
    return error_of([&] { parse(R"({"memory": {"count": 4, "assignment": ["floor: 3", )" + entry + "]}}"); });
  };
  for (const auto& [entry, why] : std::vector<std::pair<std::string, std::string>>{
           {R"("wall")", "string 1 (\"wall\") has no colon"},
           {R"(" : 2")", "string 1 (\" : 2\") names no object before its colon"},
           {R"("wall: 4")", "memory 4 is past memory.count (4 memories, 0 .. 3)"},
           {R"("wall: 1-4")", "memory 4 is past memory.count"},
           {R"("wall: 3-1")", "runs from memory 3 to the faster memory 1"},
           {R"("wall: -1")", "\"-1\" is not a memory number (nor a range a-b of them)"},
           {R"("wall: x")", "\"x\" is not a memory number"},
           {R"("wall: 1.5")", "\"1.5\" is not a memory number"},
           {R"("wall: ")", "\"\" is not a memory number"},
           {R"("floor : 0-1")", "strings 0 and 1 both name \"floor\""},
           {R"("wall\t: 1")", "string 1 has byte 0x09 at character 4: only printable ASCII allowed"}}) {
    e = assignment_error(entry);
    EXPECT_EQ(e.place(), "memory.assignment") << entry;
    EXPECT_NE(e.reason().find(why), std::string::npos) << entry << ": " << e.reason();
  }
  e = error_of([] { parse(R"({"memory": {"assignment": "floor: 1"}})"); });
  EXPECT_NE(e.reason().find("must be an array of strings"), std::string::npos) << e.reason();
  const dp::ArpConfig assigned = parse(R"({"memory": {"count": 4, "assignment": ["floor: 3", " room 2: pillar :1 - 2 "]}})");
  std::vector<dp::ObjectAssignment> a;
  std::string why;
  ASSERT_TRUE(dp::object_assignments(assigned.memory, a, why)) << why;
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].name, "floor");
  EXPECT_EQ(a[0].fastest, 3);
  EXPECT_EQ(a[0].slowest, 3);
  EXPECT_EQ(a[1].name, "room 2: pillar");
  EXPECT_EQ(a[1].fastest, 1);
  EXPECT_EQ(a[1].slowest, 2);
  EXPECT_EQ(a[0].text(), "floor: 3");
  EXPECT_EQ(a[1].text(), "room 2: pillar: 1-2");  // and read back as itself
  dp::ObjectAssignment back;
  ASSERT_TRUE(dp::ObjectAssignment::parse(a[1].text(), 4, back, why)) << why;
  EXPECT_EQ(back.name, a[1].name);
  EXPECT_EQ(back.fastest, 1);
  EXPECT_EQ(back.slowest, 2);
  EXPECT_EQ(config::apply_overrides({}, {R"(memory.assignment=["floor: 0-2"])"}).memory.assignment,
            (std::vector<std::string>{"floor: 0-2"}));
}

TEST(ConfigFile, SyntaxErrorsGiveLineAndColumn) {
  test::TempDir d;
  std::ofstream(d.file("bad.json")) << "{\n  \"datapath\": {\n    \"vec_frac\": 12,\n  }\n}\n";
  const InputError e = error_of([&] { config::load_file(d.file("bad.json")); });
  EXPECT_EQ(e.source(), d.file("bad.json"));
  EXPECT_NE(e.place().find("line 4"), std::string::npos) << e.what();
  const InputError missing = error_of([&] { config::load_file(d.file("none.json")); });
  EXPECT_NE(missing.reason().find("cannot open"), std::string::npos);
}

// The file and the --set overrides are one configuration, its rules between keys checked on the whole: a file
// valid only with its overrides is accepted, and a rule broken is blamed on what broke it.
TEST(ConfigFile, AFileAndItsOverridesAreCheckedAsOne) {
  test::TempDir d;
  // No sub-texel bit is valid without bilinear filtering only; the default filter is bilinear.
  std::ofstream(d.file("nearest.json")) << R"({"pipeline": {"aa": "off"}, "datapath": {"texel_frac": 0}})";
  std::ofstream(d.file("frac0.json")) << R"({"datapath": {"texel_frac": 0}})";
  EXPECT_EQ(config::resolve(d.file("frac0.json"), {"pipeline.aa=off"}).widths.texel_frac, 0);
  // The file alone breaks the rule: the file is named.
  const InputError alone = error_of([&] { config::resolve(d.file("frac0.json"), {}); });
  EXPECT_EQ(alone.source(), d.file("frac0.json"));
  EXPECT_EQ(alone.place(), "datapath.texel_frac");
  EXPECT_NE(alone.reason().find("sub-texel bit"), std::string::npos) << alone.what();
  // The file alone breaks it, and an override of another key does not mend it: the file is named.
  EXPECT_EQ(error_of([&] { config::resolve(d.file("frac0.json"), {"memory.count=2"}); }).source(), d.file("frac0.json"));
  // An override of another key breaks it: both are named, the key the rule reads too.
  const InputError both = error_of([&] { config::resolve(d.file("nearest.json"), {"pipeline.aa=bilinear"}); });
  EXPECT_EQ(both.source(), d.file("nearest.json") + " with --set");
  EXPECT_EQ(both.place(), "datapath.texel_frac");
  // An override of the key itself: --set is named.
  const InputError set = error_of([&] { config::resolve(d.file("frac0.json"), {"pipeline.aa=bilinear", "datapath.texel_frac=0"}); });
  EXPECT_EQ(set.source(), "--set");
  EXPECT_EQ(error_of([] { config::resolve("", {"datapath.texel_frac=0"}); }).source(), "--set");
}

TEST(ConfigFile, OverridesSetOneKeyEach) {
  const dp::ArpConfig c = config::apply_overrides(dp::ArpConfig{}, {"datapath.rot_rounding=half_even", "memory.count=2"});
  EXPECT_EQ(c.widths.rot_rounding, dp::Rounding::HalfEven);
  EXPECT_EQ(c.memory.count, 2);
  EXPECT_THROW(config::apply_overrides(dp::ArpConfig{}, {"vec_frac=3"}), InputError);
  EXPECT_THROW(config::apply_overrides(dp::ArpConfig{}, {"datapath.vec_frac=99"}), InputError);
  EXPECT_EQ(config::apply_overrides(dp::ArpConfig{}, {"pipeline.latch=\"pixel\""}).pipeline.latch, dp::LatchPolicy::PerPixel);
  const InputError e = error_of([] { config::apply_overrides(dp::ArpConfig{}, {"datapath.vec_fra=3"}); });
  EXPECT_EQ(e.source(), "--set");
  EXPECT_EQ(e.place(), "datapath.vec_fra");
  EXPECT_NE(error_of([] { config::apply_overrides(dp::ArpConfig{}, {"lens.fov_deg=9e9999"}); }).reason().find("too large"),
            std::string::npos);
}
