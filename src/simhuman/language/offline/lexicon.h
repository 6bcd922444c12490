#pragma once
/// The offline planner's lexicon: the words it knows and how everyday phrasings are rewritten to
/// one canonical word before parsing ("on top of" -> "onto", "couch" -> "sofa", "take a seat" ->
/// "sit"; fillers such as "the" and "please" are dropped). Word lists are built once and never
/// change, so every function here is thread-safe.

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "simhuman/language/offline/common.h"

namespace simhuman::language::offline {

/// Phrases rewritten to canonical tokens (possibly none) before anything else; the longest
/// match wins.
const std::vector<std::pair<Tokens, Tokens>>& Phrases();
/// Single-word synonyms: word -> canonical word.
const std::map<std::string, std::string>& Synonyms();
/// Words dropped everywhere: fillers and determiners (relations and "your" are kept).
const std::set<std::string>& Fillers();
/// Colour words an object's `color` may equal.
const std::set<std::string>& Colors();
/// Object type words (singular and plural) -> canonical type; "" for "object", "thing", "one".
const std::map<std::string, std::string>& TypeWords();
/// Part words -> the name looked up among a part's name and aliases ("backrest" -> "back
/// surface").
const std::map<std::string, std::string>& PartWords();
/// Canonical relation words ("near", "left_of", "onto", ...).
const std::set<std::string>& Relations();
/// Every other word a clause may contain (verbs, body words, sides, pronouns, ...).
const std::set<std::string>& OtherWords();

/// Everyday speech (everyday.cc), merged into the lists above: wrappers, hedges, sequencing
/// words and idioms; synonyms of verbs, objects, parts and colours; words that carry no action.
const std::vector<std::pair<Tokens, Tokens>>& EverydayPhrases();
const std::map<std::string, std::string>& EverydaySynonyms();
const std::set<std::string>& EverydayFillers();
/// Who a scripted line is about ("npc", "the character", "he", "the robot"; phrasing.cc).
const std::set<std::string>& Subjects();

/// Whether `w` (normalised) is in any of the lists above. Object ids are checked separately.
bool Known(const std::string& w);
/// Whether `w` names a body part ("hand", "knees", "other_knee", ...) or is "your".
bool IsBodyWord(const std::string& w);

/// Phrase rewriting, synonyms and filler removal over tokenized words.
Tokens Normalize(const Tokens& in);

}  // namespace simhuman::language::offline
