// Unit tests of the offline planner's general fallback (fallback.h): commands only the fallback
// reads, what it still refuses, and its word readings.

#include "simhuman/language/offline/fallback.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/planner_testing.h"
#include "simhuman/language/offline_planner.h"

namespace simhuman::language::offline {
namespace {

using ::testing::HasSubstr;

using Fixture = testing::SceneFixture;
Fixture Load(const std::string& scene) { return testing::LoadScene(scene); }

// the fallback's clauses: " | " before a sequenced clause, " & " before a coordinated one
std::string Clauses(const std::string& scene, const std::string& command) {
  Fixture f = Load(scene);
  core::StatusOr<std::vector<ClauseWords>> r = FallbackClauses(command, f.catalog);
  if (!r.ok()) return "error: " + std::string(r.status().message());
  std::string out;
  for (const ClauseWords& c : *r) {
    if (!out.empty()) out += c.sequenced ? " | " : " & ";
    out += Join(c.words);
  }
  return out;
}

std::string PlanText(const std::string& scene, const std::string& command) {
  return testing::PlanPairs(scene, command);
}

absl::StatusCode Code(const std::string& scene, const std::string& command) {
  Fixture f = Load(scene);
  OfflinePlanner planner;
  return planner.Plan(command, f.context).status().code();
}

TEST(OfflineFallbackTest, AnObjectNamedBeforeTheActionIsWhatItRefersTo) {
  EXPECT_EQ(Clauses("living_room", "um so like, uh, the couch? yeah sit on that, um, thanks"),
            "notice sofa | sit on that");
  EXPECT_EQ(PlanText("living_room", "um so like, uh, the couch? yeah sit on that, um, thanks"),
            "sofa005:none:none / sofa005:seat surface:pelvis");
  // an action that named no object takes the one named just after it
  EXPECT_EQ(PlanText("living_room", "Position: supine. Location: bed."),
            "bed003:mattress:pelvis, bed003:pillow:head");
}

TEST(OfflineFallbackTest, VerbsByStemAndAPassiveSaidAsTheOrder) {
  EXPECT_EQ(PlanText("office", "She slaps the top of the box with her left hand."),
            "box004:none:none / box004:top:left hand");
  EXPECT_EQ(Clauses("sit_demo", "The chair is to be sat on by the human."), "sit on chair");
  EXPECT_EQ(PlanText("sit_demo", "The chair is to be sat on by the human."),
            "chair000:seat surface:pelvis");
  EXPECT_EQ(PlanText("tabletop_demo", "The green cube must be placed upon the yellow cube."),
            "box002:body:right hand / box002:body:right hand, box004:top:none");
}

TEST(OfflineFallbackTest, WordsThatCarryNoActionAreDroppedAroundKnownOnes) {
  // a label before the steps, a limb moved by an unknown verb, the human's own body
  EXPECT_EQ(
      PlanText("office", "Steps to reproduce: 1) walk to box 2) touch its top with right hand"),
      "box004:none:none / box004:top:right hand");
  EXPECT_EQ(Clauses("office", "Glue both hands onto the keyboard."),
            "put both hands onto keyboard");
  EXPECT_EQ(PlanText("sit_demo", "yo plonk ur butt on that chair"), "chair000:seat surface:pelvis");
}

TEST(OfflineFallbackTest, UnknownActionsObjectsAndNegationsAreStillRefused) {
  for (const auto& [scene, command] : std::vector<std::pair<std::string, std::string>>{
           {"living_room", "Open the fridge and grab a drink."},
           {"living_room", "Go sit in the bathtub."},
           {"living_room", "You climb the bookshelf to reach the top shelf."},
           {"office", "Kick the box."},
           {"office", "Put the box on the fridge."},
           {"bedroom", "Please do not sit on the bed."},
           {"bedroom", "Never lie on the chair."},
           {"sit_demo", "sit on the chair and dance"},
           {"sit_demo", "um, print the quarterly report"},
           {"tabletop_demo", "Put the purple cube on the red cube."},
       }) {
    EXPECT_EQ(Code(scene, command), absl::StatusCode::kInvalidArgument) << command;
  }
  // the refusal is the rules' own: what was not understood and what is
  Fixture f = Load("living_room");
  OfflinePlanner planner;
  core::StatusOr<PlanResult> r = planner.Plan("Go sit in the bathtub.", f.context);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(std::string(r.status().message()), HasSubstr("bathtub"));
  EXPECT_THAT(std::string(r.status().message()), HasSubstr("sofa005"));
  EXPECT_THAT(Clauses("office", "Kick the box."), HasSubstr("error"));
}

TEST(OfflineFallbackTest, TwoPassivesInOneClauseAreReadOneAfterTheOther) {
  // the second passive starts after the first (no words of the first are taken back)
  EXPECT_THAT(Clauses("tabletop_demo",
                      "the green cube must be placed upon the yellow cube that is to be set down"),
              HasSubstr("put green box"));
}

TEST(OfflineFallbackTest, AmbiguityStillAsks) {
  Fixture f = Load("tabletop_demo");
  OfflinePlanner planner;
  core::StatusOr<PlanResult> r = planner.Plan("the box, pick it up", f.context);
  ASSERT_EQ(r.status().code(), absl::StatusCode::kFailedPrecondition) << r.status();
  EXPECT_EQ(std::string(r.status().message()).back(), '?');
  EXPECT_EQ(Code("bedroom", "er, yeah, go and sit"), absl::StatusCode::kFailedPrecondition);
}

TEST(OfflineFallbackTest, WordReadings) {
  EXPECT_EQ(ReadWord("slaps").word, "touch");
  EXPECT_EQ(ReadWord("plopped").word, "sit");
  EXPECT_EQ(ReadWord("settling").word, "sit");
  EXPECT_EQ(ReadWord("stood").word, "stand");
  EXPECT_EQ(ReadWord("hurried").word, "go");
  EXPECT_EQ(ReadWord("couches").kind, WordReading::kObject);
  EXPECT_EQ(ReadWord("couches").word, "couch");
  EXPECT_EQ(TypeWords().at(ReadWord("sofs").word), "sofa");
  EXPECT_EQ(ReadWord("butt").kind, WordReading::kDrop);
  EXPECT_EQ(ReadWord("fridge").kind, WordReading::kUnknown);
  EXPECT_TRUE(IsNegation("dont"));
  EXPECT_FALSE(IsNegation("down"));
  EXPECT_TRUE(OpensObject("the"));
  EXPECT_FALSE(OpensObject("to"));
}

}  // namespace
}  // namespace simhuman::language::offline
