// A linked GLSL program from vertex and fragment source (a current context
// needed); compile and link logs become the GlUnavailable message.
#pragma once
#include <string>

namespace arp::host {

class GlProgram {
 public:
  GlProgram(const std::string& vertex_src, const std::string& fragment_src, const std::string& name);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;
  unsigned id() const { return id_; }
  void use() const;
  int uniform(const char* name) const;  // -1 if the linker removed it

 private:
  unsigned id_ = 0;
};

// GL_NO_ERROR or GlUnavailable naming `where` and the error.
void check_gl(const char* where);

}  // namespace arp::host
