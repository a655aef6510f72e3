// What writing costs a 10 s run of the default scene at 10 kHz (the target: "a 10 s run at 10 kHz
// spends under a quarter of its time writing"), in one process, side by side, alternating:
//   run       the run sampled at 10 kHz, each sample dropped
//   as it goes  the same writing its CSV and sidecar as `rattleback simulate` does (rows
//             formatted on other threads while the run goes on), to a new file
//   kept      the samples kept (Python's simulate), then written at once (Python's to_csv), to a
//             new file and over the file just written
//   numbers   the CSV's numbers alone, one at a time into one buffer, by std::to_chars and by
//             our writeShortest (tasks/shortest.cpp): nanoseconds a number, best of the rounds
// Prints medians and the shares of writing; asserts nothing. Never part of the test run.
//
// Usage: rattleback_output_bench [ROUNDS] [FOLDER]
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tasks/scene_args.hpp"
#include "tasks/shortest.hpp"
#include "tasks/simulate.hpp"

namespace {

double seconds(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 11;
  const std::filesystem::path folder =
      argc > 2 ? argv[2] : std::filesystem::temp_directory_path() / "rattleback-output-bench";
  std::filesystem::create_directories(folder);
  const std::string csv = (folder / "run.csv").string();
  tasks::Overrides o;
  o.set(tasks::SceneOption::Duration, 10.0);
  auto loaded = tasks::loadScene(RATTLEBACK_SOURCE_DIR "/scenes/rattleback.yaml", o);
  if (!loaded) {
    std::fprintf(stderr, "%s\n", loaded.error().text().c_str());
    return 1;
  }
  const sim::Model& model = loaded->model;
  const tasks::RunScene scene{loaded->scene.file, loaded->scene.values, loaded->scene.content};
  constexpr double kRate = 10000;
  const auto fresh = [&] {
    std::filesystem::remove(csv);
    std::filesystem::remove(csv + ".json");
  };

  std::vector<double> alone, going, kept, written, over;
  std::int64_t rows = 0;
  std::vector<sim::Telemetry> samples;
  for (int round = 0; round < rounds; ++round) {
    alone.push_back(seconds([&] {
      tasks::SimulateOptions options;
      options.rate = kRate;
      options.each = [&](const sim::Telemetry&) { ++rows; };
      (void)tasks::simulate(model, options);
    }));
    fresh();
    going.push_back(seconds([&] {
      auto writer = tasks::TelemetryWriter::open(csv);
      tasks::SimulateOptions options;
      options.rate = kRate;
      options.each = [&](const sim::Telemetry& s) { writer->row(s); };
      const tasks::SimulateResult run = tasks::simulate(model, options);
      if (!writer->commit(scene, model, kRate, run.summary)) std::abort();
    }));
    samples = {};  // as Python's simulate starts, with no room made
    tasks::SimulateResult run;
    kept.push_back(seconds([&] {
      tasks::SimulateOptions options;
      options.rate = kRate;
      options.each = [&](const sim::Telemetry& s) { samples.push_back(s); };
      run = tasks::simulate(model, options);
    }));
    fresh();
    written.push_back(seconds([&] {
      if (!tasks::writeTelemetry(csv, scene, model, kRate, run.summary, samples)) std::abort();
    }));
    over.push_back(seconds([&] {
      if (!tasks::writeTelemetry(csv, scene, model, kRate, run.summary, samples)) std::abort();
    }));
  }
  const double a = median(alone), g = median(going), k = median(kept), w = median(written),
               v = median(over);
  std::printf("a 10 s run of the default scene at 10 kHz (%lld rows, %.0f MB), medians of %d:\n",
              static_cast<long long>(rows / rounds), std::filesystem::file_size(csv) / 1e6, rounds);
  std::printf("  the run alone                  %6.1f ms\n", a * 1e3);
  std::printf("  writing as it goes (simulate)  %6.1f ms: writing %.0f %% of it\n", g * 1e3,
              100 * (g - a) / g);
  std::printf("  samples kept                   %6.1f ms\n", k * 1e3);
  std::printf("  then written, a new file       %6.1f ms: %.0f %% of the whole\n", w * 1e3,
              100 * w / (k + w));
  std::printf("  then written over it           %6.1f ms: %.0f %% of the whole\n", v * 1e3,
              100 * v / (k + v));

  // The numbers the CSV has (its columns of doubles, tasks::telemetryTable), formatted alone.
  std::vector<double> numbers;
  for (const sim::Telemetry& s : samples) {
    const Eigen::Quaterniond q = tasks::attitude(s);
    for (const tasks::TelemetryColumn& c : tasks::telemetryTable())
      if (c.kind == tasks::ColumnKind::Number) numbers.push_back(c.value({s, q}));
  }
  std::vector<char> text(numbers.size() * 33);
  std::size_t theirs = 0, ours = 0;
  std::vector<double> std_ns, our_ns;
  for (int round = 0; round < std::max(rounds, 5); ++round) {
    std_ns.push_back(seconds([&] {
      char* at = text.data();
      for (double x : numbers) at = std::to_chars(at, at + 32, x, std::chars_format::general).ptr;
      theirs = static_cast<std::size_t>(at - text.data());
    }));
    our_ns.push_back(seconds([&] {
      char* at = text.data();
      for (double x : numbers) at = tasks::writeShortest(at, x);
      ours = static_cast<std::size_t>(at - text.data());
    }));
  }
  if (theirs != ours) std::abort();  // the same text, so the same length
  const double best_std = *std::min_element(std_ns.begin(), std_ns.end()) / numbers.size() * 1e9;
  const double best_ours = *std::min_element(our_ns.begin(), our_ns.end()) / numbers.size() * 1e9;
  std::printf(
      "  its %zu numbers alone, best of %zu: std::to_chars %.1f ns a number, ours %.1f ns "
      "(%.2fx)\n",
      numbers.size(), std_ns.size(), best_std, best_ours, best_std / best_ours);
  fresh();
  return 0;
}
