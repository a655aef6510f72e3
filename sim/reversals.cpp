#include "sim/reversals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "sim/crossing.hpp"

namespace sim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// The extreme of f on [l, r] the way `sign` points (+1: a maximum, −1: a minimum), as (t, f):
/// 30 golden-section steps, to 5e-7 of r − l (f there is within ~1e-12 of the extreme's
/// height relative to its rise over the interval; a count, not a width, as an interval of a
/// few ulps cannot shrink), stopping early once f is beyond `level` (all the caller needs).
template <typename F>
std::pair<double, double> extreme(F&& f, double l, double r, double sign, double level) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  double c = r - g * (r - l), d = l + g * (r - l);
  double fc = f(c), fd = f(d);
  for (int i = 0; i < 30; ++i) {
    if (sign * fc > sign * level) return {c, fc};
    if (sign * fd > sign * level) return {d, fd};
    if (sign * fc > sign * fd) {
      r = d, d = c, fd = fc;
      c = r - g * (r - l), fc = f(c);
    } else {
      l = c, c = d, fc = fd;
      d = l + g * (r - l), fd = f(d);
    }
  }
  return sign * fc > sign * fd ? std::pair{c, fc} : std::pair{d, fd};
}

/// Where f left a band: between a point inside (t_in, v_in) and the first outside (t_out,
/// v_out), through `level`; the time itself is found only when asked (`exitTime`), as a
/// candidate dropped by n going back needs none.
struct Exit {
  double t_in, v_in, t_out, v_out;  ///< s, and f there
  double level;                     ///< the band's edge crossed
  bool above;                       ///< left through its top (else through its bottom)
};

/// The time at which f meets the exit's level, by regula falsi between its points, s.
template <typename F>
double exitTime(F&& f, const Exit& e) {
  return zeroCrossing([&](double s) { return f(s) - e.level; }, e.t_in, e.t_out, e.v_in - e.level,
                      e.v_out - e.level);
}

/// The first time in (a, b] at which f leaves [lo, hi] (f(a) = fa within it, f(b) = fb), if it
/// does: f at up to kSamples equal parts of the interval, none shorter than kFinestRead, and at
/// each extreme between them (a sample above or below both neighbours is refined to the extreme
/// near it), so a brief excursion between samples is seen; then the first point outside,
/// bracketed with the point before it, is the exit.
template <typename F>
std::optional<Exit> firstExit(F&& f, double a, double b, double fa, double fb, double lo,
                              double hi) {
  constexpr int kMost = ReversalDetector::kSamples;
  const int N = static_cast<int>(
      std::clamp((b - a) / ReversalDetector::kFinestRead, 1.0, static_cast<double>(kMost)));
  std::array<double, kMost + 1> ts{}, fs{};
  for (int i = 0; i <= N; ++i) {
    ts[i] = i == N ? b : a + (b - a) * i / N;
    fs[i] = i == 0 ? fa : i == N ? fb : f(ts[i]);
  }
  std::array<std::pair<double, double>, 2 * kMost> points{};
  int count = 0;
  for (int i = 0; i <= N; ++i) {
    points[count++] = {ts[i], fs[i]};
    if (i == 0 || i == N) continue;
    const bool peak = fs[i] >= fs[i - 1] && fs[i] >= fs[i + 1] && fs[i] <= hi && hi < kInf;
    const bool dip = fs[i] <= fs[i - 1] && fs[i] <= fs[i + 1] && fs[i] >= lo && lo > -kInf;
    if (peak || dip)
      points[count++] = extreme(f, ts[i - 1], ts[i + 1], peak ? 1 : -1, peak ? hi : lo);
  }
  std::sort(points.begin(), points.begin() + count);
  for (int i = 1; i < count; ++i) {
    const auto [t, v] = points[i];
    if (v <= hi && v >= lo) continue;
    const auto [t_in, v_in] = points[i - 1];
    return Exit{t_in, v_in, t, v, v > hi ? hi : lo, v > hi};
  }
  return std::nullopt;
}

}  // namespace

ReversalDetector::ReversalDetector(double initial_spin)
    : threshold_(kFraction * std::abs(initial_spin)),
      reference_sign_(initial_spin == 0 ? 0 : std::copysign(1.0, initial_spin)) {}

