#include "simhuman/perceive/vision/vision_model.h"

#include <torch/torch.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <random>

#include "absl/strings/str_cat.h"
#include "simhuman/core/geometry.h"

namespace simhuman::perceive {

namespace {

constexpr char kFormat[] = "simhuman-vision-3";
constexpr int kClasses = 4;  // box, cylinder, sphere, not an object
// class logits, depth, offset (3), height, up (3), width, box yaw as (cos 4a, sin 4a)
constexpr int kOut = kClasses + 1 + 3 + 1 + 3 + 1 + 2;
// output scalings: depth along the centroid ray, the offset off it, height
constexpr double kDepth0 = 0.8, kDepthScale = 0.3, kOffsetScale = 0.05;
constexpr double kHeight0 = 0.13, kHeightScale = 0.05;
constexpr double kWidth0 = 0.08, kWidthScale = 0.03;

Eigen::Vector3d LevelRay(const PinholeCamera& cam, double u, double v) {
  return cam.ToLevel(cam.Ray(u, v));
}

}  // namespace

BlobSample MakeBlobSample(const std::vector<uint8_t>& rgb, const PinholeCamera& cam,
                          const Blob& b) {
  BlobSample s;
  const int w = cam.width, h = cam.height;
  std::vector<uint8_t> mask(static_cast<size_t>(w) * h, 0);
  for (int i : b.index) mask[i] = 1;
  const double cx = 0.5 * (b.x0 + b.x1 + 1), cy = 0.5 * (b.y0 + b.y1 + 1);
  const double side = 1.2 * std::max(b.x1 - b.x0 + 1, b.y1 - b.y0 + 1) + 2.0;
  const int n = kVisionCrop;
  s.crop.assign(4 * n * n, 0.0f);
  for (int r = 0; r < n; ++r) {
    const int y = static_cast<int>(std::floor(cy + ((r + 0.5) / n - 0.5) * side));
    for (int c = 0; c < n; ++c) {
      const int x = static_cast<int>(std::floor(cx + ((c + 0.5) / n - 0.5) * side));
      if (x < 0 || y < 0 || x >= w || y >= h) continue;
      const size_t i = static_cast<size_t>(y) * w + x;
      for (int k = 0; k < 3; ++k) s.crop[(k * n + r) * n + c] = rgb[3 * i + k] / 255.0f - 0.5f;
      s.crop[(3 * n + r) * n + c] = mask[i];
    }
  }
  s.ray = LevelRay(cam, b.cu, b.cv);
  const Eigen::Vector3d tl = LevelRay(cam, b.x0, b.y0);
  const Eigen::Vector3d br = LevelRay(cam, b.x1 + 1, b.y1 + 1);
  const Eigen::Vector3d bottom = LevelRay(cam, cx, b.y1 + 1);
  int k = 0;
  const Eigen::Vector3d s_ray = s.ray;
  for (const Eigen::Vector3d* r : {&s_ray, &tl, &br, &bottom}) {
    for (int j = 0; j < 3; ++j) s.features[k++] = static_cast<float>((*r)[j]);
  }
  s.features[k++] = static_cast<float>(cam.Pitch());
  s.features[k++] = static_cast<float>(cam.eye.z() - 1.2);
  s.features[k++] = static_cast<float>(std::log(b.pixels / 100.0));
  return s;
}

struct VisionModel::Net : torch::nn::Module {
  Net() {
    c1 = register_module("c1", torch::nn::Conv2d(torch::nn::Conv2dOptions(4, 16, 3).padding(1)));
    c2 = register_module("c2", torch::nn::Conv2d(torch::nn::Conv2dOptions(16, 32, 3).padding(1)));
    c3 = register_module("c3", torch::nn::Conv2d(torch::nn::Conv2dOptions(32, 64, 3).padding(1)));
    const int flat = 64 * (kVisionCrop / 8) * (kVisionCrop / 8);
    f1 = register_module("f1", torch::nn::Linear(flat + kVisionFeatures, 128));
    f2 = register_module("f2", torch::nn::Linear(128, 128));
    out = register_module("out", torch::nn::Linear(128, kOut));
  }
  torch::Tensor forward(torch::Tensor crop, torch::Tensor feat) {
    auto x = torch::max_pool2d(torch::relu(c1(crop)), 2);
    x = torch::max_pool2d(torch::relu(c2(x)), 2);
    x = torch::max_pool2d(torch::relu(c3(x)), 2);
    x = torch::cat({x.flatten(1), feat}, 1);
    x = torch::relu(f1(x));
    x = torch::relu(f2(x));
    return out(x);
  }
  torch::nn::Conv2d c1{nullptr}, c2{nullptr}, c3{nullptr};
  torch::nn::Linear f1{nullptr}, f2{nullptr}, out{nullptr};
  std::unique_ptr<torch::optim::Adam> opt_owner;
};

namespace {

struct Decoded {
  torch::Tensor logits, rel, height, up, width, yaw4;  // rel: level frame from the eye, metres
};

Decoded Decode(const torch::Tensor& y, const torch::Tensor& ray) {
  Decoded d;
  d.logits = y.slice(1, 0, kClasses);
  const torch::Tensor depth = kDepth0 + kDepthScale * y.slice(1, kClasses, kClasses + 1);
  const torch::Tensor off = kOffsetScale * y.slice(1, kClasses + 1, kClasses + 4);
  d.rel = depth * ray + off;
  d.height = kHeight0 + kHeightScale * y.slice(1, kClasses + 4, kClasses + 5).squeeze(1);
  d.up = y.slice(1, kClasses + 5, kClasses + 8) + torch::tensor({0.0f, 0.0f, 1.0f});
  d.up = d.up / d.up.norm(2, 1, true).clamp_min(1e-6);
  d.width = kWidth0 + kWidthScale * y.slice(1, kClasses + 8, kClasses + 9).squeeze(1);
  d.yaw4 = y.slice(1, kClasses + 9, kClasses + 11);
  return d;
}

struct Batch {
  torch::Tensor crop, feat, ray, shape, rel, up, height, width, yaw4, positive;
};

Batch MakeBatch(const std::vector<BlobSample>& s, const std::vector<size_t>& idx) {
  const int64_t n = static_cast<int64_t>(idx.size());
  const int c = kVisionCrop;
  Batch b;
  b.crop = torch::empty({n, 4, c, c});
  b.feat = torch::empty({n, kVisionFeatures});
  b.ray = torch::empty({n, 3});
  b.rel = torch::empty({n, 3});
  b.up = torch::empty({n, 3});
  b.height = torch::empty({n});
  b.width = torch::empty({n});
  b.yaw4 = torch::empty({n, 2});
  b.shape = torch::empty({n}, torch::kInt64);
  float* crop = b.crop.data_ptr<float>();
  for (int64_t i = 0; i < n; ++i) {
    const BlobSample& x = s[idx[i]];
    std::copy(x.crop.begin(), x.crop.end(), crop + i * 4 * c * c);
    for (int k = 0; k < kVisionFeatures; ++k) b.feat[i][k] = x.features[k];
    for (int k = 0; k < 3; ++k) {
      b.ray[i][k] = static_cast<float>(x.ray[k]);
      b.rel[i][k] = static_cast<float>(x.rel[k]);
      b.up[i][k] = static_cast<float>(x.up[k]);
    }
    b.height[i] = static_cast<float>(x.height_m);
    b.width[i] = static_cast<float>(x.width_m);
    b.yaw4[i][0] = static_cast<float>(std::cos(4 * x.yaw_rad));
    b.yaw4[i][1] = static_cast<float>(std::sin(4 * x.yaw_rad));
    b.shape[i] = x.shape;
  }
  b.positive = (b.shape < kClasses - 1).to(torch::kFloat32);
  return b;
}

// the losses of one batch: cross-entropy on the class; on objects, smooth L1 on the centre and
// the height in cm, and 1 - cos on the up axis (a sphere's up is left free)
std::pair<torch::Tensor, VisionLosses> BatchLoss(const Decoded& d, const Batch& b) {
  VisionLosses l;
  const torch::Tensor ce = torch::nn::functional::cross_entropy(d.logits, b.shape);
  const torch::Tensor pos = b.positive;
  const torch::Tensor npos = pos.sum().clamp_min(1.0);
  const torch::Tensor dp = torch::nn::functional::smooth_l1_loss(
      100 * d.rel, 100 * b.rel,
      torch::nn::functional::SmoothL1LossFuncOptions().reduction(torch::kNone));
  const torch::Tensor pos_loss = (dp.sum(1) * pos).sum() / npos;
  const torch::Tensor dh = torch::nn::functional::smooth_l1_loss(
      100 * d.height, 100 * b.height,
      torch::nn::functional::SmoothL1LossFuncOptions().reduction(torch::kNone));
  const torch::Tensor h_loss = (dh * pos).sum() / npos;
  const torch::Tensor dw = torch::nn::functional::smooth_l1_loss(
      100 * d.width, 100 * b.width,
      torch::nn::functional::SmoothL1LossFuncOptions().reduction(torch::kNone));
  const torch::Tensor w_loss = (dw * pos).sum() / npos;
  const torch::Tensor not_sphere = pos * (b.shape != 2).to(torch::kFloat32);
  const torch::Tensor up_loss =
      ((1 - (d.up * b.up).sum(1)) * not_sphere).sum() / not_sphere.sum().clamp_min(1.0);
  // the box's yaw in the level frame (the samples hold it so), as a point on the unit circle
  const torch::Tensor box = pos * (b.shape == 0).to(torch::kFloat32);
  const torch::Tensor nbox = box.sum().clamp_min(1.0);
  const torch::Tensor yaw_loss = ((d.yaw4 - b.yaw4).pow(2).sum(1) * box).sum() / nbox;
  const torch::Tensor total =
      ce + 0.3 * pos_loss + 0.3 * h_loss + 0.3 * w_loss + 10.0 * up_loss + yaw_loss;
  l.total = total.item<double>();
  l.shape = ce.item<double>();
  const torch::Tensor err = ((d.rel - b.rel).norm(2, 1) * pos).sum() / npos;
  l.position_cm = 100 * err.item<double>();
  l.height_cm = 100 * (((d.height - b.height).abs() * pos).sum() / npos).item<double>();
  l.width_cm = 100 * (((d.width - b.width).abs() * pos).sum() / npos).item<double>();
  {
    const torch::Tensor a = torch::atan2(d.yaw4.select(1, 1), d.yaw4.select(1, 0));
    const torch::Tensor t = torch::atan2(b.yaw4.select(1, 1), b.yaw4.select(1, 0));
    const torch::Tensor e = torch::remainder(a - t + M_PI, 2 * M_PI) - M_PI;
    l.yaw_deg = ((e.abs() / 4 * 180 / M_PI * box).sum() / nbox).item<double>();
  }
  l.up = up_loss.item<double>();
  return {total, l};
}

void Accumulate(VisionLosses* sum, const VisionLosses& l, double w) {
  sum->total += w * l.total;
  sum->shape += w * l.shape;
  sum->position_cm += w * l.position_cm;
  sum->height_cm += w * l.height_cm;
  sum->width_cm += w * l.width_cm;
  sum->yaw_deg += w * l.yaw_deg;
  sum->up += w * l.up;
}

}  // namespace

VisionModel::VisionModel() = default;

void VisionModel::SetThreads(int n) { torch::set_num_threads(std::max(1, n)); }
VisionModel::~VisionModel() = default;

std::unique_ptr<VisionModel> VisionModel::Create(uint64_t seed) {
  torch::manual_seed(seed);
  std::unique_ptr<VisionModel> m(new VisionModel());
  m->net_ = std::make_unique<Net>();
  return m;
}

core::Status VisionModel::Save(const std::string& path) const {
  try {
    torch::serialize::OutputArchive ar;
    ar.write("format", c10::IValue(std::string(kFormat)));
    torch::serialize::OutputArchive net;
    net_->save(net);
    ar.write("net", net);
    const std::vector<uint8_t>& lab = colours_.labels();
    ar.write("colour_table", torch::from_blob(const_cast<uint8_t*>(lab.data()),
                                              {static_cast<int64_t>(lab.size())}, torch::kUInt8)
                                 .clone());
    ar.write("min_pixels", c10::IValue(static_cast<int64_t>(min_pixels)));
    ar.write("camera",
             torch::tensor({static_cast<double>(width), static_cast<double>(height), fovy_deg},
                           torch::kFloat64));
    ar.save_to(path);
  } catch (const std::exception& e) {
    return absl::InternalError(path + ": cannot write the vision model: " + e.what());
  }
  return absl::OkStatus();
}

core::StatusOr<std::unique_ptr<VisionModel>> VisionModel::Load(const std::string& path) {
  if (!std::ifstream(path).good()) {
    return absl::NotFoundError(path +
                               ": cannot open the vision model file (make one with "
                               "`simhuman train --task vision`)");
  }
  std::unique_ptr<VisionModel> m = Create(0);
  try {
    torch::serialize::InputArchive ar;
    ar.load_from(path);
    c10::IValue format, minpx;
    if (!ar.try_read("format", format) || !format.isString() || format.toStringRef() != kFormat) {
      return absl::DataLossError(path + ": not a simhuman vision model (no format '" +
                                 std::string(kFormat) + "')");
    }
    torch::serialize::InputArchive net;
    torch::Tensor table;
    if (!ar.try_read("net", net) || !ar.try_read("colour_table", table)) {
      return absl::DataLossError(path + ": vision model lacks 'net' or 'colour_table'");
    }
    // load() takes tensors of any shape: compare each with the network's own
    std::vector<std::pair<std::string, std::vector<int64_t>>> expected;
    for (const auto& p : m->net_->named_parameters()) {
      expected.emplace_back(p.key(), p.value().sizes().vec());
    }
    m->net_->load(net);
    const auto loaded = m->net_->named_parameters();
    for (const auto& [name, shape] : expected) {
      const torch::Tensor* t = loaded.find(name);
      if (t == nullptr || t->sizes().vec() != shape) {
        return absl::DataLossError(path + ": vision model tensor '" + name +
                                   "' is missing or of the wrong shape for this build's network");
      }
    }
    table = table.to(torch::kUInt8).contiguous();
    std::vector<uint8_t> lab(table.data_ptr<uint8_t>(), table.data_ptr<uint8_t>() + table.numel());
    if (core::Status s = m->colours_.SetLabels(lab); !s.ok()) {
      return absl::DataLossError(path + ": " + std::string(s.message()));
    }
    if (ar.try_read("min_pixels", minpx) && minpx.isInt()) {
      m->min_pixels = static_cast<int>(minpx.toInt());
    }
    torch::Tensor camera;
    if (!ar.try_read("camera", camera) || camera.numel() != 3) {
      return absl::DataLossError(path + ": vision model lacks its camera (width, height, fovy)");
    }
    camera = camera.to(torch::kFloat64).contiguous();
    m->width = static_cast<int>(camera.data_ptr<double>()[0]);
    m->height = static_cast<int>(camera.data_ptr<double>()[1]);
    m->fovy_deg = camera.data_ptr<double>()[2];
  } catch (const c10::Error& e) {
    return absl::DataLossError(path + ": corrupt vision model or tensors of the wrong shape: " +
                               std::string(e.what_without_backtrace()));
  } catch (const std::exception& e) {
    return absl::DataLossError(path + ": corrupt vision model: " + e.what());
  }
  m->net_->eval();
  return m;
}

std::vector<ObjectEstimate> VisionModel::Estimate(const std::vector<uint8_t>& rgb,
                                                  const PinholeCamera& cam) const {
  std::vector<ObjectEstimate> out;
  std::vector<Blob> blobs = FindBlobs(rgb, cam.width, cam.height, colours_, min_pixels);
  // an object cut by the frame's edge is not seen whole: no estimate (its position would be a
  // guess)
  blobs.erase(std::remove_if(blobs.begin(), blobs.end(),
                             [&](const Blob& b) {
                               return b.x0 == 0 || b.y0 == 0 || b.x1 == cam.width - 1 ||
                                      b.y1 == cam.height - 1;
                             }),
              blobs.end());
  if (blobs.empty()) return out;
  std::vector<BlobSample> samples;
  for (const Blob& b : blobs) samples.push_back(MakeBlobSample(rgb, cam, b));
  std::vector<size_t> idx(samples.size());
  std::iota(idx.begin(), idx.end(), 0);
  torch::NoGradGuard ng;
  const Batch batch = MakeBatch(samples, idx);
  const Decoded d = Decode(net_->forward(batch.crop, batch.feat), batch.ray);
  const torch::Tensor prob = torch::softmax(d.logits, 1);
  for (size_t i = 0; i < blobs.size(); ++i) {
    const int64_t k = static_cast<int64_t>(i);
    const int cls = static_cast<int>(prob[k].argmax().item<int64_t>());
    if (cls == kClasses - 1) continue;
    ObjectEstimate e;
    e.shape = cls;
    e.colour = blobs[i].colour;
    e.confidence = prob[k][cls].item<double>();
    const Eigen::Vector3d rel(d.rel[k][0].item<double>(), d.rel[k][1].item<double>(),
                              d.rel[k][2].item<double>());
    e.centre = cam.eye + cam.FromLevel(rel);
    const Eigen::Vector3d up(d.up[k][0].item<double>(), d.up[k][1].item<double>(),
                             d.up[k][2].item<double>());
    e.up = cls == 2 ? Eigen::Vector3d::UnitZ() : cam.FromLevel(up).normalized();
    e.height_m = d.height[k].item<double>();
    e.width_m = d.width[k].item<double>();
    // the face yaw: level frame to world (the level frame turns by the camera's azimuth)
    const double a4 = std::atan2(d.yaw4[k][1].item<double>(), d.yaw4[k][0].item<double>());
    const Eigen::Vector3d fx = cam.FromLevel(Eigen::Vector3d::UnitX());
    e.yaw_rad = core::WrapAngle(a4 / 4 + std::atan2(fx.y(), fx.x()));
    while (e.yaw_rad > M_PI / 4) e.yaw_rad -= M_PI / 2;
    while (e.yaw_rad <= -M_PI / 4) e.yaw_rad += M_PI / 2;
    e.pixels = blobs[i].pixels;
    e.u = blobs[i].cu;
    e.v = blobs[i].cv;
    // a hand or another object can split one object into blobs: estimates of one colour whose
    // centres lie closer than any two objects can are one object, seen by its largest blob
    // (blobs come largest first)
    bool duplicate = false;
    for (const ObjectEstimate& o : out) {
      duplicate = duplicate || (o.colour == e.colour && (o.centre - e.centre).norm() < merge_m);
    }
    if (!duplicate) out.push_back(e);
  }
  return out;
}

VisionLosses VisionModel::TrainEpoch(const std::vector<BlobSample>& samples, int batch, double lr,
                                     uint64_t seed) {
  net_->train();
  if (!net_->opt_owner) {
    net_->opt_owner =
        std::make_unique<torch::optim::Adam>(net_->parameters(), torch::optim::AdamOptions(lr));
  }
  for (auto& g : net_->opt_owner->param_groups()) {
    static_cast<torch::optim::AdamOptions&>(g.options()).lr(lr);
  }
  std::vector<size_t> idx(samples.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::mt19937_64 rng(seed);
  std::shuffle(idx.begin(), idx.end(), rng);
  VisionLosses sum;
  for (size_t at = 0; at < idx.size(); at += batch) {
    const std::vector<size_t> part(idx.begin() + at,
                                   idx.begin() + std::min(idx.size(), at + batch));
    const Batch b = MakeBatch(samples, part);
    const Decoded d = Decode(net_->forward(b.crop, b.feat), b.ray);
    auto [loss, l] = BatchLoss(d, b);
    net_->opt_owner->zero_grad();
    loss.backward();
    net_->opt_owner->step();
    Accumulate(&sum, l, static_cast<double>(part.size()) / idx.size());
  }
  net_->eval();
  return sum;
}

VisionLosses VisionModel::Evaluate(const std::vector<BlobSample>& samples) const {
  torch::NoGradGuard ng;
  VisionLosses sum;
  const size_t batch = 1024;
  for (size_t at = 0; at < samples.size(); at += batch) {
    std::vector<size_t> part;
    for (size_t i = at; i < std::min(samples.size(), at + batch); ++i) part.push_back(i);
    const Batch b = MakeBatch(samples, part);
    const Decoded d = Decode(net_->forward(b.crop, b.feat), b.ray);
    Accumulate(&sum, BatchLoss(d, b).second, static_cast<double>(part.size()) / samples.size());
  }
  return sum;
}

}  // namespace simhuman::perceive
