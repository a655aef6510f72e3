// The process's exit held off while OpenGL work is under way on other threads.
//
// exit() runs the driver's exit handlers (Mesa frees llvmpipe's state in them), and a thread
// still drawing then crashes the process: a Python script that ends while a daemon thread
// renders a video, a C++ program that returns from main() with a renderer's thread running.
// Every stretch of GL calls holds a GlWork; at exit, a handler registered after the driver's
// (so run before it) waits for those in hand to end, and any other thread that starts one
// afterwards is parked there until the process is gone, as the C library ends threads anyway.
#pragma once

#include "render/frame.hpp"

namespace render {

/// One stretch of GL calls (a frame, a context's creation or destruction); nested ones on a
/// thread count once. Taken while the process exits, by a thread other than the exiting one,
/// it never returns.
class GlWork {
 public:
  GlWork();
  ~GlWork();
  GlWork(const GlWork&) = delete;
  GlWork& operator=(const GlWork&) = delete;
};

/// Registers the exit handler once for `backend`, after its driver has loaded (so after the
/// driver's own handlers, which exit() runs in the reverse order).
void holdExitForGlWork(Backend backend);

}  // namespace render
