#include "simhuman/eval/tabletop_vision.h"

#include <algorithm>
#include <chrono>

#include "absl/strings/str_cat.h"
#include "simhuman/perceive/touch.h"
#include "simhuman/perceive/vision/detect.h"
#include "simhuman/world/scene.h"

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

core::Status TabletopVision::Look(const world::SimWorld& world, const mjData* d,
                                  const Eigen::Vector3d& gaze,
                                  const perceive::SilhouetteOptions& fit, PlanningLook* look) {
  look->cam = camera_->Aim(world, d, 0, gaze);
  auto t0 = Clock::now();
  SH_RETURN_IF_ERROR(camera_->Capture(d, look->cam, &look->rgb));
  render_s_ += Since(t0);
  t0 = Clock::now();
  look->est = model_->Estimate(look->rgb, look->cam);
  vision_s_ += Since(t0);
  look->fits.assign(look->est.size(), perceive::SilhouetteFit());
  if (o_.silhouette) {
    t0 = Clock::now();
    look->fits =
        perceive::FitRestingSilhouettes(look->rgb, look->cam, model_->colours(), fit, &look->est);
    fit_s_ += Since(t0);
  }
  ++frames_;
  return absl::OkStatus();
}

core::Status TabletopVision::LookAtTable(const world::SimWorld& world, const mjData* d,
                                         const perceive::SilhouetteOptions& fit,
                                         std::vector<perceive::ObjectEstimate>* est,
                                         std::vector<perceive::SilhouetteFit>* fits) {
  PlanningLook first;
  SH_RETURN_IF_ERROR(Look(world, d, perceive::PlanningGaze(), fit, &first));
  *est = first.est;
  *fits = first.fits;
  if (!o_.second_look) return absl::OkStatus();
  // objects the frame's edge cuts are not estimated (vision_model.h): look at each (the
  // largest first, at most two), aiming where its blob's centre meets the table's top
  std::vector<perceive::Blob> blobs = perceive::FindBlobs(
      first.rgb, first.cam.width, first.cam.height, model_->colours(), model_->min_pixels);
  const int w = first.cam.width, h = first.cam.height;
  int looks = 0;
  for (const perceive::Blob& b : blobs) {
    if (looks == 2) break;
    if (b.x0 > 0 && b.y0 > 0 && b.x1 < w - 1 && b.y1 < h - 1) continue;
    const Eigen::Vector3d ray = first.cam.Ray(b.cu, b.cv);
    if (ray.z() > -1e-3) continue;
    const double s = (fit.table_z - first.cam.eye.z()) / ray.z();
    if (s <= 0) continue;
    PlanningLook again;
    SH_RETURN_IF_ERROR(Look(world, d, first.cam.eye + s * ray, fit, &again));
    ++looks;
    for (size_t i = 0; i < again.est.size(); ++i) {
      const perceive::ObjectEstimate& e = again.est[i];
      const bool known =
          std::any_of(est->begin(), est->end(), [&](const perceive::ObjectEstimate& k) {
            return k.colour == e.colour && k.shape == e.shape &&
                   (k.centre - e.centre).norm() < o_.same_object_m;
          });
      if (known) continue;
      est->push_back(e);
      fits->push_back(again.fits[i]);
    }
  }
  return absl::OkStatus();
}

core::Status TabletopVision::Begin(world::SimWorld& world, const core::SceneCatalog& catalog,
                                   const std::string& object_id, const std::string& support_id,
                                   control::manip::TabletopGoal* goal, int hand_body) {
  world_ = &world;
  hand_body_ = hand_body;
  object_body_ = goal->object_body;
  touch_.clear();
  hand_geom_ = perceive::SubtreeGeoms(world.model(), hand_body_);
  in_hand_.clear();
  held_since_ = 0;
  anchor_.reset();
  prior_c_.reset();
  prior_up_.reset();
  SH_RETURN_IF_ERROR(camera_->SetModel(world.model()));
  queue_.clear();
  arrived_.clear();
  held_ = false;
  const mjData* d = world.data();
  next_t_ = d->time;
  // task planning: one frame of the table, and a second look at what its edge cuts
  perceive::SilhouetteOptions fit = o_.silhouette_fit;
  // the table's top: the fixed surroundings the human sits in (as a place task's location)
  for (const core::CatalogObject& obj : catalog.objects) {
    if (obj.type == "table") fit.table_z = world::WorldBounds(obj).second.z();
  }
  std::vector<perceive::ObjectEstimate> est;
  std::vector<perceive::SilhouetteFit> fits;
  SH_RETURN_IF_ERROR(LookAtTable(world, d, fit, &est, &fits));
  SH_ASSIGN_OR_RETURN(moved_, Find(catalog, object_id, est));
  planned_ = est[moved_];
  moved_fit_ = fits[moved_];
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
  v.estimated = true;
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
  const std::vector<perceive::ObjectEstimate> est = model_->Estimate(rgb, cam);
  tracker_.Update(est);
  vision_s_ += Since(t0);
  ++frames_;
  Timed f;
  f.t = d->time;
  f.e = tracker_.objects()[moved_];
  if (hand_body_ >= 0) {
    f.hand_pos = Eigen::Vector3d(d->xpos + 3 * hand_body_);
    f.hand_rot =
        Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * hand_body_);
    // once the object's place in the hand is known, it is the estimate of its colour nearest
    // to where the hand holds it (the tracker may give its identity to a neighbour it passes)
    f.in_hand = !anchor_;
    if (anchor_) {
      const Eigen::Vector3d at = f.hand_rot * *anchor_ + f.hand_pos;
      double best = o_.in_hand_gate_m;
      for (const perceive::ObjectEstimate& e : est) {
        const double dist = (e.centre - at).norm();
        if (e.colour == planned_.colour && dist < best) {
          best = dist;
          f.e = e;
          f.in_hand = true;
        }
      }
    }
  }
  if (o_.touch)
    f.touch = perceive::HandTouch(world_->model(), d, hand_geom_, hand_body_, object_body_);
  queue_.push_back(f);
  // estimates arrive delay_s after their frame
  while (!queue_.empty() && queue_.front().t + o_.delay_s <= d->time + 1e-9) {
    const Timed& a = queue_.front();
    arrived_.push_back(a.e);
    touch_ = a.touch;
    if (static_cast<int>(arrived_.size()) > std::max(1, o_.smooth_frames)) arrived_.pop_front();
    if (a.in_hand && o_.in_hand_frames > 0) {
      in_hand_.push_back({a.t, a.hand_rot.transpose() * (a.e.centre - a.hand_pos),
                          a.hand_rot.transpose() * a.e.up, a.hand_rot, a.hand_pos});
      if (static_cast<int>(in_hand_.size()) > o_.in_hand_frames) in_hand_.pop_front();
    }
    queue_.pop_front();
  }
  return absl::OkStatus();
}

