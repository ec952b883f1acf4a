// SPDX-License-Identifier: GPL-2.0-or-later
/** @file budget.cpp
 *  Size and time budgets of the symbolic stages (see budget.h). */
#include "algebra/budget.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <sstream>
#include <thread>

namespace lagrange {

namespace {

thread_local budget_scope::state* current_budget = nullptr;

std::string seconds_text(double s)
{
    std::ostringstream out;
    out << s;
    return out.str();
}

std::size_t saturating_multiply(std::size_t a, std::size_t b, std::size_t cap)
{
    if (a == 0 || b == 0)
        return 0;
    if (a > cap / b)
        return cap;
    return std::min(a * b, cap);
}

/// What the watchdog sees: the innermost watched scope of the watched thread.
struct watch {
    std::mutex lock;
    std::thread::id thread;
    bool started = false;
    const budget_scope::state* open = nullptr; ///< guarded by lock
    std::string prefix;
    int exit_code = 1;
    void (*before_exit)() = nullptr;
    progress_callback progress;                     ///< show_stage_progress's (guarded by lock)
    std::string shown;                              ///< the stage whose progress was shown last
    std::chrono::steady_clock::time_point shown_at; ///< when
};

watch& the_watch()
{
    static watch* w = new watch; // never destroyed: the watchdog thread outlives main
    return *w;
}

std::string exceeded_time_message(const budget_scope::state& s)
{
    return "the `" + s.stage + "` stage exceeded its time budget of " + seconds_text(s.limits.max_seconds) +
           " s (--max-seconds)";
}

/// Takes down the stage progress shown, if any (with w.lock held).
void hide_stage(watch& w)
{
    if (w.shown.empty())
        return;
    w.shown.clear();
    if (w.progress)
        w.progress("", 0);
}

/// Tells the watchdog which scope is open on its thread (nothing on other threads).
void watch_scope(const budget_scope::state* open)
{
    watch& w = the_watch();
    if (!w.started || std::this_thread::get_id() != w.thread)
        return;
    std::lock_guard<std::mutex> guard(w.lock);
    w.open = open && open->watched ? open : nullptr;
    if (!w.open || w.open->stage != w.shown)
        hide_stage(w);
}

/// Shows the open stage's progress (with w.lock held): at once for a stage not shown yet,
/// then every 0.2 s.
void show_open_stage(watch& w)
{
    const auto now = std::chrono::steady_clock::now();
    if (!w.progress || !w.open || (w.shown == w.open->stage && now - w.shown_at < std::chrono::milliseconds(200)))
        return;
    w.shown = w.open->stage;
    w.shown_at = now;
    w.progress("the `" + w.shown + "` stage", -1);
}

} // namespace

void start_budget_watchdog(const std::string& prefix, int exit_code, void (*before_exit)())
{
    watch& w = the_watch();
    {
        std::lock_guard<std::mutex> guard(w.lock);
        if (w.started)
            return;
        w.started = true;
        w.thread = std::this_thread::get_id();
        w.prefix = prefix;
        w.exit_code = exit_code;
        w.before_exit = before_exit;
    }
    std::thread([&w] {
        for (;;) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            std::lock_guard<std::mutex> guard(w.lock);
            if (!w.open)
                continue;
            const double grace = 0.08 * w.open->limits.max_seconds; // + one 20 ms poll: within a tenth
            const auto late = w.open->stage_deadline + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                     std::chrono::duration<double>(grace));
            if (std::chrono::steady_clock::now() <= late) {
                show_open_stage(w);
                continue;
            }
            hide_stage(w);
            const std::string message = w.prefix + exceeded_time_message(*w.open) +
                                        " inside a step that cannot be interrupted, so the run stopped "
                                        "with nothing printed\n";
            std::fwrite(message.data(), 1, message.size(), stderr);
            std::fflush(stderr);
            if (w.before_exit)
                w.before_exit();
            std::_Exit(w.exit_code);
        }
    }).detach();
}

void show_stage_progress(progress_callback show)
{
    watch& w = the_watch();
    std::lock_guard<std::mutex> guard(w.lock);
    w.progress = std::move(show);
}

budget_scope::budget_scope(std::string stage, const budget_limits& limits, bool watched) : previous_(current_budget)
{
    current_.stage = std::move(stage);
    current_.limits = limits;
    auto now = std::chrono::steady_clock::now();
    double seconds = limits.max_seconds;
    if (!(seconds > 0) || seconds > 1e7)
        seconds = 1e7;
    current_.deadline = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                  std::chrono::duration<double>(seconds));
    current_.stage_deadline = current_.deadline;
    current_.watched = watched;
    current_budget = &current_;
    watch_scope(current_budget);
}

budget_scope::~budget_scope()
{
    current_budget = previous_;
    watch_scope(current_budget);
}

budget_share::budget_share(double fraction) : previous_(current_budget)
{
    if (!previous_)
        return;
    current_ = *previous_;
    const auto now = std::chrono::steady_clock::now();
    if (current_.deadline > now)
        current_.deadline = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      (current_.deadline - now) * std::clamp(fraction, 0.0, 1.0));
    current_budget = &current_;
    watch_scope(current_budget);
}

budget_share::~budget_share()
{
    if (!previous_)
        return;
    current_budget = previous_;
    watch_scope(current_budget);
}

void budget_check()
{
    if (!current_budget)
        return;
    if (std::chrono::steady_clock::now() > current_budget->deadline)
        throw budget_exceeded(current_budget->stage, exceeded_time_message(*current_budget));
}

void budget_check_count(std::size_t terms, const char* what)
{
    if (!current_budget)
        return;
    if (terms > current_budget->limits.max_terms)
        throw budget_exceeded(current_budget->stage,
                              "the `" + current_budget->stage + "` stage exceeded its size budget: " + what +
                                  " has more than " + std::to_string(current_budget->limits.max_terms) +
                                  " terms (--max-terms)");
    budget_check();
}

void budget_check_terms(const GiNaC::ex& e, const char* what)
{
    if (!current_budget)
        return;
    const std::size_t limit = current_budget->limits.max_terms;
    budget_check_count(expanded_terms(e, limit == std::numeric_limits<std::size_t>::max() ? limit : limit + 1),
                       what);
}

std::size_t expanded_terms(const GiNaC::ex& e, std::size_t cap)
{
    if (GiNaC::is_a<GiNaC::add>(e)) {
        std::size_t total = 0;
        for (const GiNaC::ex& term : e) {
            total += expanded_terms(term, cap);
            if (total >= cap)
                return cap;
        }
        return total;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        std::size_t total = 1;
        for (const GiNaC::ex& factor : e)
            total = saturating_multiply(total, std::max<std::size_t>(1, expanded_terms(factor, cap)), cap);
        return total;
    }
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::add>(e.op(0)) && e.op(1).info(GiNaC::info_flags::posint)) {
        // A sum of k terms to the n-th power has at most C(n+k-1, n) terms.
        const long double k = static_cast<long double>(expanded_terms(e.op(0), cap));
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(e.op(1));
        if (k <= 1)
            return static_cast<std::size_t>(k);
        if (n > 100000)
            return cap;
        long double count = 1;
        for (long i = 1; i <= n.to_long() && count < static_cast<long double>(cap); ++i)
            count = count * (k - 1 + i) / i;
        return count >= static_cast<long double>(cap) ? cap : static_cast<std::size_t>(count + 0.5L);
    }
    return 1;
}

std::string budget_stage() { return current_budget ? current_budget->stage : std::string(); }

} // namespace lagrange
