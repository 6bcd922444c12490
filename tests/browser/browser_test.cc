// Browser tests of the web viewer: headless Chromium (Debian's `chromium`) loads the replay page
// and the live page. Labelled `browser`; skipped with a message when chromium is not installed.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include "simhuman/core/json_io.h"
#include "simhuman/eval/episode.h"
#include "simhuman/language/offline_planner.h"
#include "simhuman/plan/validate.h"
#include "simhuman/render/image_io.h"
#include "simhuman/web/replay_html.h"
#include "simhuman/web/server.h"
#include "simhuman/world/scene.h"

namespace simhuman::web {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 640, kHeight = 480;
// a pixel "differs" when a channel moves more than this; the human covers far more than
// kMinHumanFraction of the frame, the sky and floor around it nothing
constexpr int kPixelTol = 24;
constexpr double kMinHumanFraction = 0.005;
constexpr double kMovedM = 0.15;

std::string Chromium() { return SIMHUMAN_CHROMIUM; }

fs::path TempDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("simhuman_browser_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// runs headless chromium with `args` on `url`; returns its exit code, stdout into `out`,
// stderr into `log`
int RunChromium(const fs::path& dir, const std::string& args, const std::string& url,
                std::string* out, std::string* log) {
  static int run = 0;
  const fs::path out_file = dir / ("out" + std::to_string(run) + ".txt");
  const fs::path log_file = dir / ("log" + std::to_string(run) + ".txt");
  const std::string cmd =
      "timeout 90 " + Chromium() +
      " --headless --no-sandbox --enable-unsafe-swiftshader --use-angle=swiftshader"
      " --hide-scrollbars --enable-logging=stderr --v=0 --user-data-dir=" +
      (dir / ("profile" + std::to_string(run))).string() +
      " --window-size=" + std::to_string(kWidth) + "," + std::to_string(kHeight) + " " + args +
      " '" + url + "' > " + out_file.string() + " 2> " + log_file.string();
  ++run;
  const int code = std::system(cmd.c_str());
  *out = core::ReadFile(out_file.string()).value_or("");
  *log = core::ReadFile(log_file.string()).value_or("");
  return code;
}

std::string Attr(const std::string& dom, const std::string& name) {
  std::smatch m;
  std::regex re("id=\"status\"[^>]*" + name + "=\"([^\"]*)\"");
  return std::regex_search(dom, m, re) ? m[1].str() : "";
}

// fraction of pixels that differ between two screenshots
double DiffFraction(const fs::path& a, const fs::path& b) {
  std::vector<uint8_t> pa, pb;
  int wa = 0, ha = 0, wb = 0, hb = 0;
  EXPECT_TRUE(render::ReadPng(a.string(), &pa, &wa, &ha).ok()) << a;
  EXPECT_TRUE(render::ReadPng(b.string(), &pb, &wb, &hb).ok()) << b;
  if (wa != wb || ha != hb || pa.empty()) return 0;
  size_t differ = 0;
  for (size_t p = 0; p + 2 < pa.size(); p += 3) {
    for (int c = 0; c < 3; ++c) {
      if (std::abs(static_cast<int>(pa[p + c]) - static_cast<int>(pb[p + c])) > kPixelTol) {
        ++differ;
        break;
      }
    }
  }
  return static_cast<double>(differ) / (wa * ha);
}

class BrowserTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (Chromium().empty()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium)";
  }
};

// sit_demo with its human sliding 1.2 m along x over 2 s
fs::path WriteSlidingReplay(const fs::path& dir) {
  world::SceneSpec spec = *world::LoadScene("sit_demo");
  core::SceneCatalog catalog = *world::BuildCatalog(spec);
  std::unique_ptr<world::SimWorld> w = *eval::BuildWorld(spec, catalog);
  plan::ContactChain chain = *plan::ParseAndGround(
      R"([[["chair000", "seat surface", "pelvis", "contact", "up"]]])", "<test>", w->catalog());
  control::Trajectory t;
  std::vector<double> q(w->data()->qpos, w->data()->qpos + w->model()->nq);
  for (int f = 0; f < 60; ++f) {
    t.time_s.push_back(f / 30.0);
    t.step_index.push_back(0);
    t.qpos.push_back(q);
    q[0] -= 0.02;
  }
  const fs::path page = dir / "replay.html";
  EXPECT_TRUE(WriteReplayHtml(page.string(), *w, chain, t, nullptr).ok());
  return page;
}

