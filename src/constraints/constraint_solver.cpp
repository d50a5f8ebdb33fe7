#include "edyn/constraints/constraint_solver.hpp"
#include "edyn/constraints/constraint_links.hpp"
#include "edyn/constraints/constraints.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/parallel/stage_queue.hpp"
#include <algorithm>
#include <array>
#include <numeric>
#include <stdexcept>
#include <string>
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
        // The program may have written the constraint's fields since make_constraint checked them.
        try {
            validate_constraint(con);
        } catch (const std::invalid_argument &error) {
            throw detail::entity_refusal(e, "step: constraint entity ",
                                         std::string(", changed after it was made: ") + error.what());
        }
        // Its bodies are fixed when it is made: the islands, the bodies' lists of constraints
        // and sleeping all follow the pair it was made with, which the solver alone would leave.
        if (auto *links = registry.try_get<constraint_links>(e);
            links && links->num_constraints == 1 &&
            (links->body[0] != con.body[0] || links->body[1] != con.body[1])) {
            throw detail::entity_refusal(
                e, "step: constraint entity ",
                std::string(", changed after it was made: make_constraint<") +
                    constraint_type_name<component> +
                    ">: body[] cannot change once the constraint is made; destroy it "
                    "and make another joining the new bodies");
        }
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
// Joints per parallel range when measuring their geometry, which costs a fraction of a pass.
constexpr std::uint32_t joints_per_refresh = 256;
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
// colour.
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
}

} // namespace

namespace {

// Marks unprojected every joint of a group that holds a joint open wider than `max_gap` (see
// constraint_solver_settings::max_projected_gap). A group is the moving bodies the joints link,
// one to the next: bodies that do not move (the ground) join nothing.
void leave_wide_groups_unprojected(constraint_solver_state &state, std::span<const solver_body> bodies,
                                   scalar max_gap) {
    if (state.gap_anchors.empty()) return;
    auto &group_of = state.group_of;
    group_of.resize(bodies.size());
    std::iota(group_of.begin(), group_of.end(), solver_body_index(0));
    auto root = [&](solver_body_index i) {
        while (group_of[i] != i) {
            group_of[i] = group_of[group_of[i]];
            i = group_of[i];
        }
        return i;
    };
    for (auto *anchor : state.gap_anchors) {
        auto a = anchor->body[0], b = anchor->body[1];
        if (!moves(bodies[a]) || !moves(bodies[b])) continue;
        auto ra = root(a), rb = root(b);
        if (ra != rb) group_of[std::max(ra, rb)] = std::min(ra, rb);
    }
    state.group_wide.assign(bodies.size(), 0);
    for (std::size_t k = 0; k < state.gap_anchors.size(); ++k) {
        if (state.gaps[k] <= max_gap) continue;
        for (auto body : state.gap_anchors[k]->body)
            if (moves(bodies[body])) state.group_wide[root(body)] = 1;
    }
    for (auto *anchor : state.gap_anchors) {
        auto body = moves(bodies[anchor->body[0]]) ? anchor->body[0] : anchor->body[1];
        anchor->unprojected = moves(bodies[body]) && state.group_wide[root(body)];
    }
}

} // namespace

void gather_constraints(const registry &registry, constraint_solver_state &state, body_index_map body_index,
                        std::span<const solver_body> bodies, scalar max_projected_gap) {
    state.colouring.reset(bodies);
    for_each_batch(state, [&](auto &batch) { gather_batch(registry, batch, body_index, state.colouring); });
    number_colour_blocks(state);

    state.gap_anchors.clear();
    state.gaps.clear();
    for_each_batch(state, [&](auto &batch) {
        for (auto &s : batch.solvers) {
            if constexpr (requires { projected_pivots(s); }) {
                if (auto *anchor = projected_pivots(s)) {
                    state.gap_anchors.push_back(anchor);
                    state.gaps.push_back(length(anchor->separation));
                }
            } else if constexpr (requires {
                                     project_positions(s, std::span<solver_body>{}, scalar(1), scalar(1));
                                 }) {
                state.gap_anchors.push_back(&s.anchor);
                state.gaps.push_back(projection_gap(s));
            }
        }
    });
    leave_wide_groups_unprojected(state, bodies, max_projected_gap);

    state.projected_pivots.clear();
    state.other_projected.clear();
    for_each_batch(state, [&](auto &batch) {
        for (auto &s : batch.solvers) {
            if constexpr (requires { projected_pivots(s); }) {
                auto *anchor = projected_pivots(s);
                if (anchor && !anchor->unprojected) state.projected_pivots.push_back(anchor);
            } else if constexpr (requires {
                                     project_positions(s, std::span<solver_body>{}, scalar(1), scalar(1));
                                 }) {
                if (s.anchor.unprojected) continue;
                state.other_projected.push_back(s.anchor.body[0]);
                state.other_projected.push_back(s.anchor.body[1]);
            }
        }
    });
    build_joint_paths(state.paths, state.projected_pivots, state.other_projected, bodies);
}

