#include "simhuman/web/server.h"

#include <arpa/inet.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <sys/socket.h>
#include <unistd.h>

#include <random>
#include <thread>

#include "simhuman/language/offline_planner.h"

namespace simhuman::web {
namespace {

using ::testing::HasSubstr;

// a human that sits down on the chair has its pelvis this far from where it stood
constexpr double kMovedM = 0.15;

// the offline planner, slowed down so that commands queue up
class SlowPlanner : public language::Planner {
 public:
  core::StatusOr<language::PlanResult> Plan(std::string_view command,
                                            const language::PlanContext& context) override {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    return inner_.Plan(command, context);
  }
  std::string name() const override { return "slow offline"; }

 private:
  language::OfflinePlanner inner_;
};

// a session on sit_demo (MPC only, no walking policy) served on a free port
class ServerFixture {
 public:
  explicit ServerFixture(const ServerOptions& base = {}, double speed = 1.0) {
    world::SceneSpec scene = *world::LoadScene("sit_demo");
    LiveOptions live;
    live.config = *control::MpcConfig::Preset("fast");
    live.speed = speed;
    live.max_queued = 2;
    auto s = LiveSession::Start(scene, std::make_unique<SlowPlanner>(), live);
    EXPECT_TRUE(s.ok()) << s.status();
    session = std::move(s).value();
    ServerOptions o = base;
    o.port = 0;
    server = std::make_unique<LiveServer>(session.get(), o);
    EXPECT_TRUE(server->Bind().ok());
    thread = std::thread([this] { server->Serve(); });
    client = std::make_unique<httplib::Client>("127.0.0.1", server->port());
    client->set_read_timeout(10, 0);
  }
  ~ServerFixture() {
    server->Stop();
    thread.join();
  }
  httplib::Result Post(const std::string& path, const std::string& body) {
    return client->Post(path, body, "application/json");
  }
  std::string Token() {
    auto r = Post("/api/drive", "{}");
    EXPECT_TRUE(r && r->status == 200);
    return nlohmann::json::parse(r->body)["token"];
  }
  nlohmann::json State() { return nlohmann::json::parse(client->Get("/api/state")->body); }

