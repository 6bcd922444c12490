#include "simhuman/render/gltf_export.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "simhuman/render/geom_mesh.h"

namespace simhuman::render {
namespace {

using nlohmann::ordered_json;

// glTF enums
constexpr int kFloat = 5126, kUint32 = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;

struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

// the binary buffer and the accessors into it
class Buffers {
 public:
  explicit Buffers(ordered_json* j) : j_(j) {}

  // a view of `bytes` at a 4-aligned offset; target 0: none (animation data)
  int AddView(const void* data, size_t bytes, int target) {
    bin_.append(static_cast<const char*>(data), bytes);
    ordered_json v = {{"buffer", 0}, {"byteOffset", bin_.size() - bytes}, {"byteLength", bytes}};
    if (target != 0) v["target"] = target;
    while (bin_.size() % 4 != 0) bin_.push_back('\0');
    (*j_)["bufferViews"].push_back(v);
    return static_cast<int>((*j_)["bufferViews"].size()) - 1;
  }

  // float data of `width` components per element (1 SCALAR, 3 VEC3, 4 VEC4), with min and max
  int AddFloats(const std::vector<float>& v, int width, int target) {
    static const char* const kTypes[] = {"", "SCALAR", "", "VEC3", "VEC4"};
    const int count = static_cast<int>(v.size()) / width;
    const int view = AddView(v.data(), v.size() * sizeof(float), target);
    std::vector<float> lo(width, 0), hi(width, 0);
    for (int c = 0; c < width; ++c) {
      lo[c] = hi[c] = count > 0 ? v[c] : 0.0f;
      for (int i = 0; i < count; ++i) {
        lo[c] = std::min(lo[c], v[i * width + c]);
        hi[c] = std::max(hi[c], v[i * width + c]);
      }
    }
    return AddAccessor({{"bufferView", view},
                        {"componentType", kFloat},
                        {"count", count},
                        {"type", kTypes[width]},
                        {"min", lo},
                        {"max", hi}});
  }

  int AddIndices(const std::vector<uint32_t>& idx) {
    const int view = AddView(idx.data(), idx.size() * sizeof(uint32_t), kElementArrayBuffer);
    return AddAccessor({{"bufferView", view},
                        {"componentType", kUint32},
                        {"count", idx.size()},
                        {"type", "SCALAR"}});
  }

  const std::string& bin() const { return bin_; }

 private:
  int AddAccessor(ordered_json a) {
    (*j_)["accessors"].push_back(std::move(a));
    return static_cast<int>((*j_)["accessors"].size()) - 1;
  }

