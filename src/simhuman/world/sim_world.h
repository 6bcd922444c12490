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
#include "simhuman/world/health.h"
#include "simhuman/world/humanoid.h"
#include "simhuman/world/model_builder.h"

namespace simhuman::world {

/// Addresses of one humanoid inside the shared model.
struct AgentIndex {
  int root_qpos = -1;  ///< 7 entries: pos (3), quat wxyz (4)
  int root_qvel = -1;  ///< 6 entries
  std::array<int, kHumanoidDofs> hinge_qpos{};
  std::array<int, kHumanoidDofs> hinge_qvel{};
  std::array<int, kHumanoidDofs> actuator{};
  std::array<int, core::kNumBodyJoints> site{};
  std::vector<int> bodies;  ///< body ids, pelvis first
  int pelvis_body = -1, head_body = -1, torso_body = -1;
  int left_foot_body = -1, right_foot_body = -1;
  double scale = 1.0;
};

/// Owns mjModel and mjData (freed on destruction). Not thread-safe; planners make their own
/// mjData from `model()`.
class SimWorld {
 public:
  /// Builds the model XML, compiles it and resolves all indices. Errors name the culprit.
  static core::StatusOr<std::unique_ptr<SimWorld>> Create(const core::SceneCatalog& scene,
                                                          const std::vector<AgentPlacement>& agents,
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

  /// World positions of the 15 body points of agent `a` from `d` (after kinematics).
  std::array<Eigen::Vector3d, core::kNumBodyJoints> BodyPoints(const mjData* d, int a) const;

  /// Copies the poses of movable objects from `d` into `catalog` (ids must match).
  void SyncCatalog(const mjData* d, core::SceneCatalog* catalog) const;

  /// Resets data to the initial state and sets every servo target to the current joint angle.
  void Reset();

 private:
  SimWorld() = default;
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  core::SceneCatalog catalog_;
  std::vector<AgentIndex> agents_;
  std::vector<std::pair<std::string, int>> movable_qpos_;  // object id -> qpos address
  std::string xml_;
  HealthMonitor health_;
};

/// Agent `a`'s hinge angles from `d` into `q` (28 entries).
void GetHinges(const mjData* d, const AgentIndex& a, double* q);

/// Heading (yaw, radians) of agent `a`'s pelvis forward axis in `d`.
double PelvisYaw(const mjData* d, const AgentIndex& a);

}  // namespace simhuman::world
