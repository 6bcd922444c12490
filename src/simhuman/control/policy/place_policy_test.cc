#include "simhuman/control/policy/place_policy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "simhuman/control/policy/grasp_policy.h"
#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/testing_temp.h"

namespace simhuman::control {
namespace {

std::string WritePolicy(const std::string& name, const std::string& task, int obs_dim,
                        int act_dim) {
  std::string path = core::testing::UniqueTempPath("place_policy_test_" + name);
  torch::manual_seed(1);
  GaussianActor actor(obs_dim, act_dim, std::vector<int>{8}, 0.5);
  ObsNormalizer norm(obs_dim);
  torch::serialize::OutputArchive ar;
  PolicyMeta meta;
  meta.task = task;
  meta.obs_dim = obs_dim;
  meta.act_dim = act_dim;
  meta.hidden = {8};
  SavePolicyKeys(ar, meta, actor, norm);
  ar.save_to(path);
  return path;
}

TEST(PlacePolicyTest, LoadsPlacePoliciesAndTheScriptedPlacing) {
  auto scripted = LoadPlacePolicy("scripted");
  ASSERT_TRUE(scripted.ok()) << scripted.status();
  EXPECT_FALSE(*scripted);  // empty: the pipeline's own placing

  const std::string path = WritePolicy("ok", "place", manip::kPlaceObsDim, manip::kPlaceActDim);
  auto learned = LoadPlacePolicy(path);
  ASSERT_TRUE(learned.ok()) << learned.status();
  std::vector<float> obs(manip::kPlaceObsDim, 0.5f), act(manip::kPlaceActDim, 7.0f);
  (*learned)(obs.data(), act.data());
  bool any_nonzero = false;
  for (float a : act) {
    EXPECT_TRUE(std::isfinite(a));
    EXPECT_LT(std::abs(a), 5.0f);
    any_nonzero = any_nonzero || a != 0;
  }
  EXPECT_TRUE(any_nonzero);
  obs[3] = NAN;  // a non-finite observation gets the scripted placing (a zero correction)
  (*learned)(obs.data(), act.data());
  for (float a : act) EXPECT_EQ(a, 0.0f);
}

TEST(PlacePolicyTest, OtherTasksSizesAndMissingFilesAreErrorsNamingTheFile) {
  const std::string walk = WritePolicy("walk", "walk", 12, 4);
  auto wrong = LoadPlacePolicy(walk);
  ASSERT_FALSE(wrong.ok());
  const std::string msg(wrong.status().message());
  for (const char* part : {"place policy '", "'walk' policy", "train --task place", "'scripted'"})
    EXPECT_NE(msg.find(part), std::string::npos) << part << " in: " << msg;
  EXPECT_NE(msg.find(walk), std::string::npos) << msg;

  const std::string sized = WritePolicy("sized", "place", manip::kPlaceObsDim + 1, 5);
  EXPECT_FALSE(LoadPlacePolicy(sized).ok());
  auto missing = LoadPlacePolicy("/nonexistent/place.pt");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find("/nonexistent/place.pt"), std::string::npos);

  // the grasp stage's loader says the same for a place policy
  auto grasp = LoadGraspPolicy(
      WritePolicy("place_as_grasp", "place", manip::kPlaceObsDim, manip::kPlaceActDim));
  ASSERT_FALSE(grasp.ok());
  EXPECT_NE(grasp.status().message().find("a grasp or grasp-residual policy has"),
            std::string::npos)
      << grasp.status();
}

}  // namespace
}  // namespace simhuman::control
