#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "app/commands.hpp"
#include "sim/analysis.hpp"
#include "sim/integrator.hpp"
#include "tasks/analysis.hpp"
#include "tasks/output.hpp"
#include "tasks/run_json.hpp"
#include "tasks/scene_args.hpp"
#include "util/assets.hpp"

namespace app {
namespace {

// A value that is zero but for rounding (a symmetric body's CM at −8.5e−18 m) prints as 0.
double clean(double v, double scale) {
  return std::abs(v) < 1e-12 * scale ? 0.0 : v;
}

// A mode at rest: its frequency, or how fast it grows where it topples instead of rocking.
std::string restModeText(const tasks::RestMode& mode) {
  char text[64];
  if (mode.hz)
    std::snprintf(text, sizeof text, "%.4g Hz", *mode.hz);
  else
    std::snprintf(text, sizeof text, "unstable (grows at %.4g /s)", mode.growth);
  return text;
}

// The rest, its modes, and the first-order and exact growth rates.
void printRest(std::FILE* out, const tasks::Analysis& a) {
  const double unit = a.length_unit;
  std::fprintf(out,
               "rest contact     CM %.4g above it; radii of curvature %.4g and %.4g "
               "(file units)\n",
               a.rest.h / unit, a.rest.radii(0) / unit, a.rest.radii(1) / unit);
  if (a.rest.stable) {
    std::fprintf(out, "rest             stable upright (h below both radii)\n");
  } else {
    std::fprintf(out,
                 "WARNING: the body cannot stand upright: its CM is %.4g above the contact, "
                 "above the radius of curvature %.4g (needs h below both radii)\n",
                 a.rest.h / unit, a.rest.radii(0) / unit);
  }
  std::fprintf(out, "at rest          roll %s, pitch %s (linearised rolling model)\n",
               restModeText(a.modes.roll).c_str(), restModeText(a.modes.pitch).c_str());
  std::fprintf(out,
               "first order      growth rate = n × (roll %+.4g, pitch %+.4g) 1/rad "
               "(Walker, Bondi; seed eqs. 18–20)\n",
               a.first_order.roll, a.first_order.pitch);
}

// The growth rates at a row of spins, the analysed one marked, and its eigenvalues.
void printGrowth(std::FILE* out, const tasks::Analysis& a) {
  const char* marker = a.spin_given ? "   <- --spin"
                       : a.unspun   ? "   <- the scene is not spun: at 5 rad/s"
                                    : "   <- the scene's";
  std::fprintf(out, "growth rates     exact linearised rolling model, 1/s:\n");
  std::fprintf(out, "                 %8s %10s %10s\n", "n rad/s", "roll", "pitch");
  for (const tasks::GrowthAt& g : a.growth)
    std::fprintf(out, "                 %8.3g %+10.4f %+10.4f%s\n", g.spin, g.roll, g.pitch,
                 g.spin == a.spin ? marker : "");
  std::fprintf(out, "eigenvalues      at n = %g rad/s:", a.spin);
  double largest = 0;
  for (const auto& lambda : a.at_spin.eigenvalues) largest = std::max(largest, std::abs(lambda));
  for (const auto& lambda : a.at_spin.eigenvalues)
    std::fprintf(out, " %.4g%+.4gi", clean(lambda.real(), largest), clean(lambda.imag(), largest));
  std::fprintf(out, "\n");
}

// How far the either-way rule of thumb is met: its e-folds against drag's, or no drag at all.
std::string eitherWayMargin(const tasks::Analysis& a) {
  if (!(a.drag > 0)) return "with no drag to slow the spin";
  char text[200];
  std::snprintf(text, sizeof text,
                "%.1f e-folds in all as drag slows the spin, where the rule of thumb asks %.1f, "
                "from its %.2g° start to %g°",
                a.either_way_efolds, a.either_way_needed, a.rocking_start * 180 / M_PI,
                sim::kRockingThatReverses * 180 / M_PI);
  return text;
}

// A body within half as much again of the rule's count, either side: a run must decide (the
// count is a rule of thumb, docs/physics.md P8.4).
bool nearTheLine(const tasks::Analysis& a) {
  return a.drag > 0 && a.either_way_efolds < 1.5 * a.either_way_needed &&
         a.either_way_efolds > a.either_way_needed / 1.5;
}

void printPreferred(std::FILE* out, const tasks::Analysis& a) {
  if (!a.rest.stable) {
    std::fprintf(out,
                 "preferred        none: the body cannot stand (it has no rocking about upright "
                 "for a direction of spin to favour)\n");
  } else if (a.preferred == sim::Direction::None) {
    // Which of the two: a body with no misalignment grows alike both ways at any spin; a slow
    // spin (drag damps the rocking) may see it die out both ways, though faster spins favour
    // one, and "none" alone would read as the body's at --spin 0.
    if (a.preferred_faster == sim::Direction::None)
      std::fprintf(out,
                   "preferred        none (the rocking grows alike both ways, or neither way: "
                   "no direction is predicted to reverse rather than the other)\n");
    else
      std::fprintf(out,
                   "preferred        none at %g rad/s (the rocking dies out spun either way: "
                   "neither is predicted to reverse at this spin); at 5 rad/s: %s\n",
                   std::abs(a.spin), std::string(rb::nameOf(*a.preferred_faster)).c_str());
  } else {
    std::fprintf(out,
                 "preferred        %s (%s seen from above): its rocking grows more slowly; "
                 "spun the other way it is predicted to reverse sooner\n",
                 std::string(rb::nameOf(a.preferred)).c_str(),
                 a.preferred == sim::Direction::Ccw ? "counter-clockwise" : "clockwise");
    // The spin's size, whichever way --spin gave it: the line is of the preferred way.
    if (a.grows_either_way)
      std::fprintf(out,
                   "either way       spun %s at %g rad/s too, the rocking grows (at %.4g /s, %s): "
                   "it is predicted to reverse that way as well, later (%s P8.4)%s\n",
                   std::string(rb::nameOf(a.preferred)).c_str(), std::abs(a.spin),
                   a.preferred_growth, eitherWayMargin(a).c_str(),
                   rb::docPage("physics.md").c_str(),
                   nearTheLine(a) ? "; near the rule's line: run it to see" : "");
    else if (a.preferred_growth > 0 && nearTheLine(a))
      std::fprintf(out,
                   "either way       spun %s at %g rad/s the rocking grows too (at %.4g /s, %s): "
                   "not predicted to reverse that way (%s P8.4); near the rule's line: run it "
                   "to see\n",
                   std::string(rb::nameOf(a.preferred)).c_str(), std::abs(a.spin),
                   a.preferred_growth, eitherWayMargin(a).c_str(),
                   rb::docPage("physics.md").c_str());
  }
}

// Why there is no forecast first reversal, or nothing where there is one.
std::optional<std::string> noForecast(const tasks::Analysis& a, const std::string& where) {
  const sim::ReversalForecast& forecast = a.forecast;
  if (a.unspun)
    return "none: the scene is not spun (initial.spin 0; --spin N forecasts one spun N rad/s)";
  // Not spun, nothing reverses (rather than "outside the averaged theory's range ... = inf").
  if (a.spin == 0) return "none: not spun (--spin 0), there is no spin to reverse";
  if (!forecast.applies) return "not forecast: the theory needs a body that can stand";
  if (forecast.tilt_energy == 0)
    return "none forecast: with no tilt nothing starts the rocking (" + where + ")";
  if (forecast.range == sim::ForecastRange::Outside) {
    char text[800];
    std::snprintf(text, sizeof text,
                  "not forecast: spun %g rad/s this is outside the averaged theory's range "
                  "(n²ρ/g = %.2g, rocking energy / spin energy = %.2g; either above 1; %s)",
                  a.spin, forecast.spin_parameter, forecast.energy_ratio, where.c_str());
    return text;
  }
  return std::nullopt;
}

void printForecast(std::FILE* out, const tasks::Analysis& a) {
  const std::string where = rb::docPage("physics.md") + " P8.5";
  if (const std::optional<std::string> none = noForecast(a, where)) {
    std::fprintf(out, "first reversal   %s\n", none->c_str());
    return;
  }
  const sim::ReversalForecast& forecast = a.forecast;
  if (forecast.time)
    std::fprintf(out, "first reversal   forecast at %.3g s spun %g rad/s with the scene's tilt",
                 *forecast.time, a.spin);
  else
    std::fprintf(out, "first reversal   none forecast within the run's %g s spun %g rad/s",
                 a.duration, a.spin);
  const std::string stands =
      forecast.range == sim::ForecastRange::Within
          ? "within its range, where it is within about 1.5 % of a run"
          : std::string("beyond its range (0.15 and 0.1), where runs measured it ") +
                tasks::kBeyondRangeError;
  std::fprintf(out,
               " (averaged theory, %s; n²ρ/g = %.2g, rocking energy / spin energy = %.2g: %s)\n",
               where.c_str(), forecast.spin_parameter, forecast.energy_ratio, stands.c_str());
}

// The points, the mass's source, the dents' cut, the mass and size.
void printBody(std::FILE* out, const std::string& scene, const tasks::Analysis& a) {
  const auto top = static_cast<std::size_t>(a.census.top);
  const auto bottom = static_cast<std::size_t>(a.census.bottom);
  std::fprintf(out, "scene            %s (lengths below in the file's unit, %g m)\n", scene.c_str(),
               a.length_unit);
  if (a.paraboloid)
    std::fprintf(out, "points           %lld in all, %zu on the surface (%zu top, %zu bottom)\n",
                 static_cast<long long>(a.census.points), top + bottom, top, bottom);
  else if (a.mesh)
    std::fprintf(out, "points           %zu sampled from the mesh (%zu top, %zu bottom)\n",
                 top + bottom, top, bottom);
  else
    std::fprintf(out,
                 "points           %zu drawn on the surface (%zu top, %zu bottom); the mass "
                 "properties are the scene's\n",
                 top + bottom, top, bottom);
  std::fprintf(out, "mass properties  %s\n", a.mass_source.c_str());
  // Dents left outside a body made smaller cut nothing: said, or the user sees only that the
  // body prefers no direction.
  const std::optional<double> cut = a.dents_cut_share;
  if (cut == 0.0)
    std::fprintf(out,
                 "WARNING: body.dents cut nothing: they lie wholly outside the body, which is "
                 "the plain paraboloid (move body.dents.at within its top, or remove them)\n");
  // How much of the body the dents take: deep dents cut notches through it.
  else if (cut)
    std::fprintf(
        out, "dents            cut %.3g %% of the paraboloid's volume%s\n", 100 * *cut,
        *cut > 0.25 ? " (deep: see the body's shape with `rattleback still --view above`)" : "");
  std::fprintf(out, "mass             %g kg\n", a.mass);
  // Its size, which the paraboloid's numbers do not say, and a mass no material gives it (59
  // for 0.059 kg; lengths in cm read as m).
  std::fprintf(out, "size             %s (length × width × height: the box that holds it)\n",
               tasks::sizeText(a.size, a.length_unit).c_str());
  if (a.implausible_mass) std::fprintf(out, "WARNING: %s\n", a.implausible_mass->c_str());
}

void printInertia(std::FILE* out, const tasks::Analysis& a) {
  const Eigen::Vector3d com = a.com / a.length_unit;
  std::fprintf(out, "centre of mass   (%.6g, %.6g, %.6g) in the shape's frame\n", com.x(), com.y(),
               com.z());
  std::fprintf(out, "inertia about the CM, geometric axes [kg m^2]\n");
  // Products of inertia a symmetric body does not have come out of cubature as 1e-19 of the
  // moments, not 0: shown as the 0 they are.
  const Eigen::Matrix3d& inertia = a.inertia;
  const double moment = inertia.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i)
    std::fprintf(out, "                 [% .6e  % .6e  % .6e]\n", clean(inertia(i, 0), moment),
                 clean(inertia(i, 1), moment), clean(inertia(i, 2), moment));
  std::fprintf(out, "principal        %.6e  %.6e  %.6e kg m^2, along (columns)\n", a.principal(0),
               a.principal(1), a.principal(2));
  for (int i = 0; i < 3; ++i)
    std::fprintf(out, "                 [% .6f  % .6f  % .6f]\n", a.axes(i, 0), a.axes(i, 1),
                 a.axes(i, 2));
  // The sign's convention said with the way itself: "-8.27 deg (… counter-clockwise …)" had
  // read as a contradiction.
  std::fprintf(out,
               "misalignment     %+.4f deg (the least-inertia axis is %.4f deg %s of the "
               "bottom's long axis, seen from above; + is counter-clockwise)\n",
               a.misalignment_deg, std::abs(a.misalignment_deg),
               a.misalignment_deg < 0 ? "clockwise" : "counter-clockwise");
}

void printContact(std::FILE* out, const tasks::Analysis& a) {
  const sim::ContactStability& s = a.stability;
  const bool adaptive = sim::isAdaptive(a.integrator);
  if (a.contact_model == sim::ContactModel::Rolling)
    std::fprintf(out,
                 "contact          rolling: no contact spring, so no step limit from the floor\n");
  else if (a.contact_model == sim::ContactModel::Auto && adaptive)
    std::fprintf(out,
                 "contact          auto: rolls while the floor can give the force rolling needs, "
                 "else slides (smooth: stiffest mode %.4g rad/s, damping ratio %.3g); the "
                 "adaptive integrator chooses its steps\n",
                 s.omega, s.zeta);
  else if (a.contact_model == sim::ContactModel::Auto)
    std::fprintf(out,
                 "contact          auto: rolls while the floor can give the force rolling needs, "
                 "else slides (smooth: stiffest mode %.4g rad/s, damping ratio %.3g) in steps of "
                 "%.3g s within each step\n",
                 s.omega, s.zeta, a.auto_smooth_step);
  else if (adaptive)
    std::fprintf(out,
                 "contact          stiffest mode at rest %.4g rad/s (damping ratio %.3g); the "
                 "adaptive integrator chooses its steps\n",
                 s.omega, s.zeta);
  else
    std::fprintf(out,
                 "contact          stiffest mode at rest %.4g rad/s (damping ratio %.3g); "
                 "largest stable dt for a run %.3g s with %s (the scene's integrator; %.3g s "
                 "at rest)\n",
                 s.omega, s.zeta, s.run_step, std::string(rb::nameOf(a.integrator)).c_str(),
                 s.largest_step);
}

// A mesh body's fitted bottom: its residual, its cap, and whether the smooth models can use it.
void printFittedBottom(std::FILE* out, const tasks::Analysis& a) {
  const sim::BottomFit& fit = a.fit;
  const double unit = a.length_unit;
  if (!std::isnan(fit.rms_m))  // measured (a fit refused before has no residual)
    std::fprintf(out,
                 "fitted bottom    quadric over %zu bottom points (tilts up to %.3g deg): %.3g "
                 "RMS, %.3g at most from them (%.2g %% and %.2g %% of the body's length; limit "
                 "%.2g %% RMS)\n",
                 fit.points, std::atan(fit.cap_slope) * 180 / M_PI, fit.rms_m / unit,
                 fit.max_m / unit, 100 * fit.rms_m / fit.size_m, 100 * fit.max_m / fit.size_m,
                 100 * sim::kFitRmsLimit);
  if (!fit.usable())
    std::fprintf(out,
                 "WARNING: the bottom does not fit a smooth surface, so contact.model smooth, "
                 "rolling and auto are refused (use points): %s\n",
                 fit.problem.c_str());
}

// The analysis as text or JSON, into `out`.
void writeAnalysis(std::FILE* out, const AnalyzeArgs& args, const sim::Model& model) {
  const tasks::Analysis a = tasks::analyze(model, args.spin);
  if (args.json) {
    std::fprintf(out, "%s\n", tasks::analysisJson(a).dump(2).c_str());
    return;
  }
  printBody(out, sceneWithValues(args.scene, args.overrides), a);
  printInertia(out, a);
  printContact(out, a);
  if (a.mesh) printFittedBottom(out, a);
  if (!a.theory) {
    std::fprintf(out,
                 "theory           none: the rest, frequencies, growth rates and forecast need a "
                 "smooth bottom, and the mesh's does not fit one (docs/physics.md §P11.4)\n");
    return;
  }
  printRest(out, a);
  printGrowth(out, a);
  printPreferred(out, a);
  printForecast(out, a);
}

}  // namespace

