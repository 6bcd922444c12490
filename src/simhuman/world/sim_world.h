#pragma once
/// A loaded simulation: the MuJoCo model and data of one scene with its humans, the index
/// tables controllers need (per-agent joint addresses and body-point sites), and health.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "simhuman/core/body_joint.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/world/embodiment.h"
#include "simhuman/world/health.h"
#include "simhuman/world/humanoid.h"
#include "simhuman/world/model_builder.h"

namespace simhuman::world {

/// Addresses of one agent inside the shared model; table sizes come from its kind and the
/// compiled model. Every humanoid kind's first kHumanoidDofs hinges and actuators are the body's
/// (HumanoidJointNames() order) and its first core::kNumBodyJoints sites the standard points,
/// so controllers of the humanoid body work on every kind; a controller that knows a kind's
/// extra joints (a hand) finds them after those.
struct AgentIndex {
  std::string kind = kDefaultAgentKind;
  int root_qpos = -1;           ///< 7 entries: pos (3), quat wxyz (4)
  int root_qvel = -1;           ///< 6 entries
  std::vector<int> hinge_qpos;  ///< per hinge, actuator order
  std::vector<int> hinge_qvel;
  std::vector<int> actuator;  ///< actuator ids: the agent's span of the model's controls
  std::vector<int> site;      ///< site id per body point (core::BodyJoint id)
  std::vector<int> bodies;    ///< body ids of the humanoid body, pelvis first
  int pelvis_body = -1, head_body = -1, torso_body = -1;
  int left_foot_body = -1, right_foot_body = -1;
  double scale = 1.0;

  int num_actuators() const { return static_cast<int>(actuator.size()); }
  int num_body_points() const { return static_cast<int>(site.size()); }
};

/// Owns mjModel and mjData (freed on destruction). Not thread-safe; planners make their own
/// mjData from `model()`.
class SimWorld {
 public:
  /// Builds the model XML, compiles it and resolves all indices. Errors name the culprit.
  static core::StatusOr<std::unique_ptr<SimWorld>> Create(const core::SceneCatalog& scene,
                                                          const std::vector<AgentSpec>& agents,
                                                          const ModelOptions& options = {});
  /// Compiles MJCF text (helper used by Create and by tests).
  static core::StatusOr<mjModel*> CompileXml(const std::string& xml);

  ~SimWorld();
  SimWorld(const SimWorld&) = delete;
  SimWorld& operator=(const SimWorld&) = delete;

  const mjModel* model() const { return model_; }
  mjModel* mutable_model() { return model_; }
  mjData* data() { return data_; }
  const mjData* data() const { return data_; }
  const core::SceneCatalog& catalog() const { return catalog_; }
  int num_agents() const { return static_cast<int>(agents_.size()); }
  const AgentIndex& agent(int i) const { return agents_[i]; }
  const std::string& xml() const { return xml_; }

  /// One physics step followed by a health check; a non-OK report should end the episode.
  HealthReport Step();

  /// World positions of the 15 standard body points of agent `a` from `d` (after kinematics).
  std::array<Eigen::Vector3d, core::kNumBodyJoints> BodyPoints(const mjData* d, int a) const;
  /// World positions of all body points of agent `a` (its catalog's, in id order) into `out`.
  void AllBodyPoints(const mjData* d, int a, std::vector<Eigen::Vector3d>* out) const;

  /// Copies the poses of movable objects from `d` into `catalog` (ids must match).
  void SyncCatalog(const mjData* d, core::SceneCatalog* catalog) const;

  /// Resets data to the initial state (seated agents seated) and sets every servo target to the
  /// current joint angle.
  void Reset();

 private:
  SimWorld() = default;
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  core::SceneCatalog catalog_;
  std::vector<AgentIndex> agents_;
  std::vector<std::pair<std::string, int>> movable_qpos_;  // object id -> qpos address
  std::vector<std::pair<int, double>> initial_qpos_;       // qpos address -> start value
  std::string xml_;
  HealthMonitor health_;
};

/// Agent `a`'s body hinge angles from `d` into `q` (kHumanoidDofs entries).
void GetHinges(const mjData* d, const AgentIndex& a, double* q);

/// Heading (yaw, radians) of agent `a`'s pelvis forward axis in `d`.
double PelvisYaw(const mjData* d, const AgentIndex& a);

}  // namespace simhuman::world
