#include "sim/render/rgbd_renderer.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

#include <fmt/core.h>
#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/core/utility.hpp>

#include "core/error.hpp"
#include "sim/render/gl_mesh.hpp"
#include "sim/render/gl_program.hpp"
#include "sim/render/gl_texture.hpp"
#include "sim/render/osmesa_context.hpp"

namespace wifislam::sim::render {

namespace {

constexpr int kMaxLightsInShader = 8;

// The normal is turned toward the camera per vertex (the sign of n . (p - c) is the same at all
// three corners of a planar triangle), and so is the distance of the triangle's plane from the
// camera, |n . (p - c)|: both are constant over a triangle, so they are passed `flat`.
const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position_m;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 texcoord;
uniform mat4 world_to_clip;
uniform vec3 camera_position;
out vec3 world_position;
flat out vec3 face_normal;
flat out float plane_distance_m;
out vec2 uv;
void main() {
  world_position = position_m;
  float signed_distance = dot(normal, position_m - camera_position);
  face_normal = signed_distance > 0.0 ? -normal : normal;
  plane_distance_m = abs(signed_distance);
  uv = texcoord;
  gl_Position = world_to_clip * vec4(position_m, 1.0);
}
)";

// Diffuse (Lambert) shading from downward-facing ceiling panels with inverse-square falloff
// (softened by +1 m^2 so a surface touching a light does not blow up), plus ambient. For a
// light at offset d from the surface, cos(surface) cos(panel) / (|d|^2 + 1) is
// (n . d) d.z / (|d|^2 (|d|^2 + 1)): no square roots. No branches and a loop of constant length:
// llvmpipe runs divergent control flow and dynamically indexed uniform arrays several times
// slower. MAX_LIGHTS is defined when the program is built.
// Alpha carries |cos| of the incidence angle, plane distance / ray length (8 bits, for the sensor
// model's grazing dropouts): one RGBA8 target plus the z-buffer is what a bare render reads back
// too, where separate float targets for depth and incidence cost ~40 % of the frame in llvmpipe.
const char* kFragmentShader = R"(
in vec3 world_position;
flat in vec3 face_normal;
flat in float plane_distance_m;
in vec2 uv;
uniform sampler2D albedo;
uniform vec3 camera_position;
uniform float emissive;
uniform float ambient;
uniform float light_weights[MAX_LIGHTS];
uniform vec3 light_positions[MAX_LIGHTS];
out vec4 color;
void main() {
  vec3 ray = world_position - camera_position;
  float incidence = plane_distance_m * inversesqrt(dot(ray, ray));
  float irradiance = ambient;
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    vec3 d = light_positions[i] - world_position;
    float d2 = dot(d, d);
    irradiance += light_weights[i] * max(dot(face_normal, d), 0.0) * max(d.z, 0.0) /
                  (d2 * (d2 + 1.0));
  }
  color = vec4(texture(albedo, uv).rgb * mix(irradiance, 1.0, emissive), incidence);
}
)";

bool box_outside_frustum(const Eigen::AlignedBox3f& box, const Eigen::Matrix4f& world_to_clip) {
  Eigen::Matrix<float, 4, 8> corners;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3f c = box.corner(static_cast<Eigen::AlignedBox3f::CornerType>(i));
    corners.col(i) = world_to_clip * c.homogeneous();
  }
  for (int axis = 0; axis < 3; ++axis) {
    if ((corners.row(axis).array() < -corners.row(3).array()).all()) return true;
    if ((corners.row(axis).array() > corners.row(3).array()).all()) return true;
  }
  return false;
}