int analyzeCommand(const AnalyzeArgs& args) {
  if (auto ok = tasks::checkAnalysisSpin(args.spin, "--spin"); !ok) return fail(ok);
  auto loaded = loadScene(args.scene, args.overrides);
  if (!loaded) return fail(loaded);
  noteShipped(args.scene);
  if (args.output.empty() || args.output == "-") {
    writeAnalysis(stdout, args, loaded->model);
    return kOk;
  }
  // -o: whole or not at all, and listed in the folder's manifest.
  if (auto ok = rb::checkDataOutput(args.output,
                                    args.json ? "the analysis as JSON" : "the analysis as text",
                                    args.json ? ".json" : ".txt", {args.scene});
      !ok)
    return fail(ok);
  if (auto made = tasks::makeParentFolder(args.output); !made) return fail(made);
  auto file = tasks::AtomicOutput::open(args.output);
  if (!file) return fail(file);
  char* text = nullptr;
  std::size_t size = 0;
  std::FILE* memory = ::open_memstream(&text, &size);
  writeAnalysis(memory, args, loaded->model);
  std::fclose(memory);
  file->stream().write(text, static_cast<std::streamsize>(size));
  std::free(text);
  if (auto e = file->commit(); !e) return fail(e);
  record({{args.output,
           tasks::OutputKind::Analysis,
           sceneName(args.scene),
           args.json ? "json" : "text",
           {},
           {},
           tasks::madeFrom(loaded->scene)}});
  return kOk;
}

}  // namespace app
