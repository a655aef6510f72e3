#include "scene/keys.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "sim/contact_model.hpp"
#include "sim/model.hpp"
#include "util/assets.hpp"
#include "util/picture.hpp"  // the name tables of video.view and video.surface

namespace scene {
namespace {

// A word's choices: the names of its enum's table (util/names.hpp), the one its checker parses.
template <typename E>
std::vector<std::string_view> namesOf() {
  std::vector<std::string_view> names;
  for (const auto& [value, name] : rb::NameTable<E>::entries) names.push_back(name);
  return names;
}

// body.shape has no enum: sim/compile.cpp compares the word with these three.
std::vector<std::string_view> shapeNames() {
  return {"paraboloid", "ellipsoid", "mesh"};
}

// The member of a scene that a key fills: `FIELD(spec.body.mass)`.
#define FIELD(member)        \
  +[](Loaded & l) -> auto& { \
    return l.member;         \
  }

// One row a key, in the order files list them and the loader reads them; within a map, the
// order of the loader's list of known keys in its messages.
const std::vector<Key>& table() {
  static const std::vector<Key> rows = {
      {.path = "units", .doc = "the file's unit of length"},
      {.path = "units.length",
       .field = FIELD(spec.units.length),
       .unit = "m per file length unit",
       .doc = "metres per length unit of the file (0.01: centimetres); lengths marked "
              "\"file units\" are multiplied by it",
       .check = "> 0",
       .sample = "0.01"},

      {.path = "body",
       .need = Need::Always,
       .doc = "the body: its shape, size and mass ([Physics](physics.md) §P1, §P2)"},
      {.path = "body.shape",
       .field = FIELD(spec.body.shape),
       .doc = "the shape of the body; the other shape's keys are errors "
              "(\"belongs to shape: …\")",
       .sample = "paraboloid",
       .choices = shapeNames},
      {.path = "body.paraboloid",
       .need = Need::Paraboloid,
       .shape = Shape::Paraboloid,
       .doc = "bottom z = p/(2a) x² + q/a² xy + s/(2a) y² − a, flat top at z = top (§P1)",
       .example = "paraboloid: {a: 1.0, p: 0.5, q: 0.0, s: 0.03, top: 0.5}"},
      {.path = "body.paraboloid.a",
       .field = FIELD(spec.body.paraboloid.a),
       .need = Need::Always,
       .unit = "file units",
       .doc = "depth of the apex below the origin",
       .check = "> 0",
       .sample = "1.0"},
      {.path = "body.paraboloid.p",
       .field = FIELD(spec.body.paraboloid.p),
       .need = Need::Always,
       .doc = "curvature across the short axis (x)",
       .check = "> 0",
       .sample = "0.5"},
      {.path = "body.paraboloid.q",
       .field = FIELD(spec.body.paraboloid.q),
       .unit = "file units",
       .doc = "skew term: turns the bottom's axes",
       .check = "q² < p·s·a² (the bottom must be a bowl)",
       .sample = "0.01"},
      {.path = "body.paraboloid.s",
       .field = FIELD(spec.body.paraboloid.s),
       .need = Need::Always,
       .doc = "curvature along the long axis (y)",
       .check = "> 0",
       .sample = "0.03"},
      {.path = "body.paraboloid.top",
       .field = FIELD(spec.body.paraboloid.top),
       .need = Need::Always,
       .unit = "file units",
       .doc = "height of the flat top",
       .check = "above the apex: top > −a",
       .sample = "0.6"},
      {.path = "body.dents",
       .shape = Shape::Paraboloid,
       .doc = "two paraboloid dents cut from the top, at (m_x, m_y) and (−m_x, −m_y) (§P1); "
              "none when absent",
       .given = [](Loaded& l) { l.spec.body.dents.emplace(); }},
      {.path = "body.dents.scale",
       .field = FIELD(spec.body.dents->scale),
       .need = Need::Always,
       .doc = "k of eq. P1.2: dent curvature p/(2a k²), depth (a − inset) k",
       .check = "> 0",
       .sample = "0.45"},
      {.path = "body.dents.at",
       .field = FIELD(spec.body.dents->at),
       .need = Need::Always,
       .unit = "file units",
       .doc = "(m_x, m_y): the first dent's place; the second is at (−m_x, −m_y)",
       .check = "finite",
       .sample = "[0.73, 4.50]"},
      {.path = "body.dents.inset",
       .field = FIELD(spec.body.dents->inset),
       .unit = "file units",
       .doc = "the seed's constant in the dents' depth",
       .check = "finite",
       .sample = "0.2"},
      {.path = "body.grid",
       .need = Need::Paraboloid,
       .shape = Shape::Paraboloid,
       .doc = "a uniform grid of points: the contact points of `contact.model: points`, the "
              "sums of `mass_properties: grid`",
       .check = "at most 2e8 points (estimated before building); at least two levels of "
                "points; a non-singular inertia",
       .example = "grid: {dx: 0.05, dy: 0.05, dz: 0.05}"},
      {.path = "body.grid.dx",
       .field = FIELD(spec.body.grid.dx),
       .need = Need::Always,
       .unit = "file units",
       .doc = "spacing along x",
       .check = "> 0",
       .sample = "0.05"},
      {.path = "body.grid.dy",
       .field = FIELD(spec.body.grid.dy),
       .need = Need::Always,
       .unit = "file units",
       .doc = "spacing along y",
       .check = "> 0",
       .sample = "0.1"},
      {.path = "body.grid.dz",
       .field = FIELD(spec.body.grid.dz),
       .need = Need::Always,
       .unit = "file units",
       .doc = "spacing along z",
       .check = "> 0",
       .sample = "0.02"},
      {.path = "body.mass_properties",
       .field = FIELD(spec.body.mass_properties),
       .shape = Shape::Paraboloid,
       .doc = "where the mass properties come from: the shape's volume (exact) or the grid's "
              "sums (the seed's first-order rule)",
       .sample = "continuum",
       .choices = namesOf<sim::MassSource>,
       .default_note = "`grid` with `contact.model: points`, else `continuum`"},
      {.path = "body.mass",
       .field = FIELD(spec.body.mass),
       .need = Need::Always,
       .unit = "kg",
       .doc = "the body's mass",
       .check = "> 0",
       .sample = "0.059",
       .example = "mass: 0.059 (kg)"},
      {.path = "body.ellipsoid",
       .need = Need::Ellipsoid,
       .shape = Shape::Ellipsoid,
       .doc = "a smooth ellipsoid (Kane & Levinson 1982; §P2)",
       .example = "ellipsoid: {semi_axes: [0.03, 0.20, 0.02], center: [0, 0, 0.01]} (Kane & "
                  "Levinson's, in metres: with units.length 0.01, [3, 20, 2] and [0, 0, 1])"},
      {.path = "body.ellipsoid.semi_axes",
       .field = FIELD(spec.body.ellipsoid.semi_axes),
       .need = Need::Always,
       .unit = "file units",
       .doc = "the semi-axes along x, y, z",
       .check = "each > 0",
       .sample = "[0.03, 0.20, 0.02]"},
      {.path = "body.ellipsoid.center",
       .field = FIELD(spec.body.ellipsoid.center),
       .unit = "file units",
       .doc = "the ellipsoid's centre relative to the CM",
       .check = "finite; the CM within the ellipsoid: Σ (center / semi_axes)² < 1",
       .sample = "[0, 0, 0.01]"},
      {.path = "body.mesh",
       .need = Need::Mesh,
       .shape = Shape::Mesh,
       .doc = "a closed triangle mesh from a file (§P11); points touch its surface, smooth, "
              "rolling and auto a smooth bottom fitted to it (§P11.4)",
       .example = "mesh: {file: toy.stl} (binary or ASCII STL, or OBJ)"},
      {.path = "body.mesh.file",
       .field = FIELD(spec.body.mesh.file),
       .need = Need::Always,
       .doc = "the mesh file, STL (binary or ASCII) or OBJ, relative to the scene file, its "
              "numbers in file units; uniform density unless `center_of_mass` and `inertia` are "
              "given",
       .check = "closed, wound outwards (refused inside out), no faces of zero area, 5 mm … 2 m "
                "long in metres (§P11.2)",
       .sample = "meshes/box.obj"},
      {.path = "body.center_of_mass",
       .field = FIELD(spec.body.center_of_mass),
       .shape = Shape::Mesh,
       .unit = "file units, the mesh's frame",
       .doc = "the CM of a weighted body",
       .check = "finite; within the mesh's box",
       .sample = "[0.1, 0.2, 0.3]",
       .default_note = "the uniform solid's"},
      {.path = "body.inertia",
       .field = FIELD(spec.body.inertia),
       .need = Need::Ellipsoid,
       .shape = Shape::EllipsoidOrMesh,
       .unit = "kg m², about the CM, body axes",
       .doc = "the inertia tensor (a mesh body: optional, for a weighted body; all zeros: the "
              "uniform solid's)",
       .check = "finite; symmetric, positive definite, each principal moment at most the sum of "
                "the others",
       .sample = "[[1.6e-3, -2.0e-5, 0.0], [-2.0e-5, 2.0e-4, 0.0], [0.0, 0.0, 1.7e-3]]",
       .example = "inertia: [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] (kg m², about "
                  "the CM)"},

      {.path = "contact",
       .need = Need::Always,
       .doc = "how the body meets the floor ([Physics](physics.md) §P4)",
       .example = "contact: {model: rolling}"},
      {.path = "contact.model",
       .field = FIELD(spec.contact.model),
       .doc = "springs at the grid's surface points, one spring at the lowest point of the "
              "smooth surface, rolling without slipping, or rolling while it holds and else "
              "smooth (§P4.1, §P4.4–P4.6)",
       .sample = "smooth",
       .choices = namesOf<sim::ContactModel>},
      {.path = "contact.stiffness",
       .field = FIELD(spec.contact.stiffness),
       .need = Need::UnlessRolling,
       .unit = "N/m (points: per point)",
       .doc = "the contact spring's stiffness",
       .check = "> 0",
       .sample = "2.0e4",
       .example = "stiffness: 2.0e4 (N/m), or model: rolling, which needs none"},
      {.path = "contact.damping",
       .field = FIELD(spec.contact.damping),
       .unit = "N s/m (points: per point)",
       .doc = "the contact spring's damping",
       .check = "≥ 0",
       .sample = "4"},
      {.path = "contact.friction",
       .field = FIELD(spec.contact.friction),
       .doc = "Coulomb's coefficient μ",
       .check = "≥ 0",
       .sample = "0.3"},
      {.path = "contact.friction_law",
       .field = FIELD(spec.contact.friction_law),
       .doc = "sharp stick-slip, or smoothed over `slip_velocity` (§P4.3)",
       .sample = "coulomb",
       .choices = namesOf<sim::FrictionLaw>},
      {.path = "contact.slip_velocity",
       .field = FIELD(spec.contact.slip_velocity),
       .unit = "m/s",
       .doc = "ε of eq. P4.3: the width of the regularised law",
       .check = "> 0",
       .sample = "2.0e-3"},
      {.path = "contact.air_drag",
       .field = FIELD(spec.contact.air_drag),
       .unit = "N m s",
       .doc = "σ of the viscous torque −σω",
       .check = "≥ 0",
       .sample = "5.9e-6"},

      {.path = "gravity",
       .field = FIELD(spec.gravity),
       .unit = "m/s²",
       .doc = "the acceleration of gravity",
       .check = "≥ 0, finite",
       .sample = "9.8"},

      {.path = "initial", .doc = "the state at release ([Physics](physics.md) §P5)"},
      {.path = "initial.spin",
       .field = FIELD(spec.initial.spin),
       .unit = "rad/s",
       .doc = "about the body's z axis (n = spin·cos tilt at the start); + = counter-clockwise "
              "from above; the shortcut for `angular_velocity: [0, 0, spin]`",
       .check = "finite; not with `angular_velocity` (one set over a scene that gives the "
                "other replaces it)",
       .sample = "-5.0",
       .default_note = "0, or the z of `angular_velocity`"},
      {.path = "initial.angular_velocity",
       .field = FIELD(spec.initial.angular_velocity),
       .unit = "rad/s, body axes",
       .doc = "ω at release about body x, y and z: a tap about x or y sets the body rocking "
              "([Physics](physics.md) §P5)",
       .check = "finite; not with `spin` (one set over a scene that gives the other replaces "
                "it)",
       .sample = "[0.3, -0.2, -5.0]",
       .default_note = "[0, 0, spin]"},
      {.path = "initial.tilt",
       .field = FIELD(spec.initial.tilt),
       .unit = "degrees",
       .doc = "about body x, then the new body y",
       .check = "finite, within ±180",
       .sample = "[0.5, 0.5]"},
      {.path = "initial.height",
       .field = FIELD(spec.initial.height),
       .unit = "file units",
       .doc = "the lowest point above the floor at release; 0: resting on it",
       .check = "≥ 0; 0 with `contact.model: rolling`",
       .sample = "0.1"},
      {.path = "initial.velocity",
       .field = FIELD(spec.initial.velocity),
       .unit = "m/s, world axes",
       .doc = "the CM's velocity at release; `rolling` keeps it only where it agrees with "
              "rolling without slipping, v = −ω × r (§P5); the others take it as it is",
       .check = "finite; under `rolling` within 1e-3 of −ω × r (plus 1 µm/s)",
       .sample = "[0.01, 0.0, 0.0]",
       .default_note = "the lowest point does not slide (at rest in the air, with `height`)"},

      {.path = "simulation",
       .need = Need::Always,
       .doc = "the integrator and its steps ([Physics](physics.md) §P3)"},
      {.path = "simulation.integrator",
       .field = FIELD(spec.simulation.integrator),
       .doc = "the method: `euler`, `symplectic` and `rk4` take `dt`; `dopri5` "
              "(Dormand–Prince 5(4)) and `dop853` (Dormand–Prince 8(5,3), fewer evaluations "
              "at tight tolerances) take `tolerance`; `symplectic` is refused with `rolling` and "
              "`auto`, whose energy it "
              "does not keep (rolling without slipping is non-holonomic, §P3)",
       .sample = "rk4",
       .choices = namesOf<sim::Integrator>,
       .default_note = "with `dt`: `rk4` for `rolling` and `auto`, `symplectic` for `smooth` and "
                       "`points`; `dopri5` with `tolerance`"},
      {.path = "simulation.dt",
       .field = FIELD(spec.simulation.dt),
       .unit = "s",
       .doc = "a fixed step",
       .check = "> 0; at most 1e11 steps over the duration; below the largest stable step for "
                "the contact stiffness (§P3.5), which the message names",
       .sample = "1.0e-4",
       .default_note = "exactly one of `dt` and `tolerance` is required"},
      {.path = "simulation.tolerance",
       .field = FIELD(spec.simulation.tolerance),
       .unit = "error per step, in the body's own units",
       .doc = "adaptive steps (dopri5, or dop853 when named) to this error per step",
       .check = "within 1e-14 … 0.1",
       .sample = "1.0e-8",
       .default_note = "exactly one of `dt` and `tolerance` is required"},
      {.path = "simulation.duration",
       .field = FIELD(spec.simulation.duration),
       .need = Need::Always,
       .unit = "s",
       .doc = "simulated time",
       .check = "> 0",
       .sample = "8.0",
       .example = "duration: 8.0 (s)"},

      {.path = "video",
       .doc = "read only by `render` and `still`, which check its values; `simulate` and "
              "`analyze` check only its keys and types"},
      {.path = "video.fps",
       .field = FIELD(video.fps),
       .unit = "frames per second of video",
       .doc = "the frame rate",
       .check = "1 … 240",
       .sample = "25"},
      {.path = "video.size",
       .field = FIELD(video.size),
       .unit = "pixels",
       .doc = "width and height",
       .check = "sides 16 … 8192 and even (the message suggests one that works, e.g. "
                "`not 641x363: try 642x364`)",
       .sample = "[640, 360]"},
      {.path = "video.view",
       .field = FIELD(video.view),
       .doc = "the camera",
       .sample = "above",
       .choices = namesOf<render::View>},
      {.path = "video.playback",
       .field = FIELD(video.playback),
       .unit = "simulated seconds per second of video",
       .doc = "speed as players mean it: 0.5 = slow motion, 2 = twice as fast",
       .check = "> 0; at most 1e7 frames in all",
       .sample = "0.5"},
      {.path = "video.frame",
       .field = FIELD(video.frame),
       .unit = "file units",
       .doc = "every view framed for a body this long: give bodies to be compared the same "
              "value and they are drawn at one scale, on the same floor squares",
       .check = "> 0; within 1/10 … 50 times the body's length",
       .sample = "10",
       .default_note = "the body's own length: each body fills the picture"},
      {.path = "video.surface",
       .field = FIELD(video.surface),
       .doc = "the body drawn as its surface points (spheres) or as its closed surface "
              "(shaded triangles: the mesh's own, or the shape's tessellated as `export` makes "
              "it); either way red where the surface faces up in the body frame, blue where it "
              "faces down",
       .sample = "triangles",
       .choices = namesOf<render::Surface>},
  };
  return rows;
}

#undef FIELD

// The shortest text that reads back as the same double (std::to_chars), as YAML writes it.
std::string numberText(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return std::string(text, end);
}

template <typename T, std::size_t N>
std::string listText(const std::array<T, N>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < N; ++i)
    out += (i ? ", " : "") + numberText(static_cast<double>(values[i]));
  return out + "]";
}

// A member's value as YAML flow text, or "" when it is unset (NaN, an empty word).
struct ValueText {
  std::string operator()(std::monostate) const { return ""; }
  std::string operator()(double v) const { return std::isnan(v) ? "" : numberText(v); }
  std::string operator()(int v) const { return std::to_string(v); }
  std::string operator()(const std::string& v) const { return v; }
  template <typename T, std::size_t N>
  std::string operator()(const std::array<T, N>& v) const {
    for (const auto& x : v)
      if (std::isnan(static_cast<double>(x))) return "";
    return listText(v);
  }
  std::string operator()(const sim::Matrix3Spec& m) const {
    std::string out = "[";
    for (std::size_t i = 0; i < 3; ++i) out += (i ? ", " : "") + (*this)(m[i]);
    return out + "]";
  }
};

}  // namespace

