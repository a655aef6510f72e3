// render, still and compare: option checks and messages around media/ (the drawing side).
#include "media/video.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include "app/cli.hpp"
#include "app/commands.hpp"
#include "app/interrupt.hpp"
#include "app/plot.hpp"
#include "app/progress.hpp"
#include "media/still.hpp"
#include "media/video_plan.hpp"
#include "render/image_io.hpp"
#include "tasks/output.hpp"
#include "tasks/player_data.hpp"
#include "tasks/run_json.hpp"
#include "util/assets.hpp"
#include "util/format.hpp"

namespace app {
namespace {

// --backend's value (or the environment's, named by `from`); none after a line naming the
// choices.
std::optional<render::Backend> parseBackend(const std::string& name, const std::string& from) {
  const auto backend = rb::parseName<render::Backend>(name);
  if (!backend)
    tell(Tone::Error, from + ": " + rb::choices<render::Backend>() + ", not '" + name + "'");
  return backend;
}

bool interrupted() {
  return interruptSignal() != 0;
}

// The exit status and message of a run that stopped or was interrupted before its output.
// `both_stopped`: the spin of --both's run that stopped, whose stop kept the other's video too.
int notWritten(const tasks::Outcome& outcome, const std::string& scene, const std::string& what,
               const sim::Model& model, std::optional<double> both_stopped = std::nullopt) {
  if (outcome.ending == tasks::Ending::Stopped) {
    const std::string why = saidOddBody(model);
    // A still's run ends at its --t, a video's at its --duration.
    std::string line =
        stoppedLine(scene, outcome, what, what == "still" ? "--t" : "--duration", why);
    if (both_stopped)
      line += ". It was --both's run spun " + rb::show(*both_stopped) + " rad/s; --spin " +
              rb::show(-*both_stopped) + " without --both renders the other way's alone";
    tell(Tone::Error, line);
    return kDiverged;
  }
  tell(Tone::Error, scene + ": interrupted; no " + what + " written");
  return interruptedStatus();
}

void printVideos(const media::VideoResult& r) {
  for (const std::string& note : r.notes) tell(Tone::Note, note);
  if (r.leaves) tell(Tone::Warning, *r.leaves);
  for (const media::VideoFile& f : r.files) {
    std::printf("%s  (%s", f.path.c_str(), rb::counted(f.frames, "frame").c_str());
    if (f.spin && f.first_reversal_s)
      std::printf(", spun %+g rad/s, first reversal at %.3f s", *f.spin, *f.first_reversal_s);
    else if (f.spin)
      std::printf(", spun %+g rad/s, no reversal", *f.spin);
    std::printf(")\n");
  }
  std::printf("%s in %.2f s: %.1f frames per second end to end\n",
              rb::counted(r.frames, "frame").c_str(), r.wall_s, r.frames / r.wall_s);
}

}  // namespace

int renderCommand(const RenderArgs& args) {
  installInterruptHandlers();
  if (auto ok = media::checkEncoderOptions(args.crf, args.preset); !ok) return fail(ok);
  if (auto ok = media::checkExtension(args.output, ".mp4", "MP4 video", args.both); !ok)
    return fail(ok);
  const auto backend = parseBackend(args.backend, args.backend_from);
  if (!backend) return kBadInput;
  std::jthread preload = media::preloadDriver(*backend);
  auto loaded = loadScene(args.scene, args.overrides);
  if (!loaded) return fail(loaded);
  noteShipped(args.scene);
  if (args.verbose) describeModel(loaded->model, args.scene);
  // A video over ten minutes long is said up front, on or off a terminal (where no progress
  // bar shows): a playback typed 0.001 for 1 made 180,000 frames of a 6 s scene, hundreds of
  // megabytes, with nothing said for as long as it ran.
  if (const auto plan = media::planVideo(loaded->scene, loaded->model, loaded->model.duration);
      plan && !args.quiet && plan->frames > 600LL * plan->fps)
    tell(Tone::Note,
         args.scene + ": " + std::to_string(plan->frames) + " frames, " +
             std::to_string(std::lround(static_cast<double>(plan->frames) / plan->fps / 60.0)) +
             " min of video (" + rb::show(loaded->model.duration) + " s simulated at playback " +
             rb::show(plan->playback) + ", " + rb::show(plan->fps) +
             " fps); this takes a while, and Ctrl-C stops it with nothing written");
  media::VideoRequest request;
  request.scene_name = args.scene;
  request.output = args.output;
  request.both = args.both;
  request.crf = args.crf;
  request.preset = args.preset;
  request.backend = *backend;
  request.cancelled = interrupted;
  Progress progress("render", 1, !args.quiet);
  request.progress = [&](std::int64_t done, std::int64_t total) {
    progress.setTotal(total);
    progress.update(done);
  };
  preload.join();
  auto made = media::renderVideo(loaded.value(), request);
  progress.finish();
  if (!made) return fail(made);
  const media::VideoResult& result = made.value();
  if (args.verbose) tell(Tone::Note, "render: OpenGL " + result.opengl);
  if (result.outcome.ending != tasks::Ending::Completed)
    return notWritten(result.outcome, args.scene, "video", loaded->model, result.stopped_spin);
  std::vector<tasks::OutputEntry> entries;
  for (const media::VideoFile& f : result.files)
    entries.push_back(media::videoEntry(f, loaded.value(), sceneName(args.scene)));
  record(entries);
  if (!args.quiet) printVideos(result);
  return kOk;
}

int stillCommand(const StillArgs& args) {
  installInterruptHandlers();
  if (auto ok = media::checkExtension(args.output, ".png", "PNG", false); !ok) return fail(ok);
  const auto backend = parseBackend(args.backend, args.backend_from);
  if (!backend) return kBadInput;
  const auto time = tasks::parseStillTime(args.t, args.t_named);
  if (!time) return fail(time);
  std::jthread preload = media::preloadDriver(*backend);
  auto loaded = loadScene(args.scene, args.overrides);
  if (!loaded) return fail(loaded);
  noteShipped(args.scene);
  media::StillRequest request;
  request.scene_name = args.scene;
  request.t = time->seconds;
  request.t_name = time->named;
  request.t_named = args.t_named;
  request.readouts = !args.no_readouts;
  request.transparent = args.transparent;
  request.backend = *backend;
  request.cancelled = interrupted;
  Progress progress("still", 1000, !args.quiet);
  request.progress = [&](std::int64_t done, std::int64_t) { progress.update(done); };
  preload.join();
  auto drawn = media::renderStill(loaded.value(), request);
  progress.finish();
  if (!drawn) return fail(drawn);
  const media::StillResult& still = drawn.value();
  if (args.verbose) tell(Tone::Note, "still: OpenGL " + still.opengl);
  if (still.outcome.ending != tasks::Ending::Completed)
    return notWritten(still.outcome, args.scene, "still", loaded->model);
  const std::string path = args.output.empty()
                               ? "out/" + std::filesystem::path(args.scene).stem().string() + "-" +
                                     std::string(rb::nameOf(still.view)) + ".png"
                               : args.output;
  if (auto made = tasks::makeParentFolder(path); !made) return fail(made);
  if (auto e = render::writePng(path, still.image); !e) return fail(e);
  tasks::OutputEntry listed{path,
                            tasks::OutputKind::Still,
                            sceneName(args.scene),
                            std::string(rb::nameOf(still.view)),
                            loaded->model.initial.spin,
                            still.outcome.t,
                            tasks::madeFrom(loaded->scene),
                            tasks::listedFrame(loaded->scene, loaded->model)};
  listed.surface = loaded->scene.video.surface;
  record({listed});
  if (!args.quiet) {
    if (still.leaves) tell(Tone::Warning, *still.leaves);
    if (time->named)
      std::printf("%s  (%s at t = %s s)\n", path.c_str(), rb::nameOf(*time->named).data(),
                  rb::show(still.outcome.t).c_str());
    else
      std::printf("%s\n", path.c_str());
  }
  return kOk;
}

int runRender(Cli& cli) {
  return renderCommand(cli.render_args);
}
int runStill(Cli& cli) {
  return stillCommand(cli.still_args);
}
int runCompare(Cli& cli) {
  return compareCommand(cli.compare_args);
}

namespace {

rb::Status checkCompareOptions(const CompareArgs& args) {
  if (args.channel_tolerance < 0 || args.channel_tolerance > 255)
    return rb::Status::fail("--tolerance: a channel difference within 0 … 255, not " +
                            std::to_string(args.channel_tolerance));
  if (!(args.pixel_fraction >= 0 && args.pixel_fraction <= 1))
    return rb::Status::fail(
        "--pixels: a fraction of the pixels within 0 … 1 (0.002 = 0.2 %), not " +
        rb::show(args.pixel_fraction));
  if (args.square < 0)
    return rb::Status::fail("--square: a side in pixels, 0 (no square check) or more, not " +
                            std::to_string(args.square));
  return {};
}

// --diff's place checked (its folder made, as every output's is) before the images are read: an
// unwritable one is refused at once, not after the verdict (`--diff diffs/x.png` into a missing
// folder would say "differ" and then exit 2).
rb::Status checkDiffPlace(const CompareArgs& args, tasks::MadeFolders& made) {
  if (args.diff.empty()) return {};
  // The diff written over one of the images compared would destroy it (`compare new.png
  // golden.png --diff golden.png`: the golden became a magenta diff).
  for (const auto& [image, role] : {std::pair{&args.actual, "the image compared"},
                                    std::pair{&args.expected, "the expected image"}}) {
    std::error_code ec;
    if (std::filesystem::equivalent(args.diff, *image, ec))
      return rb::Status::fail("--diff " + args.diff + ": is " + role + " (" + *image +
                              "); give the diff a name of its own");
  }
  return checkPlotFile(args.diff, &made, "--diff");
}

// The verdict's line on standard output, and what drew each image where that differs.
void printVerdict(const CompareArgs& args, const render::Image& a, const render::Image& b,
                  const render::Comparison& c, bool same, bool square) {
  std::printf(
      "%s: %lld of %lld pixels (%.4f%%) differ by more than %d in a channel "
      "(allowed %.4f%%); largest channel difference %d",
      same ? "same" : "differ", c.differing, c.pixels, 100 * c.fraction(), args.channel_tolerance,
      100 * args.pixel_fraction, c.max_channel_delta);
  if (c.differing)
    std::printf("; differing pixels within x %d–%d, y %d–%d", c.box[0], c.box[2], c.box[1],
                c.box[3]);
  if (c.square > 1)
    std::printf("; largest square of them %dx%d at x %d, y %d%s", c.square, c.square,
                c.square_at[0], c.square_at[1],
                square ? (" (--square " + std::to_string(args.square) + ")").c_str() : "");
  std::printf("\n");
  // A golden holds for the rasteriser that drew it (softpipe against llvmpipe: 2.8 % of a still's
  // pixels): where both say what drew them, and it differs, that is said, the likely cause of the
  // difference.
  if (!same && !a.drawn_by.empty() && !b.drawn_by.empty() && a.drawn_by != b.drawn_by)
    std::printf(
        "note: drawn by different OpenGL: %s by %s, %s by %s; a golden holds for the "
        "rasteriser that drew it (%s, rattleback compare)\n",
        args.actual.c_str(), a.drawn_by.c_str(), args.expected.c_str(), b.drawn_by.c_str(),
        rb::docPage("commands.md").c_str());
}

}  // namespace

int compareCommand(const CompareArgs& args) {
  if (auto ok = checkCompareOptions(args); !ok) return fail(ok);
  tasks::MadeFolders made;  // removed again when no diff is written into it
  if (auto ok = checkDiffPlace(args, made); !ok) return fail(ok);
  render::Image a, b;
  for (auto [path, image] : {std::pair{&args.actual, &a}, std::pair{&args.expected, &b}}) {
    // An image that cannot be read is the input at fault, whatever the reason.
    if (auto e = render::readPng(*path, *image); !e) {
      tell(Tone::Error, e.error().text());
      return kBadInput;
    }
  }
  const render::Comparison c = render::compareImages(a, b, args.channel_tolerance);
  if (!c.same_size) {
    if (!args.quiet)
      std::printf(
          "differ: the images have different sizes, %dx%d and %dx%d, so no pixel was "
          "compared%s\n",
          a.width, a.height, b.width, b.height,
          args.diff.empty() ? "" : " and no diff image was written");
    return 1;
  }
  const render::Tolerance tolerance{args.channel_tolerance, args.pixel_fraction, args.square};
  const bool square = render::squareDiffers(c, tolerance);
  const bool same = render::matches(c, tolerance);
  if (!args.quiet) printVerdict(args, a, b, c, same, square);
  if (!same && !args.diff.empty()) {
    const rb::OutputNamedBy naming("--diff");  // the way out an error line suggests
    if (auto e = render::writePng(args.diff, render::diffImage(a, b, args.channel_tolerance)); !e)
      return fail(e);  // 4 for a fault of the disk, 2 for a place that cannot be written
    if (!args.quiet) std::printf("diff image: %s\n", args.diff.c_str());
  }
  // The same: a diff left at --diff by an earlier comparison that differed is removed, so that it
  // does not stand beside this pass (a reused workspace would publish the stale diff with the
  // passing run).
  std::error_code ec;
  if (same && !args.diff.empty() && std::filesystem::is_regular_file(args.diff, ec)) {
    std::filesystem::remove(args.diff, ec);
    if (!args.quiet && !ec)
      std::printf("removed %s, the diff image of an earlier comparison\n", args.diff.c_str());
  }
  return same ? 0 : 1;
}

}  // namespace app