#if defined(__x86_64__) && defined(__GNUC__)
// unpack()'s vector loop 16 pixels at a time with 256-bit registers, on CPUs that have AVX2 (the
// build targets plain x86-64, so OpenCV's universal intrinsics stop at 128 bits): the pass is
// ~1/10 of the harness's CPU time per frame. The same float operations in the same order as the
// portable loop (a masked AND is v_select with zero; no FMA, which would round differently),
// so every output value is bit-identical. Returns the first pixel left to do.
__attribute__((target("avx2"))) int unpack_row_avx2(const float* window, const std::uint8_t* bgra,
                                                    int w, float numerator, float offset,
                                                    float* depth_m, float* incidence,
                                                    std::uint8_t* bgr) {
  const __m256 v_numerator = _mm256_set1_ps(numerator), v_offset = _mm256_set1_ps(offset),
               one = _mm256_set1_ps(1.0f), per_step = _mm256_set1_ps(1.0f / 255.0f);
  // Within each 128-bit lane of four BGRA pixels: their 12 BGR bytes, then their 4 alphas.
  const __m256i split = _mm256_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 3, 7, 11, 15, 0, 1,
                                         2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 3, 7, 11, 15);
  // Then across lanes: 24 BGR bytes of eight pixels, then their 8 alphas.
  const __m256i gather = _mm256_setr_epi32(0, 1, 2, 4, 5, 6, 3, 7);
  int x = 0;
  for (; x + 16 <= w; x += 16) {
    const __m256i lo = _mm256_permutevar8x32_epi32(
        _mm256_shuffle_epi8(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(bgra + 4 * x)),
                            split),
        gather);
    const __m256i hi = _mm256_permutevar8x32_epi32(
        _mm256_shuffle_epi8(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(bgra + 4 * x + 32)),
                            split),
        gather);
    // 48 BGR bytes: lo's 24 (its last 8 bytes are overwritten by hi's), then hi's 24.
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(bgr + 3 * x), lo);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(bgr + 3 * x + 24), _mm256_castsi256_si128(hi));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(bgr + 3 * x + 40), _mm256_extracti128_si256(hi, 1));
    for (int half = 0; half < 2; ++half) {
      const __m128i alphas = _mm_srli_si128(_mm256_extracti128_si256(half == 0 ? lo : hi, 1), 8);
      _mm256_storeu_ps(incidence + x + 8 * half,
                       _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(alphas)), per_step));
      const __m256 z = _mm256_loadu_ps(window + x + 8 * half);
      _mm256_storeu_ps(depth_m + x + 8 * half,
                       _mm256_and_ps(_mm256_cmp_ps(z, one, _CMP_LT_OQ),
                                     _mm256_div_ps(v_numerator, _mm256_sub_ps(v_offset, z))));
    }
  }
  return x;
}
#endif

}  // namespace

Eigen::Matrix4f RgbdRenderer::projection_matrix(const CameraIntrinsics& k, double near_m,
                                                double far_m) {
  // Pixel (u, v) of the image (OpenCV: integer coordinates at pixel centres) is the window
  // pixel whose centre is at (u + 0.5, v + 0.5); window row 0 is read back first, so v = 0 maps
  // to the bottom of clip space (no sign flip on y: the optical frame's y already points down).
  const double w = k.width_px, h = k.height_px;
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = 2.0 * k.fx_px / w;
  p(0, 2) = (2.0 * k.cx_px + 1.0) / w - 1.0;
  p(1, 1) = 2.0 * k.fy_px / h;
  p(1, 2) = (2.0 * k.cy_px + 1.0) / h - 1.0;
  p(2, 2) = (far_m + near_m) / (far_m - near_m);
  p(2, 3) = -2.0 * far_m * near_m / (far_m - near_m);
  p(3, 2) = 1.0;
  return p.cast<float>();
}

