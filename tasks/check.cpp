#include "tasks/check.hpp"

#include <cmath>
#include <sstream>

#include "sim/integrator.hpp"
#include "util/names.hpp"

namespace tasks {

TighterSetting tighterOf(const sim::Model& model) {
  TighterSetting tighter{model, "", std::nullopt};
  std::ostringstream text;
  const std::string name(rb::nameOf(model.integrator));
  if (sim::isAdaptive(model.integrator)) {
    // A hundredth of the tolerance: about 100^(1/5) = 2.5× the steps of Dormand–Prince 5(4)
    // (100^(1/8) = 1.8× of 8(5,3)), and a run about a hundred times more accurate, so the
    // difference is the run's error.
    tighter.model.tolerance = model.tolerance / 100;
    text << name << " at tolerance " << tighter.model.tolerance << " (a hundredth)";
  } else {
    tighter.model.dt = model.dt / 2;
    tighter.order = sim::integratorTraits(model.integrator).order;
    text << name << " at dt " << tighter.model.dt << " s (half the step)";
  }
  tighter.description = text.str();
  return tighter;
}

std::optional<RunCheck> checkRun(const sim::Model& model, double rate, const sim::RunSummary& run,
                                 const std::vector<double>& spins,
                                 const std::function<bool()>& cancelled) {
  const TighterSetting tighter = tighterOf(model);
  // Richardson: with run = truth + C h^p and tighter = truth + C (h/2)^p, the run's error is
  // (run − tighter) · 2^p / (2^p − 1). Adaptive: the tighter run's error is ~1 % of the run's.
  const double factor =
      tighter.order ? std::ldexp(1.0, *tighter.order) / (std::ldexp(1.0, *tighter.order) - 1) : 1.0;
  RunCheck check;
  check.setting = tighter.description;
  check.method = tighter.order ? "Richardson, order " + std::to_string(*tighter.order)
                               : "difference from the tighter run";
  sim::Rollout rollout(tighter.model);
  std::size_t k = 0;
  for (double t : sim::sampleTimes(model.duration, rate)) {
    if (cancelled && cancelled()) return std::nullopt;
    if (!rollout.advanceTo(t)) break;
    if (k < spins.size()) {
      const double error = factor * (spins[k] - rollout.sampleAt(t).spin);
      if (std::abs(error) > std::abs(check.spin_error)) {
        check.spin_error = error;
        check.spin_error_at = t;
      }
    }
    ++k;
  }
  const sim::RunSummary fine = rollout.summary();
  check.completed = !fine.divergence;
  check.tighter_reversals = fine.reversals;
  for (std::size_t i = 0; i < run.reversals.size(); ++i)
    check.reversal_errors.push_back(
        i < fine.reversals.size() ? std::optional(factor * (run.reversals[i] - fine.reversals[i]))
                                  : std::nullopt);
  check.cost_ratio = run.wall_s > 0 ? fine.wall_s / run.wall_s : 0;
  return check;
}

nlohmann::json checkJson(const RunCheck& check) {
  nlohmann::json j;
  j["setting"] = check.setting;
  j["method"] = check.method;
  nlohmann::json errors = nlohmann::json::array();
  for (const auto& e : check.reversal_errors)
    errors.push_back(e ? nlohmann::json(*e) : nlohmann::json());
  j["reversal_errors_s"] = errors;
  j["tighter_reversals_s"] = check.tighter_reversals;
  j["spin_error_rad_s"] = check.spin_error;
  j["spin_error_at_s"] = check.spin_error_at;
  j["cost_ratio"] = check.cost_ratio;
  j["tighter_completed"] = check.completed;
  return j;
}

}  // namespace tasks
