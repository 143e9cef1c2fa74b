#include "sim/render/gl_program.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <vector>

#include <fmt/core.h>

#include "core/error.hpp"

namespace wifislam::sim::render {

namespace {

GLuint compile(GLenum type, const std::string& source) {
  const GLuint shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1);
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw EnvironmentError(fmt::format("OpenGL {} shader does not compile: {}",
                                       type == GL_VERTEX_SHADER ? "vertex" : "fragment",
                                       log.data()));
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(const std::string& vertex_source, const std::string& fragment_source) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source);
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragment_source);
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1);
    glGetProgramInfoLog(id_, length, nullptr, log.data());
    glDeleteProgram(id_);
    throw EnvironmentError(fmt::format("OpenGL program does not link: {}", log.data()));
  }
}

GlProgram::~GlProgram() { glDeleteProgram(id_); }

void GlProgram::use() const { glUseProgram(id_); }

int GlProgram::uniform(const char* name) const {
  const GLint location = glGetUniformLocation(id_, name);
  if (location < 0) throw EnvironmentError(fmt::format("OpenGL program has no uniform '{}'", name));
  return location;
}

}  // namespace wifislam::sim::render
