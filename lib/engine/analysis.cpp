// SPDX-License-Identifier: GPL-2.0-or-later
/** @file analysis.cpp
 *  The stage planner. */
#include "engine/analysis.h"

#include "algebra/sign.h"
#include "engine/products.h"
#include "scene/lower.h"

#include "numeric/damped_modes.h"
#include "numeric/constrained_motion.h"
#include "numeric/free_body_motion.h"
#include "numeric/point_modes.h"
#include "numeric/steady_stability.h"
#include "verify/check_operating_point.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace lagrange {

namespace {

/// The damping matrix C at the linearization's equilibrium: the `damping` stage's where it
/// ran, else derived here.
GiNaC::matrix damping_at_equilibrium(const analysis& result, const simplifier& simplify)
{
    return result.damping ? result.damping->damping
                          : damping_matrix(*result.scene, result.linearization->at, simplify);
}

/// C for the numeric modes: nothing without generalized forces or where C = 0.
std::optional<GiNaC::matrix> damping_at_rest(const analysis& result, const simplifier& simplify)
{
    if (!result.scene->has_generalized_forces())
        return std::nullopt;
    // The linearization of a constrained scene is in its independent coordinates; C is not
    // projected onto them, and leaving it out would misstate the stability.
    if (result.constrained)
        throw computation_error("damped small oscillations with constraints (`constraint`) are not computed by "
                                "this version, so neither are the numeric modes of this scene");
    GiNaC::matrix damping = damping_at_equilibrium(result, simplify);
    if (is_zero_matrix(damping))
        return std::nullopt;
    return damping;
}

/// What the stages share while they run.
struct stage_context {
    const model& scene;
    analysis& result;
    const simulation_settings& simulation;
    bool by_default; ///< no product was named: what cannot be done is a note
    std::optional<simplifier> simplify;

