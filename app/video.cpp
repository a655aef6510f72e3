// render and still: the simulation's frames drawn and encoded. A drawing thread pulls each
// frame's state from the runs (a Rollout per spin direction, sampled at the frame's exact
// time), draws it and converts it to yuv420p; each output video has its own encoding thread
// (std::jthread), which opens its encoder and is fed by a bounded queue (about 48 MB), so no
// run holds its frames in memory.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

#include "app/commands.hpp"
#include "app/frames.hpp"
#include "app/interrupt.hpp"
#include "tasks/output.hpp"
#include "app/progress.hpp"
#include "app/queue.hpp"
#include "app/scene_args.hpp"
#include "app/spin_history.hpp"
#include "app/video_plan.hpp"
#include "render/encoder.hpp"
#include "render/image_io.hpp"
#include "render/renderer.hpp"
#include "render/yuv.hpp"
#include "sim/analysis.hpp"
#include "sim/rollout.hpp"

namespace app {
namespace {

namespace fs = std::filesystem;

// x264's presets (x264 --fullhelp).
constexpr const char* kPresets[] = {"ultrafast", "superfast", "veryfast", "faster", "fast",
                                    "medium",    "slow",      "slower",   "veryslow", "placebo"};

std::string stem(const std::string& path) { return fs::path(path).stem().string(); }

std::string describeSpin(double spin) {
  char text[64];
  std::snprintf(text, sizeof text, "%+g rad/s, %s", spin,
                spin > 0 ? "counter-clockwise" : spin < 0 ? "clockwise" : "no spin");
  return text;
}

// The title of a run's frames, the same in its video and its stills: the scene and the spin.
render::RenderSettings settingsOf(const VideoPlan& plan, double duration, double spin,
                                  const std::string& scene, render::Backend backend) {
  const std::string title = stem(scene) + ": spun " + describeSpin(spin);
  render::RenderSettings s;
  s.backend = backend;
  s.width = plan.width;
  s.height = plan.height;
  s.view = plan.view;
  s.title = title;
  s.duration = duration;
  s.spin_range = std::max(1.0, 1.1 * std::abs(spin));
  return s;
}

// How many frames may wait for an encoder: as many as fit in about 48 MB of yuv420p, 4 to 32
// (32 at 720p, 15 at 1080p). For one video the drawing thread yields to the encoder
// (yieldToEncoders) and draws ahead into this queue whenever it leaves a core idle.
std::size_t queueDepth(const render::EncoderSettings& s) {
  constexpr std::size_t kBytes = 48u << 20;
  const std::size_t frame = static_cast<std::size_t>(s.width) * s.height * 3 / 2;
  return std::clamp<std::size_t>(kBytes / frame, 4, 32);
}

// One output video fed by its own encoding thread. The thread first opens the encoder (x264's
// set-up takes about 10 ms, spent while the renderers are made), then encodes what the queue
// brings. It stops when the queue closes or its stop is requested; an error (or an exception),
// opening or encoding, is kept for the main thread and closes the queue, so that the
// producer's next push fails and rendering stops.
struct Output {
  Output(std::string path, const render::EncoderSettings& settings)
      : path(std::move(path)),
        settings(settings),
        images(queueDepth(settings)),
        spare(queueDepth(settings) + 2) {}
  std::string path;
  render::EncoderSettings settings;
  /// Set by the thread once open; read by others only after joining it.
  std::unique_ptr<render::VideoEncoder> encoder;
  // The encoder's temporary file is known to the signal handler (registered when opened),
  // which removes it on a second Ctrl-C (it exits at once); forgotten here.
  ~Output() {
    abort();
    if (encoder) tasks::unregisterTemporary(encoder->temporaryPath());
  }
  // Frames in yuv420p, converted by the drawing thread: a 720p frame is 1.4 MB where its RGBA
  // is 3.7 MB, and the conversion is off the encoding thread, the pipeline's narrowest.
  BoundedQueue<render::Yuv420Image> images;
  // Frame buffers the encoder is done with, handed back for the next frames: after the first
  // frames nothing on the render → encode path allocates (fresh pages cost page faults and
  // zeroing each time).
  BoundedQueue<render::Yuv420Image> spare;