std::span<const Key> keys() {
  return table();
}

const Key* findKey(std::string_view path) {
  for (const Key& key : table())
    if (key.path == path) return &key;
  return nullptr;
}

std::string_view parentOf(std::string_view path) {
  const auto dot = path.rfind('.');
  return dot == std::string_view::npos ? std::string_view() : path.substr(0, dot);
}

std::string_view nameIn(std::string_view path) {
  const auto dot = path.rfind('.');
  return dot == std::string_view::npos ? path : path.substr(dot + 1);
}

std::vector<const Key*> keysIn(std::string_view map) {
  std::vector<const Key*> inside;
  for (const Key& key : table())
    if (parentOf(key.path) == map) inside.push_back(&key);
  return inside;
}

std::string typeOf(const Key& key) {
  static constexpr const char* kNames[] = {
      "map",         "number",        "whole number",      "word",
      "two numbers", "three numbers", "two whole numbers", "three rows of three numbers"};
  return kNames[key.field.index()];
}

std::string valueOf(const Key& key, Loaded& scene) {
  // The dents' members exist only when the scene has dents.
  if (key.path.starts_with("body.dents.") && !scene.spec.body.dents) return "";
  return std::visit(
      [&](auto member) -> std::string {
        if constexpr (std::is_same_v<decltype(member), std::monostate>)
          return "";
        else
          return ValueText{}(member(scene));
      },
      key.field);
}

