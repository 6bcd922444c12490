#include "simhuman/language/http_chat_client.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "simhuman/language/testing/fake_chat_server.h"

namespace simhuman::language {
namespace {

using ::testing::HasSubstr;

TEST(SplitUrlTest, AcceptsHttpAndHttps) {
  std::string base, path;
  ASSERT_TRUE(SplitUrl("http://127.0.0.1:8080/v1/", &base, &path).ok());
  EXPECT_EQ(base, "http://127.0.0.1:8080");
  EXPECT_EQ(path, "/v1");
  ASSERT_TRUE(SplitUrl("https://api.example.com", &base, &path).ok());
  EXPECT_EQ(base, "https://api.example.com");
  EXPECT_EQ(path, "");
}

TEST(SplitUrlTest, RejectsMalformedUrls) {
  std::string base, path;
  for (const char* bad :
       {"127.0.0.1:8080", "ftp://host/", "http://:80/v1", "http://h:0/", "http://h:99999/",
        "http://user:pw@h/v1", "http://h/v1?x=1", "http://h /v1", ""}) {
    core::Status s = SplitUrl(bad, &base, &path);
    EXPECT_EQ(s.code(), absl::StatusCode::kInvalidArgument) << bad;
    EXPECT_THAT(std::string(s.message()), HasSubstr("expected http://host[:port][/path]")) << bad;
  }
  EXPECT_THAT(std::string(SplitUrl("http://user:pw@h/v1", &base, &path).message()),
              HasSubstr("credentials in the URL are not accepted"));
}

TEST(HttpChatClientTest, SendsTheMessagesAndReturnsTheContent) {
  testing::FakeChatServer server;
  server.Push(testing::FakeReply::Completion("hello"));
  ChatClientOptions o;
  o.url = server.url();
  o.model = "m";
  o.timeout_s = 0.5;
  o.max_tokens = 0;
  HttpChatClient client(o);
  core::StatusOr<std::string> reply = client.Complete({{"user", "hi \xff"}});
  ASSERT_TRUE(reply.ok()) << reply.status();
  EXPECT_EQ(*reply, "hello");
  EXPECT_EQ(client.last_attempts(), 1);
  std::vector<testing::RecordedRequest> reqs = server.requests();
  ASSERT_EQ(reqs.size(), 1u);
  EXPECT_FALSE(reqs[0].json.contains("max_tokens"));
  EXPECT_EQ(reqs[0].json["messages"][0]["content"], "hi \xef\xbf\xbd");
}

TEST(HttpChatClientTest, NullContentIsUnavailable) {
  testing::FakeChatServer server;
  testing::FakeReply r;
  r.body = R"({"choices": [{"message": {"role": "assistant", "content": null,
              "tool_calls": [{"function": {"name": "shell", "arguments": "rm -rf /"}}]}}]})";
  server.Push(r);
  ChatClientOptions o;
  o.url = server.url();
  o.model = "m";
  HttpChatClient client(o);
  core::StatusOr<std::string> reply = client.Complete({{"user", "x"}});
  ASSERT_FALSE(reply.ok());
  EXPECT_EQ(reply.status().code(), absl::StatusCode::kUnavailable);
  EXPECT_THAT(std::string(reply.status().message()), HasSubstr("/choices/0/message/content"));
}

}  // namespace
}  // namespace simhuman::language
