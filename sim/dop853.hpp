// Dormand–Prince 8(5,3) with its seventh-order continuous extension: the method of Hairer's
// DOP853 (Hairer, Nørsett & Wanner, Solving Ordinary Differential Equations I, 2nd ed., §II.5
// and §II.6; the coefficients are those published with the code). Written here because Boost.Odeint
// has no eighth-order pair with dense output: its runge_kutta_fehlberg78 has error control but
// no interpolant, and a cubic Hermite on steps this long would miss the 1e-4 s that a reversal's
// time is held to (sim/step_interpolant.cpp wants the state anywhere inside the last step).
//
// Twelve stages a step, the last one at the step's end reused as the next step's first. The
// interpolant needs three more evaluations; they are made only when a time inside the step is
// asked for (a sweep that wants only its first reversal asks inside one step or two of the
// hundreds it takes).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace sim {

/// Steps y' = f(y, t) for y a std::array<double, N>: `f(y, dydt, t)`.
template <std::size_t N>
class Dop853 {
 public:
  using Vector = std::array<double, N>;

  /// abs = rel = tolerance, per component, as the dopri5 stepper takes it.
  explicit Dop853(double tolerance) : tolerance_(tolerance) {}

  /// Starts at y (time t) with a first try of step h (error control shrinks it if too long).
  template <class F>
  void initialize(F&& f, const Vector& y, double t, double h) {
    y_ = y;
    t_ = t;
    h_ = h;
    f(y_, k_[0], t_);
    ++evaluations_;
    dense_ready_ = false;
  }

  /// One accepted step (error ≤ 1 in the scaled RMS norm), retrying shorter ones as needed.
  template <class F>
  void step(F&& f) {
    bool last_rejected = false;
    for (;;) {
      const double h = h_;
      Vector y_new;
      stages(f, h, y_new);
      const double err = error(h, y_new);
      // Hairer's DOP853 control (β = 0, its default): the estimate is O(h⁸), so the next step
      // is h · 0.9 · err^(−1/8), which would make its error 1; growth within 6×, shrinking
      // within 3×. (Gustafsson's β = 0.04, as for dopri5, cut the rejected tries on the
      // rattleback only from 25 % to 20 %, and moved the one knife-edge first reversal of the
      // 200-spin sweep at 1e-9: docs/speed.md.)
      const double grow = std::pow(std::max(err, 1e-300), 0.125) / kSafety;
      if (err <= 1) {
        ++accepted_;
        y_old_ = y_;
        k_first_old_ = k_[0];
        t_old_ = t_;
        y_ = y_new;
        t_ = t_ + h;
        h_old_ = h;
        // The step's end: the first stage of the next step, and the interpolant's slope there.
        f(y_, k_end_, t_);
        ++evaluations_;
        double next = h / std::clamp(grow, 1 / kMost, 1 / kLeast);
        if (last_rejected) next = std::min(next, h);
        h_ = next;
        k_[0] = k_end_;
        dense_ready_ = false;
        return;
      }
      ++rejected_;
      last_rejected = true;
      h_ = h / std::min(1 / kLeast, grow);
    }
  }

  const Vector& state() const { return y_; }
  double time() const { return t_; }
  double previousTime() const { return t_old_; }

  /// The state at t inside the last step, by the seventh-order interpolant.
  template <class F>
  void at(F&& f, double t, Vector& y) {
    if (!dense_ready_) denseCoefficients(f);
    const double s = (t - t_old_) / h_old_, s1 = 1 - s;
    for (std::size_t i = 0; i < N; ++i) {
      const double p = r_[4][i] + s * (r_[5][i] + s1 * (r_[6][i] + s * r_[7][i]));
      y[i] = r_[0][i] + s * (r_[1][i] + s1 * (r_[2][i] + s * (r_[3][i] + s1 * p)));
    }
  }

  long evaluations() const { return evaluations_; }
  long rejected() const { return rejected_; }

 private:
  static constexpr double kSafety = 0.9, kLeast = 1.0 / 3, kMost = 6;

  // Stage s of a step of size h from y0 at t0: its slope k[s], from the stages before it. The
  // step's own stages and the interpolant's three extra ones are all made this way.
  template <class F>
  void stage(F&& f, int s, Vector* k, const Vector& y0, double t0, double h) {
    Vector y;
    for (std::size_t i = 0; i < N; ++i) {
      double sum = 0;
      for (int j = 0; j < s; ++j)
        if (kA[s][j] != 0) sum += kA[s][j] * k[j][i];
      y[i] = y0[i] + h * sum;
    }
    f(y, k[s], t0 + kC[s] * h);
    ++evaluations_;
  }

