#pragma once
// A procedural texture uploaded as a mipmapped OpenGL texture. Needs a current GL context.

#include "sim/render/procedural_textures.hpp"

namespace wifislam::sim::render {

class GlTexture {
 public:
  explicit GlTexture(const TextureImage& image);
  ~GlTexture();
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  void bind() const;  // to texture unit 0
  bool emissive() const { return emissive_; }

 private:
  unsigned id_ = 0;
  bool emissive_ = false;
};

}  // namespace wifislam::sim::render