    const simplifier& simplifier_for_scene()
    {
        if (!simplify)
            simplify = make_simplifier(scene);
        return *simplify;
    }
    bool wants(product p) const { return result.wanted.count(p) > 0; }
};

/// The stages, in the order they run (the rows of stage_table(), in the same order).
enum class stage_id {
    inertia, euler, lagrangian, equations, multipliers, contact, elimination, top, time, equilibrium, linearization,
    characteristic, modes, asymptotic, damping, numeric, critical, state_space, operating_point, critical_operating,
    transfer, floquet,
    conserved, hamiltonian, reduced, steady, simulation, workprecision, virial, verification
};

/// What a stage does with a scene's constraints: handles them, or refuses them with
/// "WHAT with constraints (`constraint`) is not computed by this version" before it runs.
struct constraints_policy {
    bool handled = true;
    const char* what = "";
};
constexpr constraints_policy handles_constraints{};
constexpr constraints_policy refuses_constraints(const char* what) { return {false, what}; }

/// One stage: its id and name (in `stages` and --timings), the products it computes, the
/// products it is shown with, the stages whose results it reads, whether it applies to
/// a scene, and how a failure is reported. A stage runs when a product it computes or
/// is shown with is wanted, or when a stage that runs needs it.
struct stage_definition {
    stage_id id;
    std::string name;
    std::vector<product> produces;
    std::vector<product> shown_with;
    std::vector<stage_id> needs;
    bool (*applies)(const model&);
    std::function<void(stage_context&)> run;
    /// A stage of a group ("small oscillations", "simulation") that fails in a default
    /// run leaves out the rest of its group with the note "GROUP not computed: why";
    /// empty: the failure is an error.
    std::string group;
    /// A budget overrun leaves out this stage and those that need it, with the note
    /// "BUDGET_NOTE not computed: why"; empty: as any other failure.
    std::string budget_note;
    constraints_policy constraints = handles_constraints;
    /// Symbolic: the watchdog ends it at the time budget. Numeric stages take the time
    /// their settings ask for.
    bool watched = true;
    /// A budget overrun here leaves the wanted frequencies to the numeric modes, at the
    /// `values` points (the symbolic modes' stages).
    bool numeric_fallback = false;
};

/// The equilibrium a simulation linearizes about to choose its method: the scene's
/// `equilibrium` line, never one found by the `equilibrium` stage, so that asking for
/// other products does not change the simulation (a heavy top's found θ = 0 is singular).
std::optional<std::vector<GiNaC::ex>> equilibrium_of(const stage_context& c) { return c.scene.equilibrium; }

bool has_coordinates(const model& scene) { return !scene.coordinates.empty(); }
bool any_scene(const model&) { return true; }
/// Static equilibria and small oscillations about them: not for a scene whose
/// `equilibrium` line names a steady rate (the `steady` stage studies that motion).
bool has_constraints(const model& scene) { return !scene.coordinates.empty() && !scene.constraints.empty(); }
bool has_static_point(const model& scene) { return !scene.coordinates.empty() && !scene.steady; }
/// Critical parameters of the small oscillations, where no operating point takes their place.
bool has_static_critical(const model& scene)
{
    return has_static_point(scene) && !linearizes_about_operating_point(scene);
}
/// A steady motion on Routh's reduced system; with constraints it is an operating point of
/// `state_space` instead.
bool has_steady(const model& scene)
{
    return !scene.coordinates.empty() && scene.steady && scene.constraints.empty();
}
bool has_time(const model& scene) { return !scene.coordinates.empty() && mentions_time(scene); }
/// The equilibrium's state space, where no operating point takes its place.
bool has_equilibrium_state_space(const model& scene)
{
    return has_coordinates(scene) && !linearizes_about_operating_point(scene);
}
/// Whether A or B is a function of a coordinate left free by `linearize about`.
bool has_free_coordinate(const model& scene, const state_space_result& system)
{
    for (const coordinate& q : scene.coordinates)
        if (GiNaC::lst{system.a, system.b}.has(q.position))
            return true;
    return false;
}
/// Modes of a constrained scene are in its independent coordinates: their displacements and
/// normal coordinates name them (the modes stage numbers them from the first coordinate).
void name_independent_coordinates(const model& scene, const std::vector<std::size_t>& independent, modes_result& modes)
{
    GiNaC::exmap rename;
    for (std::size_t i = 0; i < independent.size(); ++i)
        rename[scene.coordinates[i].position] = scene.coordinates[independent[i]].position;
    for (GiNaC::ex& e : modes.displacements)
        e = e.subs(rename);
    for (GiNaC::ex& e : modes.normal_coordinates)
        e = e.subs(rename);
    for (GiNaC::ex& e : modes.normal_coordinates_in_ratio)
        e = e.subs(rename);
}

/// The stages that do not handle constraints yet say so instead of ignoring them.
void refuse_constraints(const model& scene, const std::string& what)
{
    if (!scene.constraints.empty())
        throw computation_error(what + " with constraints (`constraint`) is not computed by this version");
}

/// Whether the wanted frequencies, not found in closed form, can be given numerically
/// instead: the numeric modes were not asked for, and the scene has `values` points.
bool numeric_frequencies_possible(const model& scene, const analysis& result)
{
    return result.wanted.count(product::frequencies) && !result.wanted.count(product::numeric) &&
           !scene.values.empty() && result.linearization;
}

/// The numeric modes, where a symbolic product falls short: wanted from now on (the
/// planner plans them).
void want_numeric(stage_context& c) { c.result.wanted.insert(product::numeric); }

bool has_top(const model& scene)
{
    if (scene.coordinates.empty())
        return false;
    for (const rigid_body& b : scene.bodies)
        if (b.orientation)
            return true;
    return false;
}

/// Every product (core/products.inc).
const std::vector<product>& every_product()
{
    static const std::vector<product> all = [] {
        std::vector<product> products;
        for (const auto& [p, name] : product_names())
            products.push_back(p);
        return products;
    }();
    return all;
}

/// The stages in the order they run. Adding a product is one LAGRANGE_OWN_PRODUCT line of
/// core/products.inc (which gives it its `analysis` field and its place in the documents
/// and the report), one row here with its stage_id, and its own files.
const std::vector<stage_definition>& stage_table()
{
    static const std::vector<stage_definition> table = {
        {stage_id::inertia, "inertia", {product::inertia}, {}, {}, any_scene,
         [](stage_context& c) {
             if (c.scene.bodies.empty())
                 throw computation_error("`inertia` and `euler` need a rigid body (`body B disk(R) mass M`)");
             c.result.inertia.emplace();
             for (const rigid_body& b : c.scene.bodies)
                 c.result.inertia->push_back(derive_inertia(b));
         }, "", ""},
        {stage_id::euler, "euler", {product::euler}, {}, {stage_id::inertia}, any_scene,
         [](stage_context& c) {
             if (!has_free_body(c.scene))
                 throw computation_error("`euler` needs a free body: name its angular velocity with "
                                         "`omega B (w1, w2, w3)`");
             GiNaC::exmap values =
                 c.scene.values.empty() ? GiNaC::exmap{} : value_map(c.scene, c.scene.values.front());
             c.result.euler.emplace();
             for (std::size_t i = 0; i < c.scene.bodies.size(); ++i)
                 if (c.scene.bodies[i].omega)
                     c.result.euler->push_back(
                         derive_euler(c.scene.bodies[i], c.result.inertia->at(i), c.scene.initial, values));
             // Poinsot's construction in space over three periods of the polhode (the report's figure).
             c.result.poinsot.emplace();
             for (const euler_result& e : *c.result.euler)
                 if (e.torque_free && e.poinsot) {
                     try {
                         c.result.poinsot->push_back(compute_poinsot(e, {}));
                     } catch (const computation_error& error) {
                         c.result.notes.push_back("Poinsot's construction of body " + e.body + ": " + error.what());
                     }
                 }
         }, "", ""},
        // Every product of a scene with coordinates shows its Lagrangian.
        {stage_id::lagrangian, "lagrangian", {}, every_product(), {}, has_coordinates,
         [](stage_context& c) { c.result.lagrangian = derive_lagrangian(c.scene, c.simplifier_for_scene()); },
         "", ""},
        {stage_id::equations, "equations", {product::equations}, {}, {stage_id::lagrangian},
         has_coordinates,
         [](stage_context& c) {
             c.result.equations = derive_equations_of_motion(c.scene, *c.result.lagrangian, c.simplifier_for_scene(),
                                                             c.wants(product::equations));
             // too large to print: a note beside the rest (analyze() refuses them when asked for)
             if (const std::string& why = c.result.equations->too_large_to_print; !why.empty())
                 c.result.notes.push_back(why);
         }, "", "equations"},
        {stage_id::multipliers, "multipliers", {product::multipliers}, {}, {stage_id::equations}, has_coordinates,
         [](stage_context& c) {
             if (c.scene.constraints.empty())
                 throw computation_error(c.wants(product::multipliers)
                                             ? "`multipliers` needs a constraint (`constraint NAME: lhs = rhs`)"
                                             : "`contact` needs a wheel rolling on the ground (`rolls W on ground`)");
             c.result.multipliers = derive_multipliers(c.scene, c.result.equations->mass, c.result.equations->forcing,
                                                       *c.result.equations->constraints, c.simplifier_for_scene());
         }, "", "multipliers"},
        // The ground's force on each rolling wheel, from the multipliers.
        {stage_id::contact, "contact", {product::contact}, {}, {stage_id::multipliers}, has_coordinates,
         [](stage_context& c) {
             c.result.contact = derive_contact_forces(c.scene, *c.result.multipliers, c.simplifier_for_scene());
         }, "", "contact forces"},
        // Which constraints can be solved for a coordinate (shown with the constraints), and
        // the equations of the coordinates kept when `eliminated` is asked for.
        {stage_id::elimination, "elimination", {product::eliminated}, {product::equations, product::multipliers}, {stage_id::equations},
         has_constraints,
         [](stage_context& c) {
             c.result.elimination = find_eliminations(c.scene, c.simplifier_for_scene());
             if (!c.wants(product::eliminated) || (c.by_default && !c.result.elimination->complete))
                 return;
             c.result.elimination->equations =
                 reduced_equations(c.scene, *c.result.equations, *c.result.elimination, c.simplifier_for_scene());
         }, "", "eliminated"},
        {stage_id::top, "top", {}, {product::equations, product::inertia}, {stage_id::lagrangian}, has_top,
         [](stage_context& c) { c.result.tops = analyze_tops(c.scene, *c.result.lagrangian, c.simplifier_for_scene()); },
         "", ""},
        // Before anything else in the oscillation path: does L depend on t, and if so,
        // which points solve the equations at every t (else: no equilibrium, exit 1).
        {stage_id::time, "time", {}, {}, {stage_id::equations}, has_time,
         [](stage_context& c) {
             c.result.time = analyze_time_dependence(c.scene, *c.result.lagrangian, *c.result.equations,
                                                     c.simplifier_for_scene());
         }, "", ""},
        {stage_id::equilibrium, "equilibrium", {product::equilibrium}, {}, {stage_id::lagrangian, stage_id::time}, has_static_point,
         [](stage_context& c) {
             if (c.result.time && c.result.time->depends_on_time)
                 throw computation_error("L depends on t, so there is no static equilibrium to linearize about; "
                                         "the points that solve the equations at every t are studied by `floquet`");
             if (!c.result.lagrangian->split)
                 throw computation_error("the Lagrangian is not quadratic in the velocities, so it has no "
                                         "kinetic and potential energy to linearize");
             if (c.wants(product::asymptotic) && !c.scene.limit)
                 throw computation_error("`asymptotic` needs a `limit` line, such as `limit rho -> 0`");
             if (c.wants(product::numeric) && c.scene.values.empty())
                 throw computation_error("`numeric` needs a `values` line or --values");
             require_forces_vanish_at_rest(c.scene, c.simplifier_for_scene());
             if (!c.scene.constraints.empty()) {
                 c.result.constrained =
                     linearize_with_constraints(c.scene, *c.result.lagrangian, c.simplifier_for_scene());
                 c.result.equilibria = c.result.constrained->equilibria;
                 return;
             }
             c.result.equilibria = find_equilibria(c.scene, *c.result.lagrangian, c.simplifier_for_scene());
         }, "small oscillations", "small oscillations"},
        {stage_id::linearization, "linearization", {product::linearization, product::gyroscopic}, {}, {stage_id::equilibrium}, has_static_point,
         [](stage_context& c) {
             if (c.result.constrained) {
                 c.result.linearization = c.result.constrained->linear;
                 return;
             }
             equilibrium_point& point = c.result.equilibria->points.at(c.result.equilibria->chosen);
             c.result.linearization =
                 linearize(c.scene, *c.result.lagrangian, point.position, c.simplifier_for_scene());
             if (c.result.linearization->has_force_stiffness()) {
                 // V alone no longer decides: the numeric eigenvalues do, at each point
                 point.kind = stability::unknown;
                 c.result.notes.push_back(std::string("V includes the stiffness −∂Q/∂q of the applied forces at "
                                                      "the equilibrium") +
                                          (c.result.linearization->circulatory()
                                               ? ", which is not symmetric (circulatory forces)" : "") +
                                          "; the stability is that of the eigenvalues (`numeric`)");
             }
         }, "small oscillations", "small oscillations"},
        {stage_id::characteristic, "characteristic", {product::characteristic}, {}, {stage_id::linearization}, has_static_point,
         [](stage_context& c) {
             if (c.by_default && c.result.linearization->circulatory() && c.result.linearization->has_gyroscopic())
                 return; // not a real polynomial in ω; the modes stage says so
             c.result.characteristic = characteristic_polynomial(c.scene, *c.result.linearization);
             if (!c.result.characteristic->factored)
                 c.result.notes.push_back("the characteristic polynomial's coefficients are not factored: factoring "
                                          "them exceeded half of the stage's time budget (--max-seconds)");
         },
         "small oscillations", "symbolic modes", handles_constraints, true, true},
        {stage_id::modes, "modes", {product::frequencies, product::modes, product::normal_coordinates}, {}, {stage_id::characteristic},
         has_static_point,
         [](stage_context& c) {
             if (c.result.linearization->circulatory()) {
                 const std::string why = "the stiffness of the applied forces is not symmetric (circulatory), so "
                                         "there are no real ω², mode shapes or normal coordinates; the eigenvalues "
                                         "s are given by `numeric` (and `damping`)";
                 if (!c.by_default)
                     throw computation_error("`frequencies`, `modes` and `normal_coordinates` are not defined: " + why);
                 c.result.notes.push_back("frequencies and modes not computed: " + why);
                 if (!c.scene.values.empty())
                     want_numeric(c);
                 return;
             }
             if (c.result.linearization->has_gyroscopic() &&
                 (c.wants(product::modes) || c.wants(product::normal_coordinates))) {
                 const std::string why = "with a gyroscopic matrix G the modes are complex (see `numeric`) and there "
                                         "are no real normal coordinates";
                 if (!c.by_default)
                     throw computation_error("`modes` and `normal_coordinates` are not computed symbolically: " + why);
                 c.result.notes.push_back("modes and normal coordinates not computed: " + why);
             }
             // the mode vectors only where a product shows or reads them
             const bool vectors = c.wants(product::modes) || c.wants(product::normal_coordinates) ||
                                  c.wants(product::asymptotic) || c.wants(product::damping);
             c.result.modes = c.result.linearization->has_gyroscopic()
                                  ? gyroscopic_modes(c.scene, *c.result.linearization, *c.result.characteristic)
                                  : symbolic_modes(c.scene, *c.result.linearization, *c.result.characteristic,
                                                   vectors);
             if (c.result.constrained)
                 name_independent_coordinates(c.scene, c.result.constrained->independent, *c.result.modes);
             if (!c.result.modes->closed_form && numeric_frequencies_possible(c.scene, c.result)) {
                 want_numeric(c);
                 c.result.notes.push_back("the frequencies have no closed form; they are given numerically at the "
                                          "`values` points");
             } else if (!c.result.modes->closed_form) {
                 // computed but not printable: every format says why, not only the text
                 c.result.notes.push_back(
                     std::string("the frequencies have no closed form (a factor of the characteristic polynomial "
                                 "has no roots in closed form)") +
                     (c.wants(product::numeric) ? "; the numeric modes give them"
                                                : "; give `values` to have them numerically"));
             }
             if (c.result.modes->vectors_left_out) {
                 std::string note = "modes and normal coordinates not computed in closed form for " +
                                    c.result.modes->vectors_left_out_why;
                 if (c.wants(product::numeric))
                     note += "; the numeric modes give them";
                 else if (!c.scene.values.empty() && c.result.linearization) {
                     want_numeric(c);
                     note += "; they are given numerically at the `values` points";
                 } else
                     note += "; give `values` to have them numerically";
                 c.result.notes.push_back(note);
             }
         }, "small oscillations", "symbolic modes", handles_constraints, true, true},
        {stage_id::asymptotic, "asymptotic", {product::asymptotic}, {}, {stage_id::modes}, has_static_point,
         [](stage_context& c) {
             if (!c.result.modes)
                 throw computation_error("`asymptotic` needs the modes, which are not defined for a non-symmetric "
                                         "stiffness (circulatory forces)");
             if (c.result.modes->gyroscopic)
                 throw computation_error("`asymptotic` is not computed for a Lagrangian with a part linear in the "
                                         "velocities (gyroscopic terms)");
             if (c.result.modes->vectors_left_out)
                 throw computation_error("`asymptotic` needs the mode vectors, which are not computed in closed "
                                         "form for " + c.result.modes->vectors_left_out_why);
             c.result.asymptotic = asymptotic_limit(c.scene, *c.result.modes);
         },
         "small oscillations", "symbolic modes", refuses_constraints("`asymptotic`"), true, true},
        {stage_id::damping, "damping", {product::damping}, {}, {stage_id::linearization}, has_static_point,
         [](stage_context& c) {
             c.result.damping = damped_oscillations(c.scene, *c.result.linearization, c.simplifier_for_scene(),
                                                    c.result.modes ? &*c.result.modes : nullptr);
         }, "small oscillations", "small oscillations", refuses_constraints("`damping`")},
        {stage_id::numeric, "numeric", {product::numeric}, {}, {stage_id::linearization}, has_static_point,
         [](stage_context& c) {
             const std::optional<GiNaC::matrix> damping = damping_at_rest(c.result, c.simplifier_for_scene());
             c.result.numeric = numeric_normal_modes(c.scene, *c.result.linearization, damping ? &*damping : nullptr);
         },
         "small oscillations", "small oscillations", handles_constraints, false},
        {stage_id::critical, "critical", {product::critical}, {}, {stage_id::linearization}, has_static_critical,
         [](stage_context& c) {
             const std::optional<GiNaC::matrix> damping = damping_at_rest(c.result, c.simplifier_for_scene());
             c.result.critical = critical_parameters(c.scene, *c.result.linearization, damping ? &*damping : nullptr);
         }, "critical parameters", "", handles_constraints, false},
        // The linearized input–output system: A, B (and at the `values` points), then H(s).
        {stage_id::state_space, "state_space", {product::state_space}, {}, {stage_id::linearization},
         has_equilibrium_state_space,
         [](stage_context& c) {
             const GiNaC::matrix damping = damping_at_equilibrium(c.result, c.simplifier_for_scene());
             c.result.state_space =
                 derive_state_space(c.scene, *c.result.linearization, damping, c.simplifier_for_scene(),
                                    !c.wants(product::transfer));
             c.result.state_space_values = state_space_at_values(c.scene, *c.result.state_space);
         }, "linear system", "linear system", refuses_constraints("`state_space`")},
        // With constraints or a `linearize about` line: A and B in the independent states.
        {stage_id::operating_point, "operating_point", {product::state_space}, {}, {stage_id::equations},
         linearizes_about_operating_point,
         [](stage_context& c) {
             c.result.operating = linearize_about(c.scene, *c.result.equations, c.simplifier_for_scene());
             c.result.state_space = operating_state_space(c.scene, *c.result.operating);
             if (!has_free_coordinate(c.scene, *c.result.state_space))
                 c.result.state_space_values = state_space_at_values(c.scene, *c.result.state_space);
         }, "linear system", "linear system"},
        // About an operating point (constraints, `linearize about`): the eigenvalues of its A.
        {stage_id::critical_operating, "critical", {product::critical}, {}, {stage_id::operating_point},
         linearizes_about_operating_point,
         [](stage_context& c) { c.result.critical = critical_parameters(c.scene, c.result.operating->a); },
         "critical parameters", "", handles_constraints, false},
        {stage_id::transfer, "transfer", {product::transfer}, {}, {stage_id::state_space, stage_id::operating_point},
         has_coordinates,
         [](stage_context& c) {
             c.result.transfer = c.result.operating
                                     ? operating_transfer(c.scene, *c.result.operating, *c.result.state_space)
                                     : transfer_functions(c.scene, *c.result.linearization, *c.result.state_space);
         }, "linear system", "linear system"},
        {stage_id::floquet, "floquet", {product::floquet}, {}, {stage_id::time}, has_coordinates,
         [](stage_context& c) {
             if (!c.result.time || !c.result.time->depends_on_time) {
                 if (c.by_default)
                     return;
                 throw computation_error("`floquet` needs an L that depends on t, and this L does not");
             }
             // Refused here, not by the column: a default run of a scene whose L does not
             // depend on t leaves floquet out above, constraints or not.
             refuse_constraints(c.scene, "`floquet`");
             c.result.floquet = floquet_multipliers(c.scene, *c.result.equations, *c.result.time);
         }, "", ""},
        {stage_id::conserved, "conserved", {product::conserved}, {}, {stage_id::equations}, has_coordinates,
         [](stage_context& c) {
             c.result.conserved = conserved_quantities(c.scene, *c.result.lagrangian, *c.result.equations,
                                                       c.simplifier_for_scene());
         }, "symmetries", "symmetries", refuses_constraints("`conserved`")},
        {stage_id::hamiltonian, "hamiltonian", {product::hamiltonian}, {}, {stage_id::equations}, has_coordinates,
         [](stage_context& c) {
             c.result.hamiltonian = derive_hamiltonian(c.scene, *c.result.lagrangian, *c.result.equations,
                                                       c.simplifier_for_scene());
         }, "", "hamiltonian", refuses_constraints("`hamiltonian`")},
        {stage_id::reduced, "reduced", {product::reduced}, {}, {stage_id::equations}, has_coordinates,
         [](stage_context& c) {
             c.result.reduced =
                 reduce_cyclic(c.scene, *c.result.lagrangian, *c.result.equations, c.simplifier_for_scene());
         }, "symmetries", "symmetries", refuses_constraints("`reduced`")},
        // An `equilibrium` line that names a steady rate: the motion on the reduced system.
        {stage_id::steady, "steady", {}, {product::equilibrium, product::linearization, product::characteristic, product::frequencies,
                        product::reduced}, {stage_id::reduced}, has_steady,
         [](stage_context& c) {
             c.result.steady = steady_motion(c.scene, *c.result.lagrangian, *c.result.reduced, c.simplifier_for_scene());
             c.result.steady->at_values = steady_stability_at_values(c.scene, *c.result.steady);
         }, "", "", refuses_constraints("a steady motion")},
        {stage_id::simulation, "simulation", {product::simulation}, {}, {stage_id::equations}, any_scene,
         [](stage_context& c) {
             if (!c.result.lagrangian) {
                 if (!has_free_body(c.scene))
                     throw computation_error("the scene has no coordinates to simulate");
                 c.result.simulation = simulate_free_body(c.scene, c.simulation);
             } else {
                 c.result.simulation = !c.scene.constraints.empty()
                     ? simulate_constrained(c.scene, *c.result.equations, c.simulation)
                     : simulate(c.scene, *c.result.equations, equilibrium_of(c), c.simulation);
             }
         }, "simulation", "", handles_constraints, false},
        {stage_id::workprecision, "workprecision", {product::workprecision}, {}, {stage_id::equations}, any_scene,
         [](stage_context& c) {
             if (!c.result.lagrangian) {
                 if (!has_free_body(c.scene))
                     throw computation_error("the scene has no coordinates to simulate");
                 c.result.workprecision = free_body_work_precision(c.scene, c.simulation);
             } else {
                 c.result.workprecision =
                     scene_work_precision(c.scene, *c.result.equations, equilibrium_of(c), c.simulation);
             }
         }, "simulation", "", refuses_constraints("`workprecision`"), false},
        {stage_id::virial, "virial", {product::virial}, {}, {stage_id::lagrangian, stage_id::simulation},
         has_coordinates,
         [](stage_context& c) {
             if (!c.result.simulation)
                 throw computation_error("`virial` needs a simulation: a `simulate until T` line or --until");
             c.result.virial = time_averages(c.scene, *c.result.lagrangian, *c.result.simulation);
         }, "simulation", "", handles_constraints, false},
        // Last: checks numerically whatever symbolic results the stages above computed.
        {stage_id::verification, "verification", {product::verification}, every_product(), {},
         [](const model& scene) { return !scene.coordinates.empty() || !scene.bodies.empty(); },
         [](stage_context& c) {
             c.result.verification = verify_results(c.scene, verification_input_of(c.result), c.result.wanted);
             if (c.result.operating && c.result.equations)
                 c.result.verification->entries.push_back(
                     verify_operating_point(c.scene, *c.result.equations, *c.result.operating));
         }, "", ""},
    };
    return table;
}

} // namespace

