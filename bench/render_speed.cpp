// Frames per second of the video pipeline's stages, measured side by side in one run:
// render only (draw + read back + read-outs), encode only (RGBA → yuv420p → x264), and end
// to end (media::renderVideo, as `rattleback render`: simulate, render and encode in overlapping
// threads), and `render --both` (two renderers on one thread, three encoders), for each OpenGL
// backend; and the CPU time (all threads) encoding alone and end to end take. The last column is
// the least end / encode those cores allow: end to end cannot take less wall time than its CPU time
// spread over every core (its CPU time ÷ cores ÷ encoding's wall time). Usage:
// rattleback_render_bench [SCENE] [FRAMES] [draw] With "draw" it only draws the frames, 720p with
// EGL, ten times over: a steady load for a profiler (perf record), and the render-only figure
// alone.
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "media/frames.hpp"
#include "media/video.hpp"
#include "media/video_plan.hpp"
#include "render/encoder.hpp"
#include "render/renderer.hpp"
#include "sim/rollout.hpp"
#include "tasks/scene_args.hpp"

namespace {

constexpr int kRepeats = 3;

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

double cpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string scene = argc > 1 ? argv[1] : RATTLEBACK_SOURCE_DIR "/scenes/rattleback.yaml";
  const int frames = argc > 2 ? std::stoi(argv[2]) : 200;
  const bool draw_only = argc > 3 && std::string(argv[3]) == "draw";
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  // A folder of this run's own for the videos: two benches at once do not overwrite each other.
  char scratch_name[] = "/tmp/rattleback-render-bench-XXXXXX";
  if (!::mkdtemp(scratch_name)) return 2;
  const std::filesystem::path scratch = scratch_name;
  std::printf("scene %s, %d frames per measurement, median of %d, %u cores\n", scene.c_str(),
              frames, kRepeats, cores);
  std::printf("%-8s %-10s %11s %11s %11s %11s %11s %11s %11s %11s\n", "backend", "size",
              "render fps", "encode fps", "end-to-end", "--both", "end/encode", "encode cpu",
              "e2e cpu", "bound");
  for (render::Backend backend : {render::Backend::Egl, render::Backend::OsMesa})
    for (auto [w, h] : {std::pair{1280, 720}, std::pair{1920, 1080}}) {
      tasks::Overrides o;
      o.set(tasks::SceneOption::Size, std::array<int, 2>{w, h});
      auto loaded = tasks::loadScene(scene, o);
      if (!loaded) {
        std::fprintf(stderr, "%s\n", loaded.error().text().c_str());
        return 2;
      }
      const sim::Model& model = loaded->model;
      auto planned = media::planVideo(loaded->scene, model, model.duration);
      if (!planned) {
        std::fprintf(stderr, "%s\n", planned.error().text().c_str());
        return 2;
      }
      const media::VideoPlan& plan = planned.value();

      // The poses of the first `frames` video frames.
      std::vector<render::FrameInput> poses;
      std::vector<std::array<float, 2>> history;
      history.reserve(frames);
      sim::Rollout run(model);
      const render::Framing framing =
          media::framingOf(run.summary().first, media::bodyPointsOf(model));
      for (int k = 0; k < frames && run.advanceTo(plan.frameTime(k)); ++k) {
        const sim::Telemetry sample = run.sampleAt(plan.frameTime(k));
        history.push_back({static_cast<float>(sample.t), static_cast<float>(sample.spin)});
        poses.push_back(media::frameOf(sample));
        poses.back().framing = framing;
        poses.back().history = std::span(history.data(), history.size());
      }

      render::RenderSettings settings;
      settings.width = w;
      settings.height = h;
      settings.duration = model.duration;
      settings.spin_range = 5.5;
      settings.backend = backend;
      auto created = render::Renderer::create(settings, media::bodyPointsOf(model));
      if (!created) {
        std::fprintf(stderr, "%s\n", created.error().text().c_str());
        return 2;
      }
      render::Renderer& renderer = *created.value();
      std::vector<render::Image> images(frames);
      if (draw_only) {
        const auto start = std::chrono::steady_clock::now();
        for (int pass = 0; pass < 10; ++pass)
          for (std::size_t i = 0; i < poses.size(); ++i) renderer.draw(poses[i], images[i]);
        std::printf("%-8s %-10s %11.1f\n", std::string(rb::nameOf(backend)).c_str(),
                    (std::to_string(w) + "x" + std::to_string(h)).c_str(),
                    10 * poses.size() / seconds(start));
        std::filesystem::remove_all(scratch);
        return 0;
      }
      // Each stage three times, interleaved; the median of each (one pass's figures move by
      // ±15 % here from run to run: the stages share two cores).
      std::array<std::vector<double>, 4> fps;
      std::array<std::vector<double>, 2>
          cpu;  // CPU seconds of all threads: encode only, end to end
      for (int repeat = 0; repeat < kRepeats; ++repeat) {
        auto start = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < poses.size(); ++i) renderer.draw(poses[i], images[i]);
        fps[0].push_back(frames / seconds(start));

        render::EncoderSettings encoding;
        encoding.width = w;
        encoding.height = h;
        encoding.fps = plan.fps;
        auto opened = render::VideoEncoder::open((scratch / "encode.mp4").string(), encoding);
        if (!opened) {
          std::fprintf(stderr, "%s\n", opened.error().text().c_str());
          return 2;
        }
        std::unique_ptr<render::VideoEncoder> encoder = std::move(opened).value();
        start = std::chrono::steady_clock::now();
        double cpu_start = cpuSeconds();
        for (const auto& image : images)
          if (!encoder->add(image)) return 2;
        if (!encoder->finish()) return 2;
        fps[1].push_back(frames / seconds(start));
        cpu[0].push_back(cpuSeconds() - cpu_start);

        // End to end: the library's video, as `rattleback render` makes it.
        tasks::Overrides run = o;
        run.set(tasks::SceneOption::Duration, frames * plan.playback / plan.fps);
        auto video_scene = tasks::loadScene(scene, run);
        media::VideoRequest request;
        request.scene_name = scene;
        request.output = (scratch / "e2e.mp4").string();
        request.backend = backend;
        start = std::chrono::steady_clock::now();
        cpu_start = cpuSeconds();
        if (!video_scene || !media::renderVideo(video_scene.value(), request)) return 2;
        fps[2].push_back(frames / seconds(start));
        cpu[1].push_back(cpuSeconds() - cpu_start);
        request.both = true;
        request.output = (scratch / "both").string();
        start = std::chrono::steady_clock::now();
        if (!media::renderVideo(video_scene.value(), request)) return 2;
        fps[3].push_back(frames / seconds(start));
      }
      const double render_fps = median(fps[0]), encode_fps = median(fps[1]),
                   e2e_fps = median(fps[2]), both_fps = median(fps[3]);
      // The least end / encode the cores allow, from the CPU time end to end takes.
      const double bound = std::max(1.0, median(cpu[1]) / cores * encode_fps / frames);
      std::printf("%-8s %-10s %11.1f %11.1f %11.1f %11.1f %10.2fx %10.2fs %10.2fs %10.2fx\n",
                  std::string(rb::nameOf(backend)).c_str(),
                  (std::to_string(w) + "x" + std::to_string(h)).c_str(), render_fps, encode_fps,
                  e2e_fps, both_fps, encode_fps / e2e_fps, median(cpu[0]), median(cpu[1]), bound);
    }
  std::error_code ec;
  std::filesystem::remove_all(scratch, ec);
  return 0;
}
