// Unit tests of the offline planner's pieces (tokenizer, lexicon, clause splitting, noun
// phrases, relation words); whole commands are tested in offline_planner_test.cc.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "simhuman/language/offline/clauses.h"
#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/noun_phrase.h"
#include "simhuman/language/offline/rewrite.h"
#include "simhuman/language/offline/spatial.h"
#include "simhuman/language/offline_planner.h"

namespace simhuman::language::offline {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(OfflineTokenizeTest, WordsPunctuationAndApostrophes) {
  core::StatusOr<Tokens> t = Tokenize("Don't sit; Lie-down on the bed's_pillow.");
  ASSERT_TRUE(t.ok()) << t.status();
  EXPECT_THAT(
      *t, ElementsAre("dont", "sit", "then", "lie", "down", "on", "the", "beds", "pillow", "then"));
}

TEST(OfflineTokenizeTest, OtherBytesAndLongCommandsAreNamed) {
  core::StatusOr<Tokens> t = Tokenize("sit @ home");
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(std::string(t.status().message()), HasSubstr("character '@' at offset 4"));
  t = Tokenize("sit \xc3\xa9");
  ASSERT_FALSE(t.ok());
  EXPECT_THAT(std::string(t.status().message()), HasSubstr("byte 0xc3 at offset 4"));
  t = Tokenize(std::string(kMaxCommandBytes + 1, 'a'));
  ASSERT_FALSE(t.ok());
  EXPECT_THAT(std::string(t.status().message()), HasSubstr("at most 4096"));
}

TEST(OfflineLexiconTest, LongestPhraseWinsThenSynonymsThenFillers) {
  // "on top of" beats "on"; "couch" -> "sofa"; "please" and "the" are dropped
  EXPECT_THAT(Normalize({"please", "put", "the", "box", "on", "top", "of", "the", "couch"}),
              ElementsAre("put", "box", "onto", "sofa"));
  EXPECT_THAT(Normalize({"take", "a", "seat", "and", "then", "get", "up"}),
              ElementsAre("sit", "then", "stand", "up"));
  EXPECT_TRUE(Known("left_of"));
  EXPECT_TRUE(Known("armchair"));
  EXPECT_FALSE(Known("banana"));
  EXPECT_TRUE(IsBodyWord("other_knee"));
  EXPECT_FALSE(IsBodyWord("chair"));
}

TEST(OfflineRewordTest, SubjectsVerbFormsChatAndParticiples) {
  EXPECT_THAT(Reword({"npc", "walks", "to", "it", "then", "he", "rests", "its", "hands"}),
              ElementsAre("walk", "to", "it", "then", "rest", "your", "hands"));
  EXPECT_THAT(Reword({"goto", "high", "stool003", "and", "chill", "on", "ur", "bed"}),
              ElementsAre("go", "to", "high_stool003", "and", "rest", "on", "your", "bed"));
  EXPECT_THAT(Reword({"knees", "bent", "up", "head", "raised", "off", "the", "pillow"}),
              ElementsAre("knees", "up", "head", "up"));
  EXPECT_THAT(Reword({"sit", "without", "touching", "the", "backrest"}),
              ElementsAre("sit", "leaning", "forward"));
  EXPECT_THAT(Reword({"raise", "it", "so", "the", "foot", "stays", "flat", "then", "x"}),
              ElementsAre("raise", "it", "then", "x"));
  EXPECT_THAT(Reword({"press", "a", "key", "on", "the", "laptop"}),
              ElementsAre("touch", "a", "laptop", "keyboard"));
  EXPECT_THAT(Reword({"her", "left", "knee", "on", "its", "left", "arm"}),
              ElementsAre("your", "left", "knee", "on", "its", "left", "arm"));
  // "its arm" is the object's arm, "ok so" is not a purpose clause
  EXPECT_THAT(Reword({"its", "arm", "ok", "so", "the"}),
              ElementsAre("its", "arm", "ok", "so", "the"));
  core::StatusOr<Tokens> t = Tokenize("sit -> type");
  ASSERT_TRUE(t.ok());
  EXPECT_THAT(*t, ElementsAre("sit", "then", "type"));
}

TEST(OfflineClausesTest, SplitsOnThenAndAndDropsEmptyClauses) {
  core::StatusOr<std::vector<Tokens>> c =
      SplitClauses({"then", "sit", "chair", "then", "and", "lie", "bed", "then"});
  ASSERT_TRUE(c.ok()) << c.status();
  EXPECT_THAT(*c, ElementsAre(Tokens{"sit", "chair"}, Tokens{"lie", "bed"}));
  Tokens many;
  for (int i = 0; i <= kMaxClauses; ++i) {
    many.push_back("sit");
    many.push_back("then");
  }
  c = SplitClauses(many);
  ASSERT_FALSE(c.ok());
  EXPECT_THAT(std::string(c.status().message()), HasSubstr("more than 40 clauses"));
}

TEST(OfflineNounPhraseTest, AdjectivesHeadAndRelation) {
  const Tokens t = {"big", "red", "box", "left_of", "green", "sphere"};
  core::StatusOr<NounPhrase> np = ParseNounPhrase(t, 0, t.size(), 0, "test");
  ASSERT_TRUE(np.ok()) << np.status();
  EXPECT_EQ(np->select, Select::kBig);
  EXPECT_EQ(np->color, "red");
  EXPECT_EQ(np->type, "box");
  ASSERT_EQ(np->relations.size(), 1u);
  EXPECT_EQ(np->relations[0].rel, Rel::kLeftOf);
  EXPECT_EQ(np->relations[0].ref->color, "green");
  EXPECT_EQ(np->relations[0].ref->type, "sphere");
  EXPECT_EQ(NounOf(*np), "red box");
}

TEST(OfflineNounPhraseTest, PartsPronounsAndNesting) {
  const Tokens arm = {"left", "arm", "of", "sofa"};
  core::StatusOr<NounPhrase> np = ParseNounPhrase(arm, 0, arm.size(), 0, "test");
  ASSERT_TRUE(np.ok()) << np.status();
  EXPECT_EQ(np->part, "arm");
  EXPECT_EQ(np->part_side, "left");
  EXPECT_EQ(np->type, "sofa");
  const Tokens its = {"its", "keyboard"};
  np = ParseNounPhrase(its, 0, its.size(), 0, "test");
  ASSERT_TRUE(np.ok()) << np.status();
  EXPECT_TRUE(np->pronoun);
  EXPECT_EQ(np->part, "keyboard");
  // each relation's reference is parsed one level deeper; past kMaxNesting is refused
  const Tokens near = {"box", "near", "sphere"};
  EXPECT_TRUE(ParseNounPhrase(near, 0, near.size(), kMaxNesting - 1, "test").ok());
  np = ParseNounPhrase(near, 0, near.size(), kMaxNesting, "test");
  ASSERT_FALSE(np.ok());
  EXPECT_THAT(std::string(np.status().message()), HasSubstr("nests more than 3 relations"));
}

TEST(OfflineSpatialTest, RelationWords) {
  EXPECT_EQ(RelFromWord("at"), Rel::kNear);
  EXPECT_EQ(RelFromWord("onto"), Rel::kOn);
  EXPECT_FALSE(RelFromWord("box").has_value());
  EXPECT_EQ(RelText(Rel::kFrontOf), "in front of");
}

}  // namespace
}  // namespace simhuman::language::offline
