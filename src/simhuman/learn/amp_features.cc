#include "simhuman/learn/amp_features.h"

#include <cmath>

namespace simhuman::learn {
namespace {

// indices into world::HumanoidBodyNames() of the key bodies, in feature order
constexpr int kKeyBodies[5] = {8, 5, 14, 11,
                               2};  // left hand, right hand, left foot, right foot, head

}  // namespace

void AmpFeatures(const mjModel* m, const mjData* d, const world::AgentIndex& a, float* out) {
  (void)m;
  const int pb = a.pelvis_body;
  const mjtNum* R = d->xmat + 9 * pb;
  const mjtNum* p = d->xpos + 3 * pb;
  double yaw = world::PelvisYaw(d, a);
  double c = std::cos(yaw), s = std::sin(yaw);
  int k = 0;
  // world vector -> heading frame
  auto put = [&](double x, double y, double z) {
    out[k++] = static_cast<float>(c * x + s * y);
    out[k++] = static_cast<float>(-s * x + c * y);
    out[k++] = static_cast<float>(z);
  };
  out[k++] = static_cast<float>(p[2]);
  put(R[0], R[3], R[6]);
  put(R[2], R[5], R[8]);
  const mjtNum* v = d->qvel + a.root_qvel;
  put(v[0], v[1], v[2]);
  // the free joint's angular velocity is in the pelvis frame
  put(R[0] * v[3] + R[1] * v[4] + R[2] * v[5], R[3] * v[3] + R[4] * v[4] + R[5] * v[5],
      R[6] * v[3] + R[7] * v[4] + R[8] * v[5]);
  for (int j = 0; j < world::kHumanoidDofs; ++j) {
    out[k++] = static_cast<float>(d->qpos[a.hinge_qpos[j]]);
  }
  for (int j = 0; j < world::kHumanoidDofs; ++j) {
    out[k++] = static_cast<float>(d->qvel[a.hinge_qvel[j]]);
  }
  for (int b : kKeyBodies) {
    const mjtNum* x = d->xpos + 3 * a.bodies[b];
    put(x[0] - p[0], x[1] - p[1], x[2] - p[2]);
  }
}

namespace {

void FrameQpos(const world::AgentIndex& a, const ClipFrame& fr, mjtNum* qpos) {
  for (int k = 0; k < 3; ++k) qpos[a.root_qpos + k] = fr.root_pos_m[k];
  for (int k = 0; k < 4; ++k) qpos[a.root_qpos + 3 + k] = fr.root_quat_wxyz[k];
  for (int j = 0; j < world::kHumanoidDofs; ++j) qpos[a.hinge_qpos[j]] = fr.q_rad[j];
}

}  // namespace

void SetStateFromClip(const mjModel* m, const world::AgentIndex& a, const MotionClip& clip,
                      size_t f, mjtNum* qpos, mjtNum* qvel) {
  const size_t n = clip.frames.size();
  size_t f0 = f > 0 ? f - 1 : f, f1 = f + 1 < n ? f + 1 : f;
  std::vector<mjtNum> q0(qpos, qpos + m->nq), q1(qpos, qpos + m->nq), v(m->nv, 0.0);
  FrameQpos(a, clip.frames[f0], q0.data());
  FrameQpos(a, clip.frames[f1], q1.data());
  if (f1 > f0) mj_differentiatePos(m, v.data(), (f1 - f0) / clip.fps, q0.data(), q1.data());
  FrameQpos(a, clip.frames[f], qpos);
  for (int k = 0; k < 6; ++k) qvel[a.root_qvel + k] = v[a.root_qvel + k];
  for (int j = 0; j < world::kHumanoidDofs; ++j) qvel[a.hinge_qvel[j]] = v[a.hinge_qvel[j]];
}

std::vector<float> ClipAmpFeatures(const mjModel* m, const world::AgentIndex& a,
                                   const MotionClip& clip) {
  std::vector<float> out(clip.frames.size() * kAmpFeatureDim);
  mjData* d = mj_makeData(m);
  for (size_t f = 0; f < clip.frames.size(); ++f) {
    SetStateFromClip(m, a, clip, f, d->qpos, d->qvel);
    mj_kinematics(m, d);
    AmpFeatures(m, d, a, out.data() + f * kAmpFeatureDim);
  }
  mj_deleteData(d);
  return out;
}

}  // namespace simhuman::learn
