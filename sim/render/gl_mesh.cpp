#include "sim/render/gl_mesh.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include <fmt/core.h>

#include "core/error.hpp"

namespace wifislam::sim::render {

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

std::uint64_t position_key(const Eigen::Vector3f& p) {
  // Exact bit patterns: faces share vertex positions exactly when they were built from the
  // same corner.
  std::uint64_t h = 1469598103934665603ULL;
  for (int i = 0; i < 3; ++i) {
    h ^= std::bit_cast<std::uint32_t>(p[i]);
    h *= 1099511628211ULL;
  }
  return h;
}

Eigen::Vector3f face_normal(const world::Mesh& mesh, const world::Triangle& t) {
  const Eigen::Vector3f& a = mesh.positions_m[t.v[0]];
  return (mesh.positions_m[t.v[1]] - a).cross(mesh.positions_m[t.v[2]] - a).normalized();
}

// Per-triangle uv offset and scale so that each planar face of a fit-to-face texture spans [0,1].
std::vector<Eigen::Vector4f> fit_to_face_transforms(const world::Mesh& mesh,
                                                    const std::vector<TextureKey>& keys,
                                                    const std::vector<bool>& fit) {
  const std::size_t n = mesh.triangles.size();
  UnionFind faces(n);
  std::unordered_map<std::uint64_t, std::vector<int>> by_position;
  for (std::size_t i = 0; i < n; ++i) {
    if (!fit[i]) continue;
    for (std::uint32_t v : mesh.triangles[i].v) {
      by_position[position_key(mesh.positions_m[v])].push_back(static_cast<int>(i));
    }
  }
  for (const auto& [position, triangles] : by_position) {
    for (std::size_t a = 0; a < triangles.size(); ++a) {
      for (std::size_t b = a + 1; b < triangles.size(); ++b) {
        const world::Triangle& ta = mesh.triangles[triangles[a]];
        const world::Triangle& tb = mesh.triangles[triangles[b]];
        if (keys[triangles[a]] == keys[triangles[b]] &&
            face_normal(mesh, ta).dot(face_normal(mesh, tb)) > 0.999f) {
          faces.join(triangles[a], triangles[b]);
        }
      }
    }
  }
  std::vector<Eigen::AlignedBox2f> uv_bounds(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!fit[i]) continue;
    for (std::uint32_t v : mesh.triangles[i].v)
      uv_bounds[faces.find(static_cast<int>(i))].extend(mesh.uv_m[v]);
  }
  std::vector<Eigen::Vector4f> transforms(n, Eigen::Vector4f(0, 0, 1, 1));
  for (std::size_t i = 0; i < n; ++i) {
    if (!fit[i]) continue;
    const Eigen::AlignedBox2f& box = uv_bounds[faces.find(static_cast<int>(i))];
    const Eigen::Vector2f size = box.sizes().cwiseMax(1e-6f);
    transforms[i] = Eigen::Vector4f(box.min().x(), box.min().y(), 1.0f / size.x(), 1.0f / size.y());
  }
  return transforms;
}

}  // namespace

