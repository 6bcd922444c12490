#include "simhuman/render/geom_mesh.h"

#include <algorithm>
#include <cmath>

namespace simhuman::render {
namespace {

// one point of a profile revolved about z: radius, height and the profile's outward normal
struct ProfilePoint {
  double r, z, nr, nz;
};

void AddVertex(TriMesh* mesh, double x, double y, double z, double nx, double ny, double nz) {
  const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
  const double s = len > 0 ? 1.0 / len : 0.0;
  for (double v : {x, y, z}) mesh->position.push_back(static_cast<float>(v));
  for (double v : {nx * s, ny * s, nz * s}) mesh->normal.push_back(static_cast<float>(v));
}

// revolves a profile (bottom to top) about z; zero-radius ends become fans
void Lathe(const std::vector<ProfilePoint>& profile, int segments, TriMesh* mesh) {
  const uint32_t base = static_cast<uint32_t>(mesh->num_vertices());
  const int cols = segments + 1;  // the seam is duplicated, so each ring is a strip
  for (const ProfilePoint& p : profile) {
    for (int i = 0; i < cols; ++i) {
      const double a = 2 * M_PI * i / segments;
      const double c = std::cos(a), s = std::sin(a);
      AddVertex(mesh, p.r * c, p.r * s, p.z, p.nr * c, p.nr * s, p.nz);
    }
  }
  for (size_t k = 0; k + 1 < profile.size(); ++k) {
    for (int i = 0; i < segments; ++i) {
      const uint32_t a = base + static_cast<uint32_t>(k * cols + i);
      const uint32_t b = a + 1, c = a + cols, d = a + cols + 1;
      // skip the degenerate triangle at a pole
      if (profile[k].r > 1e-12) mesh->index.insert(mesh->index.end(), {a, b, d});
      if (profile[k + 1].r > 1e-12) mesh->index.insert(mesh->index.end(), {a, d, c});
    }
  }
}

// a hemisphere (upper when `up`), centred at height z0, as profile points bottom to top
std::vector<ProfilePoint> Hemisphere(double r, double z0, bool up, int rings) {
  std::vector<ProfilePoint> out;
  for (int k = 0; k <= rings; ++k) {
    // polar angle from the bottom pole (0) to the equator (pi/2), or equator to top pole
    const double t = up ? M_PI / 2 + M_PI / 2 * k / rings : M_PI / 2 * k / rings;
    const double nr = std::sin(t), nz = -std::cos(t);
    out.push_back({r * nr, z0 + r * nz, nr, nz});
  }
  return out;
}

void Box(double hx, double hy, double hz, TriMesh* mesh) {
  // per face: normal axis, sign; the other two axes span it
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign : {-1, 1}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const double h[3] = {hx, hy, hz};
      const uint32_t base = static_cast<uint32_t>(mesh->num_vertices());
      for (int corner = 0; corner < 4; ++corner) {
        double p[3], n[3] = {0, 0, 0};
        p[axis] = sign * h[axis];
        p[u] = ((corner == 1 || corner == 2) ? 1 : -1) * h[u];
        p[v] = (corner >= 2 ? 1 : -1) * h[v];
        n[axis] = sign;
        AddVertex(mesh, p[0], p[1], p[2], n[0], n[1], n[2]);
      }
      // corners 0 (-u,-v), 1 (+u,-v), 2 (+u,+v), 3 (-u,+v): counter-clockwise about +axis
      if (sign > 0) {
        mesh->index.insert(mesh->index.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
      } else {
        mesh->index.insert(mesh->index.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
      }
    }
  }
}

void MeshGeom(const mjModel* m, int mesh_id, TriMesh* mesh) {
  const int vadr = m->mesh_vertadr[mesh_id], nv = m->mesh_vertnum[mesh_id];
  const int fadr = m->mesh_faceadr[mesh_id], nf = m->mesh_facenum[mesh_id];
  // flat shading: three vertices per face with the face normal
  for (int f = 0; f < nf; ++f) {
    const int* face = m->mesh_face + 3 * (fadr + f);
    const float* p[3];
    for (int k = 0; k < 3; ++k) p[k] = m->mesh_vert + 3 * (vadr + std::clamp(face[k], 0, nv - 1));
    const double e1[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double e2[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                         e1[0] * e2[1] - e1[1] * e2[0]};
    const uint32_t base = static_cast<uint32_t>(mesh->num_vertices());
    for (int k = 0; k < 3; ++k) AddVertex(mesh, p[k][0], p[k][1], p[k][2], n[0], n[1], n[2]);
    mesh->index.insert(mesh->index.end(), {base, base + 1, base + 2});
  }
}

}  // namespace

TriMesh GeomMesh(const mjModel* m, int g, int segments, double infinite_plane_half_m) {
  TriMesh mesh;
  segments = std::max(segments, 3);
  const int rings = std::max(segments / 4, 2);
  const mjtNum* size = m->geom_size + 3 * g;
  switch (m->geom_type[g]) {
    case mjGEOM_PLANE: {
      const double hx = size[0] > 0 ? size[0] : infinite_plane_half_m;
      const double hy = size[1] > 0 ? size[1] : infinite_plane_half_m;
      AddVertex(&mesh, -hx, -hy, 0, 0, 0, 1);
      AddVertex(&mesh, hx, -hy, 0, 0, 0, 1);
      AddVertex(&mesh, hx, hy, 0, 0, 0, 1);
      AddVertex(&mesh, -hx, hy, 0, 0, 0, 1);
      mesh.index = {0, 1, 2, 0, 2, 3};
      break;
    }
    case mjGEOM_SPHERE:
    case mjGEOM_ELLIPSOID: {
      std::vector<ProfilePoint> p = Hemisphere(1, 0, false, rings);
      std::vector<ProfilePoint> top = Hemisphere(1, 0, true, rings);
      p.insert(p.end(), top.begin() + 1, top.end());
      Lathe(p, segments, &mesh);
      const bool ellipsoid = m->geom_type[g] == mjGEOM_ELLIPSOID;
      const double r[3] = {size[0], ellipsoid ? size[1] : size[0], ellipsoid ? size[2] : size[0]};
      for (int v = 0; v < mesh.num_vertices(); ++v) {
        double n[3];
        for (int k = 0; k < 3; ++k) {
          mesh.position[3 * v + k] *= static_cast<float>(r[k]);
          n[k] = mesh.normal[3 * v + k] / r[k];
        }
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; ++k) mesh.normal[3 * v + k] = static_cast<float>(n[k] / len);
      }
      break;
    }
    case mjGEOM_CAPSULE: {
      std::vector<ProfilePoint> p = Hemisphere(size[0], -size[1], false, rings);
      std::vector<ProfilePoint> top = Hemisphere(size[0], size[1], true, rings);
      p.insert(p.end(), top.begin(), top.end());
      Lathe(p, segments, &mesh);
      break;
    }
    case mjGEOM_CYLINDER: {
      const double r = size[0], h = size[1];
      Lathe({{0, -h, 0, -1}, {r, -h, 0, -1}}, segments, &mesh);
      Lathe({{r, -h, 1, 0}, {r, h, 1, 0}}, segments, &mesh);
      Lathe({{r, h, 0, 1}, {0, h, 0, 1}}, segments, &mesh);
      break;
    }
    case mjGEOM_BOX:
      Box(size[0], size[1], size[2], &mesh);
      break;
    case mjGEOM_MESH:
      if (m->geom_dataid[g] >= 0) MeshGeom(m, m->geom_dataid[g], &mesh);
      break;
    default:
      break;
  }
  return mesh;
}

}  // namespace simhuman::render
