#include "simhuman/world/model_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

#include "simhuman/world/humanoid.h"
#include "simhuman/world/objects.h"

namespace simhuman::world {
namespace {

std::string F(double v) {
  std::ostringstream s;
  s.precision(8);
  s << v;
  return s.str();
}
std::string V3(const Eigen::Vector3d& v) { return F(v.x()) + " " + F(v.y()) + " " + F(v.z()); }
std::string Q(const Eigen::Quaterniond& q) {
  return F(q.w()) + " " + F(q.x()) + " " + F(q.y()) + " " + F(q.z());
}

const char* GeomType(core::ShapeKind k) {
  switch (k) {
    case core::ShapeKind::kBox:
      return "box";
    case core::ShapeKind::kSphere:
      return "sphere";
    case core::ShapeKind::kCapsule:
      return "capsule";
    case core::ShapeKind::kCylinder:
      return "cylinder";
    case core::ShapeKind::kFrustum:
    case core::ShapeKind::kMesh:
      return "mesh";
  }
  return "box";
}

std::string GeomSize(const core::Shape& s) {
  switch (s.kind) {
    case core::ShapeKind::kBox:
      return V3(s.size);
    case core::ShapeKind::kSphere:
      return F(s.size.x());
    default:
      return F(s.size.x()) + " " + F(s.size.y());
  }
}

std::string Rgba(const core::CatalogObject& o, bool part) {
  auto c = ColorRgba(o.color.empty() ? DefaultColor(o.type) : o.color);
  std::array<float, 4> rgba = c ? *c : std::array<float, 4>{0.6f, 0.6f, 0.6f, 1.f};
  // unnamed structure (legs, frames) drawn slightly darker than the named parts
  float k = part ? 1.0f : 0.7f;
  return F(rgba[0] * k) + " " + F(rgba[1] * k) + " " + F(rgba[2] * k) + " " + F(rgba[3]);
}

bool SameShape(const core::Shape& a, const core::Shape& b) {
  return a.kind == b.kind && (a.size - b.size).norm() < 1e-12 &&
         (a.pose.pos - b.pose.pos).norm() < 1e-12 && a.pose.quat.isApprox(b.pose.quat, 1e-12);
}

// the radius of a round flat face of a cylinder or frustum at `end` (-1 bottom, +1 top); 0 for
// other shapes and for a cone's apex
double FaceRadius(const core::Shape& s, int end) {
  if (s.kind == core::ShapeKind::kCylinder) return s.size.x();
  if (s.kind == core::ShapeKind::kFrustum) return end < 0 ? s.size.x() : s.size.z();
  return 0;
}

std::string RimSphere(const core::CatalogObject& obj, const Eigen::Vector3d& pos, double r,
                      const std::string& contact, int* n) {
  return "<geom name=\"obj/" + obj.id + "/rim" + std::to_string((*n)++) +
         "\" type=\"sphere\" size=\"" + F(r) + "\" pos=\"" + V3(pos) + "\" mass=\"0\" group=\"3\"" +
         contact + "/>\n";
}

// A flat round face resting on a flat one touches it at one point in MuJoCo's general convex
// collision, so a standing cylinder rocks and spins for ever (measured: 0.27 rad/s after 4 s).
// Eight massless spheres inside its rim, flush with the face and clear of the side and not
// drawn, give each open face (not shared with another solid of the object) of a cylinder or a
// frustum a ring of contacts to rest on.
std::string RoundRims(const core::CatalogObject& obj, const core::Shape& s,
                      const std::string& contact, int* n) {
  const double hh = s.size.y();
  std::string out;
  const Eigen::Vector3d axis = s.pose.quat * Eigen::Vector3d::UnitZ();
  for (int end : {-1, 1}) {
    const double r = FaceRadius(s, end);
    const double rf = std::min(0.003, 0.2 * std::min(r, hh));
    if (rf <= 0) continue;  // a cone's apex
    const Eigen::Vector3d face = s.pose.pos + end * hh * axis;
    bool shared = false;
    for (const core::Shape& o : obj.shapes) {
      if (&o == &s || FaceRadius(o, -1) + FaceRadius(o, 1) <= 0) continue;
      const Eigen::Vector3d oa = o.pose.quat * Eigen::Vector3d::UnitZ();
      for (int oe : {-1, 1}) shared |= (o.pose.pos + oe * o.size.y() * oa - face).norm() < 1e-9;
    }
    if (shared) continue;
    // a frustum's side slants: its spheres sit a radius further in, clear of the side
    const double in = s.kind == core::ShapeKind::kCylinder ? rf : 2 * rf;
    for (int k = 0; k < 8; ++k) {
      const double a = 2 * M_PI * k / 8;
      const Eigen::Vector3d local((r - in) * std::cos(a), (r - in) * std::sin(a), end * (hh - rf));
      out += RimSphere(obj, s.pose.pos + s.pose.quat * local, rf, contact, n);
    }
  }
  return out;
}

// the same for a mesh standing on its lowest vertices: up to eight of them, spread out, each
// with a sphere just inside it
std::string MeshFeet(const core::CatalogObject& obj, const core::Shape& s,
                     const std::string& contact, int* n) {
  constexpr double kRf = 0.003, kLowM = 0.002;
  std::vector<Eigen::Vector3d> v;
  for (const Eigen::Vector3d& p : s.mesh->vertices) v.push_back(p.cwiseProduct(s.size));
  double z_lo = std::numeric_limits<double>::infinity();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : v) {
    z_lo = std::min(z_lo, p.z());
    centre += p / v.size();
  }
  std::vector<Eigen::Vector3d> low;
  for (const Eigen::Vector3d& p : v) {
    if (p.z() < z_lo + kLowM) low.push_back(p);
  }
  if (low.size() < 3) return "";
  // farthest-point picks, starting from the lowest vertex farthest from the centre
  std::vector<Eigen::Vector3d> feet;
  auto gap = [&](const Eigen::Vector3d& p) {
    double g = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& f : feet) g = std::min(g, (f - p).head<2>().norm());
    return feet.empty() ? (p - centre).head<2>().norm() : g;
  };
  while (feet.size() < 8) {
    auto far = std::max_element(low.begin(), low.end(),
                                [&](const auto& a, const auto& b) { return gap(a) < gap(b); });
    if (gap(*far) < 4 * kRf) break;
    feet.push_back(*far);
  }
  std::string out;
  for (const Eigen::Vector3d& f : feet) {
    Eigen::Vector2d in = (centre - f).head<2>();
    in = in.norm() > 1e-9 ? Eigen::Vector2d(in.normalized() * 2 * kRf) : Eigen::Vector2d::Zero();
    const Eigen::Vector3d local(f.x() + in.x(), f.y() + in.y(), z_lo + kRf);
    out += RimSphere(obj, s.pose.Apply(local), kRf, contact, n);
  }
  return out;
}

