#include "render/gl.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "util/arguments.hpp"
#include "util/assets.hpp"

namespace render {
namespace {

// The context current on this thread, as far as our contexts go.
thread_local GlContext* current_context = nullptr;

template <typename Lookup>
std::string loadApi(GlApi& api, Lookup lookup) {
  std::string missing;
#define RATTLEBACK_GL_LOAD(name)                                  \
  api.name = reinterpret_cast<decltype(api.name)>(lookup(#name)); \
  if (!api.name) missing += std::string(missing.empty() ? "" : ", ") + #name;
  RATTLEBACK_GL_FUNCTIONS(RATTLEBACK_GL_LOAD)
#undef RATTLEBACK_GL_LOAD
  return missing.empty() ? "" : "OpenGL functions missing: " + missing;
}

// ---- OSMesa, opened at run time -------------------------------------------------------------

struct OsMesaLibrary {
  void* handle = nullptr;
  decltype(&::OSMesaCreateContextAttribs) createContextAttribs = nullptr;
  decltype(&::OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&::OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&::OSMesaGetProcAddress) getProcAddress = nullptr;
  std::string error;
};

// Opened once for the process and never closed (Mesa keeps state until exit).
const OsMesaLibrary& osMesa() {
  static const OsMesaLibrary library = [] {
    OsMesaLibrary l;
    for (const char* name : {"libOSMesa.so.8", "libOSMesa.so"}) {
      l.handle = dlopen(name, RTLD_NOW | RTLD_LOCAL);
      if (l.handle) break;
    }
    if (!l.handle) {
      l.error = "OSMesa is not installed (libOSMesa.so.8; Debian: apt-get install libosmesa6)";
      return l;
    }
    l.createContextAttribs = reinterpret_cast<decltype(l.createContextAttribs)>(
        dlsym(l.handle, "OSMesaCreateContextAttribs"));
    l.makeCurrent = reinterpret_cast<decltype(l.makeCurrent)>(dlsym(l.handle, "OSMesaMakeCurrent"));
    l.destroyContext =
        reinterpret_cast<decltype(l.destroyContext)>(dlsym(l.handle, "OSMesaDestroyContext"));
    l.getProcAddress =
        reinterpret_cast<decltype(l.getProcAddress)>(dlsym(l.handle, "OSMesaGetProcAddress"));
    if (!l.createContextAttribs || !l.makeCurrent || !l.destroyContext || !l.getProcAddress)
      l.error = "libOSMesa lacks OSMesaCreateContextAttribs (needs Mesa 12 or later)";
    return l;
  }();
  return library;
}

class OsMesaContext final : public GlContext {
 public:
  ~OsMesaContext() override {
    if (!context_) return;
    GlWork work;
    {
      CurrentContext current(*this);
      if (current.ok()) destroyFramebuffer();
    }
    releaseIfCurrent();
    osMesa().destroyContext(context_);
  }

  std::string create(int width, int height) {
    backend_ = Backend::OsMesa;
    const OsMesaLibrary& lib = osMesa();
    if (!lib.error.empty()) return lib.error;
    // OSMesa (Mesa 22.3) has only the software drivers; named any other driver by GALLIUM_DRIVER
    // it crashes in OSMesaCreateContextAttribs (measured: zink, swrast, virpipe, a misspelt
    // name), and the command would end in a segmentation fault with nothing said.
    if (const char* driver = std::getenv("GALLIUM_DRIVER"); driver && *driver &&
                                                            std::strcmp(driver, "llvmpipe") != 0 &&
                                                            std::strcmp(driver, "softpipe") != 0)
      return std::string("GALLIUM_DRIVER=") + driver +
             " is not one of OSMesa's drivers (llvmpipe, softpipe), and Mesa would crash: unset "
             "GALLIUM_DRIVER or set it to llvmpipe";
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = lib.createContextAttribs(attributes, nullptr);
    if (!context_) return "cannot create an OpenGL 3.3 core context";
    buffer_.assign(static_cast<std::size_t>(width) * height * 4, '\0');
    width_ = width;
    height_ = height;
    if (std::string e = loadApi(
            api_,
            [&](const char* name) { return reinterpret_cast<void*>(lib.getProcAddress(name)); });
        !e.empty())
      return e;
    CurrentContext current(*this);
    if (!current.ok()) return "cannot make the context current";
    return createFramebuffer(width, height);
  }

 protected:
  bool makeCurrent() override {
    // OSMesa draws into its own buffer of the context's size; ours go to the FBO.
    return osMesa().makeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_);
  }
  void release() override { osMesa().makeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0); }

 private:
  OSMesaContext context_ = nullptr;
  std::string buffer_;
};

// ---- EGL ------------------------------------------------------------------------------------

std::string eglHex(EGLint value) {
  char text[16];
  std::snprintf(text, sizeof text, "%x", static_cast<unsigned>(value));
  return text;
}

// A GPU through the device platform when there is one (a device with a DRM node), else
// Mesa's surfaceless platform (which itself uses a render node when it can, or llvmpipe).
std::string openEglDisplay(EGLDisplay& display, std::string& platform) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const std::string extensions = client ? client : "";
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) return "EGL has no eglGetPlatformDisplayEXT";
  if (extensions.find("EGL_EXT_platform_device") != std::string::npos) {
    auto queryDevices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        eglGetProcAddress("eglQueryDeviceStringEXT"));
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (queryDevices && queryDeviceString && queryDevices(16, devices, &count)) {
      for (EGLint i = 0; i < count; ++i) {
        // A GPU: a device with a DRM node that is not Mesa's software device.
        const char* names = queryDeviceString(devices[i], EGL_EXTENSIONS);
        const std::string device = names ? std::string(" ") + names + " " : "";
        if (device.find(" EGL_EXT_device_drm ") == std::string::npos ||
            device.find(" EGL_MESA_device_software ") != std::string::npos)
          continue;
        display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) {
          platform = "device";
          return "";
        }
      }
    }
  }
  if (extensions.find("EGL_MESA_platform_surfaceless") == std::string::npos)
    return "EGL has neither a GPU device nor the surfaceless platform";
  display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
    std::string why =
        "EGL cannot initialise the surfaceless platform (error 0x" + eglHex(eglGetError()) + ")";
    // Mesa takes its driver from GALLIUM_DRIVER: one it cannot start here (zink without Vulkan) is
    // the likely cause (the message did not name it).
    if (const char* driver = std::getenv("GALLIUM_DRIVER"); driver && *driver)
      why += std::string(" with GALLIUM_DRIVER=") + driver +
             ": unset GALLIUM_DRIVER or set it to llvmpipe";
    return why;
  }
  platform = "surfaceless";
  return "";
}