  /// A frame buffer to convert into: a spare one, or a new one while the pool fills.
  render::Yuv420Image buffer() {
    if (auto picture = spare.tryPop()) return std::move(*picture);
    return {};
  }
  std::optional<std::string> error;
  std::jthread thread;

  void start() {
    thread = std::jthread([this](std::stop_token stop) {
      try {
        auto opened = render::VideoEncoder::open(path, settings);
        if (!opened) {
          error = opened.error().text();
          images.close();
          return;
        }
        encoder = std::move(opened).value();
        tasks::registerTemporary(encoder->temporaryPath());
        while (!stop.stop_requested()) {
          auto image = images.pop();
          if (!image) break;
          if (auto added = encoder->add(*image); !added) {
            error = added.error().text();
            break;
          }
          spare.tryPush(std::move(*image));
        }
      } catch (const std::exception& e) {
        error = std::string("encoding failed: ") + e.what();
      }
      images.close();
    });
  }
  /// Lets the thread encode what is queued, then joins it.
  void drain() {
    images.close();
    if (thread.joinable()) thread.join();
  }
  /// Stops the thread at its next frame, dropping what is queued, and joins it.
  void abort() {
    if (thread.joinable()) thread.request_stop();
    drain();
  }
};

constexpr unsigned char kDivider = 48;  // the grey of the line between --both's halves

// Places a and b side by side, into `out` (its buffer reused).
void sideBySide(const render::Image& a, const render::Image& b, render::Image& out) {
  out.width = a.width + b.width;
  out.height = a.height;
  out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
  for (int y = 0; y < a.height; ++y) {
    auto* row = &out.rgba[static_cast<std::size_t>(y) * out.width * 4];
    std::copy_n(&a.rgba[static_cast<std::size_t>(y) * a.width * 4], a.width * 4, row);
    std::copy_n(&b.rgba[static_cast<std::size_t>(y) * b.width * 4], b.width * 4, row + a.width * 4);
    // A dark line two pixels wide (the last column of the left, the first of the right) marks
    // where one run ends and the other begins, also where both show the same floor.
    for (int x : {a.width - 1, a.width}) {
      unsigned char* p = row + 4 * x;
      p[0] = p[1] = p[2] = kDivider;
      p[3] = 255;
    }
  }
}

// Names for --both: the spin in the direction the linearised theory prefers is "preferred",
// the other "reversed". A note says when the runs disagree with the prediction.
std::array<std::string, 2> bothNames(const std::vector<sim::Rollout>& runs) {
  const sim::Model& model = runs[0].model();
  const sim::Direction preferred_direction = sim::preferredDirection(model, model.initial.spin);
  std::array<std::string, 2> names;
  for (int i = 0; i < 2; ++i) {
    const double spin = runs[i].model().initial.spin;
    const bool preferred = sim::turns(preferred_direction, spin);
    names[i] = preferred ? "preferred" : "reversed";
    if (preferred == runs[i].summary().first_reversal_s.has_value())
      std::cerr << "note: spun " << spin << " rad/s the body "
                << (preferred ? "reversed although the theory prefers this direction"
                              : "did not reverse within the run")
                << "\n";
  }
  return names;
}

// Lowers the calling thread's priority by 5 (nice), so that the encoder's threads, started
// before it, run first whenever both want a core: encoding is the narrowest part of the
// pipeline, and drawing then fills the time the encoder leaves idle (x264 alone keeps about
// 1.65 of two cores busy) and draws ahead into its queue. The OpenGL driver's own threads,
// made with its context, inherit it. Where the system refuses, nothing changes.
// (Only for one video: --both's three encoders keep two cores busy without the drawing, and
// then wait for it; yielding made --both 9 % slower, where it made one video 6 % faster.)
void yieldToEncoders() {
  errno = 0;
  const int nice = ::getpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()));
  if (errno == 0) ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), nice + 5);
}

