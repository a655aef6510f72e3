#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "sim/analysis.hpp"
#include "sim/compile.hpp"
#include "sim/contact_model.hpp"
#include "sim/stability.hpp"
#include "sim/switching.hpp"
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

Eigen::Vector3d clean(const Eigen::Vector3d& v, double scale) {
  return {clean(v.x(), scale), clean(v.y(), scale), clean(v.z(), scale)};
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

// `given`: the spin came from --spin; else it is the scene's, or 5 rad/s for a scene not spun.
void printTheory(std::FILE* out, const sim::Model& model, double spin, bool given) {
  const bool unspun = !given && model.initial.spin == 0;
  const char* marker = given    ? "   <- --spin"
                       : unspun ? "   <- the scene is not spun: at 5 rad/s"
                                : "   <- the scene's";
  const double unit = model.length_unit;
  const sim::Rest rest = sim::restOf(model);
  std::fprintf(out,
               "rest contact     CM %.4g above it; radii of curvature %.4g and %.4g "
               "(file units)\n",
               rest.h / unit, rest.radii(0) / unit, rest.radii(1) / unit);
  if (rest.stable) {
    std::fprintf(out, "rest             stable upright (h below both radii)\n");
  } else {
    std::fprintf(out,
                 "WARNING: the body cannot stand upright: its CM is %.4g above the contact, "
                 "above the radius of curvature %.4g (needs h below both radii)\n",
                 rest.h / unit, rest.radii(0) / unit);
  }
  const tasks::RestModes modes = tasks::restModes(sim::linearise(model, 0));
  std::fprintf(out, "at rest          roll %s, pitch %s (linearised rolling model)\n",
               restModeText(modes.roll).c_str(), restModeText(modes.pitch).c_str());
  const sim::FirstOrder first = sim::firstOrderGrowth(model);
  std::fprintf(out,
               "first order      growth rate = n × (roll %+.4g, pitch %+.4g) 1/rad "
               "(Walker, Bondi; seed eqs. 18–20)\n",
               first.roll, first.pitch);
  std::fprintf(out, "growth rates     exact linearised rolling model, 1/s:\n");
  std::fprintf(out, "                 %8s %10s %10s\n", "n rad/s", "roll", "pitch");
  std::vector<double> spins = {-10, -5, -2, -1, 1, 2, 5, 10};
  if (std::find(spins.begin(), spins.end(), spin) == spins.end()) spins.push_back(spin);
  std::sort(spins.begin(), spins.end());
  for (double n : spins) {
    const sim::Linearisation l = sim::linearise(model, n);
    std::fprintf(out, "                 %8.3g %+10.4f %+10.4f%s\n", n, l.roll_growth,
                 l.pitch_growth, n == spin ? marker : "");
  }
  const sim::Linearisation l = sim::linearise(model, spin);
  std::fprintf(out, "eigenvalues      at n = %g rad/s:", spin);
  double largest = 0;
  for (const auto& lambda : l.eigenvalues) largest = std::max(largest, std::abs(lambda));
  for (const auto& lambda : l.eigenvalues)
    std::fprintf(out, " %.4g%+.4gi", clean(lambda.real(), largest), clean(lambda.imag(), largest));
  std::fprintf(out, "\n");
  const sim::Direction preferred = sim::preferredDirection(model, spin);
  if (!rest.stable)
    std::fprintf(out,
                 "preferred        none: the body cannot stand (it has no rocking about upright "
                 "for a direction of spin to favour)\n");
  else if (preferred == sim::Direction::None) {
    // Which of the two: a body with no misalignment grows alike both ways at any spin; a slow
    // spin (drag damps the rocking) may see it die out both ways, though faster spins favour
    // one (at --spin 0 "none" would read as the body's, where 5 rad/s gives ccw).
    const sim::Direction faster = sim::preferredDirection(model, std::max(5.0, std::abs(spin)));
    if (faster == sim::Direction::None)
      std::fprintf(out,
                   "preferred        none (the rocking grows alike both ways, or neither way: "
                   "no direction is predicted to reverse rather than the other)\n");
    else
      std::fprintf(out,
                   "preferred        none at %g rad/s (the rocking dies out spun either way: "
                   "neither is predicted to reverse at this spin); at 5 rad/s: %s\n",
                   std::abs(spin), std::string(rb::nameOf(faster)).c_str());
  } else
    std::fprintf(out,
                 "preferred        %s (%s seen from above): its rocking grows more slowly; "
                 "spun the other way it is predicted to reverse sooner\n",
                 std::string(rb::nameOf(preferred)).c_str(),
                 preferred == sim::Direction::Ccw ? "counter-clockwise" : "clockwise");
  if (unspun) {
    std::fprintf(out,
                 "first reversal   none: the scene is not spun (initial.spin 0; --spin N "
                 "forecasts one spun N rad/s)\n");
    return;
  }
  // --spin 0: nothing to reverse (not "outside the averaged theory's range ... = inf").
  if (spin == 0) {
    std::fprintf(out, "first reversal   none: not spun (--spin 0), there is no spin to reverse\n");
    return;
  }
  const sim::ReversalForecast forecast = sim::forecastFirstReversal(model, spin, model.duration);
  if (!forecast.applies) {
    std::fprintf(out, "first reversal   not forecast: the theory needs a body that can stand\n");
    return;
  }
  const std::string where_page = rb::docPage("physics.md") + " P8.5";
  const char* where = where_page.c_str();
  if (forecast.tilt_energy == 0) {
    std::fprintf(out,
                 "first reversal   none forecast: with no tilt nothing starts the rocking (%s)\n",
                 where);
    return;
  }
  if (forecast.range == sim::ForecastRange::Outside) {
    std::fprintf(out,
                 "first reversal   not forecast: spun %g rad/s this is outside the averaged "
                 "theory's range (n²ρ/g = %.2g, rocking energy / spin energy = %.2g; either above "
                 "1; %s)\n",
                 spin, forecast.spin_parameter, forecast.energy_ratio, where);
    return;
  }
  if (forecast.time)
    std::fprintf(out, "first reversal   forecast at %.3g s spun %g rad/s with the scene's tilt",
                 *forecast.time, spin);
  else
    std::fprintf(out, "first reversal   none forecast within the run's %g s spun %g rad/s",
                 model.duration, spin);
  const std::string stands =
      forecast.range == sim::ForecastRange::Within
          ? "within its range, where it is within about 1.5 % of a run"
          : std::string("beyond its range (0.15 and 0.1), where runs measured it ") +
                tasks::kBeyondRangeError;
  std::fprintf(out,
               " (averaged theory, %s; n²ρ/g = %.2g, rocking energy / spin energy = %.2g: %s)\n",
               where, forecast.spin_parameter, forecast.energy_ratio, stands.c_str());
}

void printText(std::FILE* out, const std::string& scene, const sim::Model& model) {
  const sim::MassProperties& m = model.body->mass_properties;
  const double unit = model.length_unit;
  const sim::ContactStability stability = sim::contactStability(model);
  const sim::GridCensus census = sim::censusOf(*model.body);
  const auto top = static_cast<std::size_t>(census.top);
  const auto bottom = static_cast<std::size_t>(census.bottom);
  std::fprintf(out, "scene            %s (lengths below in the file's unit, %g m)\n", scene.c_str(),
               unit);
  if (model.body->surface.kind == sim::Surface::Kind::Paraboloid)
    std::fprintf(out, "points           %lld in all, %zu on the surface (%zu top, %zu bottom)\n",
                 static_cast<long long>(census.points), top + bottom, top, bottom);
  else
    std::fprintf(out,
                 "points           %zu drawn on the surface (%zu top, %zu bottom); the mass "
                 "properties are the scene's\n",
                 top + bottom, top, bottom);
  std::fprintf(out, "mass properties  %s\n", tasks::massSourceText(*model.body).c_str());
  // Dents left outside a body made smaller cut nothing: said, or the user sees only that the
  // body prefers no direction.
  const std::optional<double> cut = tasks::dentsCutShare(*model.body);
  if (cut == 0.0)
    std::fprintf(out,
                 "WARNING: body.dents cut nothing: they lie wholly outside the body, which is "
                 "the plain paraboloid (move body.dents.at within its top, or remove them)\n");
  // How much of the body the dents take (deep dents can take 39 % of it, cutting notches
  // through the body).
  else if (cut)
    std::fprintf(
        out, "dents            cut %.3g %% of the paraboloid's volume%s\n", 100 * *cut,
        *cut > 0.25 ? " (deep: see the body's shape with `rattleback still --view above`)" : "");
  std::fprintf(out, "mass             %g kg\n", m.mass);
  // Its size (the paraboloid's numbers do not say how long a body they make), and a mass no
  // material gives it (59 for 0.059 kg; lengths in cm read as m).
  std::fprintf(out, "size             %s (length × width × height: the box that holds it)\n",
               tasks::sizeText(tasks::bodySize(*model.body), unit).c_str());
  if (const auto implausible = tasks::implausibleMass(*model.body, unit))
    std::fprintf(out, "WARNING: %s\n", implausible->c_str());
  const Eigen::Vector3d com = clean(m.com, model.body->surface.footprintHalf().maxCoeff()) / unit;
  std::fprintf(out, "centre of mass   (%.6g, %.6g, %.6g) in the shape's frame\n", com.x(), com.y(),
               com.z());
  std::fprintf(out, "inertia about the CM, geometric axes [kg m^2]\n");
  // Products of inertia a symmetric body does not have come out of cubature as 1e-19 of the
  // moments, not 0: shown as the 0 they are.
  const double moment = m.inertia.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i)
    std::fprintf(out, "                 [% .6e  % .6e  % .6e]\n", clean(m.inertia(i, 0), moment),
                 clean(m.inertia(i, 1), moment), clean(m.inertia(i, 2), moment));
  std::fprintf(out, "principal        %.6e  %.6e  %.6e kg m^2, along (columns)\n", m.principal(0),
               m.principal(1), m.principal(2));
  for (int i = 0; i < 3; ++i)
    std::fprintf(out, "                 [% .6f  % .6f  % .6f]\n", m.axes(i, 0), m.axes(i, 1),
                 m.axes(i, 2));
  std::fprintf(out,
               "misalignment     %+.4f deg (least-inertia axis from the bottom's long axis, "
               "counter-clockwise seen from above)\n",
               m.misalignment_deg);
  if (sim::heldOnFloor(model.contact.model))
    std::fprintf(out,
                 "contact          rolling: no contact spring, so no step limit from the floor\n");
  else if (sim::contactTraits(model.contact.model).switches && sim::isAdaptive(model.integrator))
    std::fprintf(out,
                 "contact          auto: rolls while the floor can give the force rolling needs, "
                 "else slides (smooth: stiffest mode %.4g rad/s, damping ratio %.3g); the "
                 "adaptive integrator chooses its steps\n",
                 stability.omega, stability.zeta);
  else if (sim::contactTraits(model.contact.model).switches)
    std::fprintf(out,
                 "contact          auto: rolls while the floor can give the force rolling needs, "
                 "else slides (smooth: stiffest mode %.4g rad/s, damping ratio %.3g) in steps of "
                 "%.3g s within each step\n",
                 stability.omega, stability.zeta, std::min(sim::smoothStep(model), model.dt));
  else if (sim::isAdaptive(model.integrator))
    std::fprintf(out,
                 "contact          stiffest mode at rest %.4g rad/s (damping ratio %.3g); the "
                 "adaptive integrator chooses its steps\n",
                 stability.omega, stability.zeta);
  else
    std::fprintf(out,
                 "contact          stiffest mode at rest %.4g rad/s (damping ratio %.3g); "
                 "largest stable dt for a run %.3g s with %s (the scene's integrator; %.3g s "
                 "at rest)\n",
                 stability.omega, stability.zeta, stability.run_step,
                 std::string(rb::nameOf(model.integrator)).c_str(), stability.largest_step);
}

// The analysis as text or JSON, into `out`.
void writeAnalysis(std::FILE* out, const AnalyzeArgs& args, const sim::Model& model) {
  const double spin = tasks::analysisSpin(model, args.spin);
  if (args.json) {
    std::fprintf(out, "%s\n", tasks::analysisJson(model, spin).dump(2).c_str());
  } else {
    printText(out, args.scene, model);
    printTheory(out, model, spin, args.spin.has_value());
  }
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
