#pragma once
// An off-screen OpenGL context on OSMesa (llvmpipe): no display, no GPU.
//
// One context per renderer, created once and reused for every frame (creation, shader compiles
// and texture uploads cost ~0.3 s; a frame costs a few ms). Rendering goes into framebuffer
// objects, so the context's own buffer is a tiny placeholder.
//
// llvmpipe reads LP_NUM_THREADS when the first context of the process is created; set it before
// that (unset or 0 = all cores).

#include <string>

struct osmesa_context;

namespace wifislam::sim::render {

class OsmesaContext {
 public:
  /// Creates an OpenGL >= 3.3 core-profile context. Throws EnvironmentError naming what is
  /// missing when OSMesa cannot create it or the version it gives is too old.
  OsmesaContext();
  ~OsmesaContext();
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  /// Binds the context to the calling thread (cheap when it already is). Throws EnvironmentError
  /// in a process forked from one that had rendered (see usable_in_this_process).
  void make_current();

  /// False in a child forked after its parent created a context: llvmpipe's rendering threads do
  /// not survive fork(), and a draw there would wait for them for ever. Creating a context or
  /// making one current there throws EnvironmentError instead; destructors skip the GL calls.
  static bool usable_in_this_process();

  /// GL_VERSION and GL_RENDERER strings, e.g. "4.5 (Core Profile) Mesa 22.3.6" and "llvmpipe ...".
  const std::string& gl_version() const { return gl_version_; }
  const std::string& gl_renderer() const { return gl_renderer_; }

 private:
  osmesa_context* context_ = nullptr;
  unsigned char placeholder_buffer_[4 * 4 * 4] = {};
  std::string gl_version_, gl_renderer_;
};

}  // namespace wifislam::sim::render