  ordered_json* j_;
  std::string bin_;
};

// the colour MuJoCo draws geom g in: its material's unless the geom sets its own
std::array<float, 4> GeomRgba(const mjModel* m, int g) {
  std::array<float, 4> rgba;
  for (int k = 0; k < 4; ++k) rgba[k] = m->geom_rgba[4 * g + k];
  const bool default_rgba = rgba[0] == 0.5f && rgba[1] == 0.5f && rgba[2] == 0.5f && rgba[3] == 1;
  const int mat = m->geom_matid[g];
  if (mat >= 0 && default_rgba) {
    for (int k = 0; k < 4; ++k) rgba[k] = m->mat_rgba[4 * mat + k];
    // a textured material (the checker floor): its average tone instead of white
    if (m->mat_texid[mat] >= 0) {
      for (int k = 0; k < 3; ++k) rgba[k] *= 0.76f;
    }
  }
  return rgba;
}

bool Visible(const mjModel* m, int g) {
  return m->geom_rgba[4 * g + 3] > 0 && m->geom_group[g] < 3;
}

// one mesh per body with visible geoms: a primitive per geom, vertices in the body frame
// converted to y-up; returns the mesh index or -1
int BodyMesh(const mjModel* m, int b, const GltfOptions& options, Buffers* buf, ordered_json* j,
             std::map<std::array<float, 4>, int>* materials) {
  ordered_json prims = ordered_json::array();
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_bodyid[g] != b || !Visible(m, g)) continue;
    TriMesh mesh = GeomMesh(m, g, options.segments, options.floor_half_m);
    if (mesh.index.empty()) continue;
    const Eigen::Vector3d gpos(m->geom_pos + 3 * g);
    const Eigen::Quaterniond gq(m->geom_quat[4 * g], m->geom_quat[4 * g + 1],
                                m->geom_quat[4 * g + 2], m->geom_quat[4 * g + 3]);
    const Eigen::Matrix3d R = gq.normalized().toRotationMatrix();
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      Eigen::Vector3d p(mesh.position[3 * v], mesh.position[3 * v + 1], mesh.position[3 * v + 2]);
      Eigen::Vector3d n(mesh.normal[3 * v], mesh.normal[3 * v + 1], mesh.normal[3 * v + 2]);
      p = MujocoToGltf(Eigen::Vector3d(R * p + gpos));
      n = MujocoToGltf(Eigen::Vector3d(R * n));
      for (int k = 0; k < 3; ++k) {
        mesh.position[3 * v + k] = static_cast<float>(p[k]);
        mesh.normal[3 * v + k] = static_cast<float>(n[k]);
      }
    }
    const std::array<float, 4> rgba = GeomRgba(m, g);
    auto [it, added] = materials->emplace(rgba, static_cast<int>(materials->size()));
    if (added) {
      ordered_json mat = {
          {"name", "rgba " + std::to_string(rgba[0]) + " " + std::to_string(rgba[1]) + " " +
                       std::to_string(rgba[2])},
          {"pbrMetallicRoughness",
           {{"baseColorFactor", rgba}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.8}}}};
      if (rgba[3] < 1) mat["alphaMode"] = "BLEND";
      (*j)["materials"].push_back(mat);
    }
    const int pos = buf->AddFloats(mesh.position, 3, kArrayBuffer);
    const int nrm = buf->AddFloats(mesh.normal, 3, kArrayBuffer);
    const int idx = buf->AddIndices(mesh.index);
    prims.push_back({{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}},
                     {"indices", idx},
                     {"material", it->second},
                     {"mode", kTriangles}});
  }
  if (prims.empty()) return -1;
  const char* name = mj_id2name(m, mjOBJ_BODY, b);
  (*j)["meshes"].push_back(
      {{"name", name ? name : "body" + std::to_string(b)}, {"primitives", prims}});
  return static_cast<int>((*j)["meshes"].size()) - 1;
}

// the GLB container: header, JSON chunk (space padded), BIN chunk (zero padded)
std::string PackGlb(const std::string& json_text, const std::string& bin) {
  auto u32 = [](std::string* s, uint32_t v) { s->append(reinterpret_cast<const char*>(&v), 4); };
  std::string json = json_text;
  while (json.size() % 4 != 0) json.push_back(' ');
  std::string out;
  u32(&out, 0x46546C67);  // "glTF"
  u32(&out, 2);
  u32(&out, static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  u32(&out, static_cast<uint32_t>(json.size()));
  u32(&out, 0x4E4F534A);  // "JSON"
  out += json;
  u32(&out, static_cast<uint32_t>(bin.size()));
  u32(&out, 0x004E4942);  // "BIN\0"
  out += bin;
  return out;
}

absl::Status CheckInputs(const mjModel* m, const QposFrames& frames, const GltfOptions& o) {
  if (!(o.fps > 0 && o.fps <= 1000)) {
    return absl::InvalidArgumentError("gltf export: fps " + std::to_string(o.fps) +
                                      " is not in (0, 1000]");
  }
  if (o.segments < 3 || o.segments > 256) {
    return absl::InvalidArgumentError("gltf export: segments " + std::to_string(o.segments) +
                                      " is not in 3..256");
  }
  if (!(o.floor_half_m > 0)) {
    return absl::InvalidArgumentError("gltf export: floor_half_m must be > 0");
  }
  if (frames.qpos.empty() || frames.time_s.size() != frames.qpos.size()) {
    return absl::InvalidArgumentError("gltf export: no frames (or times and rows differ in count)");
  }
  for (size_t f = 0; f < frames.qpos.size(); ++f) {
    if (static_cast<int>(frames.qpos[f].size()) != m->nq) {
      return absl::InvalidArgumentError("gltf export: frame " + std::to_string(f) + " has " +
                                        std::to_string(frames.qpos[f].size()) +
                                        " qpos values, the model " + std::to_string(m->nq));
    }
  }
  return absl::OkStatus();
}

}  // namespace

Eigen::Vector3d MujocoToGltf(const Eigen::Vector3d& p) {
  return Eigen::Vector3d(p.x(), p.z(), -p.y());
}

Eigen::Quaterniond MujocoToGltf(const Eigen::Quaterniond& q) {
  const Eigen::Quaterniond c(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()));
  return c * q * c.conjugate();
}

