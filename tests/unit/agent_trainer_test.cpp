// The training loop on Tumble (src/rl/agents/trainer.h): a run stopped after 3 episodes and
// resumed from its checkpoint records the same 6 episodes as an uninterrupted run; a resume with
// other settings, and a new run over an old one, are refused. Episodes are capped at a few moves
// to keep the test short (a move is about 20 emulated frames).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <cmath>

#include "rl/agents/learning_curve.h"
#include "rl/agents/trainer.h"

using namespace psxrl::agents;

namespace {

std::string run_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("psxrl_agent_train_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir.string();
}

TrainConfig tiny(const std::string& agent, const std::string& out, std::uint64_t episodes) {
  TrainConfig c;
  c.agent = agent;
  c.env.obs = default_obs(agent);
  c.env.max_moves = 4;
  c.options.epochs = 2;
  c.episodes = episodes;
  c.test_every = 3;  // episodes 3 and 6 are greedy tests
  c.seed = 11;
  c.out = out;
  return c;
}

// Everything a record holds but the host time, which no run reproduces.
std::vector<std::string> without_time(const std::vector<EpisodeRecord>& records) {
  std::vector<std::string> rows;
  for (const EpisodeRecord& r : records) {
    std::ostringstream os;
    os.precision(17);
    os << r.episode << ' ' << r.test << ' ' << r.score << ' ' << r.reward << ' ' << r.moves << ' ' << r.frames << ' '
       << r.outcome << ' ' << r.epsilon << ' ' << r.loss << ' ' << r.total_moves;
    rows.push_back(os.str());
  }
  return rows;
}

size_t lines(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  size_t n = 0;
  while (std::getline(in, line)) ++n;
  return n;
}

void expect_resume_equals_uninterrupted(const std::string& agent) {
  std::string whole = run_dir(agent + "_whole"), split = run_dir(agent + "_split");
  Trainer a(tiny(agent, whole, 6));
  a.run(nullptr);
  ASSERT_EQ(a.records().size(), 6u);
  {
    Trainer first(tiny(agent, split, 3));
    first.run(nullptr);
  }
  TrainConfig c = tiny(agent, split, 6);
  c.resume = true;
  Trainer resumed(c);
  resumed.run(nullptr);
  EXPECT_EQ(without_time(resumed.records()), without_time(a.records()));
  EXPECT_EQ(lines(split + "/metrics.csv"), 7u);  // header + 6 episodes
  EXPECT_EQ(lines(split + "/metrics.jsonl"), 6u);
  EXPECT_TRUE(std::filesystem::exists(split + "/learning_curve.png"));
  std::filesystem::remove_all(whole);
  std::filesystem::remove_all(split);
}

}  // namespace

TEST(Trainer, QResumeContinuesExactly) { expect_resume_equals_uninterrupted("q"); }
TEST(Trainer, DqnResumeContinuesExactly) { expect_resume_equals_uninterrupted("dqn"); }

TEST(Trainer, RefusesMismatchedResumeAndOverwrite) {
  std::string dir = run_dir("refuse");
  {
    Trainer t(tiny("q", dir, 1));
    t.run(nullptr);
  }
  EXPECT_THROW(Trainer(tiny("q", dir, 2)), std::invalid_argument);  // a run is there: --resume or another --out
  TrainConfig other = tiny("q", dir, 2);
  other.resume = true;
  other.seed = 12;
  try {
    Trainer t(other);
    ADD_FAILURE() << "resumed with another seed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("seed = 11, this command has seed = 12"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(Trainer, RefusesUnknownNamesAndLevels) {
  std::string dir = run_dir("names");
  TrainConfig c = tiny("q", dir, 1);
  c.level = 11;  // Tumble has 10
  EXPECT_THROW(Trainer{c}, std::invalid_argument);
  c = tiny("nope", dir, 1);
  c.env.obs = "simple";
  EXPECT_THROW(Trainer{c}, std::invalid_argument);
  std::filesystem::remove_all(dir);
}

TEST(LearningCurve, MovingAverageOverFive) {
  // (1) (1+2)/2 (1+2+3)/3 ... then windows of 5: (2+3+4+5+6)/5 = 4.
  EXPECT_EQ(moving_average({1, 2, 3, 4, 5, 6}, 5), (std::vector<double>{1, 1.5, 2, 2.5, 3, 4}));
}

TEST(LearningCurve, TicksAreRoundNumbers) {
  // Powers of ten below the last episode, halved when that gives fewer than 3 steps.
  EXPECT_EQ(episode_ticks(10), (std::vector<double>{0, 5, 10}));
  EXPECT_EQ(episode_ticks(27), (std::vector<double>{0, 5, 10, 15, 20, 25}));
  EXPECT_EQ(episode_ticks(350), (std::vector<double>{0, 100, 200, 300}));
  EXPECT_EQ(episode_ticks(1000), (std::vector<double>{0, 500, 1000}));
  // Every 1000 points while that makes at most 8 labels, else every 2000, 5000, 10000...
  EXPECT_EQ(score_ticks(0, 4000), (std::vector<double>{0, 1000, 2000, 3000, 4000}));
  EXPECT_EQ(score_ticks(-1000, 12000), (std::vector<double>{0, 2000, 4000, 6000, 8000, 10000, 12000}));
  EXPECT_EQ(score_ticks(0, 30000), (std::vector<double>{0, 5000, 10000, 15000, 20000, 25000, 30000}));
  // 5x7 glyphs 6 pixels apart: "1000" is 3 * 6 + 5 pixels wide.
  EXPECT_EQ(text_width("1000"), 23);
  EXPECT_EQ(text_width(""), 0);
}

TEST(LearningCurve, EveryTickHasALabel) {
  std::vector<EpisodeRecord> records;
  for (std::uint64_t e = 1; e <= 100; ++e) {
    EpisodeRecord r;
    r.episode = e;
    r.test = e % 10 == 0;
    r.score = static_cast<std::int64_t>(e * 40);  // up to 4000: score ticks 0..4000
    records.push_back(r);
  }
  RgbImage image = render_learning_curve(records);
  ASSERT_EQ(image.width, 640);
  ASSERT_EQ(image.height, 360);
  auto black_in = [&](int x0, int x1, int y0, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const std::uint8_t* p = &image.rgb[(static_cast<size_t>(y) * image.width + x) * 3];
        if (p[0] == 0 && p[1] == 0 && p[2] == 0) return true;
      }
    return false;
  };
  // The plot area spans x 56..624 and y 24..320 (margins 56 left, 16 right, 24 top, 40 bottom):
  // score s is at y = 320 - s / 4000 * 296, its label left of x = 56 - 4 (the tick mark) and
  // centred on that row; episode e at x = 56 + e / 100 * 568, its label 8 pixels under the axis.
  for (double s : {0.0, 1000.0, 2000.0, 3000.0, 4000.0}) {
    int y = 320 - static_cast<int>(std::lround(s / 4000 * 296));
    EXPECT_TRUE(black_in(0, 52, y - 3, y + 4)) << "score label " << s;
  }
  for (double e : {0.0, 50.0, 100.0}) {
    int x = 56 + static_cast<int>(std::lround(e / 100 * 568));
    EXPECT_TRUE(black_in(x - 10, x + 10, 328, 335)) << "episode label " << e;
  }
  EXPECT_FALSE(black_in(0, 48, 330, 360));  // the corner under the score labels holds no text
}
