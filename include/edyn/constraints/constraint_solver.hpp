#ifndef EDYN_CONSTRAINTS_CONSTRAINT_SOLVER_HPP
#define EDYN_CONSTRAINTS_CONSTRAINT_SOLVER_HPP

#include "edyn/constraints/cone_constraint.hpp"
#include "edyn/constraints/constraint_colouring.hpp"
#include "edyn/constraints/cvjoint_constraint.hpp"
#include "edyn/constraints/distance_constraint.hpp"
#include "edyn/constraints/generic_constraint.hpp"
#include "edyn/constraints/gravity_constraint.hpp"
#include "edyn/constraints/hinge_constraint.hpp"
#include "edyn/constraints/null_constraint.hpp"
#include "edyn/constraints/point_constraint.hpp"
#include "edyn/constraints/soft_distance_constraint.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <cstdint>
#include <span>
#include <tuple>
#include <vector>

namespace edyn {

// Tuning of joints, shared by every joint of a step.
struct constraint_solver_settings {
    // Rigid joints correct their position error as a spring of this frequency and damping
    // ratio in the biased pass; stiffer than contacts, since joints carry whole chains.
    scalar joint_hertz{60};
    scalar joint_damping_ratio{1};
    // The joint frequency is capped at this fraction of the sub-step rate, for stability.
    scalar max_hertz_ratio{scalar(0.25)};
    // A limit reached slower than this does not bounce (m/s or rad/s).
    scalar restitution_threshold{scalar(0.1)};
    // Fraction of the joints' pivot separation removed by moving the bodies after each
    // sub-step's integration (see project_point); 0 leaves it to the soft correction alone.
    scalar position_projection{1};
    // Passes of that projection over all the joints. Joined bodies of very different masses
    // (a rag doll's head on its neck) stretch their joints by centimetres under impacts with
    // one pass at 60 Hz, by millimetres with four.
    unsigned position_projection_iterations{4};
};

// The constraints of one type as the solver sees them this step, and where they came from, in
// colour order: colour k is [colour_begin[k], colour_begin[k + 1]) (see constraint_colouring).
template<typename Solver>
struct constraint_batch {
    std::vector<Solver> solvers;
    std::vector<entity> entities;
    std::vector<std::uint32_t> colour_begin;
    // Scratch for sorting by colour, reused from step to step.
    std::vector<Solver> unsorted;
    std::vector<entity> unsorted_entities;
    std::vector<std::uint32_t> colours;
};

// Every joint of a step, packed per type in contiguous arrays reused from step to step.
struct constraint_solver_state {
    std::tuple<constraint_batch<point_constraint_solver>, constraint_batch<distance_constraint_solver>,
               constraint_batch<soft_distance_constraint_solver>, constraint_batch<hinge_constraint_solver>,
               constraint_batch<cvjoint_constraint_solver>, constraint_batch<cone_constraint_solver>,
               constraint_batch<generic_constraint_solver>, constraint_batch<gravity_constraint_solver>>
        batches;
    // 1 / h of the sub-step the joints were last solved with: the projection that follows turns
    // its corrections into velocities over that sub-step.
    scalar inv_h{0};
    // Colours the joints in the order they are solved (type by type, each in the view's order),
    // so that each colour's joints are solved at once on the scheduler's threads and the
    // result is the same bit for bit. Null runs every pass on the calling thread.
    constraint_colouring colouring;
    task_scheduler *scheduler{nullptr};
};

// Maps an entity's index to its solver body (0, the static body, when it has none).
using body_index_map = std::span<const std::uint32_t>;

// The solver body of `e`: entities past the end of the map have none either.
inline solver_body_index body_index_of(body_index_map body_index, entity e) noexcept {
    auto i = to_index(e);
    return i < body_index.size() ? body_index[i] : static_solver_body;
}

// Packs every awake constraint with at least one body in the solver, with its geometry at the
// start of the step and last step's impulses, and colours them for the bodies they join.
void gather_constraints(const registry &registry, constraint_solver_state &state, body_index_map body_index,
                        std::span<const solver_body> bodies);

constraint_solve_context make_constraint_solve_context(const constraint_solver_settings &settings, scalar h,
                                                       bool use_bias) noexcept;

// Re-applies the accumulated impulses, at the start of each sub-step.
void warm_start_constraints(constraint_solver_state &state, std::span<solver_body> bodies);

// One Gauss-Seidel pass over every joint row (biased or relax, as ctx says).
void solve_joint_constraints(constraint_solver_state &state, std::span<solver_body> bodies,
                             const constraint_solve_context &ctx);

// Position projection of the joints that keep pivots together, after integrating positions.
void project_joint_positions(constraint_solver_state &state, std::span<solver_body> bodies,
                             const constraint_solver_settings &settings);

// Stores the impulses in the components, for next step's warm start.
void store_constraint_impulses(registry &registry, const constraint_solver_state &state);

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONSTRAINT_SOLVER_HPP
