/** @file analysis.cpp
 *  The stage planner. */
#include "engine/analysis.h"

#include "scene/lower.h"

#include "numeric/free_body_motion.h"

#include <chrono>
#include <functional>

namespace lagrange {

const std::set<product>& available_products()
{
    static const std::set<product> products = {
        product::equations,       product::equilibrium, product::linearization,      product::characteristic,
        product::frequencies,     product::modes,       product::normal_coordinates, product::asymptotic,
        product::numeric,         product::inertia,     product::euler,
        product::simulation,      product::workprecision,
    };
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

/// Times one stage and records it. A failure inside the algebra (GiNaC throws
/// plain std::exceptions with internal messages) becomes a computation_error
/// that names the stage.
void run_stage(analysis& result, const std::string& name, const std::function<void()>& stage,
               const budget_limits& limits = {})
{
    auto start = std::chrono::steady_clock::now();
    try {
        budget_scope budget(name, limits);
        stage();
    } catch (const computation_error&) {
        throw;
    } catch (const scene_error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception&) {
        throw computation_error("the `" + name + "` stage could not be done for this scene symbolically");
    }
    std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    result.stages.push_back({name, elapsed.count()});
}

bool wants_any(const std::set<product>& wanted, std::initializer_list<product> products)
{
    for (product p : products)
        if (wanted.count(p))
            return true;
    return false;
}

/// The products a scene supports when it has no `want` line.
std::set<product> default_products(const model& scene)
{
    std::set<product> products;
    if (!scene.coordinates.empty()) {
        products.insert({product::equations, product::equilibrium, product::linearization, product::characteristic,
                         product::frequencies, product::modes, product::normal_coordinates});
    }
    if (!scene.bodies.empty())
        products.insert(product::inertia);
    for (const rigid_body& b : scene.bodies)
        if (b.omega)
            products.insert(product::euler);
    if (scene.coordinates.empty())
        return products;
    if (scene.limit)
        products.insert(product::asymptotic);
    if (!scene.values.empty())
        products.insert(product::numeric);
    if (scene.simulation)
        products.insert(product::simulation);
    return products;
}

/// True if any of the wanted products was computed.
bool computed_any(const analysis& result)
{
    for (product p : result.wanted) {
        switch (p) {
        case product::equations: if (result.equations && result.equations->residuals) return true; break;
        case product::equilibrium: if (result.equilibria) return true; break;
        case product::linearization: if (result.linearization) return true; break;
        case product::characteristic: if (result.characteristic) return true; break;
        case product::frequencies:
        case product::modes:
        case product::normal_coordinates: if (result.modes) return true; break;
        case product::asymptotic: if (result.asymptotic) return true; break;
        case product::numeric: if (result.numeric) return true; break;
        case product::inertia: if (result.inertia) return true; break;
        case product::euler: if (result.euler) return true; break;
        case product::simulation: if (result.simulation) return true; break;
        case product::workprecision: if (result.workprecision) return true; break;
        default: break;
        }
    }
    return false;
}

analysis analyze_within(const model& scene, const std::set<product>& wanted, const budget_limits& limits,
                        std::optional<budget_exceeded>& exceeded)
{
    analysis result;
    result.scene = &scene;
    const bool by_default = wanted.empty() && scene.wanted.empty();
    result.wanted = !wanted.empty() ? wanted : !scene.wanted.empty() ? scene.wanted : default_products(scene);
    for (product p : result.wanted)
        if (!available_products().count(p))
            throw computation_error("`" + name_of(p) + "` is not computed by this version of lagrange yet");

    const std::set<product>& w = result.wanted;
    bool need_numeric = w.count(product::numeric) > 0;
    bool need_asymptotic = w.count(product::asymptotic) > 0;
    bool need_modes = need_asymptotic ||
                      wants_any(w, {product::frequencies, product::modes, product::normal_coordinates});
    bool need_characteristic = need_modes || w.count(product::characteristic) > 0;
    bool need_linearization = need_characteristic || need_numeric || w.count(product::linearization) > 0;
    bool need_equilibria = need_linearization || w.count(product::equilibrium) > 0;
    bool need_equations = w.count(product::equations) > 0;
    bool need_motion = wants_any(w, {product::simulation, product::workprecision});

    // Rigid bodies: inertia by integration, then Euler's equations of the free ones.
    bool need_euler = w.count(product::euler) > 0;
    if (need_euler || w.count(product::inertia)) {
        if (scene.bodies.empty())
            throw computation_error("`inertia` and `euler` need a rigid body (`body B disk(R) mass M`)");
        run_stage(result, "inertia", [&] {
            result.inertia.emplace();
            for (const rigid_body& b : scene.bodies)
                result.inertia->push_back(derive_inertia(b));
        }, limits);
    }
    if (need_euler) {
        bool free_body = false;
        for (const rigid_body& b : scene.bodies)
            free_body = free_body || b.omega.has_value();
        if (!free_body)
            throw computation_error("`euler` needs a free body: name its angular velocity with "
                                    "`omega B (w1, w2, w3)`");
        GiNaC::exmap values = scene.values.empty() ? GiNaC::exmap{} : value_map(scene, scene.values.front());
        run_stage(result, "euler", [&] {
            result.euler.emplace();
            for (std::size_t i = 0; i < scene.bodies.size(); ++i)
                if (scene.bodies[i].omega)
                    result.euler->push_back(derive_euler(scene.bodies[i], result.inertia->at(i), scene.initial, values));
        }, limits);
    }
    if (scene.coordinates.empty()) {
        if (wants_any(w, {product::equations, product::equilibrium, product::linearization, product::characteristic,
                          product::frequencies, product::modes, product::normal_coordinates, product::asymptotic,
                          product::numeric}))
            throw computation_error("the scene has no coordinates, so it has no equations of motion "
                                    "(only `inertia` and `euler`)");
        return result;
    }

    simplifier simplify = make_simplifier(scene);
    run_stage(result, "lagrangian", [&] { result.lagrangian = derive_lagrangian(scene, simplify); }, limits);
    if (need_equations || need_motion) {
        try {
            run_stage(result, "equations", [&] {
                result.equations = derive_equations_of_motion(scene, *result.lagrangian, simplify, need_equations);
            }, limits);
        } catch (const budget_exceeded& error) {
            result.notes.push_back(std::string("equations not computed: ") + error.what());
            exceeded = error;
        }
    }
    bool has_top = false;
    for (const rigid_body& b : scene.bodies)
        has_top = has_top || b.orientation.has_value();
    if (has_top && (need_equations || w.count(product::inertia)))
        run_stage(result, "top", [&] { result.tops = analyze_tops(scene, *result.lagrangian, simplify); }, limits);
    if (!need_equilibria)
        return result;

    // The small-oscillation stages. In a default run, what cannot be done is a note.
    try {
        if (!result.lagrangian->split)
            throw computation_error("the Lagrangian is not quadratic in the velocities, so it has no "
                                    "kinetic and potential energy to linearize");
        if (need_asymptotic && !scene.limit)
            throw computation_error("`asymptotic` needs a `limit` line, such as `limit rho -> 0`");
        if (need_numeric && scene.values.empty())
            throw computation_error("`numeric` needs a `values` line or --values");
        run_stage(result, "equilibrium",
                  [&] { result.equilibria = find_equilibria(scene, *result.lagrangian, simplify); }, limits);
        if (!need_linearization)
            return result;
        const equilibrium_point& point = result.equilibria->points.at(result.equilibria->chosen);
        run_stage(result, "linearization",
                  [&] { result.linearization = linearize(scene, *result.lagrangian, point.position, simplify); },
                  limits);
        // Budgets: a symbolic stage that swells leaves out its products (with a note)
        // and those after it, but not the numeric modes, which need only the linearization.
        try {
            if (need_characteristic)
                run_stage(result, "characteristic",
                          [&] { result.characteristic = characteristic_polynomial(scene, *result.linearization); },
                          limits);
            if (need_modes)
                run_stage(result, "modes", [&] {
                    result.modes = symbolic_modes(scene, *result.linearization, *result.characteristic);
                }, limits);
            if (need_asymptotic)
                run_stage(result, "asymptotic", [&] { result.asymptotic = asymptotic_limit(scene, *result.modes); },
                          limits);
        } catch (const budget_exceeded& error) {
            result.notes.push_back(std::string("symbolic modes not computed: ") + error.what() +
                                   (need_numeric ? "; the numeric modes are still computed" : ""));
            exceeded = error;
        }
        if (need_numeric)
            run_stage(result, "numeric",
                      [&] { result.numeric = numeric_normal_modes(scene, *result.linearization); }, limits);
    } catch (const budget_exceeded& error) {
        result.notes.push_back(std::string("small oscillations not computed: ") + error.what());
        exceeded = error;
    } catch (const computation_error& error) {
        if (!by_default)
            throw;
        result.notes.push_back(std::string("small oscillations not computed: ") + error.what());
    }
    return result;
}

/// The numeric time-integration stages: `simulation` and `workprecision`.
void run_motion_stages(analysis& result, const model& scene, bool by_default, const simulation_settings& settings,
                       const budget_limits& limits)
{
    const std::set<product>& w = result.wanted;
    if (!wants_any(w, {product::simulation, product::workprecision}))
        return;
    std::optional<std::vector<GiNaC::ex>> equilibrium = scene.equilibrium;
    if (result.equilibria)
        equilibrium = result.equilibria->points.at(result.equilibria->chosen).position;
    try {
        if (!result.lagrangian) {
            // A free body (no coordinates): Euler's equations.
            if (!has_free_body(scene))
                throw computation_error("the scene has no coordinates to simulate");
            if (w.count(product::simulation))
                run_stage(result, "simulation", [&] { result.simulation = simulate_free_body(scene, settings); }, limits);
            if (w.count(product::workprecision))
                run_stage(result, "workprecision",
                          [&] { result.workprecision = free_body_work_precision(scene, settings); }, limits);
            return;
        }
        if (!result.equations)
            return;
        if (w.count(product::simulation))
            run_stage(result, "simulation", [&] {
                result.simulation = simulate(scene, *result.equations, equilibrium, settings);
            }, limits);
        if (w.count(product::workprecision))
            run_stage(result, "workprecision", [&] {
                result.workprecision = scene_work_precision(scene, *result.equations, equilibrium, settings);
            }, limits);
    } catch (const computation_error& error) {
        if (!by_default)
            throw;
        result.notes.push_back(std::string("simulation not computed: ") + error.what());
    }
}

} // namespace

analysis analyze(const model& scene, const std::set<product>& wanted, const budget_limits& limits,
                 const simulation_settings& simulation)
{
    std::optional<budget_exceeded> exceeded;
    analysis result = analyze_within(scene, wanted, limits, exceeded);
    run_motion_stages(result, scene, wanted.empty() && scene.wanted.empty(), simulation, limits);
    if (exceeded && !computed_any(result))
        throw *exceeded;
    return result;
}

analysis analyze(const model& scene, const std::set<product>& wanted, const simulation_settings& simulation)
{
    return analyze(scene, wanted, budget_limits{}, simulation);
}

} // namespace lagrange
