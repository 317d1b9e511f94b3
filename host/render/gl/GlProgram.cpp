#include "GlProgram.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdio>
#include <vector>

#include "EglContext.hpp"

namespace arp::host {

namespace {

unsigned compile(GLenum kind, const std::string& src, const std::string& name) {
  const GLuint s = glCreateShader(kind);
  const char* text = src.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint n = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &n);
    std::vector<char> log(static_cast<size_t>(n > 0 ? n : 1) + 1, '\0');
    glGetShaderInfoLog(s, n, nullptr, log.data());
    glDeleteShader(s);
    throw GlUnavailable(name + (kind == GL_VERTEX_SHADER ? " vertex" : " fragment") + " shader: " + log.data());
  }
  return s;
}

}  // namespace

GlProgram::GlProgram(const std::string& vs, const std::string& fs, const std::string& name) {
  const GLuint v = compile(GL_VERTEX_SHADER, vs, name);
  GLuint f = 0;
  try {
    f = compile(GL_FRAGMENT_SHADER, fs, name);
  } catch (...) {
    glDeleteShader(v);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, v);
  glAttachShader(id_, f);
  glLinkProgram(id_);
  glDeleteShader(v);
  glDeleteShader(f);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(id_, sizeof log - 1, nullptr, log);
    glDeleteProgram(id_);
    throw GlUnavailable(name + " program: " + log);
  }
}

GlProgram::~GlProgram() { glDeleteProgram(id_); }

void GlProgram::use() const { glUseProgram(id_); }

int GlProgram::uniform(const char* name) const { return glGetUniformLocation(id_, name); }

void check_gl(const char* where) {
  const GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(e));
  throw GlUnavailable(std::string("OpenGL error ") + code + " in " + where);
}

}  // namespace arp::host
