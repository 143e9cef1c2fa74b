#include "sim/render/gl_texture.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <opencv2/core.hpp>

namespace wifislam::sim::render {

GlTexture::GlTexture(const TextureImage& image) : emissive_(image.emissive) {
  // Image row 0 is the top; texture coordinate t = 0 is the bottom (v grows upwards).
  cv::Mat flipped;
  cv::flip(image.bgr, flipped, 0);
  if (!flipped.isContinuous()) flipped = flipped.clone();
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, flipped.cols, flipped.rows, 0, GL_BGR, GL_UNSIGNED_BYTE,
               flipped.data);
  glGenerateMipmap(GL_TEXTURE_2D);
  const GLint wrap = image.fit_to_face ? GL_CLAMP_TO_EDGE : GL_REPEAT;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

GlTexture::~GlTexture() { glDeleteTextures(1, &id_); }

void GlTexture::bind() const {
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, id_);
}

}  // namespace wifislam::sim::render