class EglContext final : public GlContext {
 public:
  ~EglContext() override {
    if (context_ == EGL_NO_CONTEXT) return;
    GlWork work;
    {
      CurrentContext current(*this);
      if (current.ok()) destroyFramebuffer();
    }
    releaseIfCurrent();
    eglDestroyContext(display_, context_);
    // No eglTerminate: every context of this process gets the same display from
    // eglGetPlatformDisplay, and terminating it would end the others' contexts too.
  }

  std::string create(int width, int height) {
    backend_ = Backend::Egl;
    width_ = width;
    height_ = height;
    std::string platform;
    if (std::string e = openEglDisplay(display_, platform); !e.empty()) return e;
    if (!eglBindAPI(EGL_OPENGL_API)) return "EGL cannot bind the OpenGL API";
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    // Surfaceless: no config and no surface; everything is drawn into our FBO.
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT)
      return "EGL cannot create an OpenGL 3.3 core context (error 0x" + eglHex(eglGetError()) + ")";
    if (std::string e = loadApi(
            api_,
            [](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); });
        !e.empty())
      return e;
    CurrentContext current(*this);
    if (!current.ok()) return "EGL cannot make the context current";
    if (std::string e = createFramebuffer(width, height); !e.empty()) return e;
    description_ = "EGL (" + platform + "): " + description_;
    return "";
  }

 protected:
  bool makeCurrent() override {
    return eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) == EGL_TRUE;
  }
  void release() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

void preloadBackend(Backend backend) {
  GlWork work;
  if (backend != Backend::OsMesa) {
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string platform;
    if (openEglDisplay(display, platform).empty() || backend == Backend::Egl) return;
  }
  osMesa();
}

