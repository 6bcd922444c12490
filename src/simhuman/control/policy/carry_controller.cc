#include "simhuman/control/policy/carry_controller.h"

#include <torch/torch.h>

#include <algorithm>
#include <array>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/world/model_builder.h"

namespace simhuman::control {

struct CarryPolicyController::Impl {
  const world::SimWorld* world = nullptr;
  int agent = 0;
  Controller* other = nullptr;
  CarryIndex ix;
  CarryParams params;
  CarryState state;
  LoadedPolicy policy;
  mjData* scratch = nullptr;  // keyframe IK
  bool carrying = false;
  int step = -1;
  int box_geom = -1;
  std::array<float, kCarryObsDim> obs{};
  std::array<double, kWalkActDim> ctrl{};

  // the step's box geom (the object's only geom, a box); errors name the object
  absl::Status FindBox(const core::CatalogObject& object) {
    const mjModel* m = world->model();
    const std::string geom = "obj/" + object.id + "/0";
    box_geom = mj_name2id(m, mjOBJ_GEOM, geom.c_str());
    const int body = mj_name2id(m, mjOBJ_BODY, world::ObjectBodyName(object.id).c_str());
    if (box_geom < 0 || body < 0 || m->geom_type[box_geom] != mjGEOM_BOX ||
        m->geom_bodyid[box_geom] != body || object.type != "box") {
      return absl::UnimplementedError("carrying '" + object.id + "' (a " + object.type +
                                      "): the carry policy carries boxes only");
    }
    return absl::OkStatus();
  }
};

core::StatusOr<std::unique_ptr<CarryPolicyController>> CarryPolicyController::Load(
    const std::string& path, const world::SimWorld* world, int agent, Controller* other) {
  auto impl = std::make_unique<Impl>();
  impl->world = world;
  impl->agent = agent;
  impl->other = other;
  SH_ASSIGN_OR_RETURN(impl->ix, MakeCarryIndex(*world, agent));
  core::StatusOr<LoadedPolicy> p = LoadPolicyFile(path);
  if (!p.ok()) return core::Annotate(p.status(), "carry policy '" + path + "'");
  if (p->meta.task != "carry" || p->meta.obs_dim != kCarryObsDim ||
      p->meta.act_dim != kCarryActDim) {
    return absl::InvalidArgumentError("carry policy '" + path + "' holds a '" + p->meta.task +
                                      "' policy (obs " + std::to_string(p->meta.obs_dim) +
                                      "), not a carry policy (obs " + std::to_string(kCarryObsDim) +
                                      ")");
  }
  if (p->meta.carry_grip) {
    return absl::UnimplementedError(
        "carry policy '" + path +
        "' was trained with gripping hands (carry_grip); simhuman run cannot drive the grip "
        "yet: evaluate it with simhuman eval --suite carry");
  }
  core::StatusOr<WalkParams> gait = WalkGait(p->meta.variant);
  if (!gait.ok()) return core::Annotate(gait.status(), "carry policy '" + path + "'");
  impl->params.walk = *gait;
  impl->policy = std::move(*p);
  impl->policy.actor->eval();
  impl->scratch = mj_makeData(world->model());
  return std::unique_ptr<CarryPolicyController>(new CarryPolicyController(std::move(impl)));
}

CarryPolicyController::CarryPolicyController(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

CarryPolicyController::~CarryPolicyController() {
  if (impl_ && impl_->scratch) mj_deleteData(impl_->scratch);
}

std::string CarryPolicyController::name() const { return "carry-policy+" + impl_->other->name(); }

absl::Status CarryPolicyController::Act(const Observation& obs) {
  Impl& m = *impl_;
  if (!obs.task || !obs.task->carry_object) {
    m.carrying = false;
    return m.other->Act(obs);
  }
  if (!obs.task->carry_goal) {
    return absl::UnimplementedError("step " + std::to_string(obs.step_index + 1) + " holds '" +
                                    obs.task->carry_object->id +
                                    "' without a destination: the carry policy carries objects "
                                    "to a floor point or beside an object");
  }
  const mjModel* model = m.world->model();
  if (!m.carrying || m.step != obs.step_index) {
    SH_RETURN_IF_ERROR(m.FindBox(*obs.task->carry_object));
    CarryBox box = ReadCarryBox(model, obs.data, m.box_geom);
    m.state = CarryState();
    BeginCarry(m.params, m.ix, obs.data, box, obs.task->carry_goal->pos.head<2>(), &m.state);
    UpdateWalkCommand(m.params.walk, obs.data, m.ix.walk, &m.state.walk);
    m.carrying = true;
    m.step = obs.step_index;
  } else {
    CarryBox box = ReadCarryBox(model, obs.data, m.box_geom);
    UpdateCarry(m.params, model, m.scratch, obs.data, m.ix, box, &m.state);
  }
  CarryBox box = ReadCarryBox(model, obs.data, m.box_geom);
  CarryObservation(obs.data, m.ix, m.state, box, m.obs.data());
  torch::NoGradGuard no_grad;
  torch::Tensor x = torch::from_blob(m.obs.data(), {1, kCarryObsDim});
  torch::Tensor a = m.policy.actor->forward(m.policy.norm.Normalize(x)).contiguous();
  CarryTargets(m.ix, m.state, a.data_ptr<float>(), m.ctrl.data());
  return absl::OkStatus();
}

void CarryPolicyController::Targets(double time_s, core::Span<double> ctrl) const {
  if (!impl_->carrying) return impl_->other->Targets(time_s, ctrl);
  SH_CHECK(ctrl.size() >= kWalkActDim, "a carrying agent has the humanoid body's actuators first");
  std::copy(impl_->ctrl.begin(), impl_->ctrl.end(), ctrl.data());
}

double CarryPolicyController::control_period_s() const {
  return impl_->carrying ? kWalkPolicyDt : impl_->other->control_period_s();
}

double CarryPolicyController::physics_timestep_s() const {
  return impl_->carrying ? kWalkPhysicsDt : impl_->other->physics_timestep_s();
}

bool CarryPolicyController::carrying() const { return impl_->carrying; }
const CarryState& CarryPolicyController::state() const { return impl_->state; }

}  // namespace simhuman::control
