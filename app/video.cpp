// render, still and compare: the simulation's frames drawn and encoded. The pipeline runs
// simulate → render → encode in threads joined by bounded queues, so no run holds its frames.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include "app/commands.hpp"
#include "app/frames.hpp"
#include "app/progress.hpp"
#include "app/queue.hpp"
#include "app/scene_args.hpp"
#include "render/encoder.hpp"
#include "render/image_io.hpp"
#include "render/renderer.hpp"
#include "sim/analysis.hpp"
#include "sim/initial.hpp"
#include "sim/run.hpp"
#include "sim/step.hpp"

namespace app {
namespace {

namespace fs = std::filesystem;

render::RenderSettings settingsOf(const sim::Model& model, const std::string& title) {
  render::RenderSettings s;
  s.width = model.video.width;
  s.height = model.video.height;
  render::parseView(model.video.view, s.view);
  s.title = title;
  s.duration = model.steps * model.dt;
  s.spin_range = std::max(1.0, 1.1 * std::abs(model.initial.spin));
  return s;
}

std::string stem(const std::string& path) { return fs::path(path).stem().string(); }

std::string describeSpin(double spin) {
  char text[64];
  std::snprintf(text, sizeof text, "%+g rad/s, %s", spin,
                spin > 0 ? "counter-clockwise" : spin < 0 ? "clockwise" : "no spin");
  return text;
}

// One simulated run feeding video frames: a thread that steps the model and queues one frame
// every steps_per_frame steps, the first `frames` of them.
struct Track {
  sim::Model model;
  std::string title;
  BoundedQueue<sim::Telemetry> frames{8};
  sim::RunSummary summary;
  std::thread thread;

  void start() {
    thread = std::thread([this] {
      sim::State state = sim::initialState(model);
      sim::RunOptions options;
      options.steps_per_sample = model.video.steps_per_frame;
      std::int64_t queued = 0;
      options.on_sample = [&](const sim::Telemetry& t) {
        if (queued < model.video.frames && frames.push(t)) ++queued;
      };
      summary = sim::run(model, state, options);
      frames.close();
    });
  }
};

// One output video fed by its own encoding thread.
struct Output {
  std::unique_ptr<render::VideoEncoder> encoder;
  BoundedQueue<render::Image> images{4};
  std::optional<std::string> error;
  std::thread thread;