// --backend's value (or the environment's, named by `from`); none after a line naming the
// choices.
std::optional<render::Backend> parseBackend(const std::string& name, const std::string& from) {
  const auto backend = rb::parseName<render::Backend>(name);
  if (!backend)
    std::cerr << from << ": " << rb::choices<render::Backend>() << ", not '" << name << "'\n";
  return backend;
}

// Loads the OpenGL driver behind `backend` (about 40 ms with llvmpipe) on a thread of its own
// while the caller loads its scene; joined before a renderer is made.
std::jthread preloadDriver(render::Backend backend) {
  return std::jthread([backend] { render::preloadBackend(backend); });
}

rb::Status checkEncoderOptions(const RenderArgs& args) {
  if (args.crf < 1 || args.crf > 51)
    return rb::Status::fail("--crf must be within 1 … 51 (lower is better; 0 would be lossless "
                            "High 4:4:4, which browsers do not play), not " +
                            std::to_string(args.crf));
  for (const char* p : kPresets)
    if (args.preset == p) return {};
  std::string names;
  for (const char* p : kPresets) names += std::string(names.empty() ? "" : ", ") + p;
  return rb::Status::fail("--preset must be one of x264's: " + names + "; not '" + args.preset + "'");
}

// An output name whose extension says another format than the one written (x.avi holding
// MP4, s.jpg holding PNG) is refused; with --both a base without extension is fine.
rb::Status checkExtension(const std::string& output, const std::string& wanted,
                          const std::string& format, bool base_allowed) {
  if (output.empty()) return {};
  std::string ext = fs::path(output).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == wanted || (base_allowed && ext.empty())) return {};
  return rb::Status::fail("-o " + output + ": writes " + format + "; give a name ending in " + wanted);
}

}  // namespace

