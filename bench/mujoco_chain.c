/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The peer of bench/large_systems.cpp in MuJoCo (Debian's libmujoco-dev): the same planar
 * N-link chain (link k: mass 1 + k/10 at the end of a massless rod of length 1 − k/100, hinges
 * about y, gravity 9.81), with each point mass given a tiny inertia (MuJoCo needs one), and
 * the nanoseconds of one mj_forward (which computes q̈) over 64 seeded random states, best
 * of 5 runs. Plain C, so that bench/CMakeLists.txt (C++ only) leaves it to the script, which
 * builds it when MuJoCo is installed.
 *   mujoco_chain N [calls]   prints: N ns_per_forward */
#include <mujoco/mujoco.h>

#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char** argv)
{
    if (argc < 2)
        return 2;
    int n = atoi(argv[1]);
    long calls = argc > 2 ? atol(argv[2]) : 4000000L / ((long)n * n) > 2000 ? 4000000L / ((long)n * n) : 2000;
    char path[] = "/tmp/mujoco_chainXXXXXX";
    int fd = mkstemp(path);
    FILE* xml = fdopen(fd, "w");
    fprintf(xml, "<mujoco><compiler angle=\"radian\"/><option gravity=\"0 0 -9.81\"><flag contact=\"disable\"/>"
                 "</option><worldbody>\n");
    for (int k = 1; k <= n; ++k)
        fprintf(xml, "<body pos=\"0 0 %.17g\"><joint type=\"hinge\" axis=\"0 1 0\"/>"
                     "<inertial pos=\"0 0 %.17g\" mass=\"%.17g\" diaginertia=\"1e-9 1e-9 1e-9\"/>\n",
                k == 1 ? 0.0 : -(1 - 0.01 * (k - 1)), -(1 - 0.01 * k), 1 + 0.1 * k);
    for (int k = 1; k <= n; ++k)
        fputs("</body>", xml);
    fputs("</worldbody></mujoco>\n", xml);
    fclose(xml);
    char error[1000];
    mjModel* model = mj_loadXML(path, NULL, error, sizeof error);
    unlink(path);
    if (!model) {
        fprintf(stderr, "mujoco: %s\n", error);
        return 1;
    }
    mjData* data = mj_makeData(model);
    enum { states = 64 };
    double* x = malloc(sizeof(double) * states * 2 * n);
    srand(39);
    for (int j = 0; j < states; ++j)
        for (int i = 0; i < 2 * n; ++i)
            x[j * 2 * n + i] = (i < n ? 3.0 : 4.0) * ((double)rand() / RAND_MAX - 0.5);
    volatile double sink = 0;
    double best = 1e300;
    for (int run = 0; run < 5; ++run) {
        double start = now();
        for (long k = 0; k < calls; ++k) {
            const double* state = x + (k % states) * 2 * n;
            for (int i = 0; i < n; ++i) {
                data->qpos[i] = state[i];
                data->qvel[i] = state[n + i];
            }
            mj_forward(model, data);
            sink = sink + data->qacc[n - 1];
        }
        double ns = (now() - start) * 1e9 / (double)calls;
        best = ns < best ? ns : best;
    }
    printf("%d %.1f\n", n, best);
    mj_deleteData(data);
    mj_deleteModel(model);
    free(x);
    return 0;
}
