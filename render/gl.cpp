#include "render/gl.hpp"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace render {

GlContext::~GlContext() {
  if (!context_) return;
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &color_);
  glDeleteRenderbuffers(1, &depth_);
  OSMesaDestroyContext(context_);
}

std::string GlContext::create(int width, int height) {
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                            OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                            OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context_) return "cannot create an OpenGL 3.3 core context (OSMesa)";
  width_ = width;
  height_ = height;
  buffer_.assign(static_cast<std::size_t>(width) * height * 4, '\0');
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height))
    return "cannot make the OSMesa context current";
  glGenRenderbuffers(1, &color_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return "the framebuffer object is incomplete";
  glViewport(0, 0, width, height);
  return "";
}

void GlContext::readPixels(unsigned char* rgba) const {
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  // OpenGL's rows run bottom-up: flip them.
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  std::vector<unsigned char> swap(row);
  for (int y = 0; y < height_ / 2; ++y) {
    unsigned char* a = rgba + y * row;
    unsigned char* b = rgba + (height_ - 1 - y) * row;
    std::memcpy(swap.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, swap.data(), row);
  }
}

std::string assetsDir() {
  if (const char* env = std::getenv("RATTLEBACK_ASSETS"); env && *env) return env;
  std::error_code error;
  const std::filesystem::path exe_dir =
      std::filesystem::read_symlink("/proc/self/exe", error).parent_path();
  if (error) return RATTLEBACK_ASSETS_RELATIVE;
  // The installed layout (bin/ → share/rattleback, relative so the prefix can move), then the
  // build tree's copy in <build>/share/rattleback beside <build>/app, <build>/tests, ….
  const std::filesystem::path candidates[] = {exe_dir / RATTLEBACK_ASSETS_RELATIVE,
                                              exe_dir / "../share/rattleback"};
  for (const auto& dir : candidates)
    if (std::filesystem::is_directory(dir / "shaders", error))
      return dir.lexically_normal().string();
  return (exe_dir / RATTLEBACK_ASSETS_RELATIVE).lexically_normal().string();
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

GLuint compile(GLenum type, const std::string& path) {
  const std::string source = readText(path);
  const char* text = source.c_str();
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(path + ": " + log);
  }
  return shader;
}

}  // namespace

GLuint loadProgram(const std::string& vertex_file, const std::string& fragment_file) {
  const std::string dir = assetsDir() + "/shaders/";
  const GLuint vertex = compile(GL_VERTEX_SHADER, dir + vertex_file);
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, dir + fragment_file);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    throw std::runtime_error(vertex_file + " + " + fragment_file + ": " + log);
  }
  return program;
}

}  // namespace render
