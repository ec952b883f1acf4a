// SPDX-License-Identifier: GPL-2.0-or-later
/** @file hand_dop853.h
 *  The hand-written peer of the engine's integration: Hairer's DOP853 written out as a
 *  programmer would for one small fixed-size problem (E. Hairer, S. P. Nørsett, G. Wanner,
 *  Solving Ordinary Differential Equations I, 2nd ed., §II.10; the coefficients under the
 *  names of Hairer's dop853.f), with its right-hand side a template argument that inlines,
 *  and the state in fixed-size arrays. It includes nothing of the engine: it is the
 *  independent loop that bench/ensemble_limit.sh, bench/poincare.sh and
 *  bench/simulate_limit.sh hold the engine against.
 *
 *  Written by hand on purpose (the peer must not share the engine's code). Its step control
 *  is dop853.f's error norm (the 5th- and 3rd-order estimates combined, atol = rtol = tol)
 *  with the parameters where the engine departs from dop853.f's defaults set to the engine's,
 *  so that both sides take the same steps and a difference in time is a difference in
 *  overhead: SciPy's RMS-scaled starting step (dop853.f's HINIT sums without dividing by n),
 *  growth ≤ 10× and shrinking ≥ 0.2× per step (dop853.f: 6× and 1/3), and the PI control
 *  h·0.9·err^(−0.7/8)·err_old^(0.4/8) (dop853.f's default is the plain 0.9·err^(−1/8)). */
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace hand {

namespace dop {
constexpr double c2 = 0.526001519587677318785587544488e-01, c3 = 0.789002279381515978178381316732e-01,
                 c4 = 0.118350341907227396726757197510e+00, c5 = 0.281649658092772603273242802490e+00,
                 c6 = 0.333333333333333333333333333333e+00, c7 = 0.25e+00, c8 = 0.307692307692307692307692307692e+00,
                 c9 = 0.651282051282051282051282051282e+00, c10 = 0.6e+00, c11 = 0.857142857142857142857142857142e+00,
                 c14 = 0.1e+00, c15 = 0.2e+00, c16 = 0.777777777777777777777777777778e+00;
constexpr double b1 = 5.42937341165687622380535766363e-2, b6 = 4.45031289275240888144113950566e0,
                 b7 = 1.89151789931450038304281599044e0, b8 = -5.8012039600105847814672114227e0,
                 b9 = 3.1116436695781989440891606237e-1, b10 = -1.52160949662516078556178806805e-1,
                 b11 = 2.01365400804030348374776537501e-1, b12 = 4.47106157277725905176885569043e-2;
constexpr double bhh1 = 0.244094488188976377952755905512e+00, bhh2 = 0.733846688281611857341361741547e+00,
                 bhh3 = 0.220588235294117647058823529412e-01;
constexpr double er1 = 0.1312004499419488073250102996e-01, er6 = -0.1225156446376204440720569753e+01,
                 er7 = -0.4957589496572501915214079952e+00, er8 = 0.1664377182454986536961530415e+01,
                 er9 = -0.3503288487499736816886487290e+00, er10 = 0.3341791187130174790297318841e+00,
                 er11 = 0.8192320648511571246570742613e-01, er12 = -0.2235530786388629525884427845e-01;
constexpr double a21 = 5.26001519587677318785587544488e-2, a31 = 1.97250569845378994544595329183e-2,
                 a32 = 5.91751709536136983633785987549e-2, a41 = 2.95875854768068491816892993775e-2,
                 a43 = 8.87627564304205475450678981324e-2, a51 = 2.41365134159266685502369798665e-1,
                 a53 = -8.84549479328286085344864962717e-1, a54 = 9.24834003261792003115737966543e-1,
                 a61 = 3.7037037037037037037037037037e-2, a64 = 1.70828608729473871279604482173e-1,
                 a65 = 1.25467687566822425016691814123e-1, a71 = 3.7109375e-2,
                 a74 = 1.70252211019544039314978060272e-1, a75 = 6.02165389804559606850219397283e-2,
                 a76 = -1.7578125e-2;
constexpr double a81 = 3.70920001185047927108779319836e-2, a84 = 1.70383925712239993810214054705e-1,
                 a85 = 1.07262030446373284651809199168e-1, a86 = -1.53194377486244017527936158236e-2,
                 a87 = 8.27378916381402288758473766002e-3, a91 = 6.24110958716075717114429577812e-1,
                 a94 = -3.36089262944694129406857109825e0, a95 = -8.68219346841726006818189891453e-1,
                 a96 = 2.75920996994467083049415600797e1, a97 = 2.01540675504778934086186788979e1,
                 a98 = -4.34898841810699588477366255144e1, a101 = 4.77662536438264365890433908527e-1,
                 a104 = -2.48811461997166764192642586468e0, a105 = -5.90290826836842996371446475743e-1,
                 a106 = 2.12300514481811942347288949897e1, a107 = 1.52792336328824235832596922938e1,
                 a108 = -3.32882109689848629194453265587e1, a109 = -2.03312017085086261358222928593e-2;
constexpr double a111 = -9.3714243008598732571704021658e-1, a114 = 5.18637242884406370830023853209e0,
                 a115 = 1.09143734899672957818500254654e0, a116 = -8.14978701074692612513997267357e0,
                 a117 = -1.85200656599969598641566180701e1, a118 = 2.27394870993505042818970056734e1,
                 a119 = 2.49360555267965238987089396762e0, a1110 = -3.0467644718982195003823669022e0,
                 a121 = 2.27331014751653820792359768449e0, a124 = -1.05344954667372501984066689879e1,
                 a125 = -2.00087205822486249909675718444e0, a126 = -1.79589318631187989172765950534e1,
                 a127 = 2.79488845294199600508499808837e1, a128 = -2.85899827713502369474065508674e0,
                 a129 = -8.87285693353062954433549289258e0, a1210 = 1.23605671757943030647266201528e1,
                 a1211 = 6.43392746015763530355970484046e-1;
constexpr double a141 = 5.61675022830479523392909219681e-2, a147 = 2.53500210216624811088794765333e-1,
                 a148 = -2.46239037470802489917441475441e-1, a149 = -1.24191423263816360469010140626e-1,
                 a1410 = 1.5329179827876569731206322685e-1, a1411 = 8.20105229563468988491666602057e-3,
                 a1412 = 7.56789766054569976138603589584e-3, a1413 = -8.298e-3;
constexpr double a151 = 3.18346481635021405060768473261e-2, a156 = 2.83009096723667755288322961402e-2,
                 a157 = 5.35419883074385676223797384372e-2, a158 = -5.49237485713909884646569340306e-2,
                 a1511 = -1.08347328697249322858509316994e-4, a1512 = 3.82571090835658412954920192323e-4,
                 a1513 = -3.40465008687404560802977114492e-4, a1514 = 1.41312443674632500278074618366e-1;
constexpr double a161 = -4.28896301583791923408573538692e-1, a166 = -4.69762141536116384314449447206e0,
                 a167 = 7.68342119606259904184240953878e0, a168 = 4.06898981839711007970213554331e0,
                 a169 = 3.56727187455281109270669543021e-1, a1613 = -1.39902416515901462129418009734e-3,
                 a1614 = 2.9475147891527723389556272149e0, a1615 = -9.15095847217987001081870187138e0;
constexpr double d41 = -0.84289382761090128651353491142e+01, d46 = 0.56671495351937776962531783590e+00,
                 d47 = -0.30689499459498916912797304727e+01, d48 = 0.23846676565120698287728149680e+01,
                 d49 = 0.21170345824450282767155149946e+01, d410 = -0.87139158377797299206789907490e+00,
                 d411 = 0.22404374302607882758541771650e+01, d412 = 0.63157877876946881815570249290e+00,
                 d413 = -0.88990336451333310820698117400e-01, d414 = 0.18148505520854727256656404962e+02,
                 d415 = -0.91946323924783554000451984436e+01, d416 = -0.44360363875948939664310572000e+01;
constexpr double d51 = 0.10427508642579134603413151009e+02, d56 = 0.24228349177525818288430175319e+03,
                 d57 = 0.16520045171727028198505394887e+03, d58 = -0.37454675472269020279518312152e+03,
                 d59 = -0.22113666853125306036270938578e+02, d510 = 0.77334326684722638389603898808e+01,
                 d511 = -0.30674084731089398182061213626e+02, d512 = -0.93321305264302278729567221706e+01,
                 d513 = 0.15697238121770843886131091075e+02, d514 = -0.31139403219565177677282850411e+02,
                 d515 = -0.93529243588444783865713862664e+01, d516 = 0.35816841486394083752465898540e+02;
constexpr double d61 = 0.19985053242002433820987653617e+02, d66 = -0.38703730874935176555105901742e+03,
                 d67 = -0.18917813819516756882830838328e+03, d68 = 0.52780815920542364900561016686e+03,
                 d69 = -0.11573902539959630126141871134e+02, d610 = 0.68812326946963000169666922661e+01,
                 d611 = -0.10006050966910838403183860980e+01, d612 = 0.77771377980534432092869265740e+00,
                 d613 = -0.27782057523535084065932004339e+01, d614 = -0.60196695231264120758267380846e+02,
                 d615 = 0.84320405506677161018159903784e+02, d616 = 0.11992291136182789328035130030e+02;
constexpr double d71 = -0.25693933462703749003312586129e+02, d76 = -0.15418974869023643374053993627e+03,
                 d77 = -0.23152937917604549567536039109e+03, d78 = 0.35763911791061412378285349910e+03,
                 d79 = 0.93405324183624310003907691704e+02, d710 = -0.37458323136451633156875139351e+02,
                 d711 = 0.10409964950896230045147246184e+03, d712 = 0.29840293426660503123344363579e+02,
                 d713 = -0.43533456590011143754432175058e+02, d714 = 0.96324553959188282948394950600e+02,
                 d715 = -0.39177261675615439165231486172e+02, d716 = -0.14972683625798562581422125276e+03;
} // namespace dop

/// DOP853 for N equations; F is f(t, y, dy) with arrays of N doubles.
template <int N, class F>
class dop853 {
public:
    dop853(F f, double tolerance) : f_(f), tol_(tolerance) {}

    double t() const { return t_; }
    const double* y() const { return y_; }
    long steps() const { return steps_; }

    /// Starts at (t0, y0) with the starting step of SciPy's select_initial_step (RMS norms).
    void start(double t0, const double* y0, double t_end)
    {
        t_ = t0;
        std::copy(y0, y0 + N, y_);
        f_(t_, y_, k1_);
        double d0 = 0, d1 = 0;
        for (int i = 0; i < N; ++i) {
            double sk = tol_ * (1 + std::abs(y_[i]));
            d0 += (y_[i] / sk) * (y_[i] / sk);
            d1 += (k1_[i] / sk) * (k1_[i] / sk);
        }
        d0 = std::sqrt(d0 / N);
        d1 = std::sqrt(d1 / N);
        double h0 = d0 < 1e-5 || d1 < 1e-5 ? 1e-6 : 0.01 * d0 / d1;
        h0 = std::min(h0, t_end - t_);
        double y1[N], f1[N];
        for (int i = 0; i < N; ++i)
            y1[i] = y_[i] + h0 * k1_[i];
        f_(t_ + h0, y1, f1);
        double d2 = 0;
        for (int i = 0; i < N; ++i) {
            double sk = tol_ * (1 + std::abs(y_[i]));
            d2 += ((f1[i] - k1_[i]) / sk) * ((f1[i] - k1_[i]) / sk);
        }
        d2 = std::sqrt(d2 / N) / h0;
        double d12 = std::max(d1, d2);
        double h1 = d12 <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / d12, 1.0 / 8);
        h_ = std::min({100 * h0, h1, t_end - t_});
        facold_ = 1;
    }

    /// One accepted step, never past t_end; false when the step size collapsed.
    bool step(double t_end)
    {
        using namespace dop;
        bool reject = false;
        for (;;) {
            const double hmin = 10 * std::abs(std::nextafter(t_, t_end) - t_);
            if (!(h_ >= hmin))
                return false;
            const double remaining = t_end - t_;
            double h = std::min(h_, remaining);
            if (h >= remaining || remaining - h < hmin)
                h = remaining;
            double yy[N];
            for (int i = 0; i < N; ++i)
                yy[i] = y_[i] + h * a21 * k1_[i];
            f_(t_ + c2 * h, yy, k2_);
            for (int i = 0; i < N; ++i)
                yy[i] = y_[i] + h * (a31 * k1_[i] + a32 * k2_[i]);
            f_(t_ + c3 * h, yy, k3_);
            for (int i = 0; i < N; ++i)
                yy[i] = y_[i] + h * (a41 * k1_[i] + a43 * k3_[i]);
            f_(t_ + c4 * h, yy, k4_);
            for (int i = 0; i < N; ++i)
                yy[i] = y_[i] + h * (a51 * k1_[i] + a53 * k3_[i] + a54 * k4_[i]);
            f_(t_ + c5 * h, yy, k5_);
            for (int i = 0; i < N; ++i)
                yy[i] = y_[i] + h * (a61 * k1_[i] + a64 * k4_[i] + a65 * k5_[i]);
            f_(t_ + c6 * h, yy, k6_);
            for (int i = 0; i < N; ++i)
                yy[i] = y_[i] + h * (a71 * k1_[i] + a74 * k4_[i] + a75 * k5_[i] + a76 * k6_[i]);
            f_(t_ + c7 * h, yy, k7_);
            for (int i = 0; i < N; ++i)
                yy[i] = y_[i] + h * (a81 * k1_[i] + a84 * k4_[i] + a85 * k5_[i] + a86 * k6_[i] + a87 * k7_[i]);
            f_(t_ + c8 * h, yy, k8_);
            for (int i = 0; i < N; ++i)
                yy[i] = y_[i] + h * (a91 * k1_[i] + a94 * k4_[i] + a95 * k5_[i] + a96 * k6_[i] + a97 * k7_[i] +
                                     a98 * k8_[i]);
            f_(t_ + c9 * h, yy, k9_);
            for (int i = 0; i < N; ++i)
                yy[i] = y_[i] + h * (a101 * k1_[i] + a104 * k4_[i] + a105 * k5_[i] + a106 * k6_[i] +
                                     a107 * k7_[i] + a108 * k8_[i] + a109 * k9_[i]);
            f_(t_ + c10 * h, yy, k10_);
            for (int i = 0; i < N; ++i)
                yy[i] = y_[i] + h * (a111 * k1_[i] + a114 * k4_[i] + a115 * k5_[i] + a116 * k6_[i] +
                                     a117 * k7_[i] + a118 * k8_[i] + a119 * k9_[i] + a1110 * k10_[i]);
            f_(t_ + c11 * h, yy, k11_);
            const double xph = t_ + h;
            for (int i = 0; i < N; ++i)
                yy[i] = y_[i] + h * (a121 * k1_[i] + a124 * k4_[i] + a125 * k5_[i] + a126 * k6_[i] +
                                     a127 * k7_[i] + a128 * k8_[i] + a129 * k9_[i] + a1210 * k10_[i] +
                                     a1211 * k11_[i]);
            f_(xph, yy, k12_);
            double err = 0, err2 = 0;
            for (int i = 0; i < N; ++i) {
                double b = b1 * k1_[i] + b6 * k6_[i] + b7 * k7_[i] + b8 * k8_[i] + b9 * k9_[i] + b10 * k10_[i] +
                           b11 * k11_[i] + b12 * k12_[i];
                y_new_[i] = y_[i] + h * b;
                double sk = tol_ * (1 + std::max(std::abs(y_[i]), std::abs(y_new_[i])));
                double e2 = (b - bhh1 * k1_[i] - bhh2 * k9_[i] - bhh3 * k12_[i]) / sk;
                double e = (er1 * k1_[i] + er6 * k6_[i] + er7 * k7_[i] + er8 * k8_[i] + er9 * k9_[i] +
                            er10 * k10_[i] + er11 * k11_[i] + er12 * k12_[i]) / sk;
                err += e * e;
                err2 += e2 * e2;
            }
            f_(xph, y_new_, k13_);
            double deno = err + 0.01 * err2;
            if (deno <= 0)
                deno = 1;
            err = std::abs(h) * err * std::sqrt(1 / (N * deno));
            if (err < 1) { // accepted
                double e = std::max(err, 1e-4);
                double fac = std::min(10.0, 0.9 * std::pow(e, -0.7 / 8) * std::pow(facold_, 0.4 / 8));
                if (reject)
                    fac = std::min(1.0, fac);
                facold_ = e;
                h_ = h * fac;
                std::copy(y_, y_ + N, y_old_);
                std::copy(y_new_, y_new_ + N, y_);
                std::copy(k1_, k1_ + N, k_old_);
                std::copy(k13_, k13_ + N, k1_);
                t_old_ = t_;
                t_ = xph;
                if (t_end - t_ < hmin)
                    t_ = t_end;
                h_old_ = h;
                dense_ = false;
                ++steps_;
                return true;
            }
            h_ = h * (std::isfinite(err) ? std::max(0.2, 0.9 / std::pow(err, 1.0 / 8)) : 0.2);
            reject = true;
        }
    }

    /// The 7th-order dense output at t in the last step (dop853.f's CONTD8); its first call
    /// after a step evaluates the three extra stages.
    void dense(double t, double* out)
    {
        if (!dense_)
            prepare_dense();
        const double s = (t - t_old_) / h_old_, s1 = 1 - s;
        for (int i = 0; i < N; ++i) {
            double conpar = r5_[i] + s * (r6_[i] + s1 * (r7_[i] + s * r8_[i]));
            out[i] = r1_[i] + s * (r2_[i] + s1 * (r3_[i] + s * (r4_[i] + s1 * conpar)));
        }
    }

private:
    void prepare_dense()
    {
        using namespace dop;
        const double h = h_old_;
        // k_old_ is K1 of the last step and k1_ its K13 (f at the new point); k2_…k12_ its stages.
        double yy[N];
        for (int i = 0; i < N; ++i)
            yy[i] = y_old_[i] + h * (a141 * k_old_[i] + a147 * k7_[i] + a148 * k8_[i] + a149 * k9_[i] +
                                     a1410 * k10_[i] + a1411 * k11_[i] + a1412 * k12_[i] + a1413 * k1_[i]);
        f_(t_old_ + c14 * h, yy, k14_);
        for (int i = 0; i < N; ++i)
            yy[i] = y_old_[i] + h * (a151 * k_old_[i] + a156 * k6_[i] + a157 * k7_[i] + a158 * k8_[i] +
                                     a1511 * k11_[i] + a1512 * k12_[i] + a1513 * k1_[i] + a1514 * k14_[i]);
        f_(t_old_ + c15 * h, yy, k15_);
        for (int i = 0; i < N; ++i)
            yy[i] = y_old_[i] + h * (a161 * k_old_[i] + a166 * k6_[i] + a167 * k7_[i] + a168 * k8_[i] +
                                     a169 * k9_[i] + a1613 * k1_[i] + a1614 * k14_[i] + a1615 * k15_[i]);
        f_(t_old_ + c16 * h, yy, k16_);
        for (int i = 0; i < N; ++i) {
            const double k1 = k_old_[i], k13 = k1_[i];
            r1_[i] = y_old_[i];
            const double ydiff = y_[i] - y_old_[i];
            r2_[i] = ydiff;
            const double bspl = h * k1 - ydiff;
            r3_[i] = bspl;
            r4_[i] = ydiff - h * k13 - bspl;
            r5_[i] = h * (d41 * k1 + d46 * k6_[i] + d47 * k7_[i] + d48 * k8_[i] + d49 * k9_[i] + d410 * k10_[i] +
                          d411 * k11_[i] + d412 * k12_[i] + d413 * k13 + d414 * k14_[i] + d415 * k15_[i] +
                          d416 * k16_[i]);
            r6_[i] = h * (d51 * k1 + d56 * k6_[i] + d57 * k7_[i] + d58 * k8_[i] + d59 * k9_[i] + d510 * k10_[i] +
                          d511 * k11_[i] + d512 * k12_[i] + d513 * k13 + d514 * k14_[i] + d515 * k15_[i] +
                          d516 * k16_[i]);
            r7_[i] = h * (d61 * k1 + d66 * k6_[i] + d67 * k7_[i] + d68 * k8_[i] + d69 * k9_[i] + d610 * k10_[i] +
                          d611 * k11_[i] + d612 * k12_[i] + d613 * k13 + d614 * k14_[i] + d615 * k15_[i] +
                          d616 * k16_[i]);
            r8_[i] = h * (d71 * k1 + d76 * k6_[i] + d77 * k7_[i] + d78 * k8_[i] + d79 * k9_[i] + d710 * k10_[i] +
                          d711 * k11_[i] + d712 * k12_[i] + d713 * k13 + d714 * k14_[i] + d715 * k15_[i] +
                          d716 * k16_[i]);
        }
        dense_ = true;
    }

    F f_;
    double tol_;
    double t_ = 0, t_old_ = 0, h_ = 0, h_old_ = 0, facold_ = 1;
    long steps_ = 0;
    bool dense_ = false;
    double y_[N]{}, y_old_[N]{}, y_new_[N]{}, k_old_[N]{};
    double k1_[N]{}, k2_[N]{}, k3_[N]{}, k4_[N]{}, k5_[N]{}, k6_[N]{}, k7_[N]{}, k8_[N]{}, k9_[N]{}, k10_[N]{},
        k11_[N]{}, k12_[N]{}, k13_[N]{}, k14_[N]{}, k15_[N]{}, k16_[N]{};
    double r1_[N]{}, r2_[N]{}, r3_[N]{}, r4_[N]{}, r5_[N]{}, r6_[N]{}, r7_[N]{}, r8_[N]{};
};

} // namespace hand
