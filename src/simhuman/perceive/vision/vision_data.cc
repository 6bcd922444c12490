#include "simhuman/perceive/vision/vision_data.h"

#include <algorithm>
#include <chrono>
#include <map>

#include "simhuman/world/model_builder.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::perceive {

namespace {
int IndexOf(const std::vector<std::string>& names, const std::string& s) {
  const auto it = std::find(names.begin(), names.end(), s);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}
}  // namespace

std::vector<ObjectTruth> TableObjectsTruth(const world::SimWorld& w,
                                           const core::SceneCatalog& catalog, const mjData* d) {
  std::vector<ObjectTruth> out;
  for (const core::CatalogObject& o : catalog.objects) {
    const int shape = IndexOf(VisionShapes(), o.type);
    const int colour = IndexOf(VisionColours(), o.color);
    if (shape < 0 || colour < 0) continue;
    ObjectTruth t;
    t.id = o.id;
    t.body = mj_name2id(w.model(), mjOBJ_BODY, world::ObjectBodyName(o.id).c_str());
    if (t.body < 0) continue;
    t.shape = shape;
    t.colour = colour;
    const auto [lo, hi] = o.LocalBounds();
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> R(d->xmat + 9 * t.body);
    const Eigen::Map<const Eigen::Vector3d> p(d->xpos + 3 * t.body);
    t.centre = p + R * (0.5 * (lo + hi));
    t.up = shape == 2 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d(R.col(2));
    t.height_m = hi.z() - lo.z();
    t.width_m = hi.x() - lo.x();
    t.yaw_rad = std::atan2(R(1, 0), R(0, 0));
    out.push_back(t);
  }
  return out;
}

Eigen::Vector3d PlanningGaze() {
  const world::TabletopOptions o;
  return world::TableToWorld(Eigen::Vector3d(0.5 * (o.region_x_lo_m + o.region_x_hi_m),
                                             0.5 * (o.region_y_lo_m + o.region_y_hi_m), 0.0));
}

core::StatusOr<std::unique_ptr<HeadCamera>> HeadCamera::Create(const mjModel* m, int width,
                                                               int height, double fovy_deg) {
  render::RendererOptions ro;
  ro.msaa_samples = 0;
  ro.fovy_deg = fovy_deg;
  auto r = render::OffscreenRenderer::Create(m, width, height, ro);
  if (!r.ok()) {
    if (r.status().code() == absl::StatusCode::kUnavailable) {
      return absl::UnavailableError(
          "the head camera needs the offscreen renderer (EGL + OpenGL), which failed: " +
          std::string(r.status().message()) +
          "; run with --perception truth to use ground-truth object state instead");
    }
    return r.status();
  }
  auto cam = std::unique_ptr<HeadCamera>(new HeadCamera());
  cam->renderer_ = std::move(*r);
  cam->width_ = width;
  cam->height_ = height;
  cam->fovy_deg_ = cam->renderer_->model()->vis.global.fovy;
  return cam;
}

PinholeCamera HeadCamera::Aim(const world::SimWorld& w, const mjData* d, int agent,
                              const Eigen::Vector3d& gaze) const {
  return LookAt(EyePosition(w, d, agent), gaze, fovy_deg_, width_, height_);
}

core::Status HeadCamera::Capture(const mjData* d, const PinholeCamera& cam,
                                 std::vector<uint8_t>* rgb) {
  const auto t0 = std::chrono::steady_clock::now();
  core::Status s = renderer_->Render(d, cam.Spec(), rgb);
  frame_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ++frames_;
  return s;
}

core::Status HeadCamera::CaptureBodyIds(const mjData* d, const PinholeCamera& cam,
                                        std::vector<int>* ids) {
  return renderer_->RenderBodyIds(d, cam.Spec(), ids);
}

void CountPixels(const std::vector<int>& ids, int width, int height,
                 std::vector<ObjectTruth>* truth) {
  std::map<int, int> count;
  std::map<int, bool> edge;
  for (size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] < 0) continue;
    ++count[ids[i]];
    const int x = static_cast<int>(i % width), y = static_cast<int>(i / width);
    if (x == 0 || y == 0 || x == width - 1 || y == height - 1) edge[ids[i]] = true;
  }
  for (ObjectTruth& t : *truth) {
    t.pixels = count.count(t.body) ? count[t.body] : 0;
    t.at_edge = edge.count(t.body) > 0;
  }
}

void AddColourPixels(const std::vector<uint8_t>& rgb, const std::vector<int>& ids,
                     const std::vector<ObjectTruth>& truth, ColourTable* table) {
  std::map<int, int> colour_of;
  for (const ObjectTruth& t : truth) colour_of[t.body] = t.colour;
  for (size_t i = 0; i < ids.size(); ++i) {
    const auto it = colour_of.find(ids[i]);
    table->Add(&rgb[3 * i], it == colour_of.end() ? 0 : 1 + it->second);
  }
}

std::vector<BlobSample> LabelledSamples(const std::vector<uint8_t>& rgb,
                                        const std::vector<int>& ids, const PinholeCamera& cam,
                                        const std::vector<ObjectTruth>& truth,
                                        const std::vector<Blob>& blobs) {
  std::vector<BlobSample> out;
  for (const Blob& b : blobs) {
    std::map<int, int> votes;
    for (int i : b.index) ++votes[ids[i]];
    int best = -1, n = 0;
    for (const auto& [body, c] : votes) {
      if (c > n) {
        best = body;
        n = c;
      }
    }
    BlobSample s = MakeBlobSample(rgb, cam, b);
    s.shape = static_cast<int>(VisionShapes().size());  // not an object
    for (const ObjectTruth& t : truth) {
      if (t.body != best || 2 * n < b.pixels) continue;
      s.shape = t.shape;
      s.rel = cam.ToLevel(t.centre - cam.eye);
      s.up = cam.ToLevel(t.up);
      s.height_m = t.height_m;
      s.width_m = t.width_m;
      // the face yaw in the level frame
      const Eigen::Vector3d fx = cam.FromLevel(Eigen::Vector3d::UnitX());
      s.yaw_rad = t.yaw_rad - std::atan2(fx.y(), fx.x());
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace simhuman::perceive
