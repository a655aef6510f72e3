#include "media/still.hpp"

#include <algorithm>
#include <cmath>

#include "media/frames.hpp"
#include "media/spin_history.hpp"
#include "media/video_plan.hpp"
#include "render/renderer.hpp"
#include "sim/compile.hpp"
#include "sim/rollout.hpp"
#include "util/format.hpp"

namespace media {

namespace {

// The still's time in s: request.t, or the moment it names in the scene's own run. None (with
// the run's outcome in `outcome`) when that run stopped or was cancelled first.
rb::Result<std::optional<double>> stillTime(const tasks::LoadedScene& loaded,
                                            const StillRequest& request, tasks::Outcome& outcome) {
  if (!request.t_name) return std::optional<double>(request.t);
  sim::Rollout run(loaded.model);
  auto t = tasks::resolveStillTime({0, request.t_name}, run, request.t_named, request.cancelled,
                                   request.scene_duration_only);
  outcome = tasks::outcomeOf(run.summary());
  if (request.cancelled && request.cancelled()) outcome.ending = tasks::Ending::Interrupted;
  if (outcome.ending != tasks::Ending::Completed) return std::optional<double>();
  if (!t) return t.error();
  return std::optional<double>(t.value());
}

}  // namespace

rb::Result<StillResult> renderStill(const tasks::LoadedScene& loaded, const StillRequest& given) {
  StillResult stopped_early;
  auto resolved = stillTime(loaded, given, stopped_early.outcome);
  if (!resolved) return resolved.error();
  if (!resolved.value()) return stopped_early;
  StillRequest request = given;
  request.t = *resolved.value();
  if (!(request.t >= 0) || !std::isfinite(request.t))
    return rb::Error{"", request.t_named + ": must be a time ≥ 0 s, not " + rb::show(request.t)};
  sim::Model model = loaded.model;
  // A still may show a time past the scene's duration: the run then goes on to it.
  model.duration = std::max(model.duration, request.t);
  auto planned = planVideo(loaded.scene, model, model.duration);
  // The scene's own run plans, the run on to t does not (past the longest run its video may
  // show, 10 million frames): --t is named, not the file's video section nor --duration.
  if (!planned && request.t > loaded.model.duration &&
      planVideo(loaded.scene, loaded.model, loaded.model.duration)) {
    const scene::VideoSpec& video = loaded.scene.video;
    return rb::Error{"", request.t_named + ": " + rb::show(request.t) +
                             " s is past the longest run a video of this scene may show (10 "
                             "million frames at playback " +
                             rb::show(video.playback) + " and " + std::to_string(video.fps) +
                             " fps: " + rb::show(1e7 * video.playback / video.fps) +
                             " s); a still is one of its frames: choose an earlier time"};
  }
  if (!planned) return planned.error();
  // The same for the step count: the scene's run is within sim::kMaxSteps, 1e11 (compile), the run
  // on to t may not be (1e9 s at 0.5 ms would integrate for weeks).
  if (model.dt > 0 && model.duration / model.dt > sim::kMaxSteps)
    return rb::Error{"", request.t_named + ": " + rb::show(request.t) + " s at simulation.dt " +
                             rb::show(model.dt) +
                             " s is more than 1e11 steps to run: choose an earlier time"};
  const VideoPlan& plan = planned.value();
  StillResult result;
  result.view = plan.view;
  render::RenderSettings settings = settingsOf(plan, model, request.scene_name, loaded.scene.values,
                                               request.backend, request.title);
  settings.readouts = request.readouts && !request.transparent;
  settings.transparent = request.transparent;
  if (request.transparent) settings.title.clear();
  const render::BodyPoints points = bodyPointsOf(model);
  auto triangles = bodyTrianglesOf(loaded, settings.surface);
  if (!triangles) return triangles.error();
  auto created = render::Renderer::create(settings, points, triangles.value());
  if (!created) return rb::machineError(request.asked_by + ": " + created.error().text());
  result.opengl = created.value()->description();
  render::Renderer& renderer = *created.value();
  // Progress in thousandths of the simulated time of both runs (to t, then the framing's).
  const double work = request.t + model.duration;
  const auto report = [&](double simulated) {
    if (request.progress && work > 0)
      request.progress(static_cast<std::int64_t>(1000 * std::min(1.0, simulated / work)), 1000);
  };
  // Run to the still's time, keeping the spin for the inset as the video would have (in
  // slices, to show progress: the history goes on from one slice to the next unchanged).
  sim::Rollout run(model);
  SpinHistory history(model.duration, plan.width);
  constexpr int kSlices = 200;
  bool ran = true;
  for (int k = 1; k <= kSlices && ran; ++k) {
    const double slice = k == kSlices ? request.t : request.t * k / kSlices;
    ran = history.advanceTo(run, slice, request.cancelled);
    report(slice);
  }
  const auto stopped = [&] {
    result.outcome = tasks::outcomeOf(run.summary());
    if (result.outcome.ending == tasks::Ending::Completed)
      result.outcome.ending = tasks::Ending::Interrupted;
    return result;
  };
  if (!ran || !run.advanceTo(request.t)) return stopped();
  const sim::Telemetry sample = run.sampleAt(request.t);
  render::FrameInput frame = frameOf(sample);
  // The video's framing: of the run to the scene's end (or to t, when past it).
  const RunFraming framing =
      framingOfRun(model, points, static_cast<float>(plan.frame), request.cancelled,
                   [&](double t) { report(request.t + t); });
  // Stopped while framing: the framing is of part of the run, so no still.
  if (request.cancelled && request.cancelled()) return stopped();
  frame.framing = framing.framing;
  result.leaves = leavesNote(framing, points, plan.view, static_cast<float>(plan.frame),
                             model.length_unit, frameNamed(loaded.scene));
  frame.history = history.with(sample);
  frame.reversals = framing.reversals;
  renderer.draw(frame, result.image);
  result.image.drawn_by = renderer.rasteriser();
  result.outcome.t = request.t;
  return result;
}

}  // namespace media
