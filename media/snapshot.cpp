#include "media/snapshot.hpp"

#include <filesystem>

#include "media/still.hpp"
#include "tasks/job_pool.hpp"

namespace media {
namespace {

// The case's view and size, put in as the options --view and --size put them in; their errors
// then name the suite file's line (`option_prefix`).
tasks::Overrides overridesOf(const scene::SnapshotCase& c) {
  tasks::Overrides o;
  o.option_prefix = c.place + ": " + c.name + ": ";
  if (c.view) o.set(tasks::SceneOption::View, std::string(rb::nameOf(*c.view)));
  if (c.size) {
    o.set(tasks::SceneOption::Size, *c.size);
    // (the text of a size as typed, which its messages quote)
    o.given[tasks::SceneOption::Size].name =
        std::to_string((*c.size)[0]) + "x" + std::to_string((*c.size)[1]);
    // Given at the suite's top, it is every case's: named there, so that it is said once.
    if (!c.top_size_place.empty())
      o.given[tasks::SceneOption::Size].prefix = c.top_size_place + ": ";
  }
  return o;
}

// One case drawn and compared. A golden that cannot be read (not a PNG; a Git LFS pointer) is
// Unreadable: the input at fault, which --update replaces.
CaseResult runCase(const scene::SnapshotSuite& suite, const scene::SnapshotCase& c,
                   const tasks::LoadedScene& loaded, render::Backend backend,
                   const std::function<bool()>& cancelled) {
  CaseResult r;
  r.golden = (std::filesystem::path(suite.goldens) / (c.name + ".png")).string();
  StillRequest request;
  request.scene_name = c.scene;
  request.t = c.t.seconds;
  request.t_name = c.t.named;
  request.t_named = c.place + ": " + c.name + ": t";
  request.scene_duration_only = true;  // (a suite has no duration of its own)
  request.title = c.title ? *c.title : c.name;
  request.backend = c.backend.value_or(backend);
  request.asked_by = c.place + ": " + c.name;
  request.cancelled = cancelled;
  auto drawn = renderStill(loaded, request);
  if (!drawn) {
    r.error = drawn.error();
    return r;
  }
  r.ending = drawn->outcome.ending;
  if (r.ending != tasks::Ending::Completed) {
    r.error =
        rb::Error{"", c.place + ": " + c.name + ": the run stopped: " + drawn->outcome.message};
    return r;
  }
  r.t = drawn->outcome.t;
  r.image = std::move(drawn->image);
  std::error_code ec;
  if (!std::filesystem::exists(r.golden, ec)) {
    r.status = CaseStatus::Missing;
    return r;
  }
  if (auto read = render::readPng(r.golden, r.expected); !read) {
    r.status = CaseStatus::Unreadable;
    r.error = read.error();
    r.expected = {};
    return r;
  }
  r.comparison = render::compareImages(r.image, r.expected, c.tolerance.channel);
  r.status = render::matches(r.comparison, c.tolerance) ? CaseStatus::Same : CaseStatus::Differs;
  return r;
}

}  // namespace

rb::Result<std::vector<tasks::LoadedScene>> loadCases(const scene::SnapshotSuite& suite) {
  std::vector<tasks::LoadedScene> scenes;
  for (const scene::SnapshotCase& c : suite.cases) {
    auto loaded = tasks::loadScene(c.scene, overridesOf(c));
    if (!loaded) {
      rb::Error e = loaded.error();
      // The scene's own words already name its file; the case's place says which case, and
      // the error is the suite's at that line (where a report such as JUnit's puts it).
      if (!e.text().starts_with(c.place)) e.message = c.place + ": " + c.name + ": " + e.text();
      e.key.clear();
      e.where = rb::Error::Where{suite.file, c.line, ""};
      return e;
    }
    scenes.push_back(std::move(loaded).value());
  }
  return scenes;
}

std::vector<CaseResult> runCases(const scene::SnapshotSuite& suite,
                                 const std::vector<tasks::LoadedScene>& scenes,
                                 const SnapshotOptions& options) {
  std::vector<CaseResult> results(suite.cases.size());
  tasks::runJobs(
      suite.cases.size(), options.jobs,
      [&](std::size_t i, std::stop_token stop) {
        const auto cancelled = [&] {
          return stop.stop_requested() || (options.cancelled && options.cancelled());
        };
        results[i] = runCase(suite, suite.cases[i], scenes[i], options.backend, cancelled);
        return results[i].ending != tasks::Ending::Interrupted;
      },
      options.cancelled, options.progress);
  return results;
}

}  // namespace media
