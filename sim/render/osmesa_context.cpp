#include "sim/render/osmesa_context.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <unistd.h>

#include <atomic>

#include <fmt/core.h>

#include "core/error.hpp"

namespace wifislam::sim::render {

namespace {
constexpr int kPlaceholderSize = 4;

// The process whose first context started llvmpipe's rendering threads (0: none yet). A child
// forked after that inherits the contexts and the threads' queues but not the threads: its first
// draw (in a new context too) waits for them for ever. Python's multiprocessing forks by default.
std::atomic<pid_t> g_rendering_process{0};

void refuse_in_forked_child() {
  if (!OsmesaContext::usable_in_this_process()) {
    throw EnvironmentError(
        "cannot render in this process: it was forked from one that had rendered, and OSMesa's "
        "rendering threads (llvmpipe) do not survive fork(); render in processes started "
        "afresh (Python: multiprocessing's 'spawn' or 'forkserver' start method)");
  }
}
}  // namespace

bool OsmesaContext::usable_in_this_process() {
  const pid_t first = g_rendering_process.load();
  return first == 0 || first == ::getpid();
}

OsmesaContext::OsmesaContext() {
  refuse_in_forked_child();
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context_ == nullptr) {
    throw EnvironmentError(
        "OSMesa could not create an OpenGL 3.3 core-profile context (OSMesaCreateContextAttribs "
        "returned NULL); install Mesa's OSMesa with llvmpipe (Debian: libosmesa6) and do not set "
        "GALLIUM_DRIVER to a driver without GL 3.3");
  }
  if (!OSMesaMakeCurrent(context_, placeholder_buffer_, GL_UNSIGNED_BYTE, kPlaceholderSize,
                         kPlaceholderSize)) {
    OSMesaDestroyContext(context_);
    throw EnvironmentError("OSMesaMakeCurrent failed for a new OpenGL context");
  }
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (version == nullptr || renderer == nullptr) {
    OSMesaDestroyContext(context_);
    throw EnvironmentError(
        "OpenGL returns no GL_VERSION through OSMesa: libGL was probably linked before libOSMesa "
        "(link OSMesa first and not libGL)");
  }
  pid_t none = 0;
  g_rendering_process.compare_exchange_strong(none, ::getpid());
  gl_version_ = version;
  gl_renderer_ = renderer;
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major < 3 || (major == 3 && minor < 3)) {
    OSMesaDestroyContext(context_);
    throw EnvironmentError(
        fmt::format("OSMesa gives OpenGL {}.{} ({}), the renderer needs 3.3 core or newer", major,
                    minor, gl_version_));
  }
}

OsmesaContext::~OsmesaContext() {
  // In a forked child the inherited context is left alone: destroying it waits on the threads.
  if (context_ != nullptr && usable_in_this_process()) OSMesaDestroyContext(context_);
}

void OsmesaContext::make_current() {
  refuse_in_forked_child();
  if (OSMesaGetCurrentContext() == context_) return;
  if (!OSMesaMakeCurrent(context_, placeholder_buffer_, GL_UNSIGNED_BYTE, kPlaceholderSize,
                         kPlaceholderSize)) {
    throw EnvironmentError("OSMesaMakeCurrent failed for the renderer's OpenGL context");
  }
}

}  // namespace wifislam::sim::render