  std::unique_ptr<LiveSession> session;
  std::unique_ptr<LiveServer> server;
  std::thread thread;
  std::unique_ptr<httplib::Client> client;
};

std::string Error(const httplib::Result& r) {
  return r ? nlohmann::json::parse(r->body).value("error", "") : "no response";
}

TEST(LiveServerTest, BadRequestsGetClearErrorsIntegration) {
  ServerFixture f;
  const std::string token = f.Token();
  auto cmd = [&](const std::string& body) { return f.Post("/api/command", body); };
  auto r = cmd("{not json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_THAT(Error(r), HasSubstr("request body"));
  r = cmd(R"({"token": ")" + token + R"(", "txt": "sit"})");
  EXPECT_EQ(r->status, 400);
  EXPECT_THAT(Error(r), HasSubstr("unknown key 'txt'"));
  r = cmd(R"({"token": ")" + token + R"(", "text": 5})");
  EXPECT_EQ(r->status, 400);
  EXPECT_THAT(Error(r), HasSubstr("'text' must be a string"));
  r = cmd(R"({"token": "nope", "text": "sit on the chair"})");
  EXPECT_EQ(r->status, 403);
  r = cmd(R"({"token": ")" + token + R"(", "text": ")" + std::string(600, 'a') + "\"}");
  EXPECT_EQ(r->status, 413);
  EXPECT_THAT(Error(r), HasSubstr("limit is 500"));
  r = cmd(std::string(40000, ' '));
  EXPECT_EQ(r->status, 413);
  // a second tab watches
  r = f.Post("/api/drive", "{}");
  EXPECT_EQ(r->status, 409);
  r = f.Post("/api/answer", R"({"token": ")" + token + R"(", "text": "1"})");
  EXPECT_EQ(r->status, 409);
  EXPECT_THAT(Error(r), HasSubstr("no question"));
  r = f.client->Get("/nothing");
  EXPECT_EQ(r->status, 404);
  EXPECT_THAT(Error(r), HasSubstr("/api/command"));
  // a flood of commands: the queue holds 2 while the planner is busy or not
  int accepted = 0, refused = 0;
  for (int i = 0; i < 20; ++i) {
    auto q = cmd(R"({"token": ")" + token + R"(", "text": "sit on the chair"})");
    accepted += q->status == 202;
    refused += q->status == 429;
  }
  EXPECT_GE(accepted, 2);
  EXPECT_GT(refused, 0);
  EXPECT_EQ(accepted + refused, 20);
  // a command it cannot do is shown, and the server keeps running
  auto lie = cmd(R"({"token": ")" + token + R"(", "text": "lie on the chair"})");
  for (int i = 0; i < 100 && f.State()["state"] != "error"; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (lie->status == 429)
      lie = cmd(R"({"token": ")" + token + R"(", "text": "lie on the chair"})");
  }
  EXPECT_EQ(f.State()["state"], "error");
  EXPECT_THAT(f.State()["message"].get<std::string>(), HasSubstr("lie on the chair"));
}

TEST(LiveServerTest, PortInUseIsNamedIntegration) {
  ServerFixture f;
  ServerOptions o;
  o.port = f.server->port();
  LiveServer second(f.session.get(), o);
  absl::Status st = second.Bind();
  EXPECT_FALSE(st.ok());
  EXPECT_THAT(st.message(), HasSubstr("127.0.0.1:" + std::to_string(o.port)));
  EXPECT_THAT(st.message(), HasSubstr("in use"));
}

TEST(LiveServerTest, CommandMakesTheHumanMoveAndStreamsFramesIntegration) {
  ServerFixture f;
  const nlohmann::json before = f.State();
  const std::string token = f.Token();
  auto r = f.Post("/api/command", R"({"token": ")" + token + R"(", "text": "sit on the chair"})");
  ASSERT_EQ(r->status, 202) << r->body;
  // the event stream delivers frames; a client that stops reading is dropped
  int frames = 0;
  httplib::Client sse("127.0.0.1", f.server->port());
  sse.Get("/api/events", [&](const char* data, size_t n) {
    frames += static_cast<int>(std::string(data, n).find("event: frame") != std::string::npos);
    return frames < 5;
  });
  EXPECT_GE(frames, 5);
  double moved = 0;
  for (int i = 0; i < 120 && moved < kMovedM; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const nlohmann::json now = f.State();
    const auto& p0 = before["pelvis"][0];
    const auto& p1 = now["pelvis"][0];
    moved = 0;
    for (int k = 0; k < 3; ++k) {
      moved += std::pow(p1[k].get<double>() - p0[k].get<double>(), 2);
    }
    moved = std::sqrt(moved);
  }
  EXPECT_GT(moved, kMovedM) << f.State().dump();
  const nlohmann::json s = f.State();
  EXPECT_EQ(s["plan"], 1);
  EXPECT_GT(s["latency_first_frame_ms"].get<double>(), 0);
}

TEST(LiveServerTest, ClarifyingQuestionIsAnsweredIntegration) {
  world::SceneSpec scene = *world::LoadScene("tabletop_demo");
  LiveOptions live;
  live.config = *control::MpcConfig::Preset("fast");
  auto session = LiveSession::Start(scene, std::make_unique<language::OfflinePlanner>(), live);
  ASSERT_TRUE(session.ok()) << session.status();
  LiveSession& s = **session;
  auto wait_for = [&](const std::string& state) {
    for (int i = 0; i < 100 && s.Status()["state"] != state; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return s.Status();
  };
  ASSERT_TRUE(s.SubmitCommand("touch the box").ok());
  nlohmann::json st = wait_for("question");
  EXPECT_THAT(st["question"].get<std::string>(), HasSubstr("Which box"));
  EXPECT_THAT(s.Answer("the purple one").message(), HasSubstr("matches none"));
  ASSERT_TRUE(s.Answer("2").ok());
  st = wait_for("running");
  EXPECT_EQ(st["command"], "touch box002");
  EXPECT_EQ(st["plan"], 1);
  EXPECT_TRUE(absl::IsFailedPrecondition(s.Answer("2")));
}

// random bytes and random bodies to every endpoint; the server answers the next request
TEST(LiveServerTest, FuzzedRequestsDoNotHurtTheServerIntegration) {
  ServerFixture f;
  std::mt19937 rng(18);
  std::uniform_int_distribution<int> byte(0, 255), len(0, 300);
  auto random_bytes = [&] {
    std::string s(len(rng), '\0');
    for (char& c : s) c = static_cast<char>(byte(rng));
    return s;
  };
  const std::string token = f.Token();
  const std::vector<std::string> post = {
      "/api/drive", "/api/command", "/api/answer", "/api/pause", "/api/reset", "/", "/api/state"};
  const std::vector<std::string> bodies = {
      "null",
      "[]",
      "{\"token\": null}",
      "{\"token\": \"" + token + "\", \"paused\": \"yes\"}",
      "{\"token\": \"" + token + "\", \"text\": \"\\u0000\"}",
      "{\"token\": \"" + token + "\", \"text\": \"\xff\xfe\"}"};
  for (int i = 0; i < 150; ++i) {
    const std::string& path = post[i % post.size()];
    const std::string body = i % 3 == 0 ? bodies[i % bodies.size()] : random_bytes();
    auto r = f.Post(path, body);
    ASSERT_TRUE(r) << path;
    EXPECT_LT(r->status, 500) << path << " " << r->body;
  }
  // raw bytes on the socket, and connections closed mid-request
  for (int i = 0; i < 30; ++i) {
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<uint16_t>(f.server->port()));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)), 0);
    std::string junk = i % 2 ? random_bytes() : "GET /api/events HTTP/1.1\r\nHost: x\r\n\r\n";
    EXPECT_GE(send(fd, junk.data(), junk.size(), MSG_NOSIGNAL), 0);
    close(fd);
  }
  f.session->SetPaused(false);
  auto r = f.client->Get("/api/state");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_TRUE(nlohmann::json::parse(r->body).contains("sim_time_s"));
}

}  // namespace
}  // namespace simhuman::web
