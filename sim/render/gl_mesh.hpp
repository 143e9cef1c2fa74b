#pragma once
// The world mesh on the GPU side: triangles expanded to vertices (flat shading needs per-face
// attributes anyway), sorted into one batch per texture so a frame is one draw per visible
// texture, each batch with its bounding box for frustum culling.

#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Geometry>

#include "sim/render/procedural_textures.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::render {

struct MeshVertex {
  float position_m[3];
  float normal[3];
  float texcoord[2];  // in texture units: 1 = one image
};

struct MeshBatch {
  TextureKey key;
  int first_vertex = 0;
  int vertex_count = 0;
  Eigen::AlignedBox3f bounds_m;
};

/// How a texture maps onto its triangles (period or fit-to-face), looked up per key.
using TextureLayoutLookup = std::function<const TextureImage&(const TextureKey&)>;

struct BatchedMesh {
  std::vector<MeshVertex> vertices;
  std::vector<MeshBatch> batches;  // ordered by key: deterministic draw order
};

/// Expands and sorts the mesh. Texture coordinates of tiling textures are uv / period; for
/// fit-to-face textures each planar face (triangles of one key joined by shared vertex positions
/// and with the same normal) gets its uv bounding box mapped onto [0, 1]^2.
BatchedMesh batch_mesh(const world::Mesh& mesh, const TextureLayoutLookup& layout);

/// Cuts every batch into square chunks of the floor plan (`chunk_m` on a side, by triangle
/// centroid), so that frustum culling skips what is out of view: a floor or wall texture
/// otherwise spans the whole building in one batch, and llvmpipe transforms, clips and bins all
/// of it every frame. Batches stay ordered by (texture key, chunk): deterministic.
BatchedMesh chunk_mesh(const BatchedMesh& mesh, double chunk_m);

/// Vertex buffer + vertex array object of a batched mesh. Needs a current GL context.
class GlMesh {
 public:
  explicit GlMesh(const BatchedMesh& mesh);
  ~GlMesh();
  GlMesh(const GlMesh&) = delete;
  GlMesh& operator=(const GlMesh&) = delete;

  const std::vector<MeshBatch>& batches() const { return batches_; }
  void bind() const;
  void draw(const MeshBatch& batch) const;

 private:
  unsigned vertex_array_ = 0, vertex_buffer_ = 0;
  std::vector<MeshBatch> batches_;
};

}  // namespace wifislam::sim::render