void ReversalDetector::step(double t0, double n0, double t1, double n1, double last_flight,
                            bool at_end, const std::function<double(double)>& n_at) {
  if (reference_sign_ == 0 || !std::isfinite(n1)) return;
  last_flight_ = last_flight;
  // A crossing while the body was in the air or still bouncing is none.
  if (phase_ != Phase::Idle && crossing_ - last_flight < kSettleTime) phase_ = Phase::Idle;
  // Without a candidate only a change of sign between the step's ends starts one (the common
  // step: nothing to read between its ends).
  if (phase_ == Phase::Idle && !(n0 * reference_sign_ >= 0 && n1 * reference_sign_ < 0)) return;
  follow(t0, n0, t1, n1, [&](double t) { return n_at(t) * reference_sign_; });
  // A crossing within kHoldTime of the run's end counts there, its hold cut short: nothing
  // undid it.
  if (at_end && phase_ == Phase::Reached && t1 - crossing_ < kHoldTime) count();
}

void ReversalDetector::count() {
  reversals_.push_back(crossing_);
  reference_sign_ = -reference_sign_;
  phase_ = Phase::Idle;
}

// The rule read on m = n·(reference sign), the old way positive, through the step from t:
// each test holds at the time m meets its threshold, found on the interpolant.
void ReversalDetector::follow(double t, double nt, double t1, double n1,
                              const std::function<double(double)>& m_at) {
  // Each pass moves t on to the next event; the bound stops a loop on n = 0 held by rounding.
  for (int events = 0; events < 16 && t < t1; ++events) {
    const double mt = nt * reference_sign_, m1 = n1 * reference_sign_;
    if (phase_ == Phase::Idle) {
      // A new candidate: m changes sign between here and the step's end.
      if (!(mt >= 0 && m1 < 0)) return;
      const double c = zeroCrossing(m_at, t, t1, mt, m1);
      if (c - last_flight_ < kSettleTime) return;
      phase_ = Phase::Crossed, crossing_ = c, t = c, nt = 0;
    } else if (phase_ == Phase::Crossed) {
      // Before m reaches the threshold the new way, m back to the old side drops the candidate
      // (the next crossing is the candidate: the latest crossing counts).
      const std::optional<Exit> e = firstExit(m_at, t, t1, mt, m1, -threshold_, 0);
      if (!e) return;
      phase_ = e->above ? Phase::Idle : Phase::Reached;
      // Back on the old side at the step's end: no new candidate in it, so the time n went
      // back (n dithering about zero does so at most steps) is not needed.
      if (e->above && m1 >= 0) return;
      t = exitTime(m_at, *e);
      nt = e->level * reference_sign_;
    } else {
      // Reached: only m back beyond the threshold the old way undoes the crossing (a wiggle
      // about zero in the middle of a reversal keeps its first crossing); it counts once m is
      // beyond the threshold the new way kHoldTime or more after the crossing (beyond it then,
      // not merely not back: a spin braked to rest that overshot past the threshold and died
      // out at zero would be counted).
      const double held = crossing_ + kHoldTime;
      if (t < held) {
        const double until = std::min(held, t1);
        const double m_until = until == t1 ? m1 : m_at(until);
        if (const auto e = firstExit(m_at, t, until, mt, m_until, -kInf, threshold_)) {
          phase_ = Phase::Idle;
          if (m1 >= 0) return;
          t = exitTime(m_at, *e), nt = threshold_ * reference_sign_;
          continue;
        }
        if (until == t1) return;
        t = until, nt = m_until * reference_sign_;
        if (m_until < -threshold_) count();
        continue;
      }
      const std::optional<Exit> e = firstExit(m_at, t, t1, mt, m1, -threshold_, threshold_);
      if (!e) return;
      if (e->above && m1 >= 0) {
        phase_ = Phase::Idle;
        return;
      }
      // (m_at reads the reference sign, which count() turns: the time is found before.)
      t = exitTime(m_at, *e), nt = e->level * reference_sign_;
      if (e->above)
        phase_ = Phase::Idle;
      else
        count();
    }
  }
}

}  // namespace sim
