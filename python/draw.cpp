// rattleback._draw: stills and videos for Python (media/). A module apart from _core so that
// `import rattleback` loads no OpenGL or libav until something is drawn.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <optional>
#include <variant>

#include "media/presets.hpp"
#include "media/still.hpp"
#include "media/video.hpp"
#include "python/convert.hpp"
#include "python/scene_value.hpp"
#include "render/image_io.hpp"
#include "tasks/manifest.hpp"
#include "tasks/output.hpp"
#include "tasks/player_data.hpp"
#include "tasks/run_json.hpp"
#include "util/arguments.hpp"
#include "util/format.hpp"

namespace py = pybind11;

namespace pyrb {
namespace {

render::Backend backendOf(const std::string& name) {
  const auto backend = rb::parseName<render::Backend>(name);
  if (!backend)
    throw py::value_error("argument backend: " + rb::choices<render::Backend>() + ", not '" + name +
                          "'");
  return *backend;
}

// A run that stopped by itself is rattleback.RunStopped; Ctrl-C has raised already.
[[noreturn]] void raiseStopped(const tasks::Outcome& outcome, const std::string& scene) {
  py::object cls = py::module_::import("rattleback._errors").attr("RunStopped");
  py::object e =
      cls(scene + ": the run stopped: " + outcome.message,
          std::string(rb::nameOf(outcome.stop->reason)), outcome.stop->t, outcome.stop->step);
  PyErr_SetObject(cls.ptr(), e.ptr());
  throw py::error_already_set();
}

// The image as an H×W×4 (or ×3 without `alpha`) uint8 array, rows from the top.
py::array_t<std::uint8_t> arrayOf(const render::Image& image, bool alpha) {
  const py::ssize_t channels = alpha ? 4 : 3;
  py::array_t<std::uint8_t> out(
      {static_cast<py::ssize_t>(image.height), static_cast<py::ssize_t>(image.width), channels});
  std::uint8_t* p = out.mutable_data();
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  for (std::size_t i = 0; i < pixels; ++i)
    for (py::ssize_t c = 0; c < channels; ++c) *p++ = image.rgba[4 * i + c];
  return out;
}

// An H×W×3 or ×4 uint8 array (C order) as the renderer's RGBA image.
render::Image imageOf(
    const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& a) {
  if (a.ndim() != 3 || (a.shape(2) != 3 && a.shape(2) != 4))
    throw py::value_error("an image is an H×W×3 or H×W×4 uint8 array");
  render::Image image;
  image.height = static_cast<int>(a.shape(0));
  image.width = static_cast<int>(a.shape(1));
  const py::ssize_t channels = a.shape(2);
  image.rgba.resize(static_cast<std::size_t>(image.width) * image.height * 4, 255);
  const std::uint8_t* p = a.data();
  for (std::size_t i = 0; i < static_cast<std::size_t>(image.width) * image.height; ++i)
    for (py::ssize_t c = 0; c < channels; ++c) image.rgba[4 * i + c] = *p++;
  return image;
}

// The still drawn, and what the folder's manifest lists of it when it is saved (as `rattleback
// still` lists its PNG): the scene's name, the view, the initial spin and t.
py::tuple still(const LoadedScene& loaded, const std::variant<double, std::string>& t,
                bool readouts, bool transparent, const std::string& backend,
                const std::optional<std::string>& title, const std::string& t_named,
                bool scene_duration_only) {
  media::StillRequest request;
  request.title = title;
  request.scene_name = loaded.value.scene.file;
  request.t_named = t_named;
  request.scene_duration_only = scene_duration_only;
  if (const auto* name = std::get_if<std::string>(&t)) {
    // A word names a moment of the run ("reversal"); a number's text is refused (t="1.5"), as a
    // Python number is what a time in seconds is given as.
    const auto parsed = tasks::parseStillTime(*name, request.t_named);
    if (!parsed || !parsed->named)
      throw py::value_error(request.t_named + ": a time in s (e.g. 1.5) or " +
                            rb::choices<tasks::NamedTime>() + ", not '" + *name + "'");
    request.t_name = parsed->named;
  } else {
    request.t = std::get<double>(t);
  }
  request.readouts = readouts;
  request.transparent = transparent;
  request.backend = backendOf(backend);
  auto drawn = interruptibleHere([&](const std::function<bool()>& cancelled) {
    request.cancelled = cancelled;
    return media::renderStill(loaded.value, request);
  });
  if (!drawn) raise(drawn.error());
  const media::StillResult& still = drawn.value();
  if (still.outcome.ending == tasks::Ending::Stopped)
    raiseStopped(still.outcome, request.scene_name);
  py::dict listed;
  listed["scene"] = stemOf(request.scene_name, loaded.has_file);
  listed["view"] = std::string(rb::nameOf(still.view));
  listed["spin"] = loaded.value.model.initial.spin;
  listed["t"] = still.outcome.t;
  listed["made_from"] = tasks::madeFrom(loaded.value.scene);
  listed["drawn_by"] = still.image.drawn_by;  // (its PNG's Software, as the command line's)
  const std::optional<double> frame = tasks::listedFrame(loaded.value.scene, loaded.value.model);
  listed["frame_m"] = frame ? py::object(py::float_(*frame)) : py::object(py::none());
  listed["surface"] = loaded.value.scene.video.surface;
  // (What the command line warns of, for the caller to warn of as a RunWarning.)
  const py::object leaves = still.leaves ? py::object(py::str(*still.leaves)) : py::none();
  return py::make_tuple(arrayOf(still.image, transparent), listed, leaves);
}

py::tuple renderVideos(const LoadedScene& loaded, const std::string& output, bool both, int crf,
                       const std::string& preset, const std::string& backend) {
  media::VideoRequest request;
  request.scene_name = loaded.value.scene.file;
  const std::string stem = stemOf(request.scene_name, loaded.has_file);
  request.output = output.empty() ? "out/" + stem + ".mp4" : output;
  request.both = both;
  request.crf = crf;
  request.preset = preset;
  request.backend = backendOf(backend);
  auto made = interruptible([&](const std::function<bool()>& cancelled) {
    const rb::OutputNamedBy naming("render's output");  // the way out an error suggests
    request.cancelled = cancelled;
    return media::renderVideo(loaded.value, request);
  });
  if (!made) raise(made.error());
  const media::VideoResult& result = made.value();
  if (result.outcome.ending == tasks::Ending::Stopped)
    raiseStopped(result.outcome, request.scene_name);
  std::vector<tasks::OutputEntry> entries;
  for (const media::VideoFile& f : result.files)
    entries.push_back(media::videoEntry(f, loaded.value, stem));
  (void)tasks::recordOutputs(entries);  // as the command line lists them
  py::list files;
  for (const media::VideoFile& f : result.files) {
    py::dict d;
    d["path"] = f.path;
    d["role"] = f.role;
    d["frames"] = f.frames;
    d["spin"] = f.spin ? py::object(py::float_(*f.spin)) : py::object(py::none());
    d["first_reversal_s"] =
        f.first_reversal_s ? py::object(py::float_(*f.first_reversal_s)) : py::object(py::none());
    d["reversals_s"] = f.spin ? py::object(py::cast(f.reversals_s)) : py::object(py::none());
    d["final_spin"] = f.final_spin ? py::object(py::float_(*f.final_spin)) : py::object(py::none());
    files.append(d);
  }
  const py::object leaves = result.leaves ? py::object(py::str(*result.leaves)) : py::none();
  return py::make_tuple(files, leaves);
}

using U8Array = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;

// The figures of `rattleback compare` and the verdict under the tolerance, as a dict.
py::dict compareArrays(const U8Array& a, const U8Array& b, int channel, double pixels, int square) {
  if (channel < 0 || channel > 255)
    throw py::value_error("argument tolerance: a channel difference within 0 … 255, not " +
                          std::to_string(channel));
  if (!(pixels >= 0 && pixels <= 1))
    throw py::value_error("argument pixels: a fraction within 0 … 1, not " + rb::show(pixels));
  if (square < 0)
    throw py::value_error("argument square: 0 (off) or more, not " + std::to_string(square));
  const render::Image x = imageOf(a), y = imageOf(b);
  const render::Comparison c = render::compareImages(x, y, channel);
  const render::Tolerance tolerance{channel, pixels, square};
  py::dict d;
  d["same"] = render::matches(c, tolerance);
  d["same_size"] = c.same_size;
  d["pixels"] = c.pixels;
  d["differing"] = c.differing;
  d["fraction"] = c.same_size ? c.fraction() : 1.0;
  d["worst"] = c.max_channel_delta;
  d["box"] = py::make_tuple(c.box[0], c.box[1], c.box[2], c.box[3]);
  d["square"] = c.square;
  d["square_failed"] = render::squareDiffers(c, tolerance);
  return d;
}

py::bytes encodePngOf(const U8Array& a, const std::string& drawn_by) {
  render::Image image = imageOf(a);
  image.drawn_by = drawn_by;
  auto bytes = render::encodePng(image);
  if (!bytes) raise(bytes.error());
  return py::bytes(reinterpret_cast<const char*>(bytes->data()), bytes->size());
}

// A still of a scene is listed in the folder's manifest, so that the report shows it under
// Stills with its view, time and spin (a failure to list loses nothing: the report then places
// the file by its name). An image made from an array is not.
void listStill(const std::string& path, const py::dict& still) {
  const std::optional<double> frame_m = still.contains("frame_m") && !still["frame_m"].is_none()
                                            ? std::optional<double>(still["frame_m"].cast<double>())
                                            : std::nullopt;
  tasks::OutputEntry listed{
      path,
      tasks::OutputKind::Still,
      still["scene"].cast<std::string>(),
      still["view"].cast<std::string>(),
      still["spin"].cast<double>(),
      still["t"].cast<double>(),
      still.contains("made_from") ? still["made_from"].cast<std::string>() : "",
      frame_m};
  if (still.contains("surface")) listed.surface = still["surface"].cast<std::string>();
  (void)tasks::recordOutputs({listed});
}

void writePngOf(const std::string& path, const U8Array& a, const std::optional<py::dict>& still,
                const std::string& drawn_by) {
  {
    // As `still -o y.jpg` refuses it: the data is PNG whatever the name says.
    const rb::OutputNamedBy naming("save's path");
    if (auto e = media::checkExtension(path, ".png", "PNG", false); !e) raise(e.error());
  }
  const rb::OutputNamedBy naming("save");  // Image.save: the way out an error suggests
  if (auto e = tasks::makeParentFolder(path); !e) raise(e.error());
  render::Image image = imageOf(a);
  image.drawn_by = drawn_by;
  if (still && still->contains("drawn_by"))
    image.drawn_by = (*still)["drawn_by"].cast<std::string>();
  if (auto e = render::writePng(path, image); !e) raise(e.error());
  if (still) listStill(path, *still);
}

py::array_t<std::uint8_t> diffImageOf(const U8Array& a, const U8Array& b, int channel) {
  return arrayOf(render::diffImage(imageOf(a), imageOf(b), channel), false);
}

// The PNG's Software text, the rasteriser that drew it ("" when it names none): a golden holds
// for the rasteriser that drew it, so a difference says which drew each.
std::string pngDrawnByOf(const std::string& path) {
  render::Image image;
  if (auto e = render::readPng(path, image); !e) raise(e.error());
  return image.drawn_by;
}

py::array_t<std::uint8_t> readPngOf(const std::string& path) {
  render::Image image;
  if (auto e = render::readPng(path, image); !e) raise(e.error());
  bool opaque = true;
  for (std::size_t i = 3; i < image.rgba.size() && opaque; i += 4) opaque = image.rgba[i] == 255;
  return arrayOf(image, !opaque);
}

// render::Tolerance's defaults: the one place `compare`, snapshot suites and Python take them.
py::dict defaultTolerance() {
  py::dict tolerance;
  tolerance["tolerance"] = render::Tolerance{}.channel;
  tolerance["pixels"] = render::Tolerance{}.pixels;
  tolerance["square"] = render::Tolerance{}.square;
  return tolerance;
}

}  // namespace
}  // namespace pyrb