int renderCommand(const RenderArgs& args) {
  installInterruptHandlers();
  if (auto ok = checkEncoderOptions(args); !ok) {
    std::cerr << ok.error().text() << "\n";
    return kBadInput;
  }
  if (auto ok = checkExtension(args.output, ".mp4", "MP4 video", args.both); !ok) {
    std::cerr << ok.error().text() << "\n";
    return kBadInput;
  }
  const auto backend = parseBackend(args.backend, args.backend_from);
  if (!backend) return kBadInput;
  std::jthread preload = preloadDriver(*backend);
  auto loaded = loadScene(args.scene, args.overrides);
  if (!loaded) {
    std::cerr << loaded.error().text() << "\n";
    return kBadInput;
  }
  const sim::Model& model = loaded->model;
  auto planned = planVideo(loaded->scene, model.duration);
  if (!planned) {
    std::cerr << planned.error().text() << "\n";
    return kBadInput;
  }
  const VideoPlan& plan = planned.value();
  if (args.both && model.initial.spin == 0) {
    std::cerr << args.scene << ": --both renders the spin and its reverse, which at spin 0 are "
              << "the same run; give a spin (--spin, or initial.spin in the scene)\n";
    return kBadInput;
  }
  if (args.verbose) describeModel(model, args.scene);
  // One run per direction, sharing the body.
  std::vector<sim::Rollout> runs;
  runs.emplace_back(model);
  if (args.both) {
    sim::Model reversed = model;
    reversed.initial.spin = -model.initial.spin;
    runs.emplace_back(reversed);
  }

  // Output paths: -o exactly, else out/<scene>.mp4; with --both, -o (less any .mp4) is the
  // base of BASE-preferred.mp4, BASE-reversed.mp4 (renamed at the end) and BASE-both.mp4.
  std::string base = args.output.empty() ? "out/" + stem(args.scene) : args.output;
  if (base.size() > 4 && base.substr(base.size() - 4) == ".mp4") base.resize(base.size() - 4);
  const std::vector<std::string> provisional =
      args.both ? std::vector<std::string>{base + "-preferred.mp4", base + "-reversed.mp4",
                                           base + "-both.mp4"}
                : std::vector<std::string>{args.output.empty() ? base + ".mp4" : args.output};
  std::vector<std::unique_ptr<Output>> outputs;
  for (std::size_t i = 0; i < provisional.size(); ++i) {
    if (auto made = tasks::makeParentFolder(provisional[i]); !made) {
      std::cerr << made.error().text() << "\n";
      return kBadInput;
    }
    render::EncoderSettings settings;
    settings.width = i == 2 ? 2 * plan.width : plan.width;
    settings.height = plan.height;
    settings.fps = plan.fps;
    settings.crf = args.crf;
    settings.preset = args.preset;
    outputs.push_back(std::make_unique<Output>(provisional[i], settings));
    outputs.back()->start();  // opens its encoder while the renderers are made
  }

  // Makes the renderers and draws every frame into the encoders' queues, then lets the encoders
  // finish; an exit status when it cannot.
  std::int64_t frames = 0;
  double wall = 0;
  auto drawFrames = [&]() -> std::optional<int> {
    std::vector<std::unique_ptr<render::Renderer>> renderers;
    const render::BodyPoints points = bodyPointsOf(model);
    // Each run's camera for the fixed views, and the spin of its frames so far for the inset:
    // the frame values the renderers draw from.
    std::vector<render::Framing> framings;
    std::vector<SpinHistory> histories;
    for (const sim::Rollout& run : runs) {
      framings.push_back(framingOf(run.summary().first, points));
      histories.emplace_back(model.duration, plan.width);
    }
    for (const sim::Rollout& run : runs) {
      const double spin = run.model().initial.spin;
      auto created = render::Renderer::create(
          settingsOf(plan, model.duration, spin, args.scene, *backend),
          points);
      if (!created) {
        std::cerr << "render: " << created.error().text() << "\n";
        return kBadInput;
      }
      if (args.verbose && renderers.empty())
        std::cerr << "render: OpenGL " << created.value()->description() << "\n";
      renderers.push_back(std::move(created).value());
    }

    Progress progress("render", plan.frames, !args.quiet);
    const auto start = std::chrono::steady_clock::now();
    // Each run's frame as drawn, and --both's two side by side, reused from frame to frame and
    // converted here into the encoders' buffers.
    std::vector<render::Image> images(runs.size());
    render::Image both;
    render::Yuv420Converter converter;
    auto send = [&](Output& output, const render::Image& image) {
      render::Yuv420Image picture = output.buffer();
      converter.convert(image, picture);
      return output.images.push(std::move(picture));
    };
    bool running = true;
    for (std::int64_t k = 0; running && k < plan.frames && !interruptSignal(); ++k) {
      const double t = plan.frameTime(k);
      for (std::size_t i = 0; i < runs.size() && running; ++i) {
        running = histories[i].advanceTo(runs[i], t) && runs[i].advanceTo(t);
        if (!running) break;
        const sim::Telemetry sample = runs[i].sampleAt(t);
        render::FrameInput frame = frameOf(sample);
        frame.framing = framings[i];
        frame.history = histories[i].with(sample);
        renderers[i]->draw(frame, images[i]);
      }
      if (running && args.both) {
        sideBySide(images[0], images[1], both);
        running = send(*outputs[2], both);
      }
      for (std::size_t i = 0; running && i < runs.size(); ++i)
        running = send(*outputs[i], images[i]);
      if (running) progress.update(++frames);
    }
    // The renderers (their contexts and the driver's threads) go while the encoders finish
    // what is queued; the runs go on to the scene's end (frames stop at the last whole frame
    // time), so that the summary covers the same run as `simulate`.
    renderers.clear();
    for (auto& run : runs)
      if (running && !interruptSignal()) run.advanceTo(run.endTime());
    const bool complete = running && !interruptSignal();
    for (auto& o : outputs) complete ? o->drain() : o->abort();
    progress.finish();
    wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::nullopt;
  };
  // The renderers are made, and the frames drawn, on a thread of their own, which for one
  // video yields to its encoder (yieldToEncoders); the OpenGL driver's threads, made with the
  // renderers, inherit its priority.
  preload.join();
  std::optional<int> failed;
  std::jthread([&] {
    if (outputs.size() == 1) yieldToEncoders();
    try {
      failed = drawFrames();
    } catch (const std::exception& e) {
      std::cerr << "render: " << e.what() << "\n";
      failed = kBadInput;
    }
  }).join();
  if (failed) return *failed;

  if (interruptSignal()) {
    std::cerr << args.scene << ": interrupted after " << frames << " frames; no video written\n";
    return interruptedStatus();  // the encoders remove their temporary files
  }
  for (const auto& run : runs)
    if (run.summary().divergence) {
      std::cerr << args.scene << ": the run stopped: " << *run.summary().divergence
                << ". No video written\n";
      return kDiverged;
    }
  for (const auto& o : outputs)
    if (o->error) {
      std::cerr << *o->error << "\n";
      return kBadInput;
    }
  std::vector<std::string> finals = provisional;
  if (args.both) {
    const auto names = bothNames(runs);
    finals[0] = base + "-" + names[0] + ".mp4";
    finals[1] = base + "-" + names[1] + ".mp4";
  }
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (auto e = outputs[i]->encoder->finish(finals[i]); !e) {
      std::cerr << e.error().text() << "\n";
      return kBadInput;
    }
  }
  if (!args.quiet) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
      std::printf("%s  (%lld frames", finals[i].c_str(), outputs[i]->encoder->frames());
      if (i < runs.size()) {
        const auto& r = runs[i].summary().first_reversal_s;
        const double spin = runs[i].model().initial.spin;
        if (r)
          std::printf(", spun %+g rad/s, first reversal at %.3f s", spin, *r);
        else
          std::printf(", spun %+g rad/s, no reversal", spin);
      }
      std::printf(")\n");
    }
    std::printf("%lld frames in %.2f s: %.1f frames per second end to end\n",
                static_cast<long long>(frames), wall, frames / wall);
  }
  return kOk;
}

