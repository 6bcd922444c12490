#include "simhuman/learn/tasks.h"

#include "simhuman/learn/carry_env.h"
#include "simhuman/learn/grasp_env.h"
#include "simhuman/learn/place_env.h"
#include "simhuman/learn/reach_env.h"
#include "simhuman/learn/walk_env.h"

namespace simhuman::learn {

const std::vector<TaskDef>& Tasks() {
  static const std::vector<TaskDef> tasks = {
      {"walk", "walk to a target stand point and stop there facing a heading",
       [](int envs, const TaskOptions& o) -> core::StatusOr<std::unique_ptr<VecTask>> {
         WalkRewardWeights w;
         w.gait_legs = o.walk_gait_weight;
         w.gait_legs_width = o.walk_gait_width;
         w.foot_slip = o.walk_foot_slip_weight;
         SH_ASSIGN_OR_RETURN(
             std::unique_ptr<WalkTask> t,
             WalkTask::Create(
                 envs, o.solver != "newton" ? WalkPhysicsSolver::kPgs : WalkPhysicsSolver::kNewton,
                 o.body_scales, o.walk_gait, w));
         t->set_route_share(o.walk_route_share);
         return std::unique_ptr<VecTask>(std::move(t));
       },
       "", true},
      {"reach", "a toy point-reaching task (tests of the learning stack)",
       [](int envs, const TaskOptions&) -> core::StatusOr<std::unique_ptr<VecTask>> {
         return std::unique_ptr<VecTask>(new ReachTask(envs));
       },
       "", false},
      {"carry", "walk to a box, lift it, carry it to a destination, put it down, step back",
       [](int envs, const TaskOptions& o) -> core::StatusOr<std::unique_ptr<VecTask>> {
         SH_ASSIGN_OR_RETURN(std::unique_ptr<CarryTask> t,
                             CarryTask::Create(envs, o.walk_gait, o.carry_grip));
         t->set_held_start_fraction(o.carry_held_start_frac);
         t->set_put_down_start_fraction(o.carry_put_down_start_frac);
         return std::unique_ptr<VecTask>(std::move(t));
       },
       "walk", false},
      {"carry-lift",
       "the carry's lift alone: squat at the box, press both hands on it, rise holding it; "
       "success is the box up and level between both hands of a standing human",
       [](int envs, const TaskOptions& o) -> core::StatusOr<std::unique_ptr<VecTask>> {
         SH_ASSIGN_OR_RETURN(std::unique_ptr<CarryTask> t,
                             CarryTask::Create(envs, o.walk_gait, o.carry_grip, CarryStage::kLift));
         return std::unique_ptr<VecTask>(std::move(t));
       },
       "walk",
       false,
       {"carry"}},
      {"carry-deliver",
       "the carry's delivery alone: holding the box, walk to the destination and put it down; "
       "success is the box resting there within 0.2 m and the human standing",
       [](int envs, const TaskOptions& o) -> core::StatusOr<std::unique_ptr<VecTask>> {
         SH_ASSIGN_OR_RETURN(
             std::unique_ptr<CarryTask> t,
             CarryTask::Create(envs, o.walk_gait, o.carry_grip, CarryStage::kDeliver));
         return std::unique_ptr<VecTask>(std::move(t));
       },
       "walk",
       false,
       {"carry"}},
      {"grasp",
       "DASH's grasp stage: close a dexterous hand around a table object and hold it through a "
       "drop test",
       [](int envs, const TaskOptions&) -> core::StatusOr<std::unique_ptr<VecTask>> {
         SH_ASSIGN_OR_RETURN(std::unique_ptr<GraspTask> t, GraspTask::Create(envs));
         return std::unique_ptr<VecTask>(std::move(t));
       },
       "", false},
      {"grasp-residual",
       "the grasp task as a correction added to the scripted grasp's action (DASH's stage "
       "started from a training-free grasp)",
       [](int envs, const TaskOptions&) -> core::StatusOr<std::unique_ptr<VecTask>> {
         SH_ASSIGN_OR_RETURN(std::unique_ptr<GraspTask> t, GraspTask::Create(envs, true));
         return std::unique_ptr<VecTask>(std::move(t));
       },
       "", false},
      {"place",
       "DASH's placing stage: corrections to the scripted placing's segments (aim, upright, "
       "descent speed), each episode a generated table scene run through the whole pipeline",
       [](int envs, const TaskOptions&) -> core::StatusOr<std::unique_ptr<VecTask>> {
         SH_ASSIGN_OR_RETURN(std::unique_ptr<PlaceTask> t, PlaceTask::Create(envs));
         return std::unique_ptr<VecTask>(std::move(t));
       },
       "", false},
  };
  return tasks;
}

core::StatusOr<const TaskDef*> FindTask(std::string_view name) {
  std::string valid;
  for (const TaskDef& t : Tasks()) {
    if (t.name == name) return &t;
    valid += (valid.empty() ? "" : ", ") + t.name;
  }
  return absl::InvalidArgumentError("unknown task '" + std::string(name) + "'; valid: " + valid);
}

}  // namespace simhuman::learn
