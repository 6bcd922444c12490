#include "simhuman/world/sim_world.h"

#include <cmath>
#include <cstring>

namespace simhuman::world {
namespace {

int Find(const mjModel* m, mjtObj type, const std::string& name) {
  return mj_name2id(m, type, name.c_str());
}

// the addresses of agent `index` of kind `spec.kind`, looked up by name in the compiled model
core::StatusOr<AgentIndex> IndexAgent(const mjModel* m, const AgentSpec& spec, int index) {
  SH_ASSIGN_OR_RETURN(const Embodiment* kind, FindEmbodiment(spec.kind));
  const HumanoidSpec hs = MakeHumanoidSpec(*kind, spec.scale, index);
  const std::string& p = hs.prefix;
  AgentIndex ix;
  ix.kind = kind->name;
  ix.scale = spec.scale;
  int root = Find(m, mjOBJ_JOINT, p + "root");
  if (root < 0) return absl::InternalError("humanoid root joint missing");
  ix.root_qpos = m->jnt_qposadr[root];
  ix.root_qvel = m->jnt_dofadr[root];
  for (const std::string& name : HumanoidJointNames(hs)) {
    int jid = Find(m, mjOBJ_JOINT, p + name);
    int aid = Find(m, mjOBJ_ACTUATOR, p + name);
    if (jid < 0 || aid < 0) return absl::InternalError("humanoid joint missing: " + p + name);
    ix.hinge_qpos.push_back(m->jnt_qposadr[jid]);
    ix.hinge_qvel.push_back(m->jnt_dofadr[jid]);
    ix.actuator.push_back(aid);
  }
  for (const BodyPointSite& point : HumanoidBodyPoints(hs)) {
    int sid = Find(m, mjOBJ_SITE, p + point.site);
    if (sid < 0) return absl::InternalError("humanoid site missing: " + p + point.site);
    ix.site.push_back(sid);
  }
  for (const auto& b : HumanoidBodyNames()) ix.bodies.push_back(Find(m, mjOBJ_BODY, p + b));
  ix.pelvis_body = ix.bodies[0];
  ix.torso_body = Find(m, mjOBJ_BODY, p + "torso");
  ix.head_body = Find(m, mjOBJ_BODY, p + "head");
  ix.left_foot_body = Find(m, mjOBJ_BODY, p + "left_foot");
  ix.right_foot_body = Find(m, mjOBJ_BODY, p + "right_foot");
  return ix;
}

}  // namespace

core::StatusOr<mjModel*> SimWorld::CompileXml(const std::string& xml) {
  InstallMujocoHandlers();
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  const char* kName = "simhuman_model.xml";
  if (mj_makeEmptyFileVFS(&vfs, kName, static_cast<int>(xml.size())) != 0) {
    return absl::InternalError("cannot create the in-memory model file");
  }
  int idx = mj_findFileVFS(&vfs, kName);
  std::memcpy(vfs.filedata[idx], xml.data(), xml.size());
  char err[1024] = {0};
  mjModel* m = mj_loadXML(kName, &vfs, err, sizeof(err));
  mj_deleteVFS(&vfs);
  if (!m) return absl::InvalidArgumentError(std::string("MuJoCo rejected the model: ") + err);
  return m;
}

core::StatusOr<std::unique_ptr<SimWorld>> SimWorld::Create(const core::SceneCatalog& scene,
                                                           const std::vector<AgentSpec>& agents,
                                                           const ModelOptions& options) {
  if (agents.empty()) return absl::InvalidArgumentError("a scene needs at least one human");
  SH_ASSIGN_OR_RETURN(std::string xml, BuildModelXml(scene, agents, options));
  SH_ASSIGN_OR_RETURN(mjModel * m, CompileXml(xml));
  std::unique_ptr<SimWorld> w(new SimWorld());
  w->model_ = m;
  w->data_ = mj_makeData(m);
  w->catalog_ = scene;
  w->catalog_.agents.clear();  // the agents as built, whatever the scene's catalog said
  for (const AgentSpec& a : agents) {
    SH_ASSIGN_OR_RETURN(const Embodiment* kind, FindEmbodiment(a.kind));
    w->catalog_.agents.push_back(MakeCatalogAgent(*kind, a.scale));
  }
  w->xml_ = std::move(xml);
  for (size_t a = 0; a < agents.size(); ++a) {
    SH_ASSIGN_OR_RETURN(AgentIndex ix, IndexAgent(m, agents[a], static_cast<int>(a)));
    w->agents_.push_back(std::move(ix));
    // a seated human starts (and resets) with hips and knees flexed (not through qpos0: MuJoCo
    // measures hinge angles from it)
    if (agents[a].seated_pelvis_z > 0) {
      const std::string p = AgentPrefix(static_cast<int>(a));
      for (const auto& [name, angle] : SeatedHinges()) {
        const int j = Find(m, mjOBJ_JOINT, p + name);
        if (j >= 0) w->initial_qpos_.emplace_back(m->jnt_qposadr[j], angle);
      }
    }
  }
  for (const auto& o : scene.objects) {
    if (!o.movable) continue;
    int jid = mj_name2id(m, mjOBJ_JOINT, ("obj/" + o.id + "/root").c_str());
    if (jid >= 0) w->movable_qpos_.emplace_back(o.id, m->jnt_qposadr[jid]);
  }
  w->Reset();
  return w;
}

SimWorld::~SimWorld() {
  if (data_) mj_deleteData(data_);
  if (model_) mj_deleteModel(model_);
}

void SimWorld::Reset() {
  mj_resetData(model_, data_);
  for (const auto& [adr, value] : initial_qpos_) data_->qpos[adr] = value;
  for (const AgentIndex& a : agents_) {
    for (int j = 0; j < a.num_actuators(); ++j) {
      data_->ctrl[a.actuator[j]] = data_->qpos[a.hinge_qpos[j]];
    }
  }
  mj_forward(model_, data_);
  health_.Reset(data_);
}

HealthReport SimWorld::Step() {
  mj_step(model_, data_);
  return health_.Check(model_, data_);
}

std::array<Eigen::Vector3d, core::kNumBodyJoints> SimWorld::BodyPoints(const mjData* d,
                                                                       int a) const {
  std::array<Eigen::Vector3d, core::kNumBodyJoints> out;
  for (int i = 0; i < core::kNumBodyJoints; ++i) {
    const mjtNum* x = d->site_xpos + 3 * agents_[a].site[i];
    out[i] = Eigen::Vector3d(x[0], x[1], x[2]);
  }
  return out;
}

void SimWorld::AllBodyPoints(const mjData* d, int a, std::vector<Eigen::Vector3d>* out) const {
  const AgentIndex& ix = agents_[a];
  out->resize(ix.site.size());
  for (size_t i = 0; i < ix.site.size(); ++i) {
    const mjtNum* x = d->site_xpos + 3 * ix.site[i];
    (*out)[i] = Eigen::Vector3d(x[0], x[1], x[2]);
  }
}

void SimWorld::SyncCatalog(const mjData* d, core::SceneCatalog* catalog) const {
  for (const auto& [id, adr] : movable_qpos_) {
    core::CatalogObject* o = catalog->Find(id);
    if (!o) continue;
    const mjtNum* q = d->qpos + adr;
    o->pose.pos = Eigen::Vector3d(q[0], q[1], q[2]);
    o->pose.quat = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized();
  }
}

void GetHinges(const mjData* d, const AgentIndex& a, double* q) {
  for (int j = 0; j < kHumanoidDofs; ++j) q[j] = d->qpos[a.hinge_qpos[j]];
}

double PelvisYaw(const mjData* d, const AgentIndex& a) {
  const mjtNum* R = d->xmat + 9 * a.pelvis_body;
  return std::atan2(R[3], R[0]);  // forward axis (first column) projected on the floor
}

}  // namespace simhuman::world
