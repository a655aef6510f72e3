// OpenGL off screen, through one of two backends behind one interface:
//   - EGL (libglvnd's libEGL with Mesa's EGL vendor library, or a GPU's): the device platform
//     where a GPU is present, else the surfaceless platform (llvmpipe); the way Mesa renders
//     without a display since Mesa 25.1 removed OSMesa;
//   - OSMesa (Debian 12's libOSMesa.so.8), opened at run time with dlopen, so that the program
//     also starts on a system without it.
// No GL function is linked: every one is looked up from the backend in use (OSMesaGetProcAddress,
// eglGetProcAddress) into a table, so libGL's stubs can never take a call meant for OSMesa (they
// would draw black frames), and the two backends can be linked into one program.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <memory>
#include <string>
#include <vector>

#include "render/exit_gate.hpp"
#include "render/frame.hpp"
#include "util/result.hpp"

namespace render {

// The GL functions the renderer calls, looked up per backend (types from GL/gl.h's and
// GL/glext.h's declarations; nothing is linked).
// A table, laid out by hand:
// clang-format off
#define RATTLEBACK_GL_FUNCTIONS(X)                                                          \
  X(glAttachShader) X(glBindBuffer) X(glBindFramebuffer) X(glBindRenderbuffer)              \
  X(glBindVertexArray) X(glBlendFunc) X(glBufferData) X(glCheckFramebufferStatus)           \
  X(glClear) X(glClearColor) X(glCompileShader) X(glCreateProgram) X(glCreateShader)        \
  X(glDeleteBuffers) X(glDeleteFramebuffers) X(glDeleteProgram) X(glDeleteRenderbuffers)    \
  X(glDeleteShader) X(glDeleteVertexArrays) X(glDisable) X(glDrawArrays) X(glEnable)        \
  X(glEnableVertexAttribArray) X(glFinish) X(glFramebufferRenderbuffer) X(glGenBuffers)     \
  X(glGenFramebuffers) X(glGenRenderbuffers) X(glGenVertexArrays) X(glGetProgramInfoLog)    \
  X(glGetProgramiv) X(glGetShaderInfoLog) X(glGetShaderiv) X(glGetString)                   \
  X(glGetUniformLocation) X(glLinkProgram) X(glPixelStorei) X(glReadPixels)                 \
  X(glRenderbufferStorage) X(glShaderSource) X(glUniform1f) X(glUniform2f) X(glUniform3fv)  \
  X(glUniform4f)                                                                             \
  X(glUniformMatrix4fv) X(glUseProgram) X(glVertexAttribPointer) X(glViewport)              \
  X(glBlendFuncSeparate) X(glBlitFramebuffer) X(glBufferSubData) X(glPointParameteri)
// clang-format on

struct GlApi {
#define RATTLEBACK_GL_MEMBER(name) decltype(&::name) name = nullptr;
  RATTLEBACK_GL_FUNCTIONS(RATTLEBACK_GL_MEMBER)
#undef RATTLEBACK_GL_MEMBER
};

/// An off-screen OpenGL 3.3 core context drawing into a framebuffer object with colour and
/// depth. Its GL calls are valid only while it is current: see CurrentContext.
/// A framebuffer object with an RGBA8 colour and a 24-bit depth renderbuffer: the frame's, and
/// the renderer's cached floor (same formats, so one can be blitted into the other).
struct Framebuffer {
  GLuint fbo = 0, color = 0, depth = 0;
};
/// Makes one of width × height and leaves it bound; false when it is incomplete.
bool makeFramebuffer(const GlApi& gl, int width, int height, Framebuffer& out);
void deleteFramebuffer(const GlApi& gl, Framebuffer& framebuffer);

class GlContext {
 public:
  /// Creates the context and its FBO. Auto tries EGL, then OSMesa; the error names what each
  /// backend said.
  static rb::Result<std::unique_ptr<GlContext>> create(Backend backend, int width, int height);
  virtual ~GlContext() = default;

  const GlApi& api() const { return api_; }
  Backend backend() const { return backend_; }
  /// "EGL (surfaceless): Mesa/X.org llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 …"
  const std::string& description() const { return description_; }
  /// The OpenGL alone, whichever backend reaches it: "Mesa/X.org llvmpipe (LLVM 15.0.6, 256
  /// bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6" (what draws the pixels: EGL's and OSMesa's
  /// llvmpipe draw the same).
  const std::string& rasteriser() const { return rasteriser_; }
  /// The FBO that frames are drawn into and read from.
  GLuint framebuffer() const { return frame_.fbo; }
  /// Reads the FBO's pixels as they lie, bottom row of the window first: the renderer draws
  /// upside down so that this is the image's top row (no copy to flip it; the context must be
  /// current).
  void readPixels(unsigned char* rgba) const;

 protected:
  friend class CurrentContext;
  virtual bool makeCurrent() = 0;
  virtual void release() = 0;
  /// Unbinds this context from the thread if it is the current one (before destroying it).
  void releaseIfCurrent();
  /// After the backend's context exists and is current: the FBO and the description.
  std::string createFramebuffer(int width, int height);
  void destroyFramebuffer();

  GlApi api_;
  Backend backend_ = Backend::Auto;
  std::string description_, rasteriser_;
  Framebuffer frame_;
  int width_ = 0, height_ = 0;
};

/// Makes a context current on this thread (unless it already is) for the GL calls in the
/// guard's scope: every draw and every destruction takes one, so two renderers on one thread
/// each draw with their own context, whatever the order. The context stays current after the
/// scope, until another guard takes the thread or the context is destroyed (which unbinds it):
/// one renderer drawing frame after frame switches nothing. It holds a GlWork: the process's
/// exit waits for the scope's end.
class CurrentContext {
 public:
  explicit CurrentContext(GlContext& context);
  CurrentContext(const CurrentContext&) = delete;
  CurrentContext& operator=(const CurrentContext&) = delete;
  /// False when the backend refused to make the context current.
  bool ok() const { return ok_; }

 private:
  GlWork work_;  // first: taken before the context is made current
  GlContext& context_;
  bool ok_ = false;
};

/// Loads and initialises the driver behind `backend` (EGL's display and the driver it loads, or
/// the OSMesa library), so that a GlContext::create() after it finds them ready: about 40 ms a
/// process with llvmpipe, which a caller can spend on a thread of its own while it loads its
/// scene (the library makes no threads). Safe on any thread, also while another creates a
/// context; errors are left for create() to report.
void preloadBackend(Backend backend);

/// Compiles and links a program from files under the assets folder: a vertex shader and one
/// or more fragment shader parts, with the current context's functions; throws on failure
/// with the compiler's log.
GLuint loadProgram(const GlApi& gl, const std::string& vertex_file,
                   const std::vector<std::string>& fragment_files);

/// The assets folder (shaders/, fonts.txt): $RATTLEBACK_ASSETS when set; else, found from the
/// executable's own folder (/proc/self/exe), <exe dir>/../share/rattleback (the installed
/// layout bin/ → share/rattleback, any prefix) or the build tree's copy <build>/share/rattleback
/// for programs in <build>/app, <build>/tests, <build>/bench. No absolute path is compiled in.
std::string assetsDir();

}  // namespace render
