#include "media/video.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "media/frames.hpp"
#include "media/presets.hpp"
#include "media/queue.hpp"
#include "media/spin_history.hpp"
#include "media/video_plan.hpp"
#include "render/encoder.hpp"
#include "render/gl.hpp"
#include "render/renderer.hpp"
#include "render/yuv.hpp"
#include "sim/analysis.hpp"
#include "sim/rollout.hpp"
#include "tasks/against_theory.hpp"
#include "tasks/output.hpp"
#include "tasks/player_data.hpp"
#include "tasks/run_json.hpp"
#include "util/arguments.hpp"
#include "util/format.hpp"

namespace media {
namespace {

namespace fs = std::filesystem;

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
  std::optional<rb::Error> error;
  std::jthread thread;

  void start() {
    // The encoder opens on its own thread: the caller's name for the output goes with it.
    thread = std::jthread([this, named = rb::output_named_by](std::stop_token stop) {
      try {
        const rb::OutputNamedBy naming(named);
        auto opened = render::VideoEncoder::open(path, settings);
        if (!opened) {
          error = opened.error();
          images.close();
          return;
        }
        encoder = std::move(opened).value();
        tasks::registerTemporary(encoder->temporaryPath());
        while (!stop.stop_requested()) {
          auto image = images.pop();
          if (!image) break;
          if (auto added = encoder->add(*image); !added) {
            error = added.error();
            break;
          }
          spare.tryPush(std::move(*image));
        }
      } catch (const std::exception& e) {
        error = rb::machineError(std::string("encoding failed: ") + e.what());
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
// --both's text, times the usual: 1.4 × 29 px is 40 px in a 720p half, 20 px where the
// 2560-wide video is shown 1280 wide (a projector, a browser's page), as large as a single
// video's text was when a classroom found it marginal at the back.
constexpr float kBothTextScale = 1.4f;

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
// the other "reversed"; a note for each run that disagrees with the prediction. A body with no
// preferred direction names them by their spins, "ccw" and "cw".
std::array<std::string, 2> bothNames(const std::vector<sim::Rollout>& runs,
                                     std::vector<std::string>& notes) {
  const sim::Model& model = runs[0].model();
  const sim::Direction preferred_direction = sim::preferredDirection(model, model.initial.spin);
  std::array<std::string, 2> names;
  for (int i = 0; i < 2; ++i) {
    const double spin = runs[i].model().initial.spin;
    if (preferred_direction == sim::Direction::None) {
      names[i] = spin > 0 ? "ccw" : "cw";
      continue;
    }
    const bool preferred = sim::turns(preferred_direction, spin);
    names[i] = preferred ? "preferred" : "reversed";
    const bool reversed = runs[i].summary().first_reversal_s.has_value();
    const tasks::AgainstTheory said =
        tasks::againstTheory(preferred, reversed, sim::growsEitherWay(model, std::abs(spin)));
    if (said != tasks::AgainstTheory::NothingToSay)
      notes.push_back("spun " + rb::show(spin) + " rad/s" +
                      std::string(tasks::wordsFor(said, tasks::Front::Note)));
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

std::string stem(const std::string& path) {
  return fs::path(path).stem().string();
}

}  // namespace

std::array<BothHalf, 2> bothHalves(const sim::Model& model) {
  // So that a class sees the reversal on the left whichever way the scene spins the body.
  const double spin = model.initial.spin;
  const sim::Direction preferred = sim::preferredDirection(model, spin);
  if (preferred == sim::Direction::None) return {{{spin, ""}, {-spin, ""}}};
  const double against = sim::turns(preferred, spin) ? -spin : spin;
  return {{{against, "against its preferred way"}, {-against, "its preferred way"}}};
}

std::string titleWithPlayback(const std::string& title, double playback) {
  if (playback == 1) return title;
  const std::string speed = ", at " + rb::show(playback) + "\u00d7 speed";
  const std::size_t named = title.find(": ");
  return named == std::string::npos ? title + speed
                                    : title.substr(0, named) + speed + title.substr(named);
}

rb::Status checkEncoderOptions(int crf, const std::string& preset) {
  if (crf < 1 || crf > 51)
    return rb::Status::fail(rb::argumentName("crf") +
                            ": must be within 1 … 51 (lower is better; 0 would be lossless "
                            "High 4:4:4, which browsers do not play), not " +
                            std::to_string(crf));
  for (std::string_view p : kPresets)
    if (preset == p) return {};
  std::string names;
  for (std::string_view p : kPresets) names.append(names.empty() ? "" : ", ").append(p);
  return rb::Status::fail(rb::argumentName("preset") + ": must be one of x264's: " + names +
                          "; not '" + preset + "'");
}

std::jthread preloadDriver(render::Backend backend) {
  return std::jthread([backend] { render::preloadBackend(backend); });
}

rb::Result<VideoResult> renderVideo(const tasks::LoadedScene& loaded, const VideoRequest& request) {
  if (auto ok = checkEncoderOptions(request.crf, request.preset); !ok) return ok.error();
  if (auto ok = checkExtension(request.output, ".mp4", "MP4 video", request.both); !ok)
    return ok.error();
  const sim::Model& model = loaded.model;
  auto planned = planVideo(loaded.scene, model, model.duration);
  if (!planned) return planned.error();
  const VideoPlan& plan = planned.value();
  // Before any file is begun: a body that cannot be tessellated is the scene's error.
  const auto triangles = bodyTrianglesOf(loaded, plan.surface);
  if (!triangles) return triangles.error();
  if (request.both && model.initial.spin == 0)
    return rb::Error{"", request.scene_name + ": " + rb::argumentName("both") +
                             " renders the spin and its reverse, which at spin 0 are the same "
                             "run; give a spin (" +
                             rb::argumentName("spin") + ", or initial.spin in the scene)"};
  auto cancelled = [&] { return request.cancelled && request.cancelled(); };
  // One run per direction, sharing the body; with --both, in the order of the halves.
  std::vector<sim::Rollout> runs;
  std::vector<std::string> ways = {""};
  if (request.both) {
    ways.clear();
    for (const BothHalf& half : bothHalves(model)) {
      sim::Model run = model;
      run.initial.spin = half.spin;
      runs.emplace_back(run);
      ways.push_back(half.way);
    }
  } else {
    runs.emplace_back(model);
  }

  // Output paths: the request's exactly, else out/<scene>.mp4; with both, the output (less
  // any .mp4) is the base of BASE-preferred.mp4, BASE-reversed.mp4 (renamed at the end) and
  // BASE-both.mp4.
  std::string base = request.output.empty() ? "out/" + stem(request.scene_name) : request.output;
  if (base.size() > 4 && base.substr(base.size() - 4) == ".mp4") base.resize(base.size() - 4);
  const std::vector<std::string> provisional =
      request.both
          ? std::vector<std::string>{base + "-preferred.mp4", base + "-reversed.mp4",
                                     base + "-both.mp4"}
          : std::vector<std::string>{request.output.empty() ? base + ".mp4" : request.output};
  // Declared before the outputs, so that a video refused or stopped removes its temporary files
  // first and then the folders it made for them, left empty.
  tasks::MadeFolders made;
  std::vector<std::unique_ptr<Output>> outputs;
  for (std::size_t i = 0; i < provisional.size(); ++i) {
    if (auto ok = tasks::makeParentFolder(provisional[i], &made); !ok) return ok.error();
    render::EncoderSettings settings;
    settings.width = i == 2 ? 2 * plan.width : plan.width;
    settings.height = plan.height;
    settings.fps = plan.fps;
    settings.crf = request.crf;
    settings.preset = request.preset;
    outputs.push_back(std::make_unique<Output>(provisional[i], settings));
    outputs.back()->start();  // opens its encoder while the renderers are made
  }

  VideoResult result;
  // Makes the renderers and draws every frame into the encoders' queues, then lets the encoders
  // finish; an exit status when it cannot.
  std::int64_t frames = 0;
  auto drawFrames = [&]() -> std::optional<rb::Error> {
    std::vector<std::unique_ptr<render::Renderer>> renderers;
    const render::BodyPoints points = bodyPointsOf(model);
    // Each run's camera for the fixed views, and the spin of its frames so far for the inset:
    // the frame values the renderers draw from.
    std::vector<render::Framing> framings;
    std::vector<std::vector<double>> reversals;
    std::vector<SpinHistory> histories;
    for (const sim::Rollout& run : runs) {
      const RunFraming framing =
          framingOfRun(run.model(), points, static_cast<float>(plan.frame), request.cancelled);
      framings.push_back(framing.framing);
      reversals.push_back(framing.reversals);
      if (!result.leaves)  // (the first run's, with --both: one line is enough)
        result.leaves = leavesNote(framing, points, plan.view, static_cast<float>(plan.frame),
                                   model.length_unit, frameNamed(loaded.scene));
      histories.emplace_back(model.duration, plan.width);
    }
    for (std::size_t i = 0; i < runs.size(); ++i) {
      render::RenderSettings settings =
          settingsOf(plan, runs[i].model(), request.scene_name, loaded.scene.values,
                     request.backend, std::nullopt, ways[i]);
      // --both's frames are its halves too (each run is drawn once, for its own video and its
      // half): their text is drawn for the side-by-side video shown at half size.
      if (request.both) settings.text_scale = kBothTextScale;
      settings.title = titleWithPlayback(settings.title, plan.playback);
      for (std::string& shorter : settings.shorter_titles)
        shorter = titleWithPlayback(shorter, plan.playback);
      auto created = render::Renderer::create(settings, points, triangles.value());
      if (!created) return rb::machineError("render: " + created.error().text());
      if (renderers.empty()) result.opengl = created.value()->description();
      renderers.push_back(std::move(created).value());
    }

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
    for (std::int64_t k = 0; running && k < plan.frames && !cancelled(); ++k) {
      const double t = plan.frameTime(k);
      for (std::size_t i = 0; i < runs.size() && running; ++i) {
        running = histories[i].advanceTo(runs[i], t, request.cancelled) && runs[i].advanceTo(t);
        if (!running) break;
        const sim::Telemetry sample = runs[i].sampleAt(t);
        render::FrameInput frame = frameOf(sample);
        frame.framing = framings[i];
        frame.history = histories[i].with(sample);
        frame.reversals = reversals[i];
        renderers[i]->draw(frame, images[i]);
      }
      if (running && request.both) {
        sideBySide(images[0], images[1], both);
        running = send(*outputs[2], both);
      }
      for (std::size_t i = 0; running && i < runs.size(); ++i)
        running = send(*outputs[i], images[i]);
      if (!running) break;
      ++frames;
      if (request.progress) request.progress(frames, plan.frames);
    }
    // The renderers (their contexts and the driver's threads) go while the encoders finish
    // what is queued; the runs go on to the scene's end (frames stop at the last whole frame
    // time), so that the summary covers the same run as `simulate`.
    renderers.clear();
    for (auto& run : runs)
      if (running && !cancelled()) run.advanceTo(run.endTime());
    const bool complete = running && !cancelled();
    for (auto& o : outputs) complete ? o->drain() : o->abort();
    result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::nullopt;
  };
  // The renderers are made, and the frames drawn, on a thread of their own, which for one
  // video yields to its encoder (yieldToEncoders); the OpenGL driver's threads, made with the
  // renderers, inherit its priority.
  std::optional<rb::Error> failed;
  std::jthread([&] {
    if (outputs.size() == 1) yieldToEncoders();
    try {
      failed = drawFrames();
    } catch (const std::exception& e) {
      failed = rb::machineError(std::string("render: ") + e.what());
    }
  }).join();
  if (failed) return *failed;
  result.frames = frames;
  // A stopped run, or a cancel, writes nothing (the encoders removed their temporary files).
  for (const auto& run : runs) {
    result.outcome = tasks::outcomeOf(run.summary());
    if (result.outcome.ending != tasks::Ending::Stopped) continue;
    if (request.both) result.stopped_spin = run.model().initial.spin;
    return result;
  }
  if (cancelled()) {
    result.outcome.ending = tasks::Ending::Interrupted;
    return result;
  }
  for (const auto& o : outputs)
    if (o->error) return *o->error;
  std::vector<std::string> finals = provisional;
  std::vector<std::string> roles = {"single"};
  if (request.both) {
    const auto names = bothNames(runs, result.notes);
    finals[0] = base + "-" + names[0] + ".mp4";
    finals[1] = base + "-" + names[1] + ".mp4";
    roles = {names[0], names[1], "both"};
  }
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (auto e = outputs[i]->encoder->finish(finals[i]); !e) return e.error();
    VideoFile file;
    file.path = finals[i];
    file.role = roles[i];
    file.frames = outputs[i]->encoder->frames();
    if (i < runs.size()) {
      file.spin = runs[i].model().initial.spin;
      file.first_reversal_s = runs[i].summary().first_reversal_s;
      file.reversals_s = runs[i].summary().reversals;
      file.final_spin = runs[i].summary().last.spin;
    }
    result.files.push_back(file);
  }
  result.outcome.ending = tasks::Ending::Completed;
  return result;
}

tasks::OutputEntry videoEntry(const VideoFile& file, const tasks::LoadedScene& loaded,
                              const std::string& scene_name) {
  tasks::OutputEntry e;
  e.file = file.path;
  e.kind = tasks::OutputKind::Video;
  e.scene = scene_name;
  e.role = file.role;
  e.spin = file.spin;
  e.made_from = tasks::madeFrom(loaded.scene);
  e.frame_m = tasks::listedFrame(loaded.scene, loaded.model);
  e.view = loaded.scene.video.view;
  e.surface = loaded.scene.video.surface;
  if (file.spin) {  // one run's video (a side-by-side shows two)
    e.simulated_s = loaded.model.duration;
    e.first_reversal_s = file.first_reversal_s;
    e.reversals_s = file.reversals_s;
    e.final_spin = file.final_spin;
  }
  return e;
}

}  // namespace media
