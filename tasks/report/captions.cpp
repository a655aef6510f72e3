#include "tasks/report/captions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "tasks/against_theory.hpp"
#include "tasks/analysis.hpp"
#include "tasks/report/html.hpp"

namespace tasks::report {
namespace {

// A mode at rest (analyze's "frequencies_hz"): its frequency, or how fast it grows where it
// topples instead ("growth_rates_at_rest").
std::string restModeOf(const nlohmann::json& theory, const char* mode) {
  const nlohmann::json& hz = field(field(theory, "frequencies_hz"), mode);
  const nlohmann::json& growth = field(field(theory, "growth_rates_at_rest"), mode);
  if (hz.is_null() && growth.is_number())
    return "<b>unstable</b> (grows at " + number(growth, "%.3g") + " /s)";
  return number(hz, "%.2f") + " Hz";
}

// The first reversal the averaged theory predicts (analyze's "predicted_first_reversal").
std::string forecastOf(const nlohmann::json& theory) {
  const nlohmann::json& f = field(theory, "predicted_first_reversal");
  if (!f.is_object()) return "";
  std::string text = "<br>first reversal (averaged theory): ";
  if (field(f, "applies") == false) return text + "none: the body cannot stand";
  const std::string measures = " (n²ρ/g " + number(field(f, "spin_parameter"), "%.2g") +
                               ", rocking / spin energy " +
                               number(field(f, "energy_ratio"), "%.2g") + ")";
  if (field(f, "range") == "outside") return text + "outside its range" + measures;
  if (!field(f, "time_s").is_number())
    return text + "none within " + number(field(f, "within_s"), "%g") + " s" + measures;
  return text + "<b>" + number(field(f, "time_s"), "%.2f") + " s</b>" + measures +
         (field(f, "range") == "within"
              ? ", within its range: within about 1.5 %"
              : std::string(", beyond its range: ") + kBeyondRangeError + " in the runs measured");
}

// The preferred direction in words, where analyze found one (or found the body topples).
const char* preferredWords(const nlohmann::json& theory) {
  const nlohmann::json& preferred = field(theory, "preferred");
  const bool topples = preferred.is_null() && field(theory, "rest_stable") == false;
  return preferred == "ccw"    ? "counter-clockwise"
         : preferred == "cw"   ? "clockwise"
         : preferred == "none" ? "none"
         : topples             ? "none: the body cannot stand"
                               : "–";
}

// The run's estimated errors (simulate --check); empty without one.
std::string checkOf(const std::optional<CheckRecord>& check) {
  if (!check) return "";
  std::string text = "<br>estimated error (<code>--check</code>, against " +
                     escape(stringOr(check->setting, "a tighter run")) + "): ";
  const std::vector<Number>& errors = check->reversal_errors;
  if (!errors.empty()) {
    text += errors[0] ? "first reversal ±" + number(std::abs(*errors[0]), "%.2g") + " s, "
                      : "first reversal <b>not converged</b> (the tighter run has none), ";
  }
  const Number& spin = check->spin_error;
  return text + "n(t) ±" + (spin ? number(std::abs(*spin), "%.2g") : "–") + " rad/s";
}

// The values put in over the scene file (--set, with_values), which make this run's body:
// variants of one scene would otherwise each say only the scene's name.
std::string valuesOf(const RunRecord& run) {
  if (run.scene_values.empty()) return "";
  std::string out = "values put in: ";
  for (std::size_t i = 0; i < run.scene_values.size(); ++i) {
    const auto& [key, value] = run.scene_values[i];
    out += (i ? ", " : "") + std::string("<code>") +
           escape(stringOr(key, "?") + " = " + stringOr(value, "?")) + "</code>";
  }
  return out + "<br>";
}

// A number for a caption: %g, with U+2212 for its minus sign as the plots' tic labels have.
std::string shown(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text[0] == '-' ? "\u2212" + std::string(text + 1) : text;
}

// A still's time as its picture's read-out gives it, to the hundredth (a still at the reversal
// was captioned "t = 1.21301 s" beside a picture saying 1.21 s), less trailing zeros.
std::string shownTime(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", t);
  std::string out = text;
  if (out.find('.') != std::string::npos) {
    out.erase(out.find_last_not_of('0') + 1);
    if (out.back() == '.') out.pop_back();
  }
  if (out == "-0") out = "0";
  return out[0] == '-' ? "\u2212" + out.substr(1) : out;
}

}  // namespace

std::string spinWords(double spin) {
  return spin > 0 ? "counter-clockwise" : spin < 0 ? "clockwise" : "no spin";
}

std::string reversalOf(const RunRecord& run) {
  constexpr std::size_t kReversalsNamed = 4;
  std::vector<std::string> times;
  for (const Number& t : run.reversals_s) times.push_back(number(t, "%.3f"));
  if (times.empty() && run.first_reversal_s) times.push_back(number(run.first_reversal_s, "%.3f"));
  if (times.empty()) return "no reversal in " + number(run.simulated_s, "%g") + " s";
  if (times.size() == 1) return "<b>reversed at " + times[0] + " s</b>";
  const std::size_t named = std::min(times.size(), kReversalsNamed);
  std::string text = "<b>reversed " + std::to_string(times.size()) + " times</b>, ";
  text += named < times.size() ? "the first " + std::to_string(named) + " at " : "at ";
  for (std::size_t i = 0; i < named; ++i)
    text += times[i] + (i + 2 < named ? ", " : i + 2 == named ? " and " : " s");
  return text;
}

namespace {

// How the run started: its spin, or a body struck about its x or y axis (a tap) by its ω.
std::string startOf(const RunRecord& run) {
  const std::vector<Number>& w = run.model_angular_velocity;
  if (w.size() == 3 && (w[0].value_or(0) != 0 || w[1].value_or(0) != 0))
    return "struck at ω = [" + number(w[0], "%.3g") + ", " + number(w[1], "%.3g") + ", " +
           number(w[2], "%.3g") + "] rad/s (body axes)";
  return "spun " + number(run.initial_spin, "%+.3g") + " rad/s (" +
         spinWords(run.initial_spin.value_or(0.0)) + ")";
}

}  // namespace

std::string measuredOf(const RunRecord& run) {
  std::ostringstream out;
  out << valuesOf(run);
  // How long, and how often sampled: runs of one scene told apart by these would say the same.
  out << startOf(run)
      << (run.simulated_s ? ", " + number(run.simulated_s, "%.4g") + " s" : std::string())
      << (run.rate_hz ? " at " + number(run.rate_hz, "%.4g") + " samples/s" : std::string())
      << "<br>" << reversalOf(run) << "<br>final spin " << number(run.final_spin, "%+.3f")
      << " rad/s<br>energy " << number(run.energy_initial, "%.4g") << " J → "
      << number(run.energy_final, "%.4g") << " J";
  // What simulate's summary warned of, where the page is read without it (a step too large
  // would show as "no reversal in 5 s" with nothing said).
  for (const Text& w : run.warnings)
    out << "<br><span class=\"warning\">⚠ " << escape(stringOr(w, "?")) << "</span>";
  out << checkOf(run.check);
  return out.str();
}

namespace {

// Which way a run that reversed ends turning: after two reversals it turns as it started, and a
// class told only "it reversed" expects the other way.
std::string endingOf(const RunRecord& run, bool reversed) {
  if (!reversed || !run.final_spin) return "";
  if (*run.final_spin == 0) return "; at the end it is not turning";
  return "; at the end it turns <b>" + spinWords(*run.final_spin) + "</b> (" +
         number(run.final_spin, "%+.2f") + " rad/s)";
}

}  // namespace

std::string measuredAs(const std::optional<RunRecord>& run, bool ccw, std::optional<bool> preferred,
                       bool either_way) {
  if (!run) return "";
  const Number& spin = run->initial_spin;
  if (!spin || *spin == 0 || (*spin > 0) != ccw) return "";
  const bool video = run->command == "render";
  // (A video listed by an older manifest knows its first reversal only.)
  std::string text =
      (video ? "<br>in this video (" : "<br>measured (<code>simulate</code>, ") +
      number(spin, "%+.3g") + " rad/s): " +
      (video && run->first_reversal_s && run->reversals_s.empty()
           ? "<b>first reversal at " + number(run->first_reversal_s, "%.3f") + " s</b>"
           : reversalOf(*run));
  const bool reversed = !run->reversals_s.empty() || run->first_reversal_s.has_value();
  if (preferred) text += wordsFor(againstTheory(*preferred, reversed, either_way), Front::Caption);
  return text + endingOf(*run, reversed);
}

std::string predictedOf(const nlohmann::json& t) {
  std::ostringstream out;
  const std::string way = preferredWords(t);
  out << "preferred direction: <b>" << way << "</b>"
      << (field(t, "grows_either_way") == true
              ? "; spun " + way +
                    " too its rocking grows: <b>predicted to reverse either way</b>, " + way +
                    " later"
              : "")
      << "<br>growth rates at n = " << number(field(t, "spin"), "%+g") << " rad/s: roll "
      << number(field(field(t, "growth_rates"), "roll"), "%+.3f") << " /s, pitch "
      << number(field(field(t, "growth_rates"), "pitch"), "%+.3f")
      << " /s<br>rocking at rest: roll " << restModeOf(t, "roll") << ", pitch "
      << restModeOf(t, "pitch") << "<br>misalignment "
      << number(field(t, "misalignment_deg"), "%+.2f") << "°; "
      << (field(t, "rest_stable") == true    ? "stands upright"
          : field(t, "rest_stable") == false ? "<b>cannot stand upright</b>"
                                             : "upright: –")
      << forecastOf(t);
  return out.str();
}

std::string stillCaption(const OutputEntry& e) {
  std::string caption = (e.role.empty() ? std::string("a") : e.role) + " view";
  if (e.t) caption += ", t = " + shownTime(*e.t) + " s";
  if (e.spin) caption += *e.spin == 0 ? ", not spun" : ", spun " + shown(*e.spin) + " rad/s";
  return caption;
}

std::string plotCaption(const std::string& file) {
  const std::pair<const char*, const char*> plots[] = {
      {"-spin.png", "spin n against time"},
      {"-energy.png", "energy against time"},
      {"-tilt.png", "tilt against time"},
      {"-normal.png", "normal force against time"}};
  for (const auto& [suffix, caption] : plots)
    if (endsWith(file, suffix)) return caption;
  return "";
}

}  // namespace tasks::report
