#include "simhuman/web/scene_view.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/escaping.h"
#include "simhuman/control/task.h"

namespace simhuman::web {
namespace {

// MuJoCo's viewer shows geom groups 0-2 by default; higher groups are collision or helpers
constexpr int kMaxVisibleGroup = 2;
// a plane of size 0 is infinite; the viewer draws it this large (half-size, m)
constexpr double kInfinitePlaneHalfM = 10.0;

// rounded to 0.1 mm / 1e-5, so the page's JSON stays short
double Round(double v, double unit) { return std::round(v / unit) * unit; }

nlohmann::json Vec(const mjtNum* v, int n, double unit = 1e-5) {
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < n; ++i) a.push_back(Round(v[i], unit));
  return a;
}

// one geom in its body's frame; null for an invisible one
nlohmann::json Geom(const mjModel* m, int g) {
  if (m->geom_group[g] > kMaxVisibleGroup || m->geom_rgba[4 * g + 3] <= 0) return nullptr;
  nlohmann::json j;
  const mjtNum* s = m->geom_size + 3 * g;
  std::vector<mjtNum> size(s, s + 3);
  switch (m->geom_type[g]) {
    case mjGEOM_PLANE:
      j["type"] = "plane";
      for (int i = 0; i < 2; ++i) size[i] = size[i] > 0 ? size[i] : kInfinitePlaneHalfM;
      break;
    case mjGEOM_SPHERE:
      j["type"] = "sphere";
      break;
    case mjGEOM_CAPSULE:
      j["type"] = "capsule";
      break;
    case mjGEOM_CYLINDER:
      j["type"] = "cylinder";
      break;
    case mjGEOM_ELLIPSOID:
      j["type"] = "ellipsoid";
      break;
    case mjGEOM_BOX:
      j["type"] = "box";
      break;
    case mjGEOM_MESH: {
      // the mesh's vertices (its own frame, 0.1 mm) and triangles
      j["type"] = "mesh";
      const int mesh = m->geom_dataid[g];
      const int nv = m->mesh_vertnum[mesh], nf = m->mesh_facenum[mesh];
      nlohmann::json v = nlohmann::json::array(), f = nlohmann::json::array();
      for (int k = 0; k < 3 * nv; ++k)
        v.push_back(Round(m->mesh_vert[3 * m->mesh_vertadr[mesh] + k], 1e-4));
      for (int k = 0; k < 3 * nf; ++k) f.push_back(m->mesh_face[3 * m->mesh_faceadr[mesh] + k]);
      j["vertices"] = std::move(v);
      j["faces"] = std::move(f);
      break;
    }
    default:
      return nullptr;  // heightfields, SDFs: none in our scenes
  }
  j["size"] = Vec(size.data(), 3);
  j["pos"] = Vec(m->geom_pos + 3 * g, 3);
  j["quat"] = Vec(m->geom_quat + 4 * g, 4);
  std::vector<mjtNum> rgba(m->geom_rgba + 4 * g, m->geom_rgba + 4 * g + 4);
  j["rgba"] = Vec(rgba.data(), 4, 1e-3);
  return j;
}

}  // namespace

SceneView DescribeScene(const world::SimWorld& world, const mjData* d) {
  const mjModel* m = world.model();
  std::vector<int> agent_of(m->nbody, -1);
  for (int a = 0; a < world.num_agents(); ++a) {
    for (int b : world.agent(a).bodies) agent_of[b] = a;
  }
  SceneView view;
  view.json["bodies"] = nlohmann::json::array();
  for (int b = 0; b < m->nbody; ++b) {
    nlohmann::json geoms = nlohmann::json::array();
    for (int g = m->body_geomadr[b]; g >= 0 && g < m->body_geomadr[b] + m->body_geomnum[b]; ++g) {
      nlohmann::json geom = Geom(m, g);
      if (!geom.is_null()) geoms.push_back(std::move(geom));
    }
    if (geoms.empty()) continue;
    const bool moving = b > 0 && m->body_weldid[b] != 0;
    const char* name = mj_id2name(m, mjOBJ_BODY, b);
    nlohmann::json body = {{"name", name ? name : "body" + std::to_string(b)},
                           {"agent", agent_of[b]},
                           {"moving", moving}};
    body["pos"] = Vec(d->xpos + 3 * b, 3);
    body["quat"] = Vec(d->xquat + 4 * b, 4);
    body["geoms"] = std::move(geoms);
    view.json["bodies"].push_back(std::move(body));
    if (moving) view.moving_bodies.push_back(b);
  }
  return view;
}

void AppendPoses(const SceneView& view, const mjData* d, std::vector<float>* out) {
  for (int b : view.moving_bodies) {
    for (int i = 0; i < 3; ++i) out->push_back(static_cast<float>(d->xpos[3 * b + i]));
    for (int i = 0; i < 4; ++i) out->push_back(static_cast<float>(d->xquat[4 * b + i]));
  }
}

int AppendTargets(const world::SimWorld& world, const plan::ContactChain& chain, int step,
                  const mjData* d, core::SceneCatalog* catalog, std::vector<float>* out) {
  if (chain.steps.empty()) return 0;
  step = std::clamp(step, 0, static_cast<int>(chain.steps.size()) - 1);
  world.SyncCatalog(d, catalog);
  auto push = [out](const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    for (int i = 0; i < 3; ++i) out->push_back(static_cast<float>(from[i]));
    for (int i = 0; i < 3; ++i) out->push_back(static_cast<float>(to[i]));
  };
  int n = 0;
  std::vector<Eigen::Vector3d> pts;
  for (int a = 0; a < world.num_agents(); ++a) {
    control::StepTask task =
        control::BuildStepTask(chain.steps[step], *catalog, a, world.agent(a).scale, {});
    world.AllBodyPoints(d, a, &pts);
    const Eigen::Vector3d& pelvis = pts[static_cast<int>(core::BodyJoint::kPelvis)];
    if (task.get_close) {
      push(pelvis, Eigen::Vector3d(task.walk_point.x(), task.walk_point.y(), 0.0));
      ++n;
    }
    for (const control::ContactTerm& term : task.terms) {
      if (term.type != plan::ContactType::kContact) continue;
      const Eigen::Vector3d& p = pts[static_cast<int>(term.joint)];
      push(p, term.Nearest(p, pts));
      ++n;
    }
  }
  return n;
}

std::string FloatsBase64(const std::vector<float>& floats) {
  return absl::Base64Escape(absl::string_view(reinterpret_cast<const char*>(floats.data()),
                                              floats.size() * sizeof(float)));
}

std::string JsonForScript(const nlohmann::json& j) {
  const std::string text = j.dump();
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out += '\\';
  }
  return out;
}

}  // namespace simhuman::web
