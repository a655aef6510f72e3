// OpenGL through OSMesa only (never libGL: its stubs draw black frames).
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <string>

namespace render {

/// An off-screen OpenGL 3.3 core context (OSMesa, llvmpipe) drawing into a framebuffer object
/// with colour and depth.
class GlContext {
 public:
  GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  ~GlContext();

  /// Creates the context and the FBO; an error message when impossible.
  std::string create(int width, int height);
  /// Reads the FBO's pixels, rows top to bottom.
  void readPixels(unsigned char* rgba) const;

 private:
  OSMesaContext context_ = nullptr;
  std::string buffer_;  // OSMesa's own (unused) colour buffer
  GLuint fbo_ = 0, color_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
};

/// Compiles and links a program from two files under the assets folder; throws on failure
/// with the compiler's log.
GLuint loadProgram(const std::string& vertex_file, const std::string& fragment_file);

/// The assets folder (shaders/, fonts.txt): $RATTLEBACK_ASSETS when set; else, found from the
/// executable's own folder (/proc/self/exe), <exe dir>/../share/rattleback (the installed
/// layout bin/ → share/rattleback, any prefix) or the build tree's copy <build>/share/rattleback
/// for programs in <build>/app, <build>/tests, <build>/bench. No absolute path is compiled in.
std::string assetsDir();

}  // namespace render
