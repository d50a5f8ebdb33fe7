#include "edyn/constraints/constraint_solver.hpp"
#include "edyn/constraints/constraints.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/parallel/parallel_for.hpp"
#include "edyn/parallel/parallel_for_stages.hpp"
#include <algorithm>
#include <array>
#include <tuple>
#include <utility>

namespace edyn {

namespace {

template<typename Solver>
void gather_batch(const registry &registry, constraint_batch<Solver> &batch, body_index_map body_index,
                  constraint_colouring &colouring) {
    using component = typename Solver::component;
    batch.unsorted.clear();
    batch.unsorted_entities.clear();
    batch.colours.clear();
    auto view = registry.view<component>(exclude<sleeping_tag>);
    std::uint32_t num_colours = 0;
    for (auto e : view) {
        auto &con = view.template get<component>(e);
        constraint_body_indices indices{body_index_of(body_index, con.body[0]),
                                        body_index_of(body_index, con.body[1])};
        // Neither body moves this step (both static, or asleep): nothing to solve.
        if (indices.a == 0 && indices.b == 0) continue;
        batch.unsorted.push_back(make_constraint_solver(registry, con, indices));
        batch.unsorted_entities.push_back(e);
        batch.colours.push_back(colouring.assign(indices.a, indices.b));
        num_colours = std::max(num_colours, batch.colours.back() + 1);
    }

    // Colour by colour, in the order found within a colour (a counting sort).
    batch.colour_begin.assign(num_colours + 1, 0);
    for (auto colour : batch.colours)
        ++batch.colour_begin[colour + 1];
    for (std::uint32_t k = 0; k < num_colours; ++k)
        batch.colour_begin[k + 1] += batch.colour_begin[k];
    batch.solvers.resize(batch.unsorted.size());
    batch.entities.resize(batch.unsorted.size());
    for (std::size_t i = 0; i < batch.unsorted.size(); ++i) {
        auto place = batch.colour_begin[batch.colours[i]]++;
        batch.solvers[place] = batch.unsorted[i];
        batch.entities[place] = batch.unsorted_entities[i];
    }
    // The counters now hold each colour's end; shifted back, its beginning.
    for (auto k = num_colours; k > 0; --k)
        batch.colour_begin[k] = batch.colour_begin[k - 1];
    batch.colour_begin[0] = 0;
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

namespace {

// Joints per parallel range: a joint's rows cost more than a contact's.
constexpr std::uint32_t joints_per_task = 32;
constexpr std::size_t num_types = std::tuple_size_v<decltype(constraint_solver_state::batches)>;

// Calls fn(batch) with the batch at place `type` of state.batches.
template<typename Fn>
void with_batch(constraint_solver_state &state, std::uint32_t type, Fn &&fn) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (void)((type == I && (fn(std::get<I>(state.batches)), true)) || ...);
    }
    (std::make_index_sequence<num_types>{});
}

// Cuts each colour's joints of each type into blocks of at most joints_per_task, colour by
// colour; then joins the blocks that follow one another in a batch into the runs of a pass on
// one thread.
void number_colour_blocks(constraint_solver_state &state) {
    // The types that have joints this step: a chain has as many colours as joints.
    std::array<std::uint32_t, num_types> active{};
    std::uint32_t num_active = 0, type = 0;
    for_each_batch(state, [&](auto &batch) {
        if (!batch.solvers.empty()) active[num_active++] = type;
        ++type;
    });
    state.blocks.clear();
    state.colour_block_begin.clear();
    for (std::size_t k = 0; k < state.colouring.num_colours(); ++k) {
        state.colour_block_begin.push_back(static_cast<std::uint32_t>(state.blocks.size()));
        for (std::uint32_t a = 0; a < num_active; ++a) {
            with_batch(state, active[a], [&](auto &batch) {
                if (k + 1 >= batch.colour_begin.size()) return;
                auto end = batch.colour_begin[k + 1];
                for (auto first = batch.colour_begin[k]; first < end; first += joints_per_task)
                    state.blocks.push_back({active[a], first, std::min(first + joints_per_task, end)});
            });
        }
    }
    state.colour_block_begin.push_back(static_cast<std::uint32_t>(state.blocks.size()));

    state.runs.clear();
    for (auto &block : state.blocks) {
        if (!state.runs.empty() && state.runs.back().type == block.type &&
            state.runs.back().last == block.first) {
            state.runs.back().last = block.last;
        } else {
            state.runs.push_back(block);
        }
    }
}

} // namespace

void gather_constraints(const registry &registry, constraint_solver_state &state, body_index_map body_index,
                        std::span<const solver_body> bodies) {
    state.colouring.reset(bodies);
    for_each_batch(state, [&](auto &batch) { gather_batch(registry, batch, body_index, state.colouring); });
    number_colour_blocks(state);

    state.projected_pivots.clear();
    state.other_projected.clear();
    for_each_batch(state, [&](auto &batch) {
        for (auto &s : batch.solvers) {
            if constexpr (requires { projected_pivots(s); }) {
                if (auto *anchor = projected_pivots(s)) state.projected_pivots.push_back(anchor);
            } else if constexpr (requires {
                                     project_positions(s, std::span<solver_body>{}, scalar(1), scalar(1));
                                 }) {
                state.other_projected.push_back(s.anchor.body[0]);
                state.other_projected.push_back(s.anchor.body[1]);
            }
        }
    });
    build_joint_paths(state.paths, state.projected_pivots, state.other_projected, bodies);
}

namespace {

// Calls fn(solver) for every joint, colour after colour, each colour's joints (of every type) at
// once on the scheduler's threads; all colours in one task (see parallel_for_stages). On one
// thread the joints go in the same order, run after run.
template<typename Fn>
void for_each_in_colour_order(constraint_solver_state &state, Fn &&fn) {
    auto run_joints = [&](const constraint_solver_state::joint_run &run) {
        with_batch(state, run.type, [&](auto &batch) {
            for (auto i = run.first; i < run.last; ++i)
                fn(batch.solvers[i]);
        });
    };
    if (!state.scheduler || state.scheduler->concurrency() < 2) {
        for (auto &run : state.runs)
            run_joints(run);
        return;
    }
    parallel_for_stages(state.scheduler, state.block_sync, state.colour_block_begin,
                        [&](std::size_t, std::uint32_t b) { run_joints(state.blocks[b]); });
}

} // namespace

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

void refresh_joint_geometry(constraint_solver_state &state, std::span<const solver_body> bodies) {
    // Each joint writes only its own state: any order gives the same result.
    for_each_batch(state, [&](auto &batch) {
        parallel_for(state.scheduler, std::size_t(0), batch.solvers.size(), joints_per_task,
                     [&](std::size_t i) {
                         auto &s = batch.solvers[i];
                         if constexpr (requires { s.anchor; }) {
                             refresh_pose(s.anchor, bodies[s.anchor.body[0]], bodies[s.anchor.body[1]]);
                         }
                         if constexpr (requires { refresh_geometry(s, bodies); }) refresh_geometry(s, bodies);
                     });
    });
}

void warm_start_constraints(constraint_solver_state &state, std::span<solver_body> bodies) {
    for_each_in_colour_order(state, [&](auto &s) { warm_start(s, bodies); });
}

void solve_joint_constraints(constraint_solver_state &state, std::span<solver_body> bodies,
                             const constraint_solve_context &ctx) {
    state.inv_h = ctx.inv_h;
    for_each_in_colour_order(state, [&](auto &s) { solve(s, bodies, ctx); });
}

void project_joint_positions(constraint_solver_state &state, std::span<solver_body> bodies,
                             const constraint_solver_settings &settings) {
    if (settings.position_projection <= 0) return;
    // Each pass solves every path of pivots exactly, then the other joints one at a time; the
    // paths meet one another, and those joints, at shared bodies, which a few passes settle.
    // Every pass reuses the factors of the pass's first: K changes little over a sub-step's
    // corrections.
    bool others = false;
    for_each_batch(state, [&](auto &batch) {
        using solver = typename std::decay_t<decltype(batch.solvers)>::value_type;
        if constexpr (requires(solver & s) { project_positions(s, bodies, scalar(1), scalar(1)); })
            others = others || !batch.solvers.empty();
    });
    for (unsigned pass = 0; pass < settings.position_projection_iterations; ++pass) {
        project_joint_paths(state.paths, bodies, settings.position_projection, state.inv_h, pass == 0,
                            state.scheduler);
        if (!others) continue;
        for_each_in_colour_order(state, [&](auto &s) {
            if constexpr (requires {
                              project_positions(s, bodies, settings.position_projection, state.inv_h);
                          }) {
                project_positions(s, bodies, settings.position_projection, state.inv_h);
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
