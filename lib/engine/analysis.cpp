/** @file analysis.cpp
 *  The stage planner. */
#include "engine/analysis.h"

#include <chrono>
#include <functional>

namespace lagrange {

const std::set<product>& available_products()
{
    static const std::set<product> products = {product::equations};
    return products;
}

namespace {

std::string name_of(product p)
{
    for (const auto& [q, name] : product_names())
        if (q == p)
            return name;
    return "?";
}

/// Times one stage and records it.
void run_stage(analysis& result, const std::string& name, const std::function<void()>& stage)
{
    auto start = std::chrono::steady_clock::now();
    stage();
    std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    result.stages.push_back({name, elapsed.count()});
}

} // namespace

analysis analyze(const model& scene, const std::set<product>& wanted)
{
    analysis result;
    result.scene = &scene;
    result.wanted = !wanted.empty() ? wanted : !scene.wanted.empty() ? scene.wanted : available_products();
    for (product p : result.wanted)
        if (!available_products().count(p))
            throw computation_error("`" + name_of(p) + "` is not computed by this version of lagrange yet");

    bool need_equations = result.wanted.count(product::equations) > 0;
    bool need_lagrangian = need_equations;

    simplifier simplify = make_simplifier(scene);
    if (need_lagrangian)
        run_stage(result, "lagrangian", [&] { result.lagrangian = derive_lagrangian(scene, simplify); });
    if (need_equations)
        run_stage(result, "equations", [&] { result.equations = derive_equations(scene, *result.lagrangian, simplify); });
    return result;
}

} // namespace lagrange