core::StatusOr<std::string> SceneGlb(const mjModel* m, const QposFrames& frames,
                                     const GltfOptions& options) {
  SH_RETURN_IF_ERROR(CheckInputs(m, frames, options));
  ordered_json j;
  j["asset"] = {{"version", "2.0"}, {"generator", "simhuman export"}};
  j["scene"] = 0;
  Buffers buf(&j);
  std::map<std::array<float, 4>, int> materials;

  // the bodies drawn, and their meshes
  std::vector<int> bodies, meshes;
  for (int b = 0; b < m->nbody; ++b) {
    const int mesh = BodyMesh(m, b, options, &buf, &j, &materials);
    if (mesh < 0) continue;
    bodies.push_back(b);
    meshes.push_back(mesh);
  }

  // the body poses at every sample (y-up)
  const double t0 = frames.time_s.front();
  const int count =
      1 + static_cast<int>(std::floor((frames.time_s.back() - t0) * options.fps + 1e-6));
  const size_t nb = bodies.size();
  std::vector<std::vector<float>> trans(nb), rot(nb);
  std::unique_ptr<mjData, DataDeleter> d(mj_makeData(m));
  std::vector<float> times(count);
  for (int f = 0; f < count; ++f) {
    times[f] = static_cast<float>(f / options.fps);
    const std::vector<double> q = SampleQpos(m, frames, t0 + f / options.fps);
    std::copy(q.begin(), q.end(), d->qpos);
    mj_kinematics(m, d.get());
    for (size_t i = 0; i < nb; ++i) {
      const int b = bodies[i];
      const Eigen::Vector3d p = MujocoToGltf(Eigen::Vector3d(d->xpos + 3 * b));
      Eigen::Quaterniond r = MujocoToGltf(Eigen::Quaterniond(
          d->xquat[4 * b], d->xquat[4 * b + 1], d->xquat[4 * b + 2], d->xquat[4 * b + 3]));
      r.normalize();
      // keep neighbouring samples in the same hemisphere, so interpolation turns the short way
      std::vector<float>& rv = rot[i];
      if (f > 0) {
        const size_t o = rv.size() - 4;
        const double dot =
            rv[o + 3] * r.w() + rv[o] * r.x() + rv[o + 1] * r.y() + rv[o + 2] * r.z();
        if (dot < 0) r.coeffs() *= -1;
      }
      for (int k = 0; k < 3; ++k) trans[i].push_back(static_cast<float>(p[k]));
      for (double c : {r.x(), r.y(), r.z(), r.w()}) rv.push_back(static_cast<float>(c));
    }
  }

  // nodes at the first pose; channels for those that move
  ordered_json samplers = ordered_json::array(), channels = ordered_json::array();
  int input = -1;
  for (size_t i = 0; i < nb; ++i) {
    const char* name = mj_id2name(m, mjOBJ_BODY, bodies[i]);
    j["nodes"].push_back(
        {{"name", name ? name : "body" + std::to_string(bodies[i])},
         {"mesh", meshes[i]},
         {"translation", std::vector<float>(trans[i].begin(), trans[i].begin() + 3)},
         {"rotation", std::vector<float>(rot[i].begin(), rot[i].begin() + 4)}});
    j["scenes"][0]["nodes"].push_back(i);
    bool moves = options.animate_all;
    for (size_t k = 3; k < trans[i].size() && !moves; ++k)
      moves = std::abs(trans[i][k] - trans[i][k % 3]) > 1e-6f;
    for (size_t k = 4; k < rot[i].size() && !moves; ++k)
      moves = std::abs(rot[i][k] - rot[i][k % 4]) > 1e-6f;
    if (!moves || count < 2) continue;
    if (input < 0) input = buf.AddFloats(times, 1, 0);
    for (const char* path : {"translation", "rotation"}) {
      const bool t = path[0] == 't';
      const int output = buf.AddFloats(t ? trans[i] : rot[i], t ? 3 : 4, 0);
      channels.push_back({{"sampler", samplers.size()}, {"target", {{"node", i}, {"path", path}}}});
      samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
    }
  }
  j["scenes"][0]["name"] = "simhuman";
  if (!channels.empty()) {
    j["animations"].push_back(
        {{"name", "simhuman"}, {"channels", channels}, {"samplers", samplers}});
  }
  j["buffers"] = ordered_json::array({{{"byteLength", buf.bin().size()}}});
  return PackGlb(j.dump(), buf.bin());
}

}  // namespace simhuman::render