PYBIND11_MODULE(_draw, m) {
  using namespace pyrb;
  m.doc() =
      "rattleback's drawing side: stills and videos (see rattleback.still, rattleback.render).";
  py::module_::import("rattleback._core");  // registers LoadedScene
  // Messages name "argument crf", not "--crf" (each module holds its own copy of the style).
  rb::argument_style = rb::ArgumentStyle::Keyword;
  m.def("still", &still, py::arg("scene"), py::arg("t"), py::arg("readouts"),
        py::arg("transparent"), py::arg("backend"), py::arg("title") = py::none(),
        py::arg("t_named") = "argument t", py::arg("scene_duration_only") = false);
  m.def("render", &renderVideos, py::arg("scene"), py::arg("output"), py::arg("both"),
        py::arg("crf"), py::arg("preset"), py::arg("backend"));
  m.def("encode_png", &encodePngOf, py::arg("array"), py::arg("drawn_by") = "");
  m.def("write_png", &writePngOf, py::arg("path"), py::arg("array"), py::arg("still") = py::none(),
        py::arg("drawn_by") = "");
  m.def("png_drawn_by", &pngDrawnByOf, py::arg("path"));
  m.def("compare", &compareArrays, py::arg("a"), py::arg("b"), py::arg("tolerance"),
        py::arg("pixels"), py::arg("square"));
  m.def("diff_image", &diffImageOf, py::arg("a"), py::arg("b"), py::arg("tolerance"));
  m.def("read_png", &readPngOf, py::arg("path"));
  m.attr("default_tolerance") = defaultTolerance();
  py::list presets;
  for (std::string_view p : media::kPresets) presets.append(std::string(p));
  m.attr("presets") = presets;
}