RgbdRenderer::RgbdRenderer(const CameraIntrinsics& intrinsics, const RenderOptions& options)
    : intrinsics_(intrinsics), options_(options) {
  if (intrinsics.width_px <= 0 || intrinsics.height_px <= 0 || intrinsics.fx_px <= 0 ||
      intrinsics.fy_px <= 0) {
    throw InvalidInputError(fmt::format(
        "camera intrinsics: width/height/fx/fy must be positive (got {}x{}, fx {}, fy {})",
        intrinsics.width_px, intrinsics.height_px, intrinsics.fx_px, intrinsics.fy_px));
  }
  if (options.max_lights < 0 || options.max_lights > kMaxLightsInShader) {
    throw InvalidInputError(fmt::format("render options: max_lights must be in 0..{} (got {})",
                                        kMaxLightsInShader, options.max_lights));
  }
  context_ = std::make_unique<OsmesaContext>();
  const std::string fragment_source = fmt::format("#version 330 core\n#define MAX_LIGHTS {}\n{}",
                                                  std::max(options.max_lights, 1), kFragmentShader);
  program_ = std::make_unique<GlProgram>(kVertexShader, fragment_source);
  uniforms_ = {program_->uniform("world_to_clip"),
               program_->uniform("camera_position"),
               program_->uniform("emissive"),
               program_->uniform("ambient"),
               program_->uniform("light_weights[0]"),
               program_->uniform("light_positions[0]"),
               program_->uniform("albedo")};

  const int w = intrinsics.width_px, h = intrinsics.height_px;
  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  auto make_target = [&](GLenum internal_format, GLenum attachment) {
    GLuint id = 0;
    glGenRenderbuffers(1, &id);
    glBindRenderbuffer(GL_RENDERBUFFER, id);
    glRenderbufferStorage(GL_RENDERBUFFER, internal_format, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, id);
    return id;
  };
  color_target_ = make_target(GL_RGBA8, GL_COLOR_ATTACHMENT0);
  z_buffer_ = make_target(GL_DEPTH_COMPONENT32F, GL_DEPTH_ATTACHMENT);
  const GLenum draw_buffers[] = {GL_COLOR_ATTACHMENT0};
  glDrawBuffers(1, draw_buffers);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw EnvironmentError(
        fmt::format("OpenGL framebuffer for {}x{} RGB-D rendering is incomplete (status 0x{:x})", w,
                    h, status));
  }
  glViewport(0, 0, w, h);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // the y-flipped projection mirrors winding; walls are two-sided
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);  // black, incidence 0 where nothing is drawn
  glReadBuffer(GL_COLOR_ATTACHMENT0);
}

RgbdRenderer::~RgbdRenderer() {
  // A forked child's copy of a renderer cannot make GL calls (osmesa_context.hpp); its memory
  // is the child's copy, released with it.
  if (!OsmesaContext::usable_in_this_process()) {
    static_cast<void>(mesh_.release());
    for (auto& [key, texture] : textures_) static_cast<void>(texture.release());
    static_cast<void>(program_.release());
    return;
  }
  context_->make_current();
  mesh_.reset();
  textures_.clear();
  program_.reset();
  const GLuint targets[] = {color_target_, z_buffer_};
  glDeleteRenderbuffers(2, targets);
  glDeleteFramebuffers(1, &framebuffer_);
}

void RgbdRenderer::set_world(const world::Mesh& mesh,
                             const std::vector<world::CeilingLight>& lights, std::uint64_t seed,
                             const scene::AppearanceThemes& themes) {
  context_->make_current();
  const ProceduralTextures generator(seed, themes);
  std::vector<TextureKey> keys;
  for (const world::Triangle& t : mesh.triangles) keys.push_back(texture_key_of(t));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  // Each texture draws from its own random stream, so generating them in parallel gives the
  // same images in any order.
  std::vector<TextureImage> made(keys.size());
  cv::parallel_for_(cv::Range(0, static_cast<int>(keys.size())), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) made[i] = generator.make(keys[i]);
  });
  std::map<TextureKey, TextureImage> images;
  for (std::size_t i = 0; i < keys.size(); ++i) images.emplace(keys[i], std::move(made[i]));
  const BatchedMesh batched = chunk_mesh(
      batch_mesh(mesh,
                 [&](const TextureKey& key) -> const TextureImage& { return images.at(key); }),
      options_.chunk_m);
  mesh_.reset();
  textures_.clear();
  for (const auto& [key, image] : images)
    textures_.emplace(key, std::make_unique<GlTexture>(image));
  mesh_ = std::make_unique<GlMesh>(batched);
  lights_ = lights;
}

void RgbdRenderer::set_world(const world::World& world, const scene::Scene& scene) {
  set_world(world.mesh, world.plan.lights, scene.seed, scene.appearance.themes);
}

