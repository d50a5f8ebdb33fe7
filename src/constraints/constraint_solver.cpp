#include "edyn/constraints/constraint_solver.hpp"
#include "edyn/constraints/constraints.hpp"
#include "edyn/dynamics/tags.hpp"
#include <algorithm>

namespace edyn {

namespace {

template<typename Solver>
void gather_batch(const registry &registry, constraint_batch<Solver> &batch, body_index_map body_index) {
    using component = typename Solver::component;
    batch.solvers.clear();
    batch.entities.clear();
    auto view = registry.view<component>(exclude<sleeping_tag>);
    for (auto e : view) {
        auto &con = view.template get<component>(e);
        constraint_body_indices indices{body_index_of(body_index, con.body[0]),
                                        body_index_of(body_index, con.body[1])};
        // Neither body moves this step (both static, or asleep): nothing to solve.
        if (indices.a == 0 && indices.b == 0) continue;
        batch.solvers.push_back(make_constraint_solver(registry, con, indices));
        batch.entities.push_back(e);
    }
}

template<typename Fn>
void for_each_batch(constraint_solver_state &state, Fn &&fn) {
    std::apply([&](auto &...batch) { (fn(batch), ...); }, state.batches);
}

template<typename Fn>
void for_each_batch(const constraint_solver_state &state, Fn &&fn) {
    std::apply([&](const auto &...batch) { (fn(batch), ...); }, state.batches);
}

} // namespace

void gather_constraints(const registry &registry, constraint_solver_state &state, body_index_map body_index) {
    for_each_batch(state, [&](auto &batch) { gather_batch(registry, batch, body_index); });
}

constraint_solve_context make_constraint_solve_context(const constraint_solver_settings &settings, scalar h,
                                                       bool use_bias) noexcept {
    constraint_solve_context ctx;
    ctx.h = h;
    ctx.inv_h = scalar(1) / h;
    // A spring stiffer than a fraction of the sub-step rate cannot be integrated stably.
    auto hertz = std::min(settings.joint_hertz, settings.max_hertz_ratio / h);
    ctx.joint = make_softness(hertz, settings.joint_damping_ratio, h);
    ctx.use_bias = use_bias;
    ctx.rigid_pivots = settings.position_projection > 0;
    ctx.restitution_threshold = settings.restitution_threshold;
    return ctx;
}

void warm_start_constraints(constraint_solver_state &state, std::span<solver_body> bodies) noexcept {
    for_each_batch(state, [&](auto &batch) {
        for (auto &s : batch.solvers)
            warm_start(s, bodies);
    });
}

void solve_joint_constraints(constraint_solver_state &state, std::span<solver_body> bodies,
                             const constraint_solve_context &ctx) noexcept {
    state.inv_h = ctx.inv_h;
    for_each_batch(state, [&](auto &batch) {
        for (auto &s : batch.solvers)
            solve(s, bodies, ctx);
    });
}

void project_joint_positions(constraint_solver_state &state, std::span<solver_body> bodies,
                             const constraint_solver_settings &settings) noexcept {
    if (settings.position_projection <= 0) return;
    // Each joint's projection moves bodies that other joints share: in a chain one pass leaves
    // the error spread along it, and a few passes gather it out.
    for (unsigned pass = 0; pass < settings.position_projection_iterations; ++pass) {
        for_each_batch(state, [&](auto &batch) {
            for (auto &s : batch.solvers) {
                if constexpr (requires {
                                  project_positions(s, bodies, settings.position_projection, state.inv_h);
                              }) {
                    project_positions(s, bodies, settings.position_projection, state.inv_h);
                }
            }
        });
    }
}

void store_constraint_impulses(registry &registry, const constraint_solver_state &state) {
    for_each_batch(state, [&](const auto &batch) {
        using component = typename std::decay_t<decltype(batch.solvers)>::value_type::component;
        for (std::size_t i = 0; i < batch.solvers.size(); ++i) {
            store_impulses(batch.solvers[i], registry.get<component>(batch.entities[i]));
        }
    });
}

} // namespace edyn
