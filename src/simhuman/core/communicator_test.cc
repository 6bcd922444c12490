#include "simhuman/core/communicator.h"

#include <gtest/gtest.h>

#include <atomic>

#include "simhuman/core/testing/thread_communicator.h"

namespace simhuman::core {
namespace {

TEST(CommunicatorTest, SerialIsOneRankAndPassesStatusesThrough) {
  SerialCommunicator c;
  EXPECT_EQ(c.rank(), 0);
  EXPECT_EQ(c.size(), 1);
  double x[2] = {1.5, -2};
  ASSERT_TRUE(c.AllreduceSum(x, 2).ok());
  EXPECT_EQ(x[0], 1.5);
  EXPECT_EQ(c.stats().allreduce_bytes, 16);
  EXPECT_EQ(AgreeOk(c, absl::NotFoundError("f.json")), absl::NotFoundError("f.json"));
  EXPECT_TRUE(CheckSameOnAllRanks(c, "x", "anything").ok());
  EXPECT_FALSE(c.Gather("a", 1).ok());
}

TEST(CommunicatorTest, HashIsFnv1a64) {
  EXPECT_EQ(HashHex(""), "cbf29ce484222325");
  EXPECT_EQ(HashHex("a"), "af63dc4c8601ec8c");
  EXPECT_FALSE(FileHashHex("/nonexistent/file").ok());
}

TEST(CommunicatorTest, AgreeOkStopsEveryRankWithTheLowestFailingRanksError) {
  testing::ThreadGroup group(3);
  std::atomic<int> agreed_failures{0};
  group.Run([&](Communicator& c) {
    absl::Status local = absl::OkStatus();
    if (c.rank() == 2) local = absl::PermissionDeniedError("cannot write 'x'");
    if (c.rank() == 1) local = absl::InvalidArgumentError("bad flag");
    absl::Status st = AgreeOk(c, local);
    EXPECT_EQ(st.code(), absl::StatusCode::kInvalidArgument);
    EXPECT_EQ(st.message(), "rank 1: bad flag");
    agreed_failures += !st.ok();
    EXPECT_TRUE(AgreeOk(c, absl::OkStatus()).ok());
  });
  EXPECT_EQ(agreed_failures.load(), 3);
}

TEST(CommunicatorTest, CheckSameOnAllRanksNamesTheRanksThatDiffer) {
  testing::ThreadGroup group(3);
  group.Run([&](Communicator& c) {
    EXPECT_TRUE(CheckSameOnAllRanks(c, "options", "same").ok());
    absl::Status st = CheckSameOnAllRanks(c, "options", c.rank() == 2 ? "other" : "same");
    EXPECT_EQ(st.code(), absl::StatusCode::kInvalidArgument);
    EXPECT_NE(st.message().find("mismatched options across ranks: rank 0 has " + HashHex("same") +
                                ", rank 2 has " + HashHex("other")),
              std::string::npos)
        << st.message();
  });
}

TEST(CommunicatorTest, ThreadGroupSumsInRankOrderAndDeliversPosts) {
  testing::ThreadGroup group(2);
  group.Run([&](Communicator& c) {
    float v[2] = {static_cast<float>(c.rank() + 1), 0.5f};
    ASSERT_TRUE(c.AllreduceSum(v, 2).ok());
    EXPECT_EQ(v[0], 3.f);
    EXPECT_EQ(v[1], 1.f);
    c.PostToRoot("hello from " + std::to_string(c.rank()));
    StatusOr<std::vector<std::pair<int, std::string>>> rest = c.FinishPosts();
    ASSERT_TRUE(rest.ok());
    if (c.rank() == 0) {
      ASSERT_EQ(rest->size(), 1u);
      EXPECT_EQ((*rest)[0].first, 1);
      EXPECT_EQ((*rest)[0].second, "hello from 1");
    }
  });
}

}  // namespace
}  // namespace simhuman::core