// a mesh asset for a frustum (two rings of vertices; a cone's apex is one vertex) or a mesh
// shape (its scaled vertices); MuJoCo takes the convex hull
std::string MeshAsset(const std::string& name, const core::Shape& s) {
  std::vector<Eigen::Vector3d> v;
  if (s.kind == core::ShapeKind::kMesh) {
    for (const Eigen::Vector3d& p : s.mesh->vertices) v.push_back(p.cwiseProduct(s.size));
  } else {
    constexpr int kSegments = 32;
    for (int end : {-1, 1}) {
      const double r = FaceRadius(s, end);
      const int count = r > 1e-6 ? kSegments : 1;
      for (int k = 0; k < count; ++k) {
        const double a = 2 * M_PI * k / kSegments;
        v.emplace_back(r * std::cos(a), r * std::sin(a), end * s.size.y());
      }
    }
  }
  std::string out = "<mesh name=\"" + name + "\" vertex=\"";
  for (size_t i = 0; i < v.size(); ++i) out += (i ? " " : "") + V3(v[i]);
  return out + "\"/>\n";
}

// the objects' bodies; mesh assets they need are appended to `assets`
core::StatusOr<std::string> ObjectsXml(const core::SceneCatalog& scene, std::string* assets) {
  std::ostringstream o;
  for (const core::CatalogObject& obj : scene.objects) {
    o << "<body name=\"" << ObjectBodyName(obj.id) << "\" pos=\"" << V3(obj.pose.pos)
      << "\" quat=\"" << Q(obj.pose.quat) << "\">\n";
    if (obj.movable) o << "<freejoint name=\"obj/" << obj.id << "/root\"/>\n";
    if (obj.friction && !(*obj.friction > 0 && std::isfinite(*obj.friction))) {
      return absl::InvalidArgumentError("object '" + obj.id + "': friction " + F(*obj.friction) +
                                        " must be a positive finite number");
    }
    const std::string sliding = F(obj.friction.value_or(kDefaultSlidingFriction));
    // a movable object's mass spread over its solids by volume: uniform density, so a cylinder
    // built as a thin top slab over the rest has its centre of mass at half its height (an
    // equal share per solid put half the mass in the slab, the centre at 0.7 of the height)
    double volume = 0;
    for (const core::Shape& s : obj.shapes) volume += core::ShapeVolume(s);
    int n = 0, rims = 0;
    for (const core::Shape& s : obj.shapes) {
      if (!s.size.allFinite() || (s.size.array() < 0).any()) {
        return absl::InvalidArgumentError("object '" + obj.id + "': shape " + std::to_string(n) +
                                          " has an invalid size");
      }
      bool in_part = false, soft = false, cushion = false;
      for (const auto& part : obj.parts) {
        for (const auto& ps : part.shapes) {
          bool same = SameShape(ps, s);
          in_part |= same;
          soft |= same && part.name == "pillow";
          cushion |= same && part.name == "mattress";
        }
      }
      const std::string geom = "obj/" + obj.id + "/" + std::to_string(n++);
      o << "<geom name=\"" << geom << "\" type=\"" << GeomType(s.kind) << "\"";
      if (std::string(GeomType(s.kind)) == "mesh") {
        *assets += MeshAsset(geom, s);
        o << " mesh=\"" << geom << "\"";
      } else {
        o << " size=\"" << GeomSize(s) << "\"";
      }
      o << " pos=\"" << V3(s.pose.pos) << "\" quat=\"" << Q(s.pose.quat) << "\" rgba=\""
        << (soft ? "0.95 0.95 0.92 1" : Rgba(obj, in_part)) << "\"";
      if (!obj.collides) o << " contype=\"0\" conaffinity=\"0\"";
      // pillows give: a head sinks a few centimetres
      if (soft) o << " solref=\"0.04 1\" solimp=\"0.2 0.9 0.05\"";
      // mattresses give a little less than pillows
      if (cushion) o << " solref=\"0.03 1\" solimp=\"0.4 0.95 0.04\"";
      std::string contact;
      if (obj.movable) {
        const double share = volume > 0 ? core::ShapeVolume(s) / volume : 1.0 / obj.shapes.size();
        o << " mass=\"" << F(obj.mass_kg * share) << "\"";
        // a hand is a patch, not a point: torsional friction lets two pressing palms resist
        // the object turning about the line between them (what carrying relies on)
        contact = " condim=\"4\" friction=\"" + sliding + " 0.05 0.01\"";
      } else if (obj.friction) {
        contact = " friction=\"" + sliding + " 0.02 0.01\"";
      }
      // MuJoCo combines two geoms' friction by the larger; priority 1 makes an object's own
      // coefficient the one its contacts use (with the table, the floor, a hand)
      if (obj.friction) contact += " priority=\"1\"";
      o << contact << "/>\n";
      if (obj.movable && obj.collides) {
        o << (s.kind == core::ShapeKind::kMesh ? MeshFeet(obj, s, contact, &rims)
                                               : RoundRims(obj, s, contact, &rims));
      }
    }
    o << "</body>\n";
  }
  return o.str();
}

}  // namespace