  void start() {
    thread = std::thread([this] {
      while (auto image = images.pop()) {
        if (error) continue;
        error = encoder->add(*image);
        if (error) images.close();
      }
    });
  }
};

// Places a and b side by side.
render::Image sideBySide(const render::Image& a, const render::Image& b) {
  render::Image out;
  out.width = a.width + b.width;
  out.height = a.height;
  out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
  for (int y = 0; y < a.height; ++y) {
    auto* row = &out.rgba[static_cast<std::size_t>(y) * out.width * 4];
    std::copy_n(&a.rgba[static_cast<std::size_t>(y) * a.width * 4], a.width * 4, row);
    std::copy_n(&b.rgba[static_cast<std::size_t>(y) * b.width * 4], b.width * 4, row + a.width * 4);
  }
  return out;
}

std::variant<std::unique_ptr<render::VideoEncoder>, std::string> openVideo(
    const std::string& path, int width, int height, const RenderArgs& args, int fps) {
  render::EncoderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.fps = fps;
  settings.crf = args.crf;
  settings.preset = args.preset;
  return render::VideoEncoder::open(path, settings);
}

// Names for --both: the spin in the direction the linearised theory prefers is "preferred",
// the other "reversed". A note says when the runs disagree with the prediction.
std::array<std::string, 2> bothNames(const std::array<Track*, 2>& tracks) {
  const sim::Model& model = tracks[0]->model;
  const bool ccw_preferred =
      std::string(sim::preferredDirection(model, model.initial.spin)) == "ccw";
  std::array<std::string, 2> names;
  for (int i = 0; i < 2; ++i) {
    const bool preferred = (tracks[i]->model.initial.spin > 0) == ccw_preferred;
    names[i] = preferred ? "preferred" : "reversed";
    if (preferred == tracks[i]->summary.first_reversal_s.has_value())
      std::cerr << "note: spun " << tracks[i]->model.initial.spin << " rad/s the body "
                << (preferred ? "reversed although the theory prefers this direction"
                              : "did not reverse within the run")
                << "\n";
  }
  return names;
}

}  // namespace

int renderCommand(const RenderArgs& args) {
  Overrides o = args.overrides;
  auto compiled = loadScene(args.scene, o);
  if (auto* e = std::get_if<std::string>(&compiled)) {
    std::cerr << *e << "\n";
    return kBadInput;
  }
  std::vector<std::unique_ptr<Track>> tracks;
  tracks.push_back(std::make_unique<Track>());
  tracks[0]->model = std::move(std::get<sim::Model>(compiled));
  const sim::Model& model = tracks[0]->model;
  if (args.verbose) describeModel(model, args.scene, model.video.steps_per_frame, "frame");
  if (model.video.width % 2 || model.video.height % 2) {
    std::cerr << "--size: the width and height of a video must be even\n";
    return kBadInput;
  }
  if (args.both) {
    tracks.push_back(std::make_unique<Track>());
    tracks[1]->model = model;
    tracks[1]->model.initial.spin = -model.initial.spin;
  }
  for (auto& t : tracks) t->title = stem(args.scene) + ": spun " + describeSpin(t->model.initial.spin);

  // Output paths: -o exactly, else out/<scene>.mp4; with --both, -o (less any .mp4) is the
  // base of BASE-preferred.mp4, BASE-reversed.mp4 (renamed at the end) and BASE-both.mp4.
  if (args.output.empty()) fs::create_directories("out");
  std::string base = args.output.empty() ? "out/" + stem(args.scene) : args.output;
  if (base.size() > 4 && base.substr(base.size() - 4) == ".mp4") base.resize(base.size() - 4);
  std::vector<std::unique_ptr<Output>> outputs;
  const std::vector<std::string> provisional =
      args.both ? std::vector<std::string>{base + "-preferred.mp4", base + "-reversed.mp4",
                                           base + "-both.mp4"}
                : std::vector<std::string>{args.output.empty() ? base + ".mp4" : args.output};
  for (std::size_t i = 0; i < provisional.size(); ++i) {
    const int width = i == 2 ? 2 * model.video.width : model.video.width;
    auto opened = openVideo(provisional[i], width, model.video.height, args, model.video.fps);
    if (auto* e = std::get_if<std::string>(&opened)) {
      std::cerr << *e << "\n";
      return kBadInput;
    }
    outputs.push_back(std::make_unique<Output>());
    outputs.back()->encoder = std::move(std::get<std::unique_ptr<render::VideoEncoder>>(opened));
  }

  auto created = render::Renderer::create(settingsOf(model, tracks[0]->title), bodyPointsOf(model));
  if (auto* e = std::get_if<std::string>(&created)) {
    std::cerr << "render: " << *e << "\n";
    return kBadInput;
  }
  std::vector<std::unique_ptr<render::Renderer>> renderers;
  renderers.push_back(std::move(std::get<std::unique_ptr<render::Renderer>>(created)));
  if (args.both) {
    auto second = render::Renderer::create(settingsOf(tracks[1]->model, tracks[1]->title),
                                           bodyPointsOf(model));
    if (auto* e = std::get_if<std::string>(&second)) {
      std::cerr << "render: " << *e << "\n";
      return kBadInput;
    }
    renderers.push_back(std::move(std::get<std::unique_ptr<render::Renderer>>(second)));
  }

  for (auto& t : tracks) t->start();
  for (auto& o : outputs) o->start();
  Progress progress("render", model.video.frames, !args.quiet);
  const auto start = std::chrono::steady_clock::now();
  std::int64_t frames = 0;
  std::vector<render::Image> images(tracks.size());
  for (bool running = true; running && frames < model.video.frames;) {
    for (std::size_t i = 0; i < tracks.size() && running; ++i) {
      auto telemetry = tracks[i]->frames.pop();
      if (!telemetry) {
        running = false;
        break;
      }
      renderers[i]->draw(frameOf(*telemetry), images[i]);
    }
    if (!running) break;
    for (std::size_t i = 0; i < tracks.size(); ++i) outputs[i]->images.push(images[i]);
    if (args.both) outputs[2]->images.push(sideBySide(images[0], images[1]));
    progress.update(++frames);
  }
  for (auto& t : tracks) {
    t->frames.close();
    t->thread.join();
  }
  for (auto& o : outputs) {
    o->images.close();
    o->thread.join();
  }
  progress.finish();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  for (auto& t : tracks)
    if (t->summary.divergence) {
      std::cerr << args.scene << ": the run stopped: " << *t->summary.divergence
                << ". No video written\n";
      return kDiverged;
    }
  std::vector<std::string> finals = provisional;
  if (args.both) {
    const auto names = bothNames({tracks[0].get(), tracks[1].get()});
    finals[0] = base + "-" + names[0] + ".mp4";
    finals[1] = base + "-" + names[1] + ".mp4";
  }
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i]->error) {
      std::cerr << *outputs[i]->error << "\n";
      return kBadInput;
    }
  }
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (auto e = outputs[i]->encoder->finish(finals[i])) {
      std::cerr << *e << "\n";
      return kBadInput;
    }
  }
  if (!args.quiet) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
      std::printf("%s  (%lld frames", finals[i].c_str(), outputs[i]->encoder->frames());
      if (i < tracks.size()) {
        const auto& r = tracks[i]->summary.first_reversal_s;
        if (r)
          std::printf(", spun %+g rad/s, first reversal at %.3f s", tracks[i]->model.initial.spin, *r);
        else
          std::printf(", spun %+g rad/s, no reversal", tracks[i]->model.initial.spin);
      }
      std::printf(")\n");
    }
    std::printf("%lld frames in %.2f s: %.1f frames per second end to end\n",
                static_cast<long long>(frames), wall, frames / wall);
  }
  return kOk;
}