void RgbdRenderer::upload_lights(const Eigen::Vector3d& camera_position_m) {
  std::vector<std::pair<double, int>> by_distance;
  for (int i = 0; i < static_cast<int>(lights_.size()); ++i) {
    by_distance.emplace_back((lights_[i].center_m - camera_position_m).norm(), i);
  }
  std::sort(by_distance.begin(), by_distance.end());  // ties broken by index: deterministic
  const int slots = std::max(options_.max_lights, 1);
  // A light's weight fades to zero as it approaches the range limit or the distance of the
  // nearest light left out, so lights enter and leave the shaded set smoothly as the camera
  // moves instead of popping (a brightness jump would look like a scene change to SLAM).
  double cutoff_m = options_.light_range_m;
  if (static_cast<int>(by_distance.size()) > options_.max_lights) {
    cutoff_m = std::min(cutoff_m, by_distance[options_.max_lights].first);
  }
  std::vector<float> weights(slots, 0.0f);
  std::vector<float> positions(3 * static_cast<std::size_t>(slots));
  for (int i = 0; i < slots; ++i) {
    Eigen::Vector3d p = camera_position_m + Eigen::Vector3d(0, 0, 1000.0);  // unused slot
    if (i < options_.max_lights && i < static_cast<int>(by_distance.size())) {
      const auto [distance_m, index] = by_distance[i];
      // Just below the panel: the ceiling around a light gets no direct light (and no 1/0).
      p = lights_[index].center_m - Eigen::Vector3d(0, 0, 0.05);
      const double fade = std::clamp((cutoff_m - distance_m) / options_.light_fade_m, 0.0, 1.0);
      weights[i] = static_cast<float>(options_.light_power * fade);
    }
    for (int k = 0; k < 3; ++k) positions[3 * i + k] = static_cast<float>(p[k]);
  }
  glUniform1fv(uniforms_.light_weights, slots, weights.data());
  glUniform3fv(uniforms_.light_positions, slots, positions.data());
}

void RgbdRenderer::submit(const Pose& camera_to_world) {
  if (submitted_) throw std::logic_error("RgbdRenderer::submit: the last view was not collected");
  context_->make_current();
  const Eigen::Matrix4f world_to_clip =
      projection_matrix(intrinsics_, options_.near_m, options_.far_m) *
      camera_to_world.inverse().matrix().cast<float>();

  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  last_draw_count_ = 0;
  if (mesh_) {
    program_->use();
    glUniformMatrix4fv(uniforms_.world_to_clip, 1, GL_FALSE, world_to_clip.data());
    const Eigen::Vector3f camera_position = camera_to_world.translation().cast<float>();
    glUniform3fv(uniforms_.camera_position, 1, camera_position.data());
    glUniform1f(uniforms_.ambient, options_.ambient);
    glUniform1i(uniforms_.albedo, 0);
    upload_lights(camera_to_world.translation());
    mesh_->bind();
    for (const MeshBatch& batch : mesh_->batches()) {
      if (options_.frustum_culling && box_outside_frustum(batch.bounds_m, world_to_clip)) continue;
      const GlTexture& texture = *textures_.at(batch.key);
      texture.bind();
      glUniform1f(uniforms_.emissive, texture.emissive() ? 1.0f : 0.0f);
      mesh_->draw(batch);
      ++last_draw_count_;
    }
  }

  // llvmpipe bins the draws on this thread and rasterizes on its own threads once the frame is
  // flushed: after the flush the caller is free until collect() waits for the pixels.
  glFlush();
  submitted_ = true;
}

void RgbdRenderer::collect(RenderedView& out) {
  if (!submitted_) throw std::logic_error("RgbdRenderer::collect: no view was submitted");
  submitted_ = false;
  context_->make_current();
  const int w = intrinsics_.width_px, h = intrinsics_.height_px;
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  // Read back straight into the output images and unpack in place: BGRA into the incidence
  // image (four bytes a pixel, as its floats), the z-buffer into the depth image. Separate
  // read-back buffers cost one more trip of 2.4 MB a 640x480 frame through the cache.
  out.depth_m.create(h, w, CV_32FC1);
  out.incidence_cos.create(h, w, CV_32FC1);
  out.color_bgr.create(h, w, CV_8UC3);
  glPixelStorei(GL_PACK_ROW_LENGTH, static_cast<GLint>(out.incidence_cos.step1()));
  glReadPixels(0, 0, w, h, GL_BGRA, GL_UNSIGNED_BYTE, out.incidence_cos.data);
  glPixelStorei(GL_PACK_ROW_LENGTH, static_cast<GLint>(out.depth_m.step1()));
  glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, out.depth_m.data);
  unpack(out);
}