verification_input verification_input_of(const analysis& r)
{
    verification_input input;
#define LAGRANGE_POINT_AT(type, name) input.name = r.name ? &*r.name : nullptr;
    LAGRANGE_VERIFIED_RESULTS(LAGRANGE_POINT_AT)
#undef LAGRANGE_POINT_AT
    // Routh's reduction is checked where it is shown; A and B about an operating point are
    // checked by the verification stage itself.
    if (!r.wanted.count(product::reduced))
        input.reduced = nullptr;
    if (r.operating)
        input.state_space = nullptr;
    return input;
}

const std::set<product>& available_products()
{
    static const std::set<product> products = [] {
        std::set<product> all;
        for (const stage_definition& stage : stage_table())
            all.insert(stage.produces.begin(), stage.produces.end());
        return all;
    }();
    return products;
}

namespace {

bool wants_any(const std::set<product>& wanted, const std::vector<product>& products)
{
    for (product p : products)
        if (wanted.count(p))
            return true;
    return false;
}

const stage_definition& find_stage(stage_id id)
{
    const stage_definition& stage = stage_table().at(static_cast<std::size_t>(id));
    if (stage.id != id) // the rows are in the order of stage_id
        throw std::logic_error("the stage table is out of the order of stage_id at `" + stage.name + "`");
    return stage;
}

/// The stages to run for `wanted`: those that apply to the scene and compute or are shown
/// with a wanted product, and, walking back, what they need.
std::set<stage_id> plan(const model& scene, const std::set<product>& wanted)
{
    std::set<stage_id> chosen;
    std::function<void(const stage_definition&)> choose = [&](const stage_definition& stage) {
        if (!stage.applies(scene) || !chosen.insert(stage.id).second)
            return;
        for (stage_id need : stage.needs)
            choose(find_stage(need));
    };
    for (const stage_definition& stage : stage_table())
        if (wants_any(wanted, stage.produces) || wants_any(wanted, stage.shown_with))
            choose(stage);
    return chosen;
}

/// Times one stage and records it. A failure inside the algebra (GiNaC throws
/// plain std::exceptions with internal messages) becomes a computation_error
/// that names the stage.
void run_stage(stage_context& context, const stage_definition& stage, const budget_limits& limits)
{
    auto start = std::chrono::steady_clock::now();
    try {
        budget_scope budget(stage.name, limits, stage.watched);
        if (!stage.constraints.handled)
            refuse_constraints(context.scene, stage.constraints.what);
        stage.run(context);
    } catch (const computation_error&) {
        throw;
    } catch (const scene_error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception&) {
        throw computation_error("the `" + stage.name + "` stage could not be done for this scene symbolically");
    }
    std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    context.result.stages.push_back({stage.name, elapsed.count()});
    if (stage.id == stage_id::simulation && context.result.simulation &&
        context.result.simulation->integration_runs > 0) {
        const simulation_result& s = *context.result.simulation;
        auto& parts = context.result.stages.back().parts;
        parts = {{"preparation (equations compiled or loaded, linearization)", s.preparation_seconds}};
        if (s.jacobian_seconds > 0)
            parts.push_back({"Jacobian compiled or loaded (the implicit method's)", s.jacobian_seconds});
        parts.push_back({"integration (" + std::to_string(s.integration_runs) +
                             (s.integration_runs == 1 ? " run" : " runs") + ": the run reported, reference runs and reruns)",
                         s.integration_seconds});
    }
}

/// Whether a budget overrun in `stage` leaves the wanted frequencies to be given numerically.
bool numeric_frequencies_instead(const model& scene, const analysis& result, const stage_definition& stage)
{
    return stage.numeric_fallback && !result.modes && numeric_frequencies_possible(scene, result);
}

/// Runs the planned stages in table order. A stage runs once all that it needs has
/// run; a budget overrun leaves out the stage (and so what needs it) with a note, and
/// in a default run a failure leaves out the rest of the stage's group with a note.
analysis run_stages(const model& scene, const std::set<product>& wanted, const budget_limits& limits,
                    const simulation_settings& simulation, std::optional<budget_exceeded>& exceeded)
{
    analysis result;
    result.scene = &scene;
    const std::set<product> verification_only{product::verification};
    const std::set<product>& asked = !wanted.empty() ? wanted : scene.wanted;
    // `verification` alone checks what a default run computes: those products, with their checks
    const bool by_default = asked.empty() || asked == verification_only;
    result.wanted = !asked.empty() ? asked : default_products(scene);
    if (asked == verification_only)
        result.wanted.merge(default_products(scene));
    for (product p : result.wanted)
        if (!available_products().count(p))
            throw computation_error("`" + name_of(p) + "` is not computed by this version of lagrange yet");
    if (scene.coordinates.empty() && std::any_of(result.wanted.begin(), result.wanted.end(), needs_coordinates))
        throw computation_error("the scene has no coordinates, so it has no equations of motion "
                                "(only `inertia` and `euler`)");

    stage_context context{scene, result, simulation, by_default, std::nullopt};
    std::set<stage_id> planned = plan(scene, result.wanted);
    // A stage may want more (the numeric modes where the symbolic ones fall short): the
    // stages after it are planned again.
    auto replan = [&] { planned = plan(scene, result.wanted); };
    std::set<stage_id> done;
    std::set<std::string> failed_groups;
    for (const stage_definition& stage : stage_table()) {
        if (!planned.count(stage.id) || failed_groups.count(stage.group))
            continue;
        bool ready = true;
        for (stage_id need : stage.needs)
            ready = ready && (done.count(need) || !find_stage(need).applies(scene));
        if (!ready)
            continue;
        const std::size_t wanted_before = result.wanted.size(); // a stage may only add
        try {
            run_stage(context, stage, limits);
            done.insert(stage.id);
        } catch (const budget_exceeded& error) {
            if (stage.budget_note.empty()) {
                if (stage.group.empty() || !by_default)
                    throw;
                result.notes.push_back(stage.group + " not computed: " + error.what());
                failed_groups.insert(stage.group);
                continue;
            }
            std::string note = stage.budget_note + " not computed: " + error.what();
            if (stage.numeric_fallback && result.wanted.count(product::numeric))
                note += "; the numeric modes are still computed";
            else if (numeric_frequencies_instead(scene, result, stage)) {
                // degrade: the frequencies at the `values` points instead of in closed form
                want_numeric(context);
                note += "; the frequencies are given numerically at the `values` points instead";
            }
            result.notes.push_back(note);
            exceeded = error;
        } catch (const computation_error& error) {
            if (stage.group.empty() || !by_default)
                throw;
            result.notes.push_back(stage.group + " not computed: " + error.what());
            failed_groups.insert(stage.group);
        }
        if (result.wanted.size() != wanted_before)
            replan();
    }
    return result;
}

/// True if any stage that computes a wanted product has run.
bool computed_any(const analysis& result)
{
    for (const stage_time& ran : result.stages)
        for (const stage_definition& stage : stage_table())
            if (stage.name == ran.stage && wants_any(result.wanted, stage.produces))
                return true;
    return false;
}

} // namespace

