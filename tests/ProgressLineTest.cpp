// The progress line, drawn into a temporary file against a clock the test sets.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "common/ProgressLine.hpp"

namespace {

// Everything written to f so far.
std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  for (int c = std::fgetc(f); c != EOF; c = std::fgetc(f)) s += static_cast<char>(c);
  return s;
}

// The line now on screen: what follows the last carriage return.
std::string shown(const std::string& s) { return s.substr(s.rfind('\r') + 1); }

struct Drawn {
  std::FILE* f = std::tmpfile();
  double t = 100.0;  // the test's clock, s
  ~Drawn() { std::fclose(f); }
};

}  // namespace

TEST(ProgressLine, AStepsETAIsFromItsOwnStart) {
  // A long first step then a short second one: the second's ETA follows its own rate, not the whole's.
  Drawn d;
  arp::ProgressLine p("plan", d.f, [&d] { return d.t; });
  p.update_step(1, 3, 0.0, "sizing");
  d.t += 10.0;
  p.update_step(2, 3, 0.0, "measuring");
  d.t += 2.0;
  p.update_step(2, 3, 0.5, "measuring");  // half of step 2 in 2 s: 2 s to go (from the start, 12 s)
  const std::string line = shown(contents(d.f));
  EXPECT_NE(line.find("[2/3] measuring  50%"), std::string::npos) << line;
  EXPECT_NE(line.find("elapsed   12.0 s"), std::string::npos) << line;
  EXPECT_NE(line.find("step ETA    2.0 s"), std::string::npos) << line;
}

TEST(ProgressLine, ANewStepIsShownAtOnceAndNoFigureBeforeARate) {
  Drawn d;
  arp::ProgressLine p("plan", d.f, [&d] { return d.t; });
  p.update_step(1, 2, 0.5, "one");
  d.t += 0.01;  // within the redraw interval: a new step is drawn all the same, a fraction of the same step is not
  p.update_step(2, 2, 0.0, "two");
  EXPECT_NE(shown(contents(d.f)).find("[2/2] two   0%"), std::string::npos);
  EXPECT_NE(shown(contents(d.f)).find("step ETA      ? s"), std::string::npos) << "nothing done: no rate";
  d.t += 0.01;
  p.update_step(2, 2, 0.5, "two");
  EXPECT_NE(shown(contents(d.f)).find("[2/2] two   0%"), std::string::npos);
}

TEST(ProgressLine, AShorterLineCoversTheLongerBeforeIt) {
  Drawn d;
  arp::ProgressLine p("plan", d.f, [&d] { return d.t; });
  p.update_step(1, 2, 0.0, "measuring the display's pixel angles");
  const size_t longer = shown(contents(d.f)).size();
  p.update_step(2, 2, 0.0, "widths");
  const std::string line = shown(contents(d.f));
  EXPECT_GE(line.size(), longer) << "the tail of the longer line would stay on screen";
  EXPECT_EQ(line.find("angles"), std::string::npos);
}

TEST(ProgressLine, CompletionAndDestructionEndTheLine) {
  Drawn d;
  {
    arp::ProgressLine p("plan", d.f, [&d] { return d.t; });
    p.update_step(1, 1, 0.5, "working");
    d.t += 1.0;
    p.update(1.0, "planned");
  }
  std::string s = contents(d.f);
  ASSERT_FALSE(s.empty());
  EXPECT_EQ(s.back(), '\n');
  EXPECT_EQ(s.find('\n'), s.size() - 1) << "ended once";
  Drawn e;
  {
    arp::ProgressLine p("run", e.f, [&e] { return e.t; });
    p.update_step(1, 2, 0.5, "working");  // then an error thrown through the work
  }
  s = contents(e.f);
  ASSERT_FALSE(s.empty());
  EXPECT_EQ(s.back(), '\n') << "an error printed next would share the line";
}