  // The stages 2…12 from k_[0] = f(y, t), and the eighth-order end point.
  template <class F>
  void stages(F&& f, double h, Vector& y_new) {
    for (int s = 1; s < 12; ++s) stage(f, s, k_.data(), y_, t_, h);
    for (std::size_t i = 0; i < N; ++i) {
      double sum = 0;
      for (int j = 0; j < 12; ++j) sum += kB[j] * k_[j][i];
      y_new[i] = y_[i] + h * sum;
    }
  }

  // Hairer's error of DOP853: the fifth-order estimate, damped where the third-order one is
  // large against it, err5² / √(err5² + 0.01 err3²) · h, each an RMS norm over components
  // scaled by tolerance · (1 + max(|y|, |y_new|)).
  double error(double h, const Vector& y_new) const {
    double e5 = 0, e3 = 0;
    for (std::size_t i = 0; i < N; ++i) {
      const double scale = tolerance_ * (1 + std::max(std::abs(y_[i]), std::abs(y_new[i])));
      double d5 = 0, d3 = 0;
      for (int j = 0; j < 12; ++j) {
        d5 += kE5[j] * k_[j][i];
        d3 += kE3[j] * k_[j][i];
      }
      e5 += (d5 / scale) * (d5 / scale);
      e3 += (d3 / scale) * (d3 / scale);
    }
    if (e5 == 0 && e3 == 0) return 0;
    return std::abs(h) * e5 / std::sqrt((e5 + 0.01 * e3) * static_cast<double>(N));
  }

  // The interpolant of the last step (Hairer's CONTD8 form): three more stages at 0.1, 0.2 and
  // 7/9 of it, then eight coefficient vectors.
  template <class F>
  void denseCoefficients(F&& f) {
    const double h = h_old_;
    // The last step's stages are still in k_ but k_[0] is already the next step's: its first
    // stage is kept aside, and its end's slope is k_end_.
    std::array<Vector, 16> k;
    k[0] = k_first_old_;
    for (int s = 1; s < 12; ++s) k[s] = k_[s];
    k[12] = k_end_;
    for (int s = 13; s < 16; ++s) stage(f, s, k.data(), y_old_, t_old_, h);
    for (std::size_t i = 0; i < N; ++i) {
      const double dy = y_[i] - y_old_[i];
      const double b = h * k[0][i] - dy;
      r_[0][i] = y_old_[i];
      r_[1][i] = dy;
      r_[2][i] = b;
      r_[3][i] = dy - h * k[12][i] - b;
      for (int row = 0; row < 4; ++row) {
        double sum = 0;
        for (int j = 0; j < 16; ++j) sum += kD[row][j] * k[j][i];
        r_[4 + row][i] = h * sum;
      }
    }
    dense_ready_ = true;
  }