std::string AgentPrefix(int agent) { return agent == 0 ? "" : "h" + std::to_string(agent) + "/"; }

std::string ObjectBodyName(const std::string& id) { return "obj/" + id; }

core::StatusOr<std::string> BuildModelXml(const core::SceneCatalog& scene,
                                          const std::vector<AgentSpec>& agents,
                                          const ModelOptions& options) {
  if (!(options.timestep_s > 0) || !std::isfinite(options.timestep_s)) {
    return absl::InvalidArgumentError("model option timestep_s must be a positive number");
  }
  if (options.solver != "newton" && options.solver != "pgs") {
    return absl::InvalidArgumentError("model option solver '" + options.solver +
                                      "' is unknown; valid: newton, pgs");
  }
  if (options.cone != "pyramidal" && options.cone != "elliptic") {
    return absl::InvalidArgumentError("model option cone '" + options.cone +
                                      "' is unknown; valid: pyramidal, elliptic");
  }
  if (!(options.impratio >= 1) || !std::isfinite(options.impratio)) {
    return absl::InvalidArgumentError("model option impratio " + F(options.impratio) +
                                      " must be a finite number >= 1");
  }
  for (auto [key, value, low] : {std::tuple<const char*, int, int>{"nconmax", options.nconmax, 1},
                                 {"njmax", options.njmax, 1},
                                 {"nstack", options.nstack, 1000}}) {
    if (value < low) {
      return absl::InvalidArgumentError(std::string("model option ") + key + " " +
                                        std::to_string(value) + " must be at least " +
                                        std::to_string(low));
    }
  }
  std::string mesh_assets;
  SH_ASSIGN_OR_RETURN(const std::string objects, ObjectsXml(scene, &mesh_assets));
  std::ostringstream o;
  o << "<mujoco model=\"simhuman\">\n"
    << "<compiler angle=\"degree\" autolimits=\"true\"/>\n"
    << "<option timestep=\"" << F(options.timestep_s) << "\" iterations=\""
    << options.solver_iterations << "\" integrator=\"Euler\" solver=\""
    << (options.solver == "pgs" ? "PGS" : "Newton") << "\" cone=\"" << options.cone
    << "\" impratio=\"" << F(options.impratio) << "\"/>\n"
    << "<size nconmax=\"" << options.nconmax << "\" njmax=\"" << options.njmax << "\" nstack=\""
    << options.nstack << "\"/>\n"
    << "<visual><global offwidth=\"" << options.offscreen_width << "\" offheight=\""
    << options.offscreen_height << "\"/><quality shadowsize=\"2048\"/>"
    << "<headlight ambient=\"0.35 0.35 0.35\" diffuse=\"0.5 0.5 0.5\"/></visual>\n"
    << "<asset><texture name=\"grid\" type=\"2d\" builtin=\"checker\" rgb1=\"0.82 0.82 0.8\" "
       "rgb2=\"0.7 0.7 0.68\" width=\"512\" height=\"512\"/>"
    << "<material name=\"floor\" texture=\"grid\" texrepeat=\"8 8\" reflectance=\"0\"/>"
    << mesh_assets << "</asset>\n"
    << "<default><geom condim=\"3\" friction=\"" << F(kDefaultSlidingFriction)
    << " 0.02 0.01\" solref=\"0.015 1\"/></default>\n"
    << "<worldbody>\n"
    << "<light name=\"sun\" directional=\"true\" pos=\"0 0 6\" dir=\"-0.3 -0.2 -1\" "
       "diffuse=\"0.6 0.6 0.6\" castshadow=\"false\"/>\n"
    << "<geom name=\"floor\" type=\"plane\" size=\"30 30 0.1\" material=\"floor\"/>\n";
  for (size_t a = 0; a < agents.size(); ++a) {
    const AgentSpec& p = agents[a];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw_rad) ||
        !(p.scale > 0.3 && p.scale < 1.5)) {
      return absl::InvalidArgumentError("human " + std::to_string(a) +
                                        ": position/yaw must be finite and scale in (0.3, 1.5)");
    }
    core::StatusOr<const Embodiment*> kind = FindEmbodiment(p.kind);
    if (!kind.ok()) return core::Annotate(kind.status(), "human " + std::to_string(a));
    if (!std::isfinite(p.seated_pelvis_z) || p.seated_pelvis_z < 0 || p.seated_pelvis_z > 2) {
      return absl::InvalidArgumentError("human " + std::to_string(a) + ": seated pelvis height " +
                                        F(p.seated_pelvis_z) + " m is outside [0, 2]");
    }
    o << HumanoidBodyXml(MakeHumanoidSpec(**kind, p.scale, static_cast<int>(a)), p.x, p.y,
                         p.yaw_rad, p.seated_pelvis_z);
  }
  o << objects;
  o << "</worldbody>\n";
  std::string excludes;
  for (size_t a = 0; a < agents.size(); ++a) {
    const Embodiment* kind = *FindEmbodiment(agents[a].kind);  // checked above
    excludes += HumanoidContactXml(MakeHumanoidSpec(*kind, agents[a].scale, static_cast<int>(a)));
  }
  if (!excludes.empty()) o << "<contact>\n" << excludes << "</contact>\n";
  // held pelvises: a weld to the world at the pose the model starts in (relpose from qpos0)
  std::string welds;
  for (size_t a = 0; a < agents.size(); ++a) {
    if (!agents[a].hold_pelvis) continue;
    welds += "<weld name=\"" + AgentPrefix(static_cast<int>(a)) + "hold_pelvis\" body1=\"" +
             AgentPrefix(static_cast<int>(a)) + "pelvis\"/>\n";
  }
  if (!welds.empty()) o << "<equality>\n" << welds << "</equality>\n";
  o << "<actuator>\n";
  for (size_t a = 0; a < agents.size(); ++a) {
    const Embodiment* kind = *FindEmbodiment(agents[a].kind);  // checked above
    o << HumanoidActuatorXml(MakeHumanoidSpec(*kind, agents[a].scale, static_cast<int>(a)));
  }
  o << "</actuator>\n</mujoco>\n";
  return o.str();
}

}  // namespace simhuman::world