void RgbdRenderer::unpack(RenderedView& out) const {
  const int w = intrinsics_.width_px, h = intrinsics_.height_px;
  // Window depth w in [0, 1] of a point at optical depth d is (f/(f-n)) - (f n/(f-n)) / d for
  // the projection above, so d = (f n/(f-n)) / (f/(f-n) - w); w = 1 is the cleared background.
  // With a 32-bit float z-buffer this recovers d to ~2e-5 m at 4 m and ~2 mm at 40 m.
  const double n = options_.near_m, f = options_.far_m;
  const float numerator = static_cast<float>(f * n / (f - n));
  const float offset = static_cast<float>(f / (f - n));
  // In sequence: a thread pool's wake-up and spinning workers cost more than this pass saves.
  // The vector loops and the scalar tail do the same float operations. In place: every loop
  // reads a pixel's window depth and BGRA before it writes that pixel's depth and incidence.
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool has_avx2 = __builtin_cpu_supports("avx2");
#endif
  for (int y = 0; y < h; ++y) {
    float* depth_m = out.depth_m.ptr<float>(y);
    const float* window = depth_m;
    float* incidence = out.incidence_cos.ptr<float>(y);
    const std::uint8_t* bgra = out.incidence_cos.ptr<std::uint8_t>(y);
    std::uint8_t* bgr = out.color_bgr.ptr<std::uint8_t>(y);
    int x = 0;
#if defined(__x86_64__) && defined(__GNUC__)
    if (has_avx2) x = unpack_row_avx2(window, bgra, w, numerator, offset, depth_m, incidence, bgr);
#endif
#if CV_SIMD128
    const cv::v_float32x4 v_numerator = cv::v_setall_f32(numerator),
                          v_offset = cv::v_setall_f32(offset), one = cv::v_setall_f32(1.0f),
                          zero = cv::v_setzero_f32(), per_step = cv::v_setall_f32(1.0f / 255.0f);
    for (; x + 16 <= w; x += 16) {
      cv::v_uint8x16 b, g, r, a;
      cv::v_load_deinterleave(bgra + 4 * x, b, g, r, a);
      cv::v_store_interleave(bgr + 3 * x, b, g, r);
      cv::v_uint16x8 a_lo, a_hi;
      cv::v_expand(a, a_lo, a_hi);
      cv::v_uint32x4 a_quarters[4];
      cv::v_expand(a_lo, a_quarters[0], a_quarters[1]);
      cv::v_expand(a_hi, a_quarters[2], a_quarters[3]);
      for (int k = 0; k < 4; ++k) {
        cv::v_store(incidence + x + 4 * k,
                    cv::v_cvt_f32(cv::v_reinterpret_as_s32(a_quarters[k])) * per_step);
        const cv::v_float32x4 z = cv::v_load(window + x + 4 * k);
        cv::v_store(depth_m + x + 4 * k, cv::v_select(z < one, v_numerator / (v_offset - z), zero));
      }
    }
#endif
    for (; x < w; ++x) {
      depth_m[x] = window[x] < 1.0f ? numerator / (offset - window[x]) : 0.0f;
      bgr[3 * x] = bgra[4 * x];
      bgr[3 * x + 1] = bgra[4 * x + 1];
      bgr[3 * x + 2] = bgra[4 * x + 2];
      incidence[x] = static_cast<float>(bgra[4 * x + 3]) * (1.0f / 255.0f);
    }
  }
}

void RgbdRenderer::render(const Pose& camera_to_world, RenderedView& out) {
  submit(camera_to_world);
  collect(out);
}

RenderedView RgbdRenderer::render(const Pose& camera_to_world) {
  RenderedView view;
  render(camera_to_world, view);
  return view;
}

}  // namespace wifislam::sim::render
