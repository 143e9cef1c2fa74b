// Cutting texture batches into plan chunks (for frustum culling) keeps every triangle exactly
// once, puts each in the chunk of its centroid, and keeps batches ordered by texture key.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "sim/render/gl_mesh.hpp"
#include "sim/render/procedural_textures.hpp"
#include "tests/sim/render/test_meshes.hpp"

namespace wifislam::sim {
namespace {

using TriangleCorners = std::array<float, 9>;

std::vector<TriangleCorners> triangles_of(const render::BatchedMesh& mesh) {
  std::vector<TriangleCorners> out;
  for (std::size_t v = 0; v < mesh.vertices.size(); v += 3) {
    TriangleCorners t{};
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) t[3 * c + k] = mesh.vertices[v + c].position_m[k];
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ChunkMesh, KeepsEveryTriangleOnceInTheChunkOfItsCentroid) {
  const test::HandCorridor corridor = test::hand_corridor();
  const render::ProceduralTextures textures(3, scene::AppearanceThemes{});
  std::map<render::TextureKey, render::TextureImage> images;
  for (const world::Triangle& t : corridor.mesh.triangles) {
    if (!images.contains(render::texture_key_of(t)))
      images.emplace(render::texture_key_of(t), textures.make(render::texture_key_of(t)));
  }
  const render::BatchedMesh whole = render::batch_mesh(
      corridor.mesh,
      [&](const render::TextureKey& key) -> const render::TextureImage& { return images.at(key); });
  constexpr double kChunkM = 4.0;
  const render::BatchedMesh chunked = render::chunk_mesh(whole, kChunkM);

  EXPECT_EQ(triangles_of(chunked), triangles_of(whole));
  EXPECT_GT(chunked.batches.size(), whole.batches.size());  // the 20 m corridor spans chunks
  int covered = 0;
  for (std::size_t b = 0; b < chunked.batches.size(); ++b) {
    const render::MeshBatch& batch = chunked.batches[b];
    if (b > 0) {
      EXPECT_FALSE(batch.key < chunked.batches[b - 1].key) << "batch " << b;
    }
    EXPECT_EQ(batch.first_vertex, covered);
    covered += batch.vertex_count;
    std::set<std::pair<long, long>> cells;
    for (int v = batch.first_vertex; v < batch.first_vertex + batch.vertex_count; v += 3) {
      double cx = 0.0, cy = 0.0;
      for (int q = v; q < v + 3; ++q) {
        const render::MeshVertex& vertex = chunked.vertices[q];
        EXPECT_TRUE(batch.bounds_m.contains(
            Eigen::Vector3f(vertex.position_m[0], vertex.position_m[1], vertex.position_m[2])));
        cx += vertex.position_m[0] / 3.0;
        cy += vertex.position_m[1] / 3.0;
      }
      cells.emplace(std::lround(std::floor(cx / kChunkM)), std::lround(std::floor(cy / kChunkM)));
    }
    EXPECT_EQ(cells.size(), 1u) << "batch " << b << " mixes chunks";
  }
  EXPECT_EQ(covered, static_cast<int>(chunked.vertices.size()));
  EXPECT_THROW(render::chunk_mesh(whole, 0.0), InvalidInputError);
}

}  // namespace
}  // namespace wifislam::sim
