// SPDX-License-Identifier: GPL-2.0-or-later
/** @file dop853.h
 *  Hairer's DOP853: the explicit Runge–Kutta method of order 8 (Dormand–Prince
 *  coefficients as improved by Hairer), with its error estimator built from a 5th- and a
 *  3rd-order embedded formula and its 7th-order dense output (E. Hairer, S. P. Nørsett,
 *  G. Wanner, Solving Ordinary Differential Equations I, 2nd ed., §II.10; the coefficients
 *  as in Hairer's Fortran dop853.f and SciPy's solve_ivp).
 *
 *  Written here by hand: no library this project can use has it — Boost.Odeint's
 *  8th-order stepper is Fehlberg 7(8) (13 stages, no interpolant), GSL's rk8pd has no
 *  dense output, SUNDIALS 6.4's ARKODE has neither this pair nor its interpolant — and
 *  its per-step work over a small state (2–6 entries here) is most of a step's cost when
 *  the right-hand side is compiled straight-line code, so the state is a fixed-size array
 *  when the dimension is known at compile time (`Dim` > 0; 0: any dimension at run time). */
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

/// The stepper's functions inline into their caller, always: ode.cpp compiles the whole
/// integration twice, portable and for CPUs with FMA (numeric/ode.cpp, run_dop853), and a
/// function left out of line would be compiled once, without FMA.
#if defined(__GNUC__)
#define LAGRANGE_DOP853_INLINE __attribute__((always_inline)) inline
#define LAGRANGE_LAMBDA_INLINE __attribute__((always_inline))
#else
#define LAGRANGE_DOP853_INLINE inline
#define LAGRANGE_LAMBDA_INLINE
#endif

