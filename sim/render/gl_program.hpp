#pragma once
// A linked GLSL program. Needs a current GL context.

#include <string>

namespace wifislam::sim::render {

class GlProgram {
 public:
  /// Compiles and links; throws EnvironmentError with the driver's log when that fails.
  GlProgram(const std::string& vertex_source, const std::string& fragment_source);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  unsigned id() const { return id_; }
  void use() const;
  /// Location of a uniform; throws EnvironmentError when the program has no such uniform.
  int uniform(const char* name) const;

 private:
  unsigned id_ = 0;
};

}  // namespace wifislam::sim::render
