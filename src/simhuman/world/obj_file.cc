#include "simhuman/world/obj_file.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace simhuman::world {
namespace {

core::Status LineError(const std::string& source, int line, const std::string& what) {
  return absl::InvalidArgumentError("mesh file '" + source + "', line " + std::to_string(line) +
                                    ": " + what);
}

// one face corner "i", "i/t", "i//n" or "i/t/n" -> a 0-based vertex index (negative indices
// count back from the last vertex read)
core::StatusOr<int> CornerIndex(const std::string& token, int num_vertices,
                                const std::string& source, int line) {
  const std::string head = token.substr(0, token.find('/'));
  long index = 0;
  size_t used = 0;
  try {
    index = std::stol(head, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != head.size() || index == 0) {
    return LineError(source, line,
                     "face corner '" + token +
                         "' is not a vertex index (valid: 1-based, "
                         "e.g. 'f 1 2 3' or 'f 1/1/1 2/2/2 3/3/3')");
  }
  const long zero_based = index > 0 ? index - 1 : num_vertices + index;
  if (zero_based < 0 || zero_based >= num_vertices) {
    return LineError(source, line,
                     "face corner " + head + " names a vertex not yet defined (" +
                         std::to_string(num_vertices) + " vertices so far)");
  }
  return static_cast<int>(zero_based);
}

}  // namespace

core::StatusOr<std::shared_ptr<const core::Mesh>> ParseObjMesh(const std::string& text,
                                                               const std::string& source) {
  auto mesh = std::make_shared<core::Mesh>();
  mesh->source = source;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    std::istringstream ls(raw);
    std::string tag;
    if (!(ls >> tag) || tag[0] == '#') continue;
    if (tag == "v") {
      double x = 0, y = 0, z = 0;
      if (!(ls >> x >> y >> z) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
        return LineError(source, line, "a vertex needs three finite numbers ('v x y z')");
      }
      if (static_cast<int>(mesh->vertices.size()) >= kObjMaxVertices) {
        return LineError(source, line,
                         "more than " + std::to_string(kObjMaxVertices) + " vertices");
      }
      mesh->vertices.emplace_back(x, y, z);
    } else if (tag == "f") {
      std::vector<int> corners;
      std::string token;
      while (ls >> token) {
        SH_ASSIGN_OR_RETURN(
            int c, CornerIndex(token, static_cast<int>(mesh->vertices.size()), source, line));
        corners.push_back(c);
      }
      if (corners.size() < 3) {
        return LineError(source, line, "a face needs at least three corners ('f 1 2 3')");
      }
      for (size_t k = 1; k + 1 < corners.size(); ++k) {
        mesh->faces.push_back({corners[0], corners[k], corners[k + 1]});
      }
    }
    // vn, vt, o, g, s, usemtl, mtllib, l, ...: not needed for a solid's shape
  }
  if (mesh->vertices.size() < 4) {
    return absl::InvalidArgumentError("mesh file '" + source + "' has " +
                                      std::to_string(mesh->vertices.size()) +
                                      " vertices; a solid needs at least 4 ('v x y z' lines)");
  }
  if (mesh->faces.empty()) {
    return absl::InvalidArgumentError("mesh file '" + source +
                                      "' has no faces ('f i j k' lines, 1-based vertex indices)");
  }
  mesh->lo = mesh->hi = mesh->vertices[0];
  for (const Eigen::Vector3d& v : mesh->vertices) {
    mesh->lo = mesh->lo.cwiseMin(v);
    mesh->hi = mesh->hi.cwiseMax(v);
  }
  const Eigen::Vector3d ext = mesh->hi - mesh->lo;
  if (ext.minCoeff() < kObjMinExtentM || ext.maxCoeff() > kObjMaxExtentM) {
    std::ostringstream e;
    e << "mesh file '" << source << "' spans " << ext.x() << " x " << ext.y() << " x " << ext.z()
      << " m; each side must be within [" << kObjMinExtentM << ", " << kObjMaxExtentM
      << "] m (vertices are read in metres)";
    return absl::InvalidArgumentError(e.str());
  }
  return std::shared_ptr<const core::Mesh>(std::move(mesh));
}

core::StatusOr<std::shared_ptr<const core::Mesh>> ReadObjMesh(const std::string& path) {
  std::ifstream f(path);
  if (!f) {
    return absl::NotFoundError("mesh file '" + path +
                               "' cannot be read (a relative path is read from the current "
                               "directory)");
  }
  std::stringstream text;
  text << f.rdbuf();
  return ParseObjMesh(text.str(), path);
}

}  // namespace simhuman::world