namespace lagrange {

namespace dop853_tableau {
constexpr double c[16] = {0.0, 0.526001519587677318785587544488e-01, 0.789002279381515978178381316732e-01,
                           0.118350341907227396726757197510, 0.281649658092772603273242802490,
                           0.333333333333333333333333333333, 0.25, 0.307692307692307692307692307692,
                           0.651282051282051282051282051282, 0.6, 0.857142857142857142857142857142, 1.0,
                           1.0, 0.1, 0.2, 0.777777777777777777777777777778};
/// a[s][j], j < s: stages 1…11 (the step), 12 (the 8th-order weights b), 13…15 (dense output)
constexpr double a[16][15] = {
    {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {5.26001519587677318785587544488e-2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {1.97250569845378994544595329183e-2, 5.91751709536136983633785987549e-2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0},
    {2.95875854768068491816892993775e-2, 0, 8.87627564304205475450678981324e-2, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0},
    {2.41365134159266685502369798665e-1, 0, -8.84549479328286085344864962717e-1,
     9.24834003261792003115737966543e-1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {3.7037037037037037037037037037e-2, 0, 0, 1.70828608729473871279604482173e-1,
     1.25467687566822425016691814123e-1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {3.7109375e-2, 0, 0, 1.70252211019544039314978060272e-1, 6.02165389804559606850219397283e-2,
     -1.7578125e-2, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {3.70920001185047927108779319836e-2, 0, 0, 1.70383925712239993810214054705e-1,
     1.07262030446373284651809199168e-1, -1.53194377486244017527936158236e-2,
     8.27378916381402288758473766002e-3, 0, 0, 0, 0, 0, 0, 0, 0},
    {6.24110958716075717114429577812e-1, 0, 0, -3.36089262944694129406857109825,
     -8.68219346841726006818189891453e-1, 2.75920996994467083049415600797e1,
     2.01540675504778934086186788979e1, -4.34898841810699588477366255144e1, 0, 0, 0, 0, 0, 0, 0},
    {4.77662536438264365890433908527e-1, 0, 0, -2.48811461997166764192642586468,
     -5.90290826836842996371446475743e-1, 2.12300514481811942347288949897e1,
     1.52792336328824235832596922938e1, -3.32882109689848629194453265587e1,
     -2.03312017085086261358222928593e-2, 0, 0, 0, 0, 0, 0},
    {-9.3714243008598732571704021658e-1, 0, 0, 5.18637242884406370830023853209,
     1.09143734899672957818500254654, -8.14978701074692612513997267357, -1.85200656599969598641566180701e1,
     2.27394870993505042818970056734e1, 2.49360555267965238987089396762, -3.0467644718982195003823669022, 0,
     0, 0, 0, 0},
    {2.27331014751653820792359768449, 0, 0, -1.05344954667372501984066689879e1,
     -2.00087205822486249909675718444, -1.79589318631187989172765950534e1,
     2.79488845294199600508499808837e1, -2.85899827713502369474065508674, -8.87285693353062954433549289258,
     1.23605671757943030647266201528e1, 6.43392746015763530355970484046e-1, 0, 0, 0, 0},
    {5.42937341165687622380535766363e-2, 0, 0, 0, 0, 4.45031289275240888144113950566,
     1.89151789931450038304281599044, -5.8012039600105847814672114227, 3.1116436695781989440891606237e-1,
     -1.52160949662516078556178806805e-1, 2.01365400804030348374776537501e-1,
     4.47106157277725905176885569043e-2, 0, 0, 0},
    {5.61675022830479523392909219681e-2, 0, 0, 0, 0, 0, 2.53500210216624811088794765333e-1,
     -2.46239037470802489917441475441e-1, -1.24191423263816360469010140626e-1,
     1.5329179827876569731206322685e-1, 8.20105229563468988491666602057e-3,
     7.56789766054569976138603589584e-3, -8.298e-3, 0, 0},
    {3.18346481635021405060768473261e-2, 0, 0, 0, 0, 2.83009096723667755288322961402e-2,
     5.35419883074385676223797384372e-2, -5.49237485713909884646569340306e-2, 0, 0,
     -1.08347328697249322858509316994e-4, 3.82571090835658412954920192323e-4,
     -3.40465008687404560802977114492e-4, 1.41312443674632500278074618366e-1, 0},
    {-4.28896301583791923408573538692e-1, 0, 0, 0, 0, -4.69762141536116384314449447206,
     7.68342119606259904184240953878, 4.06898981839711007970213554331, 3.56727187455281109270669543021e-1,
     0, 0, 0, -1.39902416515901462129418009734e-3, 2.9475147891527723389556272149,
     -9.15095847217987001081870187138},
};
/// 5th-order error estimator (weights of K[0…12], K[12] = f at the new point)
constexpr double e5[13] = {0.1312004499419488073250102996e-1, 0, 0, 0, 0,
                           -0.1225156446376204440720569753e+1, -0.4957589496572501915214079952,
                           0.1664377182454986536961530415e+1, -0.3503288487499736816886487290,
                           0.3341791187130174790297318841, 0.8192320648511571246570742613e-1,
                           -0.2235530786388629525884427845e-1, 0};
/// 3rd-order error estimator = b − bhat3 (the three subtracted weights)
constexpr double bhat3_0 = 0.244094488188976377952755905512,
                 bhat3_8 = 0.733846688281611857341361741547,
                 bhat3_11 = 0.220588235294117647058823529412e-1;
/// dense output: rows 3…6 of the interpolant, weights of K[0…15]
constexpr double d[4][16] = {
    {-0.84289382761090128651353491142e+1, 0, 0, 0, 0, 0.56671495351937776962531783590,
     -0.30689499459498916912797304727e+1, 0.23846676565120698287728149680e+1,
     0.21170345824450282767155149946e+1, -0.87139158377797299206789907490,
     0.22404374302607882758541771650e+1, 0.63157877876946881815570249290,
     -0.88990336451333310820698117400e-1, 0.18148505520854727256656404962e+2,
     -0.91946323924783554000451984436e+1, -0.44360363875948939664310572000e+1},
    {0.10427508642579134603413151009e+2, 0, 0, 0, 0, 0.24228349177525818288430175319e+3,
     0.16520045171727028198505394887e+3, -0.37454675472269020279518312152e+3,
     -0.22113666853125306036270938578e+2, 0.77334326684722638389603898808e+1,
     -0.30674084731089398182061213626e+2, -0.93321305264302278729567221706e+1,
     0.15697238121770843886131091075e+2, -0.31139403219565177677282850411e+2,
     -0.93529243588444783865713862664e+1, 0.35816841486394083752465898540e+2},
    {0.19985053242002433820987653617e+2, 0, 0, 0, 0, -0.38703730874935176555105901742e+3,
     -0.18917813819516756882830838328e+3, 0.52780815920542364900561016686e+3,
     -0.11573902539959630126141871134e+2, 0.68812326946963000169666922661e+1,
     -0.10006050966910838403183860980e+1, 0.77771377980534432092869265740,
     -0.27782057523535084065932004339e+1, -0.60196695231264120758267380846e+2,
     0.84320405506677161018159903784e+2, 0.11992291136182789328035130030e+2},
    {-0.25693933462703749003312586129e+2, 0, 0, 0, 0, -0.15418974869023643374053993627e+3,
     -0.23152937917604549567536039109e+3, 0.35763911791061412378285349910e+3,
     0.93405324183624310003907691704e+2, -0.37458323136451633156875139351e+2,
     0.10409964950896230045147246184e+3, 0.29840293426660503123344363579e+2,
     -0.43533456590011143754432175058e+2, 0.96324553959188282948394950600e+2,
     -0.39177261675615439165231486172e+2, -0.14972683625798562581422125276e+3},
};
constexpr int stages = 12;      ///< stages per step (K[0] … K[11]); K[12] is f at the new point
constexpr int all_stages = 16;  ///< with the three that only the dense output needs
} // namespace dop853_tableau

/// One DOP853 integration: the current point, the last accepted step and its dense output.
/// `F` is any callable f(t, x, dxdt) with x and dxdt arrays of `dimension()` doubles.
/// `Fused`: the stages' sums, the new state, the error norm's sums and the interpolant's
/// Horner steps as fused multiply-adds (std::fma; only where the CPU has them, see
/// run_dop853 in numeric/ode.cpp); else a multiplication and an addition, each rounded.
template <int Dim, bool Fused = false>
class dop853_stepper {
public:
    /// Relative tolerance `tolerance` and absolute tolerance `tolerance` × `absolute_scale`
    /// per step (Hairer's error norm: the root mean square of
    /// error_i / (tolerance (absolute_scale + max(|x_i|, |x_new_i|)))).
    dop853_stepper(std::size_t dimension, double tolerance, double absolute_scale = 1)
        : tolerance_(tolerance), absolute_scale_(absolute_scale)
    {
        if constexpr (Dim == 0) {
            n_ = dimension;
            k_.resize(dop853_tableau::all_stages * n_);
            x_.resize(n_), x_old_.resize(n_), trial_.resize(n_), stage_.resize(n_), dense_.resize(7 * n_);
        }
    }

    std::size_t dimension() const { return n(); }
    double time() const { return t_; }
    const double* state() const { return x_.data(); }
    /// The step size the controller proposes next (for a restart with start()'s `first_step`).
    double step_size() const { return h_; }

    /// Starts at (t0, x0) with f there and an initial step after Hairer's `hinit`
    /// (two evaluations), or `first_step` when it is positive.
    template <class F>
    LAGRANGE_DOP853_INLINE void start(F& f, double t0, const double* x0, double t_end, double first_step = 0)
    {
        t_ = t0;
        t_low_ = 0;
        std::copy(x0, x0 + n(), x_.begin());
        f(t_, x_.data(), row(0));
        stale_ = false; // K[0] holds f at the current point
        h_ = first_step > 0 ? first_step : initial_step(f, t_end);
    }

    /// One trial step of size h from the current point: the stages, the new state and f
    /// there; returns the error norm (≤ 1: acceptable). Nothing is accepted.
    template <class F>
    LAGRANGE_DOP853_INLINE double attempt(F& f, double h)
    {
        const std::size_t m = n();
        if (stale_) { // the previous step's f at its end is this step's K[0]
            std::copy(row(12), row(12) + m, row(0));
            stale_ = false;
        }
        stages(f, h, std::make_integer_sequence<int, dop853_tableau::stages>());
        f(t_ + h, trial_.data(), row(12));
        double err5 = 0, err3 = 0;
        for (std::size_t i = 0; i < m; ++i) {
            double scale = tolerance_ * (absolute_scale_ + std::max(std::abs(x_[i]), std::abs(trial_[i])));
            double e5 = weighted<error5_weights>(i, std::make_integer_sequence<int, 13>()) / scale;
            double e3 = weighted<error3_weights>(i, std::make_integer_sequence<int, 12>()) / scale;
            err5 = madd(e5, e5, err5);
            err3 = madd(e3, e3, err3);
        }
        if (err5 == 0 && err3 == 0)
            return 0;
        return std::abs(h) * err5 / std::sqrt((err5 + 0.01 * err3) * static_cast<double>(m));
    }

    /// Accepts the last attempt: the new state becomes the current point.
    LAGRANGE_DOP853_INLINE void accept(double h)
    {
        std::swap(x_old_, x_);
        std::swap(x_, trial_);
        t_old_ = t_;
        t_old_low_ = t_low_;
        // t + h with its rounding error kept (Knuth's two-sum, then renormalized): over
        // thousands of steps the rounded sum alone drifts by up to √steps · ulp(t)/2, a phase
        // error of ω·δt in the motion, which on the linearized double pendulum at 1e-12 was
        // a third of the error.
        double sum = t_ + h, h_part = sum - t_, t_part = sum - h_part;
        double low = t_low_ + ((t_ - t_part) + (h - h_part));
        t_ = sum + low;
        t_low_ = low - (t_ - sum);
        h_last_ = h;
        stale_ = true;
        dense_ready_ = false;
    }

    /// One accepted step towards t_end (never past it). The next step size: PI control
    /// after an accepted step (grow ≤ 10×, none right after a rejection), 0.9 err^(−1/8)
    /// (shrink ≥ 0.2×) after a rejected one. Returns false, with nothing changed, when the
    /// step size has fallen below ten units in the last place of t (it collapsed).
    template <class F>
    LAGRANGE_DOP853_INLINE bool step(F& f, double t_end)
    {
        bool rejected = false;
        for (;;) {
            double min_step = 10 * std::abs(std::nextafter(t_, t_end) - t_);
            if (!(h_ >= min_step))
                return false;
            double remaining = (t_end - t_) - t_low_;
            double h = std::min(h_, remaining);
            if (h >= remaining || remaining - h < min_step)
                h = remaining;
            double error = attempt(f, h);
            if (error < 1) {
                // PI control (Gustafsson): 0.9 err^(−0.7/8) err_previous^(0.4/8) rather than
                // SciPy's 0.9 err^(−1/8): fewer evaluations for the same error, with fewer
                // rejected steps.
                double log_error = std::log(std::max(error, 1e-4));
                double factor =
                    std::min(10.0, 0.9 * std::exp((0.4 * log_previous_error_ - 0.7 * log_error) / 8));
                log_previous_error_ = log_error;
                if (rejected)
                    factor = std::min(1.0, factor);
                h_ = h * factor;
                accept(h);
                if (t_end - t_ < min_step) {
                    t_ = t_end;
                    t_low_ = 0;
                }
                return true;
            }
            // also a non-finite error (a state that ran away): shrink until it collapses
            h_ = h * (std::isfinite(error) ? std::max(0.2, 0.9 / eighth_root(error)) : 0.2);
            rejected = true;
        }
    }

    /// The 7th-order dense output at t in the last accepted step [t_old, t]; the first call
    /// after a step evaluates the three extra stages it needs.
    template <class F>
    LAGRANGE_DOP853_INLINE void interpolate(F& f, double t, double* out)
    {
        const std::size_t m = n();
        if (!dense_ready_)
            prepare_dense(f);
        double s = ((t - t_old_) - t_old_low_) / h_last_, r = 1 - s;
        const double* q = dense_.data();
        for (std::size_t i = 0; i < m; ++i) {
            double y = q[6 * m + i];
            y = madd(y, s, q[5 * m + i]) * r;
            y = (y + q[4 * m + i]) * s;
            y = (y + q[3 * m + i]) * r;
            y = (y + q[2 * m + i]) * s;
            y = (y + q[1 * m + i]) * r;
            y = (y + q[0 * m + i]) * s;
            out[i] = x_old_[i] + y;
        }
    }

private:
    using storage = std::conditional_t<Dim == 0, std::vector<double>, std::array<double, Dim>>;
    using stage_storage = std::conditional_t<Dim == 0, std::vector<double>,
                                             std::array<double, dop853_tableau::all_stages * Dim>>;
    using dense_storage = std::conditional_t<Dim == 0, std::vector<double>, std::array<double, 7 * Dim>>;

    LAGRANGE_DOP853_INLINE std::size_t n() const
    {
        if constexpr (Dim == 0)
            return n_;
        else
            return Dim;
    }
    LAGRANGE_DOP853_INLINE double* row(int s) { return k_.data() + static_cast<std::size_t>(s) * n(); }
    /// The weight tables that combine the stages, as types (so that a weight is a constant).
    template <int S>
    struct stage_weights { ///< row S of a (S = 12: b)
        static constexpr double w(int j) { return dop853_tableau::a[S][j]; }
    };
    struct error5_weights {
        static constexpr double w(int j) { return dop853_tableau::e5[j]; }
    };
    struct error3_weights { ///< b − b̂₃
        static constexpr double w(int j)
        {
            using namespace dop853_tableau;
            return a[12][j] - (j == 0 ? bhat3_0 : j == 8 ? bhat3_8 : j == 11 ? bhat3_11 : 0.0);
        }
    };
    template <int R>
    struct dense_weights { ///< row R of d
        static constexpr double w(int j) { return dop853_tableau::d[R][j]; }
    };

    /// a·b + c, fused or not (`Fused`).
    LAGRANGE_DOP853_INLINE static double madd(double a, double b, double c)
    {
        if constexpr (Fused)
            return std::fma(a, b, c);
        else
            return a * b + c;
    }

    /// x^(1/8) by three square roots (each correctly rounded; far cheaper than pow).
    LAGRANGE_DOP853_INLINE static double eighth_root(double x) { return std::sqrt(std::sqrt(std::sqrt(x))); }

    /// Σ_j W::w(j) K[j][i] over the nonzero weights only: the tableau is sparse, and its zeros
    /// are dropped at compile time (the compiler may not drop them itself: 0·K is not 0 for K = ∞).
    template <class W, int... J>
    LAGRANGE_DOP853_INLINE double weighted(std::size_t i, std::integer_sequence<int, J...>) const
    {
        double sum = 0;
        (add_term<W, J>(sum, i), ...);
        return sum;
    }

    template <class W, int J>
    LAGRANGE_DOP853_INLINE void add_term(double& sum, std::size_t i) const
    {
        if constexpr (W::w(J) != 0)
            sum = madd(W::w(J), k_[static_cast<std::size_t>(J) * n() + i], sum);
    }

    /// Stages 1 … 11 (f at each) and, at s = 12, the new state (row 12 of a holds b).
    template <class F, int... S>
    LAGRANGE_DOP853_INLINE void stages(F& f, double h, std::integer_sequence<int, S...>)
    {
        (stage<S + 1>(f, h), ...);
    }

    template <int S, class F>
    LAGRANGE_DOP853_INLINE void stage(F& f, double h)
    {
        const std::size_t m = n();
        double* y = S == dop853_tableau::stages ? trial_.data() : stage_.data();
        for (std::size_t i = 0; i < m; ++i)
            y[i] = madd(h, weighted<stage_weights<S>>(i, std::make_integer_sequence<int, S>()), x_[i]);
        if constexpr (S < dop853_tableau::stages)
            f(t_ + dop853_tableau::c[S] * h, y, row(S));
    }

    template <class F>
    LAGRANGE_DOP853_INLINE void prepare_dense(F& f)
    {
        const std::size_t m = n();
        const double h = h_last_;
        extra_stage<13>(f, h);
        extra_stage<14>(f, h);
        extra_stage<15>(f, h);
        constexpr auto all = std::make_integer_sequence<int, dop853_tableau::all_stages>();
        double* q = dense_.data();
        for (std::size_t i = 0; i < m; ++i) {
            double change = x_[i] - x_old_[i], f_old = k_[i], f_new = k_[12 * m + i];
            q[i] = change;
            q[m + i] = h * f_old - change;
            q[2 * m + i] = 2 * change - h * (f_new + f_old);
            q[3 * m + i] = h * weighted<dense_weights<0>>(i, all);
            q[4 * m + i] = h * weighted<dense_weights<1>>(i, all);
            q[5 * m + i] = h * weighted<dense_weights<2>>(i, all);
            q[6 * m + i] = h * weighted<dense_weights<3>>(i, all);
        }
        dense_ready_ = true;
    }

    /// Stage S ≥ 13 of the last accepted step (only the dense output needs it).
    template <int S, class F>
    LAGRANGE_DOP853_INLINE void extra_stage(F& f, double h)
    {
        for (std::size_t i = 0; i < n(); ++i)
            stage_[i] = madd(h, weighted<stage_weights<S>>(i, std::make_integer_sequence<int, S>()), x_old_[i]);
        f(t_old_ + dop853_tableau::c[S] * h, stage_.data(), row(S));
    }

    /// Hairer's starting step (hinit): h0 from ‖x‖/‖f‖, h1 from a second derivative
    /// estimate, min(100 h0, h1); RMS norms scaled by the tolerance.
    template <class F>
    LAGRANGE_DOP853_INLINE double initial_step(F& f, double t_end)
    {
        const std::size_t m = n();
        double d0 = 0, d1 = 0;
        for (std::size_t i = 0; i < m; ++i) {
            double scale = tolerance_ * (absolute_scale_ + std::abs(x_[i]));
            d0 += (x_[i] / scale) * (x_[i] / scale);
            d1 += (k_[i] / scale) * (k_[i] / scale);
        }
        d0 = std::sqrt(d0 / static_cast<double>(m));
        d1 = std::sqrt(d1 / static_cast<double>(m));
        double h0 = d0 < 1e-5 || d1 < 1e-5 ? 1e-6 : 0.01 * d0 / d1;
        h0 = std::min(h0, t_end - t_);
        for (std::size_t i = 0; i < m; ++i)
            stage_[i] = x_[i] + h0 * k_[i];
        f(t_ + h0, stage_.data(), row(1));
        double d2 = 0;
        for (std::size_t i = 0; i < m; ++i) {
            double scale = tolerance_ * (absolute_scale_ + std::abs(x_[i]));
            double second = (k_[m + i] - k_[i]) / scale;
            d2 += second * second;
        }
        d2 = std::sqrt(d2 / static_cast<double>(m)) / h0;
        double h1 = std::max(d1, d2) <= 1e-15 ? std::max(1e-6, h0 * 1e-3)
                                               : std::pow(0.01 / std::max(d1, d2), 1.0 / 8);
        return std::min({100 * h0, h1, t_end - t_});
    }

    std::size_t n_ = Dim;
    double tolerance_;
    double absolute_scale_;
    double t_ = 0, t_old_ = 0, h_ = 0, h_last_ = 0;
    double t_low_ = 0, t_old_low_ = 0; ///< the time is t_ + t_low_ (and t_old_ + t_old_low_)
    bool stale_ = false, dense_ready_ = false;
    double log_previous_error_ = 0; ///< log of the last accepted step's error norm (≥ 1e-4)
    stage_storage k_{};
    storage x_{}, x_old_{}, trial_{}, stage_{};
    dense_storage dense_{};
};

} // namespace lagrange
