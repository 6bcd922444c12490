#include "simhuman/learn/data_parallel.h"

#include <gtest/gtest.h>

#include "simhuman/core/testing/thread_communicator.h"

namespace simhuman::learn {
namespace {

constexpr double kTol = 1e-9;

TEST(DataParallelTest, MergedNormalizerEqualsOneNormalizerThatSawEveryRollout) {
  torch::manual_seed(7);
  const int d = 5;
  const torch::Tensor start = torch::randn({300, d}) * 2 + 1;
  const std::vector<torch::Tensor> rollouts = {torch::randn({64, d}) * 3 - 2,
                                               torch::randn({100, d}) + 4, torch::randn({7, d})};
  control::ObsNormalizer before(d);
  before.Update(start);
  control::ObsNormalizer expected = before;
  for (const torch::Tensor& r : rollouts) expected.Update(r);

  core::testing::ThreadGroup group(3);
  std::vector<control::ObsNormalizer> merged(3);
  group.Run([&](core::Communicator& c) {
    control::ObsNormalizer norm = before;
    norm.Update(rollouts[c.rank()]);
    ASSERT_TRUE(MergeNormalizer(before, &norm, c).ok());
    merged[c.rank()] = norm;
  });
  for (const control::ObsNormalizer& m : merged) {
    EXPECT_NEAR(m.count(), expected.count(), kTol);
    EXPECT_LT((m.mean() - expected.mean()).abs().max().item<double>(), kTol);
    EXPECT_LT((m.var() - expected.var()).abs().max().item<double>(), kTol);
  }
  // the ranks hold the very same statistics
  EXPECT_TRUE(torch::equal(merged[0].mean(), merged[2].mean()));
  EXPECT_TRUE(torch::equal(merged[0].var(), merged[1].var()));
}

TEST(DataParallelTest, GradientsAreAveragedAndOneBadRankSkipsTheStepEverywhere) {
  core::testing::ThreadGroup group(2);
  group.Run([&](core::Communicator& c) {
    torch::Tensor w = torch::zeros({3}, torch::requires_grad());
    torch::Tensor b = torch::zeros({2}, torch::requires_grad());  // no gradient on rank 1
    torch::Tensor loss = (w * static_cast<float>(c.rank() + 1)).sum();
    if (c.rank() == 0) loss = loss + (b * 4).sum();
    loss.backward();
    ASSERT_TRUE(AverageGradients({w, b}, c, false));
    EXPECT_TRUE(torch::allclose(w.grad(), torch::full({3}, 1.5f)));
    EXPECT_TRUE(torch::allclose(b.grad(), torch::full({2}, 2.f)));
    EXPECT_FALSE(AverageGradients({w, b}, c, c.rank() == 1));
  });
  core::SerialCommunicator serial;
  torch::Tensor w = torch::ones({2}, torch::requires_grad());
  (w * 3).sum().backward();
  EXPECT_TRUE(AverageGradients({w}, serial, false));
  EXPECT_TRUE(torch::allclose(w.grad(), torch::full({2}, 3.f)));
  EXPECT_FALSE(AverageGradients({w}, serial, true));
}

TEST(DataParallelTest, CountsAreSummed) {
  core::testing::ThreadGroup group(3);
  group.Run([&](core::Communicator& c) {
    std::vector<double> counts{1.0, static_cast<double>(c.rank())};
    ASSERT_TRUE(SumCounts(&counts, c).ok());
    EXPECT_EQ(counts[0], 3.0);
    EXPECT_EQ(counts[1], 3.0);
  });
}

}  // namespace
}  // namespace simhuman::learn