std::string defaultOf(const Key& key) {
  Loaded defaults;
  defaults.spec.body.dents.emplace();  // the members a `dents` map starts with
  return valueOf(key, defaults);
}

bool requiredIn(const Key& key, const sim::SceneSpec& spec) {
  switch (key.need) {
    case Need::Optional:
      return false;
    case Need::Always:
      return true;
    case Need::Paraboloid:
      return spec.body.shape != "ellipsoid" && spec.body.shape != "mesh";
    case Need::Ellipsoid:
      return spec.body.shape == "ellipsoid";
    case Need::Mesh:
      return spec.body.shape == "mesh";
    case Need::UnlessRolling: {
      const auto model = rb::parseName<sim::ContactModel>(spec.contact.model);
      return model && !sim::heldOnFloor(*model);
    }
  }
  return false;
}

std::string requiredMessage(const Key& key) {
  if (key.example.empty()) return "is required";
  return "is required, e.g. " + std::string(key.example) + " (" + rb::docPage("scenes.md") +
         " has a complete scene)";
}

bool belongsTo(const Key& key, const sim::BodySpec& body) {
  const bool ellipsoid = body.shape == "ellipsoid", mesh = body.shape == "mesh";
  switch (key.shape) {
    case Shape::Any:
      return true;
    case Shape::Paraboloid:
      return !ellipsoid && !mesh;  // a misspelt shape is taken for the default
    case Shape::Ellipsoid:
      return ellipsoid;
    case Shape::Mesh:
      return mesh;
    case Shape::EllipsoidOrMesh:
      return ellipsoid || mesh;
  }
  return false;
}

std::string shapeWords(Shape shape) {
  switch (shape) {
    case Shape::Any:
      return "any";
    case Shape::Paraboloid:
      return "paraboloid";
    case Shape::Ellipsoid:
      return "ellipsoid";
    case Shape::Mesh:
      return "mesh";
    case Shape::EllipsoidOrMesh:
      return "ellipsoid or mesh";
  }
  return "";
}

}  // namespace scene