control::manip::ObjectView TabletopVision::GraspView(const mjData* d) const {
  perceive::ObjectEstimate e = planned_;
  if (!o_.touch || !o_.touch_grasp || planned_.shape == 2) return ToView(e);
  // the hand's touch now (a tactile sense, read with the hand's control: no camera delay)
  const std::vector<perceive::TouchContact> felt =
      perceive::HandTouch(world_->model(), d, hand_geom_, hand_body_, object_body_);
  if (felt.empty()) return ToView(e);
  const Eigen::Matrix3d r =
      Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * hand_body_);
  const Eigen::Vector3d p(d->xpos + 3 * hand_body_);
  std::vector<perceive::TouchContact> world_touch;
  for (const perceive::TouchContact& c : felt)
    world_touch.push_back({r * c.point + p, r * c.normal});
  perceive::RefineHeldByTouch(world_touch, 0.5 * planned_.width_m, o_.touch_refine, &e.centre,
                              &e.up);
  return ToView(e);
}

namespace {

// per-axis medians of the centres and up axes of `frames` (in the hand's frame)
void MedianInHand(const std::vector<const TabletopVision::InHand*>& frames, Eigen::Vector3d* c,
                  Eigen::Vector3d* up) {
  std::vector<double> v(frames.size());
  for (int k = 0; k < 6; ++k) {
    for (size_t i = 0; i < frames.size(); ++i)
      v[i] = k < 3 ? frames[i]->centre[k] : frames[i]->up[k - 3];
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    (k < 3 ? (*c)[k] : (*up)[k - 3]) = v[v.size() / 2];
  }
}

}  // namespace

control::manip::ObjectView TabletopVision::View(const mjData* d, bool held) const {
  if (held && !held_) held_since_ = d->time;
  held_ = held_ || held;
  if (!held) return GraspView(d);
  if (arrived_.empty()) return ToView(planned_);
  // in the hand's frame: the frames since the grip closed, carried by the hand's pose now
  std::vector<const InHand*> use;
  for (const InHand& h : in_hand_) {
    if (h.t >= held_since_ - o_.in_hand_lead_s) use.push_back(&h);
  }
  if (!use.empty()) {
    Eigen::Vector3d c, up;
    MedianInHand(use, &c, &up);
    if (!prior_c_) {
      // the grasp prior: the object where the plan saw it, upright as it stood, when the grip
      // had closed (the oldest frame counted as held), carried by the hand since
      const InHand& h0 = *use.front();
      prior_c_ = h0.hand_rot.transpose() * (planned_.centre - h0.hand_pos);
      prior_up_ = h0.hand_rot.transpose() * planned_.up;
    }
    c = o_.prior_weight * *prior_c_ + (1 - o_.prior_weight) * c;
    if (up.norm() > 1e-6) up.normalize();
    up = o_.prior_up_weight * *prior_up_ + (1 - o_.prior_up_weight) * up;
    if (up.norm() > 1e-6) up.normalize();
    if (o_.touch && planned_.shape != 2) {
      perceive::RefineHeldByTouch(touch_, 0.5 * planned_.width_m, o_.touch_refine, &c, &up);
    }
    if (!anchor_) anchor_ = c;
    const Eigen::Matrix3d r =
        Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * hand_body_);
    perceive::ObjectEstimate e = arrived_.back();
    e.centre = r * c + Eigen::Vector3d(d->xpos + 3 * hand_body_);
    e.up = up.norm() > 1e-6 ? Eigen::Vector3d(r * up.normalized()) : e.up;
    return ToView(e);
  }
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
