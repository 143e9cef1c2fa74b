// `wifislam info`: this build's version and the version of every library it uses (for bug
// reports: another Mesa renders other pixels, another OpenCV finds other features). A library
// that can say which version is loaded says so at run time; the others give the version of the
// headers the build used. yaml-cpp's headers carry no version: Debian's package says it.
#include <CGAL/version.h>
#include <cairo.h>
#include <ceres/version.h>
#include <embree3/rtcore_config.h>
#include <fmt/core.h>
#include <gdal.h>
#include <geos_c.h>
#include <ogr_srs_api.h>
#include <openssl/crypto.h>
#include <png.h>
#include <spdlog/version.h>
#include <sqlite3.h>
#include <zlib.h>
#include <CLI/Version.hpp>
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <opencv2/core/utility.hpp>

#include "apps/command_registry.hpp"
#include "core/error.hpp"
#include "sim/render/osmesa_context.hpp"

namespace wifislam::cli {

namespace {

/// OpenGL through OSMesa, as the renderer gets it; why not, when it cannot.
std::string opengl_version() {
  try {
    const sim::render::OsmesaContext context;
    return context.gl_version() + " (" + context.gl_renderer() + ")";
  } catch (const EnvironmentError& error) {
    return std::string("unavailable: ") + error.what();
  }
}

void print_versions() {
  int proj_major = 0, proj_minor = 0, proj_patch = 0;
  OSRGetPROJVersion(&proj_major, &proj_minor, &proj_patch);
  fmt::print("wifislam   {}\n", WIFISLAM_VERSION);
  fmt::print("scenes     {}\n", WIFISLAM_SCENES_DIR);
  fmt::print("OpenGL     {}\n", opengl_version());
  fmt::print("OpenCV     {}\n", cv::getVersionString());
  fmt::print("Embree     {}\n", RTC_VERSION_STRING);
  fmt::print("Ceres      {}\n", CERES_VERSION_STRING);
  fmt::print("Eigen      {}.{}.{}\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION,
             EIGEN_MINOR_VERSION);
  fmt::print("CGAL       {}\n", CGAL_VERSION_STR);
  fmt::print("GDAL       {}\n", GDALVersionInfo("RELEASE_NAME"));
  fmt::print("PROJ       {}.{}.{}\n", proj_major, proj_minor, proj_patch);
  fmt::print("GEOS       {}\n", GEOSversion());
  fmt::print("SQLite     {}\n", sqlite3_libversion());
  fmt::print("cairo      {}\n", cairo_version_string());
  fmt::print("OpenSSL    {}\n", OpenSSL_version(OPENSSL_VERSION));
  // libpng and zlib write every PNG of a dataset: their versions decide its bytes.
  fmt::print("libpng     {}\n", png_get_libpng_ver(nullptr));
  fmt::print("zlib       {}\n", zlibVersion());
  fmt::print("nlohmann   {}.{}.{}\n", NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR,
             NLOHMANN_JSON_VERSION_PATCH);
  fmt::print("fmt        {}.{}.{}\n", FMT_VERSION / 10000, FMT_VERSION / 100 % 100,
             FMT_VERSION % 100);
  fmt::print("spdlog     {}.{}.{}\n", SPDLOG_VER_MAJOR, SPDLOG_VER_MINOR, SPDLOG_VER_PATCH);
  fmt::print("CLI11      {}\n", CLI11_VERSION);
}

}  // namespace

WIFISLAM_COMMAND(info, 90) {
  CLI::App* app = parent.add_subcommand(
      "info", "Print the build's version and the version of every library it uses.");
  app->callback(print_versions);
}

}  // namespace wifislam::cli
