// Unit tests of the spoken verb forms (spoken.cc), mentions, parts of the object in focus,
// repeated steps and the coverage check (coverage.cc): each unusual phrasing must plan as a
// plain phrasing the rules already read. The sentences are the test's own.

#include <gtest/gtest.h>

#include <string>

#include "simhuman/language/offline/clauses.h"
#include "simhuman/language/offline/fallback.h"
#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/planner_testing.h"
#include "simhuman/language/offline/rewrite.h"
#include "simhuman/language/offline_planner.h"

namespace simhuman::language::offline {
namespace {

using Fixture = testing::SceneFixture;
Fixture Load(const std::string& scene) { return testing::LoadScene(scene); }

std::string PlanText(const std::string& scene, const std::string& command) {
  return testing::PlanPairs(scene, command);
}

std::string Spoken(const std::string& command) { return Join(ReadSpokenForms(*Tokenize(command))); }

// `said` plans exactly as `plain` does, and `plain` plans
void ExpectSame(const std::string& scene, const std::string& said, const std::string& plain) {
  const std::string want = PlanText(scene, plain);
  ASSERT_EQ(want.rfind("error", 0), std::string::npos) << plain << ": " << want;
  EXPECT_EQ(PlanText(scene, said), want) << said;
}

TEST(SpokenFormsTest, ReflexiveAndCausativeVerbs) {
  EXPECT_EQ(Spoken("plant yourself on the stool"), "sit on the stool");
  EXPECT_EQ(Spoken("lay yourself down on the mattress"), "lie down on the mattress");
  EXPECT_EQ(Spoken("put yourself on your right side"), "turn onto your right side");
  EXPECT_EQ(Spoken("let your hands rest on the armrests"), "rest your hands on the armrests");
  EXPECT_EQ(Spoken("make your knees higher"), "raise your knees");
  ExpectSame("bedroom", "Park yourself on the chair, then let both hands rest on your knees.",
             "sit on the chair, then put both hands on your knees");
  ExpectSame("sit_demo", "Allow yourself to sink down into the chair", "sit on the chair");
  ExpectSame("living_room", "lay yourself on the bed and put yourself on your right side",
             "lie on the bed and turn onto your right side");
  ExpectSame("living_room", "lay yourself on the bed, make your knees high",
             "lie on the bed, raise your knees");
  ExpectSame("sit_demo", "sit on the chair and lay the hands on the knees",
             "sit on the chair and put your hands on your knees");
}

TEST(SpokenFormsTest, WordsThatCarryNoAction) {
  ExpectSame("sit_demo", "Go on, sit down on the chair, go on.", "sit on the chair");
  ExpectSame("sit_demo", "I do hope this is not a bother. Sit on the chair please.",
             "sit on the chair");
  ExpectSame("sit_demo", "I'm sorry about the noise. My son is asleep. Sit on the chair.",
             "sit on the chair");
  ExpectSame("sit_demo", "If it is no trouble, sit on the chair, then hold that pose.",
             "sit on the chair");
  ExpectSame("office", "Try out the stool: sit down on it and feel how it wobbles.",
             "sit on the high stool");
  ExpectSame("office", "Sit on the chair and type on the laptop until you are finished",
             "sit on the chair and type on the laptop");
  ExpectSame("sit_demo", "Walk to the chair. Sit down. Leave to settle for ten minutes.",
             "walk to the chair, then sit down");
  ExpectSame("bedroom", "Would you ever lie on the bed there", "lie on the bed");
  ExpectSame("tabletop_demo",
             "As a tester I want you to stack the blue box on the red box and then the green "
             "sphere on the yellow box",
             "put the blue box on the red box, then put the green sphere on the yellow box");
}

TEST(SpokenFormsTest, WordOrderAndIdioms) {
  ExpectSame("bedroom", "The chair. Sit on it, then left hand put on left knee.",
             "sit on the chair, then put your left hand on your left knee");
  ExpectSame("bedroom", "The bed, go and lie down.", "lie on the bed");
  ExpectSame("living_room", "The sofa, sit down. The armchair, go sit.",
             "sit on the sofa, then go to the armchair and sit on it");
  ExpectSame("office", "Chair, go and sit. Then the box, touch with right hand.",
             "go to the chair and sit, then touch the box with your right hand");
  ExpectSame("sit_demo", "lean right back in the chair", "sit on the chair and lean back");
  ExpectSame("bedroom", "sit on the rim of the bed", "sit on the edge of the bed");
  ExpectSame("living_room", "over to the armchair, pop down in it",
             "go to the armchair, then sit on it");
  ExpectSame("office", "sit at the desk and give the laptop a quick type",
             "sit at the desk and type on the laptop");
  ExpectSame("sit_demo", "sit on the chair, the back against the backrest",
             "sit on the chair with your back against the backrest");
  ExpectSame("sit_demo", "sit on the chair and fold your hands over your belly",
             "sit on the chair and put your hands on your stomach");
}

TEST(SpokenFormsTest, ObjectsAsSubjectsAndPassives) {
  ExpectSame("tabletop_demo", "the green sphere should go onto the yellow box",
             "put the green sphere on the yellow box");
  ExpectSame("tabletop_demo", "the red cube wants to sit on the cylinder",
             "put the red box on the cylinder");
  ExpectSame("tabletop_demo", "stack yellow red", "stack the yellow box on the red box");
  ExpectSame("tabletop_demo", "pick up this green ball and put it on the red box",
             "put the green sphere on the red box");
  EXPECT_EQ(PlanText("tabletop_demo", "the golden crown goes on the red box").rfind("error", 0),
            0u);
  ExpectSame("bedroom", "The stool is sat on by the avatar, after which the box is walked to.",
             "sit on the stool, then walk to the box");
}

TEST(SpokenFormsTest, AFocusedObjectsPartAndARepeatedStep) {
  // "the top" after the box was named is the box's top (the office's table has a top too)
  ExpectSame("office", "walk to the box, then touch the top", "walk to the box, then touch it");
  // an echo of the object just touched adds no step
  ExpectSame("office", "go to the box and touch it. the box!", "go to the box and touch it");
  // a negated clause after what to do is a correction
  ExpectSame("bedroom", "lie on the bed. do not sit on the chair.", "lie on the bed");
  EXPECT_EQ(PlanText("bedroom", "Please do not lie on the bed.").rfind("error", 0), 0u);
  // an unknown action on an object the scene lacks stays refused
  EXPECT_EQ(PlanText("living_room", "plug the lamp in and sit on the sofa").rfind("error", 0), 0u);
}

TEST(SpokenFormsTest, TypingWithOneNamedHand) {
  EXPECT_EQ(PlanText("office", "sit at the desk and type with your left hand"),
            "chair002:seat surface:pelvis / chair002:seat surface:pelvis, "
            "laptop001:keyboard:left hand");
}

TEST(SpokenFormsTest, CoverageCountsWhatThePlanLeavesOut) {
  Fixture f = Load("tabletop_demo");
  OfflinePlanner planner;
  core::StatusOr<PlanResult> r = planner.Plan("put the red box on the yellow box", f.context);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_EQ(Uncovered({"put", "box", "onto", "box"}, *r, f.catalog), 0);
  EXPECT_EQ(
      Uncovered({"put", "box", "onto", "box", "then", "sphere", "onto", "cylinder"}, *r, f.catalog),
      2);
  EXPECT_EQ(Uncovered({"put", "box", "with", "your", "left", "hand"}, *r, f.catalog), 0);
  EXPECT_EQ(Uncovered({"put", "box", "with", "your", "left", "foot"}, *r, f.catalog), 1);
}

}  // namespace
}  // namespace simhuman::language::offline
