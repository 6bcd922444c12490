#include "simhuman/control/mpc/getting_up.h"

#include <algorithm>
#include <cmath>

#include "simhuman/world/humanoid.h"

namespace simhuman::control {
namespace {

constexpr double kDeg = M_PI / 180.0;
// a pelvis this far (degrees) or more from upright sits up through a curl first
constexpr double kMinSitUpDeg = 45.0;

int Hinge(const char* name) {
  const auto& names = world::HumanoidJointNames();
  for (int i = 0; i < world::kHumanoidDofs; ++i) {
    if (names[i] == name) return i;
  }
  return -1;
}

void SetBoth(ReferencePose* p, const char* right, const char* left, double deg) {
  p->hinges[Hinge(right)] = deg * kDeg;
  p->hinges[Hinge(left)] = deg * kDeg;
}

Eigen::Quaterniond RootQuat(const ReferencePose& p) {
  return Eigen::Quaterniond(p.root[3], p.root[4], p.root[5], p.root[6]).normalized();
}

void SetRootQuat(const Eigen::Quaterniond& q, ReferencePose* p) {
  p->root[3] = q.w();
  p->root[4] = q.x();
  p->root[5] = q.y();
  p->root[6] = q.z();
}

Eigen::Vector3d HipMiddle(const world::SimWorld& world, int agent, const ReferencePose& p,
                          mjData* scratch) {
  SetAgentPose(world.agent(agent), p, scratch);
  mj_kinematics(world.model(), scratch);
  const auto pts = world.BodyPoints(scratch, agent);
  return 0.5 * (pts[static_cast<int>(core::BodyJoint::kLeftHip)] +
                pts[static_cast<int>(core::BodyJoint::kRightHip)]);
}

// `p` with the trunk pitched forward by `pitch_deg` about the hips (the pelvis turns, the hips
// flex by as much, so the thighs stay where they were), the hip joints kept in place
ReferencePose PitchedAboutHips(const world::SimWorld& world, int agent, ReferencePose p,
                               double pitch_deg, mjData* scratch) {
  const Eigen::Vector3d hips = HipMiddle(world, agent, p, scratch);
  SetRootQuat(RootQuat(p) *
                  Eigen::Quaterniond(Eigen::AngleAxisd(pitch_deg * kDeg, Eigen::Vector3d::UnitY())),
              &p);
  for (const char* n : {"right_hip_y", "left_hip_y"}) p.hinges[Hinge(n)] += pitch_deg * kDeg;
  const Eigen::Vector3d moved = HipMiddle(world, agent, p, scratch) - hips;
  for (int i = 0; i < 3; ++i) p.root[i] -= moved[i];
  return p;
}

}  // namespace

bool TrunkTiltedMoreThan(core::Span<const Eigen::Vector3d> pts, double deg) {
  const Eigen::Vector3d up = pts[static_cast<int>(core::BodyJoint::kHead)] -
                             pts[static_cast<int>(core::BodyJoint::kPelvis)];
  return up.z() < std::cos(deg * kDeg) * up.norm();
}

std::optional<StepTask> EdgeSitBeforeRising(const StepTask& task, double scale) {
  const bool to_stand = task.posture == Posture::kStand || task.posture == Posture::kLean;
  const core::CatalogPart* mattress = task.focus ? task.focus->FindPart("mattress") : nullptr;
  if (!to_stand || !mattress) return std::nullopt;
  StepTask sit;
  sit.label = task.label;
  sit.posture = Posture::kSit;
  sit.focus = task.focus;
  ContactTerm t;
  t.joint = core::BodyJoint::kPelvis;
  t.object = task.focus;
  t.part = mattress;
  t.dir = Eigen::Vector3d::UnitZ();
  t.clearance_m = scale * BodyPointClearance(core::BodyJoint::kPelvis);
  sit.terms.push_back(t);
  return sit;
}

void SitWhereLying(const StepTask& edge_sit_task, const Eigen::Vector3d& pelvis_now,
                   ReferencePose* edge_sit) {
  const core::CatalogObject* bed = edge_sit_task.focus;
  const core::CatalogPart* mattress = bed ? bed->FindPart("mattress") : nullptr;
  if (!mattress) return;
  auto [lo, hi] = core::ShapesBounds(mattress->shapes);
  const Eigen::Vector3d root(edge_sit->root[0], edge_sit->root[1], edge_sit->root[2]);
  const double now_y = bed->pose.ApplyInverse(pelvis_now).y();
  const double y = std::clamp(now_y, lo.y() + 0.2, std::max(lo.y() + 0.2, hi.y() - 0.2));
  const Eigen::Vector3d shift =
      bed->pose.quat * Eigen::Vector3d(0, y - bed->pose.ApplyInverse(root).y(), 0);
  for (int i = 0; i < 3; ++i) edge_sit->root[i] += shift[i];
}

bool LegsHangDown(core::Span<const Eigen::Vector3d> pts, double scale) {
  const double pelvis_z = pts[static_cast<int>(core::BodyJoint::kPelvis)].z();
  for (core::BodyJoint foot : {core::BodyJoint::kLeftFoot, core::BodyJoint::kRightFoot}) {
    if (pts[static_cast<int>(foot)].z() > pelvis_z - 0.3 * scale) return false;
  }
  return true;
}

std::vector<ReferencePose> SitUpKeys(const world::SimWorld& world, int agent, const mjData* d,
                                     mjData* scratch) {
  const world::AgentIndex& a = world.agent(agent);
  const ReferencePose lying = GetAgentPose(a, d);
  // the pitch about the pelvis's own left-right axis that stands its trunk axis upright: about
  // 90 degrees on the back, none sitting
  const Eigen::Quaterniond q = RootQuat(lying);
  const double upright_deg =
      std::atan2((q * Eigen::Vector3d::UnitX()).z(), (q * Eigen::Vector3d::UnitZ()).z()) / kDeg;
  if (upright_deg < kMinSitUpDeg) return {};
  mj_copyData(scratch, world.model(), d);
  // the curl: spine and neck flexed, arms reaching toward the knees; the legs stay as they are
  ReferencePose curl = lying;
  curl.hinges[Hinge("abdomen_y")] = 60 * kDeg;
  curl.hinges[Hinge("abdomen_x")] = 0;
  curl.hinges[Hinge("abdomen_z")] = 0;
  curl.hinges[Hinge("neck_y")] = 45 * kDeg;
  SetBoth(&curl, "right_shoulder_y", "left_shoulder_y", 70);
  SetBoth(&curl, "right_shoulder_x", "left_shoulder_x", 5);
  SetBoth(&curl, "right_elbow", "left_elbow", 10);
  // sitting up: the pelvis turns upright about the hips (to 15 degrees back, the spine's lean
  // forward on top), the thighs stay where they are
  ReferencePose sat = PitchedAboutHips(world, agent, curl, upright_deg - 15, scratch);
  sat.hinges[Hinge("abdomen_y")] = 25 * kDeg;
  sat.hinges[Hinge("neck_y")] = 15 * kDeg;
  SetBoth(&sat, "right_shoulder_y", "left_shoulder_y", 45);
  return {curl, sat};
}

}  // namespace simhuman::control
