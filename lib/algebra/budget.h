// SPDX-License-Identifier: GPL-2.0-or-later
/** @file budget.h
 *  Budgets instead of hangs: a size budget (terms) and a time budget for the
 *  symbolic stages.
 *
 *  How to use it (for whoever writes a stage):
 *
 *  - The planner (lib/engine/analysis.cpp) opens a `budget_scope` around each
 *    stage; the scope names the stage and starts its clock. Nothing else is needed
 *    to get the stage boundary checks.
 *  - Inside an expensive loop of a symbolic stage (elimination, series products,
 *    simplification passes), call
 *        budget_check();                 // throws if the stage is out of time
 *        budget_check_terms(e, "the determinant");  // ... or if `e` is too large
 *    These are cheap (one clock read; a walk over the top of the expression) and do
 *    nothing when no budget_scope is open (library calls from tests, say).
 *  - Both throw `budget_exceeded` (a computation_error, so exit code 1 if it reaches
 *    the command line), whose message names the stage and the limit:
 *        the `characteristic` stage exceeded its size budget: the determinant has
 *        more than 1000000 terms (--max-terms)
 *    The planner catches it, writes a note for the products of that stage and
 *    continues with what does not depend on it (numeric modes need only the
 *    linearization, so they are still computed).
 *
 *  The limits come from the command line (`--max-terms`, `--max-seconds`). Time is
 *  what the budget is about: a 12-link chain with distinct masses gives up on its
 *  symbolic determinant when its stage's time runs out, rather than hang. The term
 *  limit only guards memory, so its default is set by memory (an expression of a
 *  million terms takes some hundreds of megabytes), not by time: it must never refuse
 *  work that finishes in a fraction of the time budget, as a tighter default once
 *  refused the 7-link chain's characteristic polynomial (0.25 s).
 *
 *  The budget is per thread (thread_local), so parallel analyses do not interfere. */
#pragma once

#include "core/errors.h"
#include "core/progress.h"

#include <ginac/ginac.h>

#include <chrono>
#include <cstddef>
#include <string>

namespace lagrange {

struct budget_limits {
    std::size_t max_terms = 1000000; ///< terms of any one expression (counted as if expanded): a memory guard
    double max_seconds = 30;       ///< wall-clock time of any one symbolic stage
};

/// A symbolic stage ran out of its size or time budget.
class budget_exceeded : public computation_error {
public:
    budget_exceeded(std::string stage, std::string message)
        : computation_error(message), stage_(std::move(stage)) {}
    const std::string& stage() const { return stage_; }

private:
    std::string stage_;
};

/// Opens a budget for one stage on this thread; the previous one is restored on exit.
/// `watched`: the watchdog (start_budget_watchdog) may end the process when the stage
/// overruns; false for stages whose time is the user's to choose (a simulation).
class budget_scope {
public:
    budget_scope(std::string stage, const budget_limits& limits, bool watched = true);
    ~budget_scope();
    budget_scope(const budget_scope&) = delete;
    budget_scope& operator=(const budget_scope&) = delete;

    struct state {
        std::string stage;
        budget_limits limits;
        std::chrono::steady_clock::time_point deadline;       ///< where budget_check() throws
        std::chrono::steady_clock::time_point stage_deadline; ///< the stage's own, which the watchdog holds
        bool watched = true;
    };

private:
    state current_;
    state* previous_;
};

/// A share of the open stage's time for a step that has a cheaper way out (factoring the
/// coefficients of the characteristic polynomial, which can be printed unfactored):
/// budget_check() inside throws budget_exceeded once `fraction` of the stage's remaining
/// time has passed, which leaves the stage the rest to finish without the step. The
/// watchdog still holds the stage's own deadline. Nothing when no budget is open.
class budget_share {
public:
    explicit budget_share(double fraction);
    ~budget_share();
    budget_share(const budget_share&) = delete;
    budget_share& operator=(const budget_share&) = delete;

private:
    budget_scope::state current_;
    budget_scope::state* previous_;
};

/// Throws budget_exceeded if the current stage is past its time budget.
void budget_check();

/// Throws budget_exceeded if `e` has more terms than the size budget allows
/// (or the stage is out of time). `what` names `e` in the message ("the determinant").
void budget_check_terms(const GiNaC::ex& e, const char* what);

/// Same for a count computed by the caller.
void budget_check_count(std::size_t terms, const char* what);

/// The number of terms `e` would have if expanded, saturating at `cap` (cheap:
/// products of sums multiply, powers of sums are raised, nothing is expanded).
std::size_t expanded_terms(const GiNaC::ex& e, std::size_t cap);

/// The name of the stage whose budget is open on this thread, or "" if none.
std::string budget_stage();

/// For programs, not libraries (it ends the process): watches the watched stages opened on
/// the calling thread from now on. One GiNaC call (a gcd, a factorization) cannot be
/// interrupted by the cooperative checks above; when a stage runs past its time budget by
/// 8 %, a watchdog thread writes `prefix` + "the `STAGE` stage exceeded its time budget of
/// S s (--max-seconds) inside a step that cannot be interrupted, …" to standard error and
/// ends the process with `exit_code`, so that --max-seconds holds within a tenth on every path;
/// `before_exit` (if any) runs just before, to remove temporary files.
void start_budget_watchdog(const std::string& prefix, int exit_code, void (*before_exit)() = nullptr);

/// For programs, with the watchdog: while a watched stage is open, the watchdog thread calls
/// `show("the `STAGE` stage", -1)` when it opens and then about every 0.2 s (a program may
/// draw a progress line), and `show("", 0)` once the stage closes (on the thread that closes
/// it) or before the watchdog ends the process. An empty `show` stops the calls.
void show_stage_progress(progress_callback show);

} // namespace lagrange
