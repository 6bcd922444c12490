#pragma once
/// How the offline planner names and inspects catalog objects: descriptions for plans and
/// messages ("chair000 (brown chair)"), part lookup by name or alias, and lists of what the
/// scene offers.

#include <string>
#include <vector>

#include "simhuman/language/offline/common.h"

namespace simhuman::language::offline {

/// "chair000 (brown chair)": the id, then the colour and type in words.
std::string Describe(const CatalogObject& o);
/// An object type in words ("high_stool" -> "high stool", "long_box" -> "long box").
std::string TypeText(const std::string& type);
/// Whether `o` has a part whose canonical name is exactly `name`.
bool HasPart(const CatalogObject& o, const std::string& name);
/// The parts of `o` whose name or an alias equals `word` under core::NormalizeName.
std::vector<const core::CatalogPart*> PartsNamed(const CatalogObject& o, const std::string& word);
/// The canonical part names of `o` joined for a message, or "(no parts)".
std::string PartsText(const CatalogObject& o);
/// Describe() of every object with a part named `part`, or "none in this scene".
std::string ObjectsWith(const core::SceneCatalog& scene, const std::string& part);

}  // namespace simhuman::language::offline