rb::Result<std::unique_ptr<GlContext>> GlContext::create(Backend backend, int width, int height) {
  GlWork work;
  std::string egl_error, osmesa_error;
  if (backend != Backend::OsMesa) {
    auto egl = std::make_unique<EglContext>();
    egl_error = egl->create(width, height);
    if (egl_error.empty()) {
      holdExitForGlWork(Backend::Egl);
      return std::unique_ptr<GlContext>(std::move(egl));
    }
    if (backend == Backend::Egl)
      return rb::machineError(rb::argumentGiven("backend", "egl") + ": " + egl_error + "; " +
                              rb::argumentGiven("backend", "osmesa") + " draws on the CPU");
  }
  auto osmesa = std::make_unique<OsMesaContext>();
  osmesa_error = osmesa->create(width, height);
  if (osmesa_error.empty()) {
    holdExitForGlWork(Backend::OsMesa);
    osmesa->description_ = "OSMesa: " + osmesa->description_;
    return std::unique_ptr<GlContext>(std::move(osmesa));
  }
  if (backend == Backend::OsMesa)
    return rb::machineError(rb::argumentGiven("backend", "osmesa") + ": " + osmesa_error);
  return rb::machineError("no OpenGL for rendering: EGL: " + egl_error +
                          "; OSMesa: " + osmesa_error);
}

bool makeFramebuffer(const GlApi& gl, int width, int height, Framebuffer& out) {
  gl.glGenRenderbuffers(1, &out.color);
  gl.glBindRenderbuffer(GL_RENDERBUFFER, out.color);
  gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  gl.glGenRenderbuffers(1, &out.depth);
  gl.glBindRenderbuffer(GL_RENDERBUFFER, out.depth);
  gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  gl.glGenFramebuffers(1, &out.fbo);
  gl.glBindFramebuffer(GL_FRAMEBUFFER, out.fbo);
  gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, out.color);
  gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, out.depth);
  return gl.glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

void deleteFramebuffer(const GlApi& gl, Framebuffer& f) {
  if (f.fbo) gl.glDeleteFramebuffers(1, &f.fbo);
  if (f.color) gl.glDeleteRenderbuffers(1, &f.color);
  if (f.depth) gl.glDeleteRenderbuffers(1, &f.depth);
  f = {};
}

std::string GlContext::createFramebuffer(int width, int height) {
  const GlApi& gl = api_;
  auto text = [&](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(gl.glGetString(name));
    return std::string(s ? s : "?");
  };
  description_ = text(GL_VENDOR) + " " + text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
  rasteriser_ = description_;
  if (!makeFramebuffer(gl, width, height, frame_)) return "the framebuffer object is incomplete";
  gl.glViewport(0, 0, width, height);
  return "";
}

void GlContext::destroyFramebuffer() {
  deleteFramebuffer(api_, frame_);
}

void GlContext::readPixels(unsigned char* rgba) const {
  const GlApi& gl = api_;
  gl.glPixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

CurrentContext::CurrentContext(GlContext& context) : context_(context) {
  if (current_context == &context_) {
    ok_ = true;
    return;
  }
  ok_ = context_.makeCurrent();
  current_context = ok_ ? &context_ : nullptr;
}

void GlContext::releaseIfCurrent() {
  if (current_context != this) return;
  release();
  current_context = nullptr;
}

std::string assetsDir() {
  return rb::assetsDir();
}

namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error(
        path + ": cannot read the shader (set RATTLEBACK_ASSETS to the assets folder)");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

GLuint compile(const GlApi& gl, GLenum type, const std::string& path) {
  const std::string source = readText(path);
  const char* text = source.c_str();
  const GLuint shader = gl.glCreateShader(type);
  gl.glShaderSource(shader, 1, &text, nullptr);
  gl.glCompileShader(shader);
  GLint ok = 0;
  gl.glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    gl.glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(path + ": " + log);
  }
  return shader;
}

}  // namespace

GLuint loadProgram(const GlApi& gl, const std::string& vertex_file,
                   const std::vector<std::string>& fragment_files) {
  const std::string dir = assetsDir() + "/shaders/";
  std::vector<GLuint> shaders = {compile(gl, GL_VERTEX_SHADER, dir + vertex_file)};
  for (const std::string& file : fragment_files)
    shaders.push_back(compile(gl, GL_FRAGMENT_SHADER, dir + file));
  const GLuint program = gl.glCreateProgram();
  for (GLuint shader : shaders) gl.glAttachShader(program, shader);
  gl.glLinkProgram(program);
  for (GLuint shader : shaders) gl.glDeleteShader(shader);
  GLint ok = 0;
  gl.glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048];
    gl.glGetProgramInfoLog(program, sizeof log, nullptr, log);
    std::string names = vertex_file;
    for (const std::string& file : fragment_files) names += " + " + file;
    throw std::runtime_error(names + ": " + log);
  }
  return program;
}

}  // namespace render