TEST_F(BrowserTest, ReplayPageDrawsTheHumanAndPlays) {
  const fs::path dir = TempDir("replay");
  const std::string url = "file://" + WriteSlidingReplay(dir).string();
  std::string out, log;
  // the page plays: after 3 s of virtual time the timeline is past its first frame
  ASSERT_EQ(RunChromium(dir, "--virtual-time-budget=3000 --dump-dom", url, &out, &log), 0) << log;
  EXPECT_EQ(Attr(out, "data-ready"), "1") << out.substr(0, 2000);
  EXPECT_EQ(Attr(out, "data-errors"), "0") << Attr(out, "data-last-error");
  EXPECT_GT(std::atoi(Attr(out, "data-frame").c_str()), 0);
  EXPECT_THAT(out, ::testing::HasSubstr("step 1/1: pelvis on chair000 seat surface"));
  EXPECT_THAT(log, ::testing::Not(::testing::HasSubstr("Uncaught")));
  // screenshots, paused: at the start, the same without the humans, and at the end
  const std::string shot = "--virtual-time-budget=1500 --screenshot=";
  for (const char* name : {"start", "empty", "end"}) {
    const std::string query = std::string(name) == "start"   ? "?t=0&pause=1"
                              : std::string(name) == "empty" ? "?t=0&pause=1&hide=humans"
                                                             : "?t=1.9&pause=1";
    const fs::path png = dir / (std::string(name) + ".png");
    ASSERT_EQ(RunChromium(dir, shot + png.string(), url + query, &out, &log), 0) << log;
    ASSERT_TRUE(fs::exists(png)) << log;
  }
  // the human is drawn, and it moves along the timeline
  EXPECT_GT(DiffFraction(dir / "start.png", dir / "empty.png"), kMinHumanFraction);
  EXPECT_GT(DiffFraction(dir / "start.png", dir / "end.png"), kMinHumanFraction);
}

// the live page: a command typed into its box (the page's test hook ?command= types it and
// presses send) is planned and makes the human move, as the server's state shows
TEST_F(BrowserTest, LivePageCommandMakesTheHumanMove) {
  world::SceneSpec scene = *world::LoadScene("sit_demo");
  LiveOptions live;
  live.config = *control::MpcConfig::Preset("fast");
  auto session = LiveSession::Start(scene, std::make_unique<language::OfflinePlanner>(), live);
  ASSERT_TRUE(session.ok()) << session.status();
  ServerOptions o;
  o.port = 0;
  LiveServer server(session->get(), o);
  ASSERT_TRUE(server.Bind().ok());
  std::thread serving([&] { server.Serve(); });
  const nlohmann::json before = (*session)->State();
  const fs::path dir = TempDir("live");
  const std::string url =
      "http://127.0.0.1:" + std::to_string(server.port()) + "/?command=sit%20on%20the%20chair";
  // the page stays open in the background (a dump would stop its scripts at the load event)
  const fs::path pid_file = dir / "chromium.pid", log_file = dir / "log.txt";
  const std::string cmd = "timeout 120 " + Chromium() +
                          " --headless --no-sandbox --enable-unsafe-swiftshader "
                          "--use-angle=swiftshader --enable-logging=stderr --v=0 "
                          "--remote-debugging-port=0 --user-data-dir=" +
                          (dir / "profile").string() + " '" + url + "' > /dev/null 2> " +
                          log_file.string() + " & echo $! > " + pid_file.string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  // the command came from the page (nothing else sent one) and the human moves
  double moved = 0;
  nlohmann::json s;
  for (int i = 0; i < 300 && moved < kMovedM; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    s = (*session)->State();
    if (s["pelvis"].empty()) continue;
    moved = 0;
    for (int k = 0; k < 3; ++k) {
      moved += std::pow(s["pelvis"][0][k].get<double>() - before["pelvis"][0][k].get<double>(), 2);
    }
    moved = std::sqrt(moved);
  }
  const std::string pid = core::ReadFile(pid_file.string()).value_or("");
  if (!pid.empty()) std::system(("kill " + pid).c_str());
  EXPECT_THAT(core::ReadFile(log_file.string()).value_or(""),
              ::testing::Not(::testing::HasSubstr("Uncaught")));
  EXPECT_EQ(s["command"], "sit on the chair") << s.dump();
  EXPECT_EQ(s["plan"], 1);
  EXPECT_GT(moved, kMovedM) << s.dump();
  server.Stop();
  serving.join();
}

}  // namespace
}  // namespace simhuman::web