namespace {

/// analyze() but for equations too large to print, which `export` does not print.
analysis analyze_unprinted(const model& scene, const std::set<product>& wanted, const budget_limits& limits,
                           const simulation_settings& simulation)
{
    std::optional<budget_exceeded> exceeded;
    simulation_settings settings = simulation; // the C compiler runs within the time budget too
    settings.compile_seconds = std::min(settings.compile_seconds, limits.max_seconds);
    analysis result = run_stages(scene, wanted, limits, settings, exceeded);
    if (exceeded && !computed_any(result))
        throw *exceeded;
    return result;
}

} // namespace

analysis analyze(const model& scene, const std::set<product>& wanted, const budget_limits& limits,
                 const simulation_settings& simulation)
{
    analysis result = analyze_unprinted(scene, wanted, limits, simulation);
    const std::set<product>& asked = !wanted.empty() ? wanted : scene.wanted;
    if (asked.count(product::equations) && result.equations && !result.equations->too_large_to_print.empty())
        throw computation_error(result.equations->too_large_to_print);
    return result;
}

analysis analyze(const model& scene, const std::set<product>& wanted, const simulation_settings& simulation)
{
    return analyze(scene, wanted, budget_limits{}, simulation);
}

analysis analyze_for_export(const model& scene, const budget_limits& limits)
{
    std::set<product> wanted{product::equations};
    // the conserved quantities of a Lagrangian alone (as the `conserved` stage has them)
    if (scene.constraints.empty() && !scene.has_generalized_forces())
        wanted.insert(product::conserved);
    if (scene.constraints.empty() && !scene.steady)
        try {
            std::set<product> linear = wanted;
            linear.insert(product::linearization);
            return analyze_unprinted(scene, linear, limits, {});
        } catch (const computation_error&) { // budget_exceeded too: then without the linearization
        }
    return analyze_unprinted(scene, wanted, limits, {});
}

point_modes numeric_modes_path(const analysis& result)
{
    if (!result.scene || !result.linearization)
        throw std::invalid_argument("numeric_modes_path: the analysis has no linearization");
    const std::optional<GiNaC::matrix> damping = damping_at_rest(result, make_simplifier(*result.scene));
    return point_modes(*result.scene, *result.linearization, damping ? &*damping : nullptr);
}

} // namespace lagrange
