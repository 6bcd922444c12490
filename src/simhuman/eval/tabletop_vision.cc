#include "simhuman/eval/tabletop_vision.h"

#include <algorithm>
#include <chrono>

#include "absl/strings/str_cat.h"
#include "simhuman/perceive/vision/detect.h"

namespace simhuman::eval {

namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

int IndexOf(const std::vector<std::string>& names, const std::string& s) {
  const auto it = std::find(names.begin(), names.end(), s);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

std::string Describe(const perceive::ObjectEstimate& e) {
  return perceive::VisionColours()[e.colour] + " " + perceive::VisionShapes()[e.shape];
}

// the estimate of the catalog object `id` (by its shape and colour), most confident first
core::StatusOr<int> Find(const core::SceneCatalog& catalog, const std::string& id,
                         const std::vector<perceive::ObjectEstimate>& est) {
  const core::CatalogObject* o = catalog.Find(id);
  if (o == nullptr) return absl::NotFoundError("no object '" + id + "' in the scene");
  const int shape = IndexOf(perceive::VisionShapes(), o->type);
  const int colour = IndexOf(perceive::VisionColours(), o->color);
  int best = -1;
  for (size_t i = 0; i < est.size(); ++i) {
    if (est[i].shape != shape || est[i].colour != colour) continue;
    if (best < 0 || est[i].confidence > est[best].confidence) best = static_cast<int>(i);
  }
  if (best >= 0) return best;
  std::string seen;
  for (const perceive::ObjectEstimate& e : est) seen += (seen.empty() ? "" : ", ") + Describe(e);
  return absl::NotFoundError(
      absl::StrCat("vision: the ", o->color, " ", o->type, " (", id,
                   ") is not seen at task planning; seen: ", seen.empty() ? "nothing" : seen));
}

}  // namespace

core::StatusOr<std::unique_ptr<TabletopVision>> TabletopVision::Create(
    const std::string& model_path, const mjModel* first_model, const VisionLoopOptions& o) {
  std::unique_ptr<TabletopVision> v(new TabletopVision());
  v->o_ = o;
  SH_ASSIGN_OR_RETURN(v->model_, perceive::VisionModel::Load(model_path));
  perceive::VisionModel::SetThreads(1);  // the pipeline runs on one thread
  SH_ASSIGN_OR_RETURN(v->camera_,
                      perceive::HeadCamera::Create(first_model, v->model_->width, v->model_->height,
                                                   v->model_->fovy_deg));
  return v;
}

core::Status TabletopVision::Begin(world::SimWorld& world, const core::SceneCatalog& catalog,
                                   const std::string& object_id, const std::string& support_id,
                                   control::manip::TabletopGoal* goal) {
  world_ = &world;
  SH_RETURN_IF_ERROR(camera_->SetModel(world.model()));
  queue_.clear();
  arrived_.clear();
  held_ = false;
  const mjData* d = world.data();
  next_t_ = d->time;
  // task planning: one frame of the table
  const perceive::PinholeCamera cam = camera_->Aim(world, d, 0, perceive::PlanningGaze());
  std::vector<uint8_t> rgb;
  auto t0 = Clock::now();
  SH_RETURN_IF_ERROR(camera_->Capture(d, cam, &rgb));
  render_s_ += Since(t0);
  t0 = Clock::now();
  const std::vector<perceive::ObjectEstimate> est = model_->Estimate(rgb, cam);
  vision_s_ += Since(t0);
  ++frames_;
  SH_ASSIGN_OR_RETURN(moved_, Find(catalog, object_id, est));
  planned_ = est[moved_];
  tracker_.Reset(est);
  height_m_ = planned_.height_m;
  goal->planned_pos = planned_.centre - 0.5 * planned_.height_m * planned_.up;
  goal->half_width_m = 0.5 * planned_.width_m;
  goal->height_m =
      goal->shape == control::manip::GraspShape::kSphere ? planned_.width_m : planned_.height_m;
  if (!support_id.empty()) {
    SH_ASSIGN_OR_RETURN(const int s, Find(catalog, support_id, est));
    goal->target = est[s].centre + 0.5 * est[s].height_m * est[s].up;
  }
  target_ = goal->target;
  goal->observe = [this](const mjData* dd, bool held) { return View(dd, held); };
  return absl::OkStatus();
}

control::manip::ObjectView TabletopVision::ToView(const perceive::ObjectEstimate& e) const {
  control::manip::ObjectView v;
  v.centre = e.centre;
  v.up = e.shape == 2 ? Eigen::Vector3d::UnitZ() : e.up;
  v.base = e.centre - 0.5 * height_m_ * v.up;
  v.yaw_rad = e.yaw_rad;
  return v;
}

core::Status TabletopVision::OnStep(const mjData* d) {
  if (world_ == nullptr || d->time + 1e-9 < next_t_) return absl::OkStatus();
  next_t_ += 1.0 / o_.rate_hz;
  // look at the object until it is held, then at where it goes
  const Eigen::Vector3d gaze = held_ ? target_ : tracker_.objects()[moved_].centre;
  const perceive::PinholeCamera cam = camera_->Aim(*world_, d, 0, gaze);
  std::vector<uint8_t> rgb;
  auto t0 = Clock::now();
  SH_RETURN_IF_ERROR(camera_->Capture(d, cam, &rgb));
  render_s_ += Since(t0);
  t0 = Clock::now();
  tracker_.Update(model_->Estimate(rgb, cam));
  vision_s_ += Since(t0);
  ++frames_;
  queue_.push_back({d->time, tracker_.objects()[moved_]});
  // estimates arrive delay_s after their frame
  while (!queue_.empty() && queue_.front().t + o_.delay_s <= d->time + 1e-9) {
    arrived_.push_back(queue_.front().e);
    queue_.pop_front();
    if (static_cast<int>(arrived_.size()) > std::max(1, o_.smooth_frames)) arrived_.pop_front();
  }
  return absl::OkStatus();
}

control::manip::ObjectView TabletopVision::View(const mjData* /*d*/, bool held) const {
  held_ = held_ || held;
  if (!held || arrived_.empty()) return ToView(planned_);
  // per-axis medians of the centre and the up axis over the arrived frames
  perceive::ObjectEstimate e = arrived_.back();
  std::vector<double> v(arrived_.size());
  for (int k = 0; k < 6; ++k) {
    for (size_t i = 0; i < arrived_.size(); ++i) {
      v[i] = k < 3 ? arrived_[i].centre[k] : arrived_[i].up[k - 3];
    }
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    (k < 3 ? e.centre[k] : e.up[k - 3]) = v[v.size() / 2];
  }
  if (e.up.norm() > 1e-6) e.up.normalize();
  return ToView(e);
}

}  // namespace simhuman::eval
