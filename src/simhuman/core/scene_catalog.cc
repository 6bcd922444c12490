#include "simhuman/core/scene_catalog.h"

#include <cctype>

namespace simhuman::core {

std::string NormalizeName(std::string_view name, TrailingDigits digits) {
  std::string s;
  for (char c : name) {
    s += (c == '_') ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  const bool drop_digits = digits == TrailingDigits::kDrop;
  while (!s.empty() &&
         (s.back() == ' ' || (drop_digits && std::isdigit(static_cast<unsigned char>(s.back()))))) {
    s.pop_back();
  }
  size_t b = s.find_first_not_of(' ');
  return b == std::string::npos ? std::string() : s.substr(b);
}

const CatalogPart* CatalogObject::FindPart(std::string_view name) const {
  std::string n = NormalizeName(name);
  for (const CatalogPart& p : parts) {
    if (NormalizeName(p.name) == n) return &p;
  }
  for (const CatalogPart& p : parts) {
    for (const std::string& a : p.aliases) {
      if (NormalizeName(a) == n) return &p;
    }
  }
  return nullptr;
}

std::vector<std::string> CatalogObject::PartNames() const {
  std::vector<std::string> out;
  for (const CatalogPart& p : parts) out.push_back(p.name);
  return out;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> CatalogObject::LocalBounds() const {
  return ShapesBounds(shapes);
}

int CarryInfo::min_carriers() const { return layouts.empty() ? 0 : layouts.front().carriers(); }

int CarryInfo::max_carriers() const { return layouts.empty() ? 0 : layouts.back().carriers(); }

const CarryLayout* CarryInfo::ForTeam(int carriers) const {
  for (const CarryLayout& l : layouts) {
    if (l.carriers() == carriers) return &l;
  }
  return nullptr;
}

double TeamCapacityKg(int carriers) {
  constexpr double kAloneKg = 13.0;
  constexpr double kPerTeamMemberKg = 20.0;
  if (carriers < 1) return 0.0;
  return carriers == 1 ? kAloneKg : kPerTeamMemberKg * carriers;
}

const CatalogObject* SceneCatalog::Find(std::string_view id) const {
  for (const CatalogObject& o : objects) {
    if (o.id == id) return &o;
  }
  return nullptr;
}

CatalogObject* SceneCatalog::Find(std::string_view id) {
  for (CatalogObject& o : objects) {
    if (o.id == id) return &o;
  }
  return nullptr;
}

std::vector<std::string> SceneCatalog::ObjectIds() const {
  std::vector<std::string> out;
  for (const CatalogObject& o : objects) out.push_back(o.id);
  return out;
}

}  // namespace simhuman::core