BatchedMesh batch_mesh(const world::Mesh& mesh, const TextureLayoutLookup& layout) {
  const std::size_t n = mesh.triangles.size();
  std::vector<TextureKey> keys(n);
  std::vector<bool> fit(n);
  for (std::size_t i = 0; i < n; ++i) {
    keys[i] = texture_key_of(mesh.triangles[i]);
    fit[i] = layout(keys[i]).fit_to_face;
  }
  const std::vector<Eigen::Vector4f> fit_transform = fit_to_face_transforms(mesh, keys, fit);

  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return keys[a] < keys[b]; });

  BatchedMesh out;
  out.vertices.reserve(3 * n);
  for (int i : order) {
    const world::Triangle& t = mesh.triangles[i];
    if (out.batches.empty() || !(out.batches.back().key == keys[i])) {
      MeshBatch batch;
      batch.key = keys[i];
      batch.first_vertex = static_cast<int>(out.vertices.size());
      out.batches.push_back(batch);
    }
    MeshBatch& batch = out.batches.back();
    const TextureImage& texture = layout(keys[i]);
    for (std::uint32_t v : t.v) {
      MeshVertex vertex;
      const Eigen::Vector3f& p = mesh.positions_m[v];
      const Eigen::Vector3f& nrm = mesh.normals[v];
      const Eigen::Vector2f& uv = mesh.uv_m[v];
      for (int k = 0; k < 3; ++k) {
        vertex.position_m[k] = p[k];
        vertex.normal[k] = nrm[k];
      }
      if (fit[i]) {
        const Eigen::Vector4f& f = fit_transform[i];
        vertex.texcoord[0] = (uv.x() - f[0]) * f[2];
        vertex.texcoord[1] = (uv.y() - f[1]) * f[3];
      } else {
        vertex.texcoord[0] = static_cast<float>(uv.x() / texture.period_u_m);
        vertex.texcoord[1] = static_cast<float>(uv.y() / texture.period_v_m);
      }
      out.vertices.push_back(vertex);
      batch.bounds_m.extend(p);
      ++batch.vertex_count;
    }
  }
  return out;
}

BatchedMesh chunk_mesh(const BatchedMesh& mesh, double chunk_m) {
  if (!(chunk_m > 0.0)) {
    throw InvalidInputError(fmt::format("mesh chunk size must be positive (got {})", chunk_m));
  }
  // (batch index, chunk x, chunk y) -> vertices; the map's order is the draw order.
  std::map<std::tuple<std::size_t, long, long>, std::vector<MeshVertex>> chunks;
  for (std::size_t b = 0; b < mesh.batches.size(); ++b) {
    const MeshBatch& batch = mesh.batches[b];
    for (int v = batch.first_vertex; v < batch.first_vertex + batch.vertex_count; v += 3) {
      double cx = 0.0, cy = 0.0;
      for (int q = v; q < v + 3; ++q) {
        cx += mesh.vertices[q].position_m[0] / 3.0;
        cy += mesh.vertices[q].position_m[1] / 3.0;
      }
      auto& target =
          chunks[{b, std::lround(std::floor(cx / chunk_m)), std::lround(std::floor(cy / chunk_m))}];
      target.insert(target.end(), mesh.vertices.begin() + v, mesh.vertices.begin() + v + 3);
    }
  }
  BatchedMesh out;
  out.vertices.reserve(mesh.vertices.size());
  for (const auto& [where, vertices] : chunks) {
    MeshBatch batch;
    batch.key = mesh.batches[std::get<0>(where)].key;
    batch.first_vertex = static_cast<int>(out.vertices.size());
    batch.vertex_count = static_cast<int>(vertices.size());
    for (const MeshVertex& v : vertices) {
      batch.bounds_m.extend(Eigen::Vector3f(v.position_m[0], v.position_m[1], v.position_m[2]));
    }
    out.vertices.insert(out.vertices.end(), vertices.begin(), vertices.end());
    out.batches.push_back(batch);
  }
  return out;
}

GlMesh::GlMesh(const BatchedMesh& mesh) : batches_(mesh.batches) {
  glGenVertexArrays(1, &vertex_array_);
  glBindVertexArray(vertex_array_);
  glGenBuffers(1, &vertex_buffer_);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(MeshVertex)),
               mesh.vertices.data(), GL_STATIC_DRAW);
  const auto stride = static_cast<GLsizei>(sizeof(MeshVertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(MeshVertex, position_m)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(MeshVertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(MeshVertex, texcoord)));
  glBindVertexArray(0);
}

GlMesh::~GlMesh() {
  glDeleteBuffers(1, &vertex_buffer_);
  glDeleteVertexArrays(1, &vertex_array_);
}

void GlMesh::bind() const { glBindVertexArray(vertex_array_); }

void GlMesh::draw(const MeshBatch& batch) const {
  glDrawArrays(GL_TRIANGLES, batch.first_vertex, batch.vertex_count);
}

}  // namespace wifislam::sim::render