int stillCommand(const StillArgs& args) {
  installInterruptHandlers();
  const Overrides& o = args.overrides;
  if (!(args.t >= 0) || !std::isfinite(args.t)) {
    std::cerr << "--t must be a time ≥ 0 s\n";
    return kBadInput;
  }
  if (auto ok = checkExtension(args.output, ".png", "PNG", false); !ok) {
    std::cerr << ok.error().text() << "\n";
    return kBadInput;
  }
  const auto backend = parseBackend(args.backend, args.backend_from);
  if (!backend) return kBadInput;
  std::jthread preload = preloadDriver(*backend);
  auto loaded = loadScene(args.scene, o);
  if (!loaded) {
    std::cerr << loaded.error().text() << "\n";
    return kBadInput;
  }
  sim::Model model = loaded->model;
  // A still may show a time past the scene's duration: the run then goes on to it.
  model.duration = std::max(model.duration, args.t);
  auto planned = planVideo(loaded->scene, model.duration);
  if (!planned) {
    std::cerr << planned.error().text() << "\n";
    return kBadInput;
  }
  const VideoPlan& plan = planned.value();
  const std::string path =
      args.output.empty()
          ? "out/" + stem(args.scene) + "-" + std::string(rb::nameOf(plan.view)) + ".png"
          : args.output;
  if (auto made = tasks::makeParentFolder(path); !made) {
    std::cerr << made.error().text() << "\n";
    return kBadInput;
  }

  render::RenderSettings settings =
      settingsOf(plan, model.duration, model.initial.spin, args.scene, *backend);
  settings.readouts = !args.no_readouts && !args.transparent;
  settings.transparent = args.transparent;
  if (args.transparent) settings.title.clear();
  const render::BodyPoints points = bodyPointsOf(model);
  preload.join();
  auto created = render::Renderer::create(settings, points);
  if (!created) {
    std::cerr << "still: " << created.error().text() << "\n";
    return kBadInput;
  }
  if (args.verbose) std::cerr << "still: OpenGL " << created.value()->description() << "\n";
  render::Renderer& renderer = *created.value();
  // Run to the still's time, keeping the spin for the inset as the video would have.
  sim::Rollout run(model);
  SpinHistory history(model.duration, plan.width);
  if (!history.advanceTo(run, args.t) || !run.advanceTo(args.t)) {
    if (interruptSignal()) return interruptedStatus();
    std::cerr << args.scene << ": the run stopped before t = " << args.t
              << " s: " << run.summary().divergence.value_or("interrupted") << "\n";
    return run.summary().divergence ? kDiverged : interruptedStatus();
  }
  render::Image image;
  const sim::Telemetry sample = run.sampleAt(args.t);
  render::FrameInput frame = frameOf(sample);
  frame.framing = framingOf(run.summary().first, points);
  frame.history = history.with(sample);
  renderer.draw(frame, image);
  if (auto e = render::writePng(path, image); !e) {
    std::cerr << e.error().text() << "\n";
    return kBadInput;
  }
  if (!args.quiet) std::printf("%s\n", path.c_str());
  return kOk;
}

