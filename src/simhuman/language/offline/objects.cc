#include "simhuman/language/offline/objects.h"

#include <algorithm>

namespace simhuman::language::offline {

std::string Describe(const CatalogObject& o) {
  std::string colour = o.color.empty() ? "" : o.color + " ";
  return o.id + " (" + colour + TypeText(o.type) + ")";
}

std::string TypeText(const std::string& type) {
  std::string out = type;
  std::replace(out.begin(), out.end(), '_', ' ');
  return out;
}

bool HasPart(const CatalogObject& o, const std::string& name) {
  for (const core::CatalogPart& p : o.parts) {
    if (p.name == name) return true;
  }
  return false;
}

// parts of `o` whose name or an alias equals `word` (normalized)
std::vector<const core::CatalogPart*> PartsNamed(const CatalogObject& o, const std::string& word) {
  std::vector<const core::CatalogPart*> out;
  const std::string want = core::NormalizeName(word);
  for (const core::CatalogPart& p : o.parts) {
    bool hit = core::NormalizeName(p.name) == want;
    for (const std::string& a : p.aliases) hit = hit || core::NormalizeName(a) == want;
    if (hit) out.push_back(&p);
  }
  return out;
}

std::string PartsText(const CatalogObject& o) {
  std::vector<std::string> names = o.PartNames();
  return names.empty() ? std::string("(no parts)") : core::JoinNames(names);
}

std::string ObjectsWith(const core::SceneCatalog& scene, const std::string& part) {
  std::vector<std::string> ids;
  for (const CatalogObject& o : scene.objects) {
    if (HasPart(o, part)) ids.push_back(Describe(o));
  }
  return ids.empty() ? std::string("none in this scene") : core::JoinNames(ids);
}

}  // namespace simhuman::language::offline
