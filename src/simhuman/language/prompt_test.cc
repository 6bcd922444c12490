#include "simhuman/language/prompt.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "simhuman/plan/test_scene.h"

namespace simhuman::language {
namespace {

using ::testing::HasSubstr;

std::string PromptDir() { return std::string(SIMHUMAN_SOURCE_DIR) + "/assets/prompts"; }

TEST(PromptTest, ShippedTemplatesLoad) {
  core::StatusOr<PromptTemplates> t = LoadPromptTemplates(PromptDir());
  ASSERT_TRUE(t.ok()) << t.status();
  EXPECT_THAT(t->user, HasSubstr("{{command}}"));
  EXPECT_THAT(t->system, HasSubstr("[start of rules]"));
}

TEST(PromptTest, DescribeSceneFillsTheBackground) {
  core::SceneCatalog scene = plan::fixtures::MakeTestScene();
  AgentStart sitting;
  sitting.x_m = 1.1;
  sitting.posture = "sit";
  std::map<std::string, std::string> v = DescribeScene(scene, {sitting});
  EXPECT_EQ(v["objects"], "chair000 (red chair), bed001 (bed)");
  EXPECT_THAT(v["parts"], HasSubstr("[OBJECT: bed001] has PARTS: [mattress, pillow]"));
  // bed001 is 3 m along +x of the chair, i.e. in front of it; the bed is turned by 90 degrees
  // (its front faces +y, its left -x), so the chair is to its left
  EXPECT_THAT(v["layout"], HasSubstr("[OBJECT: bed001] is at x = 3.00 m, y = 0.00 m, its front "
                                     "facing 90 degrees. It is 3.0 m from [OBJECT: chair000], "
                                     "in front of it."));
  EXPECT_THAT(v["layout"], HasSubstr("from [OBJECT: bed001], to the left of it."));
  EXPECT_THAT(v["humans"], HasSubstr("Human 0 (agent 0) is sitting at x = 1.10 m"));
  // distances to the footprints: the chair's front edge is at x = 0.25, the bed's near long
  // side at x = 2.5
  EXPECT_THAT(v["humans"], HasSubstr("[OBJECT: chair000] is 0.9 m away (close)"));
  EXPECT_THAT(v["humans"], HasSubstr("[OBJECT: bed001] is 1.4 m away (not close)"));
  EXPECT_THAT(v["joints"], HasSubstr("pelvis, torso, head, left shoulder"));
  EXPECT_EQ(v["directions"], "up, down, front, back, left, right, none");
}

TEST(PromptTest, FillTemplateIsOnePass) {
  core::StatusOr<std::string> s = FillTemplate("a {{command}} b {{objects}}",
                                               {{"command", "{{objects}}"}, {"objects", "X"}}, "t");
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(*s, "a {{objects}} b X");
  EXPECT_THAT(std::string(FillTemplate("{{nope}}", {}, "user.txt").status().message()),
              HasSubstr("user.txt: no value for placeholder '{{nope}}'"));
}

TEST(PromptTest, TemplateChecksNameTheFileAndPlaceholder) {
  PromptTemplates t{"rules {{colour}}", "{{command}}", "{{errors}}"};
  core::Status s = CheckPromptTemplates(t, "dir");
  EXPECT_THAT(std::string(s.message()),
              HasSubstr("dir/system.txt: unknown placeholder '{{colour}}'; valid "
                        "placeholders: objects, parts"));
  t = {"", "no command here", "{{errors}}"};
  EXPECT_THAT(std::string(CheckPromptTemplates(t, "dir").message()),
              HasSubstr("dir/user.txt: the required placeholder '{{command}}' is missing"));
}

TEST(PromptTest, QuoteCommandEscapes) {
  EXPECT_EQ(QuoteCommand("say \"hi\"\n"), "\"say \\\"hi\\\"\\n\"");
  EXPECT_EQ(QuoteCommand("\xff"), "\"\xef\xbf\xbd\"");  // invalid UTF-8 replaced
}

}  // namespace
}  // namespace simhuman::language