int compareCommand(const CompareArgs& args) {
  if (args.channel_tolerance < 0 || args.channel_tolerance > 255) {
    std::cerr << "--tolerance: a channel difference within 0 … 255, not " << args.channel_tolerance << "\n";
    return kBadInput;
  }
  if (!(args.pixel_fraction >= 0 && args.pixel_fraction <= 1)) {
    std::cerr << "--pixels: a fraction of the pixels within 0 … 1 (0.002 = 0.2 %), not "
              << args.pixel_fraction << "\n";
    return kBadInput;
  }
  render::Image a, b;
  for (auto [path, image] : {std::pair{&args.actual, &a}, std::pair{&args.expected, &b}}) {
    if (auto e = render::readPng(*path, *image); !e) {
      std::cerr << e.error().text() << "\n";
      return kBadInput;
    }
  }
  const render::Comparison c = render::compareImages(a, b, args.channel_tolerance);
  if (!c.same_size) {
    if (!args.quiet)
      std::printf("differ: the images have different sizes, %dx%d and %dx%d, so no pixel was "
                  "compared%s\n",
                  a.width, a.height, b.width, b.height,
                  args.diff.empty() ? "" : " and no diff image was written");
    return 1;
  }
  const bool same = c.fraction() <= args.pixel_fraction;
  if (!args.quiet) {
    std::printf("%s: %lld of %lld pixels (%.4f%%) differ by more than %d in a channel "
                "(allowed %.4f%%); largest channel difference %d",
                same ? "same" : "differ", c.differing, c.pixels, 100 * c.fraction(),
                args.channel_tolerance, 100 * args.pixel_fraction, c.max_channel_delta);
    if (c.differing)
      std::printf("; differing pixels within x %d–%d, y %d–%d", c.box[0], c.box[2], c.box[1],
                  c.box[3]);
    std::printf("\n");
  }
  if (!same && !args.diff.empty()) {
    if (auto e = render::writePng(args.diff, render::diffImage(a, b, args.channel_tolerance)); !e) {
      std::cerr << e.error().text() << "\n";
      return kBadInput;
    }
    if (!args.quiet) std::printf("diff image: %s\n", args.diff.c_str());
  }
  return same ? 0 : 1;
}

}  // namespace app