int stillCommand(const StillArgs& args) {
  const Overrides& o = args.overrides;
  if (!(args.t >= 0) || !std::isfinite(args.t)) {
    std::cerr << "--t must be a time ≥ 0 s\n";
    return kBadInput;
  }
  auto compiled = loadScene(args.scene, o);
  if (auto* e = std::get_if<std::string>(&compiled)) {
    std::cerr << *e << "\n";
    return kBadInput;
  }
  const sim::Model& model = std::get<sim::Model>(compiled);
  const std::string path = args.output.empty()
                               ? "out/" + stem(args.scene) + "-" + model.video.view + ".png"
                               : args.output;
  if (args.output.empty()) fs::create_directories("out");

  render::RenderSettings settings = settingsOf(model, stem(args.scene));
  settings.readouts = !args.no_readouts;
  settings.duration = std::max(settings.duration, args.t);
  auto created = render::Renderer::create(settings, bodyPointsOf(model));
  if (auto* e = std::get_if<std::string>(&created)) {
    std::cerr << "render: " << *e << "\n";
    return kBadInput;
  }
  auto& renderer = *std::get<std::unique_ptr<render::Renderer>>(created);
  // Run to the still's time, keeping the spin at each video frame for the inset.
  sim::State state = sim::initialState(model);
  const std::int64_t steps = std::llround(args.t / model.dt);
  render::Image image;
  for (;;) {
    const bool last = state.step >= steps;
    if (state.step % model.video.steps_per_frame == 0 || last) {
      const sim::Telemetry t = sim::telemetryOf(model, state);
      if (last) {
        renderer.draw(frameOf(t), image);
        break;
      }
      renderer.remember(t.t, t.spin);
    }
    sim::step(model, state);
  }
  if (auto e = render::writePng(path, image)) {
    std::cerr << *e << "\n";
    return kBadInput;
  }
  if (!args.quiet) std::printf("%s\n", path.c_str());
  return kOk;
}

int compareCommand(const CompareArgs& args) {
  render::Image a, b;
  for (auto [path, image] : {std::pair{&args.actual, &a}, std::pair{&args.expected, &b}}) {
    if (auto e = render::readPng(*path, *image)) {
      std::cerr << *e << "\n";
      return kBadInput;
    }
  }
  const render::Comparison c = render::compareImages(a, b, args.channel_tolerance);
  if (!c.same_size) {
    std::printf("differ: sizes %dx%d and %dx%d\n", a.width, a.height, b.width, b.height);
    return 1;
  }
  const bool same = c.fraction() <= args.pixel_fraction;
  std::printf("%s: %lld of %lld pixels (%.4f%%) differ by more than %d in a channel "
              "(allowed %.4f%%); largest channel difference %d",
              same ? "same" : "differ", c.differing, c.pixels, 100 * c.fraction(),
              args.channel_tolerance, 100 * args.pixel_fraction, c.max_channel_delta);
  if (c.differing)
    std::printf("; differing pixels within x %d–%d, y %d–%d", c.box[0], c.box[2], c.box[1], c.box[3]);
  std::printf("\n");
  if (!same && !args.diff.empty()) {
    if (auto e = render::writePng(args.diff, render::diffImage(a, b, args.channel_tolerance))) {
      std::cerr << *e << "\n";
      return kBadInput;
    }
    std::printf("diff image: %s\n", args.diff.c_str());
  }
  return same ? 0 : 1;
}

}  // namespace app