  // The published coefficients (Hairer's dop853.f). Stage 13 (index 12) is the step's end; its
  // row of kA is the weights kB. Stages 14–16 serve only the interpolant.
  static constexpr std::array<double, 16> kC{0.0,
                                             0.526001519587677318785587544488e-01,
                                             0.789002279381515978178381316732e-01,
                                             0.118350341907227396726757197510,
                                             0.281649658092772603273242802490,
                                             0.333333333333333333333333333333,
                                             0.25,
                                             0.307692307692307692307692307692,
                                             0.651282051282051282051282051282,
                                             0.6,
                                             0.857142857142857142857142857142,
                                             1.0,
                                             1.0,
                                             0.1,
                                             0.2,
                                             0.777777777777777777777777777778};
  static constexpr std::array<std::array<double, 16>, 16> kA = [] {
    std::array<std::array<double, 16>, 16> a{};
    a[1][0] = 5.26001519587677318785587544488e-2;
    a[2][0] = 1.97250569845378994544595329183e-2;
    a[2][1] = 5.91751709536136983633785987549e-2;
    a[3][0] = 2.95875854768068491816892993775e-2;
    a[3][2] = 8.87627564304205475450678981324e-2;
    a[4][0] = 2.41365134159266685502369798665e-1;
    a[4][2] = -8.84549479328286085344864962717e-1;
    a[4][3] = 9.24834003261792003115737966543e-1;
    a[5][0] = 3.7037037037037037037037037037e-2;
    a[5][3] = 1.70828608729473871279604482173e-1;
    a[5][4] = 1.25467687566822425016691814123e-1;
    a[6][0] = 3.7109375e-2;
    a[6][3] = 1.70252211019544039314978060272e-1;
    a[6][4] = 6.02165389804559606850219397283e-2;
    a[6][5] = -1.7578125e-2;
    a[7][0] = 3.70920001185047927108779319836e-2;
    a[7][3] = 1.70383925712239993810214054705e-1;
    a[7][4] = 1.07262030446373284651809199168e-1;
    a[7][5] = -1.53194377486244017527936158236e-2;
    a[7][6] = 8.27378916381402288758473766002e-3;
    a[8][0] = 6.24110958716075717114429577812e-1;
    a[8][3] = -3.36089262944694129406857109825;
    a[8][4] = -8.68219346841726006818189891453e-1;
    a[8][5] = 2.75920996994467083049415600797e1;
    a[8][6] = 2.01540675504778934086186788979e1;
    a[8][7] = -4.34898841810699588477366255144e1;
    a[9][0] = 4.77662536438264365890433908527e-1;
    a[9][3] = -2.48811461997166764192642586468;
    a[9][4] = -5.90290826836842996371446475743e-1;
    a[9][5] = 2.12300514481811942347288949897e1;
    a[9][6] = 1.52792336328824235832596922938e1;
    a[9][7] = -3.32882109689848629194453265587e1;
    a[9][8] = -2.03312017085086261358222928593e-2;
    a[10][0] = -9.3714243008598732571704021658e-1;
    a[10][3] = 5.18637242884406370830023853209;
    a[10][4] = 1.09143734899672957818500254654;
    a[10][5] = -8.14978701074692612513997267357;
    a[10][6] = -1.85200656599969598641566180701e1;
    a[10][7] = 2.27394870993505042818970056734e1;
    a[10][8] = 2.49360555267965238987089396762;
    a[10][9] = -3.0467644718982195003823669022;
    a[11][0] = 2.27331014751653820792359768449;
    a[11][3] = -1.05344954667372501984066689879e1;
    a[11][4] = -2.00087205822486249909675718444;
    a[11][5] = -1.79589318631187989172765950534e1;
    a[11][6] = 2.79488845294199600508499808837e1;
    a[11][7] = -2.85899827713502369474065508674;
    a[11][8] = -8.87285693353062954433549289258;
    a[11][9] = 1.23605671757943030647266201528e1;
    a[11][10] = 6.43392746015763530355970484046e-1;
    a[12][0] = 5.42937341165687622380535766363e-2;
    a[12][5] = 4.45031289275240888144113950566;
    a[12][6] = 1.89151789931450038304281599044;
    a[12][7] = -5.8012039600105847814672114227;
    a[12][8] = 3.1116436695781989440891606237e-1;
    a[12][9] = -1.52160949662516078556178806805e-1;
    a[12][10] = 2.01365400804030348374776537501e-1;
    a[12][11] = 4.47106157277725905176885569043e-2;
    a[13][0] = 5.61675022830479523392909219681e-2;
    a[13][6] = 2.53500210216624811088794765333e-1;
    a[13][7] = -2.46239037470802489917441475441e-1;
    a[13][8] = -1.24191423263816360469010140626e-1;
    a[13][9] = 1.5329179827876569731206322685e-1;
    a[13][10] = 8.20105229563468988491666602057e-3;
    a[13][11] = 7.56789766054569976138603589584e-3;
    a[13][12] = -8.298e-3;
    a[14][0] = 3.18346481635021405060768473261e-2;
    a[14][5] = 2.83009096723667755288322961402e-2;
    a[14][6] = 5.35419883074385676223797384372e-2;
    a[14][7] = -5.49237485713909884646569340306e-2;
    a[14][10] = -1.08347328697249322858509316994e-4;
    a[14][11] = 3.82571090835658412954920192323e-4;
    a[14][12] = -3.40465008687404560802977114492e-4;
    a[14][13] = 1.41312443674632500278074618366e-1;
    a[15][0] = -4.28896301583791923408573538692e-1;
    a[15][5] = -4.69762141536116384314449447206;
    a[15][6] = 7.68342119606259904184240953878;
    a[15][7] = 4.06898981839711007970213554331;
    a[15][8] = 3.56727187455281109270669543021e-1;
    a[15][12] = -1.39902416515901462129418009734e-3;
    a[15][13] = 2.9475147891527723389556272149;
    a[15][14] = -9.15095847217987001081870187138;
    return a;
  }();
  static constexpr std::array<double, 12> kB = [] {
    std::array<double, 12> b{};
    for (int j = 0; j < 12; ++j) b[j] = kA[12][j];
    return b;
  }();
  // The fifth-order and third-order error estimators (differences of weights).
  static constexpr std::array<double, 12> kE5{0.1312004499419488073250102996e-1,
                                              0,
                                              0,
                                              0,
                                              0,
                                              -0.1225156446376204440720569753e1,
                                              -0.4957589496572501915214079952,
                                              0.1664377182454986536961530415e1,
                                              -0.3503288487499736816886487290,
                                              0.3341791187130174790297318841,
                                              0.8192320648511571246570742613e-1,
                                              -0.2235530786388629525884427845e-1};
  static constexpr std::array<double, 12> kE3 = [] {
    std::array<double, 12> e = kB;
    e[0] -= 0.244094488188976377952755905512;
    e[8] -= 0.733846688281611857341361741547;
    e[11] -= 0.220588235294117647058823529412e-1;
    return e;
  }();
  // The interpolant's four highest coefficients, over the sixteen stages.
  static constexpr std::array<std::array<double, 16>, 4> kD = [] {
    std::array<std::array<double, 16>, 4> d{};
    d[0] = {-0.84289382761090128651353491142e1,
            0,
            0,
            0,
            0,
            0.56671495351937776962531783590,
            -0.30689499459498916912797304727e1,
            0.23846676565120698287728149680e1,
            0.21170345824450282767155149946e1,
            -0.87139158377797299206789907490,
            0.22404374302607882758541771650e1,
            0.63157877876946881815570249290,
            -0.88990336451333310820698117400e-1,
            0.18148505520854727256656404962e2,
            -0.91946323924783554000451984436e1,
            -0.44360363875948939664310572000e1};
    d[1] = {0.10427508642579134603413151009e2,
            0,
            0,
            0,
            0,
            0.24228349177525818288430175319e3,
            0.16520045171727028198505394887e3,
            -0.37454675472269020279518312152e3,
            -0.22113666853125306036270938578e2,
            0.77334326684722638389603898808e1,
            -0.30674084731089398182061213626e2,
            -0.93321305264302278729567221706e1,
            0.15697238121770843886131091075e2,
            -0.31139403219565177677282850411e2,
            -0.93529243588444783865713862664e1,
            0.35816841486394083752465898540e2};
    d[2] = {0.19985053242002433820987653617e2,
            0,
            0,
            0,
            0,
            -0.38703730874935176555105901742e3,
            -0.18917813819516756882830838328e3,
            0.52780815920542364900561016686e3,
            -0.11573902539959630126141871134e2,
            0.68812326946963000169666922661e1,
            -0.10006050966910838403183860980e1,
            0.77771377980534432092869265740,
            -0.27782057523535084065932004339e1,
            -0.60196695231264120758267380846e2,
            0.84320405506677161018159903784e2,
            0.11992291136182789328035130030e2};
    d[3] = {-0.25693933462703749003312586129e2,
            0,
            0,
            0,
            0,
            -0.15418974869023643374053993627e3,
            -0.23152937917604549567536039109e3,
            0.35763911791061412378285349910e3,
            0.93405324183624310003907691704e2,
            -0.37458323136451633156875139351e2,
            0.10409964950896230045147246184e3,
            0.29840293426660503123344363579e2,
            -0.43533456590011143754432175058e2,
            0.96324553959188282948394950600e2,
            -0.39177261675615439165231486172e2,
            -0.14972683625798562581422125276e3};
    return d;
  }();

  double tolerance_;
  Vector y_{}, y_old_{};
  double t_ = 0, t_old_ = 0, h_ = 0, h_old_ = 0;
  std::array<Vector, 12> k_{};      // this step's stages; k_[0] is f at y_
  Vector k_end_{}, k_first_old_{};  // f at the last step's end and at its start
  std::array<Vector, 8> r_{};       // the interpolant's coefficients
  bool dense_ready_ = false;
  long evaluations_ = 0, accepted_ = 0, rejected_ = 0;
};

}  // namespace sim