namespace {

// Queues fn(solver) for every joint, colour after colour: each colour a stage of `queue`, its
// blocks (of one type each) run at once on the scheduler's threads. Colours of one block each
// that follow one another (a chain's joints, one colour each) are one stage of one block, run in
// order on one thread: as parallel_for_stages would run them, at the cost of one stage. fn is
// copied into the queue.
template<typename Fn>
void queue_in_colour_order(constraint_solver_state &state, stage_queue &queue, Fn fn) {
    auto *joints = &state;
    auto run_blocks = [joints, fn](std::uint32_t first, std::uint32_t last) {
        for (auto b = first; b < last; ++b) {
            auto &block = joints->blocks[b];
            with_batch(*joints, block.type, [&](auto &batch) {
                for (auto i = block.first; i < block.last; ++i)
                    fn(batch.solvers[i]);
            });
        }
    };
    auto &begin = state.colour_block_begin;
    for (std::size_t k = 0; k + 1 < begin.size();) {
        auto first = begin[k];
        auto end = k + 1;
        if (begin[k + 1] - first == 1) {
            while (end + 1 < begin.size() && begin[end + 1] - begin[end] <= 1)
                ++end;
            queue.add(1, [run_blocks, first, last = begin[end]](std::uint32_t) { run_blocks(first, last); });
        } else {
            queue.add(begin[k + 1] - first,
                      [run_blocks, first](std::uint32_t b) { run_blocks(first + b, first + b + 1); });
        }
        k = end;
    }
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
    ctx.max_correction_speed = settings.max_correction_speed;
    ctx.restitution_threshold = settings.restitution_threshold;
    return ctx;
}

void refresh_joint_geometry(constraint_solver_state &state, std::span<const solver_body> bodies,
                            stage_queue &queue) {
    // Each joint writes only its own state: any order gives the same result.
    for_each_batch(state, [&](auto &batch) {
        using solver = std::remove_reference_t<decltype(batch.solvers[0])>;
        constexpr bool has_anchor = requires(solver & s) { s.anchor; };
        constexpr bool has_geometry = requires(solver & s) { refresh_geometry(s, bodies); };
        // Joints whose rows read no geometry (gravity) have nothing to refresh.
        if constexpr (has_anchor || has_geometry) {
            auto *solvers = batch.solvers.data();
            queue.add_for(0u, std::uint32_t(batch.solvers.size()), joints_per_refresh,
                          [solvers, bodies](std::uint32_t i) {
                              auto &s = solvers[i];
                              if constexpr (has_anchor) {
                                  refresh_pose(s.anchor, bodies[s.anchor.body[0]], bodies[s.anchor.body[1]]);
                              }
                              if constexpr (has_geometry) refresh_geometry(s, bodies);
                          });
        }
    });
}

void warm_start_constraints(constraint_solver_state &state, std::span<solver_body> bodies,
                            stage_queue &queue) {
    queue_in_colour_order(state, queue, [bodies](auto &s) { warm_start(s, bodies); });
}

void solve_joint_constraints(constraint_solver_state &state, std::span<solver_body> bodies,
                             const constraint_solve_context &ctx, stage_queue &queue) {
    state.inv_h = ctx.inv_h;
    queue_in_colour_order(state, queue, [bodies, ctx](auto &s) { solve(s, bodies, ctx); });
}

void project_joint_positions(constraint_solver_state &state, std::span<solver_body> bodies,
                             const constraint_solver_settings &settings, stage_queue &queue) {
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
    auto fraction = settings.position_projection;
    auto inv_h = state.inv_h;
    for (unsigned pass = 0; pass < settings.position_projection_iterations; ++pass) {
        project_joint_paths(state.paths, bodies, fraction, inv_h, pass == 0, queue);
        if (!others) continue;
        queue_in_colour_order(state, queue, [bodies, fraction, inv_h](auto &s) {
            if constexpr (requires { project_positions(s, bodies, fraction, inv_h); }) {
                project_positions(s, bodies, fraction, inv_h);
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
