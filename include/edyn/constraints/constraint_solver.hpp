#ifndef EDYN_CONSTRAINTS_CONSTRAINT_SOLVER_HPP
#define EDYN_CONSTRAINTS_CONSTRAINT_SOLVER_HPP

#include "edyn/constraints/cone_constraint.hpp"
#include "edyn/constraints/constraint_colouring.hpp"
#include "edyn/constraints/cvjoint_constraint.hpp"
#include "edyn/constraints/distance_constraint.hpp"
#include "edyn/constraints/generic_constraint.hpp"
#include "edyn/constraints/gravity_constraint.hpp"
#include "edyn/constraints/hinge_constraint.hpp"
#include "edyn/constraints/joint_paths.hpp"
#include "edyn/constraints/null_constraint.hpp"
#include "edyn/constraints/point_constraint.hpp"
#include "edyn/constraints/soft_distance_constraint.hpp"
#include "edyn/parallel/stage_queue.hpp"
#include <cstdint>
#include <span>
#include <tuple>
#include <vector>

namespace edyn {

/// Tuning of joints, shared by every joint of a step.
/// Held by the world's settings (`settings::joint`); the solver reads it at every step.
struct constraint_solver_settings {
    /// Rigid joints correct their position error as a spring of this frequency and damping
    /// ratio in the biased pass; stiffer than contacts, since joints carry whole chains.
    /// The frequency in Hz; default 60.
    scalar joint_hertz{60};
    /// Damping ratio of that spring (1: critically damped, the default).
    scalar joint_damping_ratio{1};
    /// The joint frequency is capped at this fraction of the sub-step rate, for stability.
    /// Default 0.25.
    scalar max_hertz_ratio{scalar(0.25)};
    /// A limit reached slower than this does not bounce (m/s or rad/s). Default 0.1.
    scalar restitution_threshold{scalar(0.1)};
    /// Fraction of the joints' pivot separation removed by moving the bodies after each
    /// sub-step's integration (see project_point); 0 leaves it to the soft correction alone.
    /// Default 1. While it is above 0 the pivot rows carry no position bias.
    scalar position_projection{1};
    /// Passes of that projection over all the joints. Each pass solves every run of joints
    /// linked one after another (a chain, a limb) exactly (see joint_path_set); the passes
    /// settle the bodies where such runs meet (a rag doll's pelvis and chest). With 3 passes the
    /// 64 rag dolls of edyn-bench open their joints by at most 0.08 mm, with 2 by 0.4 mm.
    /// Default 3.
    unsigned position_projection_iterations{3};
    /// When a joint's pivots lie farther apart than this at the start of a step (m; for a
    /// distance constraint, when its length is off by more), the joints of its group (the
    /// joints linking the bodies it moves, one to the next) are not projected that step: their
    /// pivot rows carry the soft correction of `joint_hertz` instead, as they do with the
    /// projection off. Projecting such a gap shut in one sub-step turns the bodies by large angles, and
    /// where the gaps cannot all close (a bridge whose posts stand farther apart than its deck
    /// is long, a body pinned to a kinematic body moving away) it threw them about, faster every
    /// sub-step, while the soft correction lets them settle; projecting only some joints of
    /// such a group still shook it. Joints in use open far less
    /// (the chain and rag dolls of edyn-bench by at most a few millimetres); a joint made with
    /// its pivots apart is drawn together by the spring. Default 0.05 m; infinity projects
    /// every joint.
    scalar max_projected_gap{scalar(0.05)};
    /// The fastest the soft correction closes a joint's pivot gap (m/s), where the pivot rows
    /// carry it (joints left out of the projection, or all of them with `position_projection`
    /// at 0). A spring of `joint_hertz` closing a gap of metres would fling the bodies together
    /// at hundreds of m/s and leave them spinning; held to this speed, a joint made with its
    /// bodies 3 m apart draws them together in about a second. A cone's point found outside the
    /// cone is drawn back across its wall no faster either. Default 3, as contacts'
    /// max_push_out_velocity.
    scalar max_correction_speed{3};

    /// Whether every field is the same.
    bool operator==(const constraint_solver_settings &) const = default;
};

/// The constraints of one type as the solver sees them this step, and where they came from, in
/// colour order: colour k is [colour_begin[k], colour_begin[k + 1]) (see constraint_colouring).
/// Filled by gather_constraints(); its arrays keep their capacity from step to step.
/// @tparam Solver The solver state type of the constraint, e.g. hinge_constraint_solver.
template<typename Solver>
struct constraint_batch {
    std::vector<Solver> solvers;             ///< The constraints' solver states, in colour order.
    std::vector<entity> entities;            ///< The constraint entity of each solver state.
    std::vector<std::uint32_t> colour_begin; ///< First index of each colour, then one past the last.
    /// Scratch for sorting by colour, reused from step to step.
    /// The solver states in the order they were gathered.
    std::vector<Solver> unsorted;
    std::vector<entity> unsorted_entities; ///< Scratch: the entities in the order gathered.
    std::vector<std::uint32_t> colours;    ///< Scratch: the colour of each gathered constraint.
};

/// Every joint of a step, packed per type in contiguous arrays reused from step to step.
/// Owned by the world; made by gather_constraints() and used by the other functions of this
/// header, on the thread that runs the step.
struct constraint_solver_state {
    /// One batch per joint type, in the order of `constraint_types` (null constraints, which
    /// have no rows, excepted).
    std::tuple<constraint_batch<point_constraint_solver>, constraint_batch<distance_constraint_solver>,
               constraint_batch<soft_distance_constraint_solver>, constraint_batch<hinge_constraint_solver>,
               constraint_batch<cvjoint_constraint_solver>, constraint_batch<cone_constraint_solver>,
               constraint_batch<generic_constraint_solver>, constraint_batch<gravity_constraint_solver>>
        batches;
    /// 1 / h of the sub-step the joints were last solved with: the projection that follows turns
    /// its corrections into velocities over that sub-step.
    scalar inv_h{0};
    /// Colours the joints in the order they are solved (type by type, each in the view's order),
    /// so that each colour's joints are solved at once on the scheduler's threads and the
    /// result is the same bit for bit.
    constraint_colouring colouring;
    /// Joints of one type and one colour, [first, last) of the type's batch.
    struct joint_run {
        std::uint32_t type;  ///< The batch's place in `batches`.
        std::uint32_t first; ///< The first joint's place in the batch.
        std::uint32_t last;  ///< One past the last joint's place.
    };
    /// Each colour's joints cut into blocks for the scheduler's threads, colour by colour and
    /// within a colour type by type. Filled by gather_constraints().
    std::vector<joint_run> blocks;
    /// The first block of each colour, then one past the last block.
    std::vector<std::uint32_t> colour_block_begin;
    /// The pivots the position projection brings together, cut into paths solved exactly.
    joint_path_set paths;
    /// Scratch for building `paths`: every projected pivot in the order gathered.
    std::vector<joint_anchor *> projected_pivots;
    /// Scratch for building `paths`: the bodies of the other joints the projection moves.
    std::vector<solver_body_index> other_projected;
    /// Scratch for deciding which joints the projection leaves out (see
    /// constraint_solver_settings::max_projected_gap): every joint it could take, how far each
    /// is open, and the groups of moving bodies joined by them (a union-find forest over the
    /// solver bodies, with whether each group holds a joint open too wide).
    std::vector<joint_anchor *> gap_anchors;
    std::vector<scalar> gaps;                ///< How far each of `gap_anchors` is open (m).
    std::vector<solver_body_index> group_of; ///< Each body's parent in the forest.
    std::vector<std::uint8_t> group_wide;    ///< Per root: whether its group has a wide joint.
};

/// Whether the state holds any joint to solve.
/// @param state The joints' state, as gathered.
/// @return False when every joint pass would do nothing.
inline bool has_joints(const constraint_solver_state &state) noexcept { return !state.blocks.empty(); }

/// Maps an entity's index to its solver body (0, the static body, when it has none).
using body_index_map = std::span<const std::uint32_t>;

/// The solver body of `e`: entities past the end of the map have none either.
/// @param body_index The step's map from entity index to solver body index.
/// @param e The entity.
/// @return Its solver body index, or `static_solver_body` (0) when it has none.
inline solver_body_index body_index_of(body_index_map body_index, entity e) noexcept {
    auto i = to_index(e);
    return i < body_index.size() ? body_index[i] : static_solver_body;
}

/// Packs every awake constraint with at least one body in the solver, with its geometry at the
/// start of the step and last step's impulses, and colours them for the bodies they join.
/// Called once per step, before the sub-steps; constraints whose bodies both map to the static
/// body are skipped.
/// @param registry The registry holding the constraints and their bodies.
/// @param state The joints' state, overwritten.
/// @param body_index The step's map from entity index to solver body index.
/// @param bodies The step's solver bodies; they must outlive the state's use this step.
/// @param max_projected_gap Joints open wider than this (m) are left out of the position
/// projection this step (constraint_solver_settings::max_projected_gap).
void gather_constraints(const registry &registry, constraint_solver_state &state, body_index_map body_index,
                        std::span<const solver_body> bodies, scalar max_projected_gap);

/// The context of one kind of pass over the joints, from the settings and the sub-step.
/// The joint frequency is capped at `max_hertz_ratio / h`.
/// @param settings The joint settings.
/// @param h The sub-step (s), positive.
/// @param use_bias True for the biased pass, false for the relax pass.
/// @return The context to pass to solve_joint_constraints().
constraint_solve_context make_constraint_solve_context(const constraint_solver_settings &settings, scalar h,
                                                       bool use_bias) noexcept;

// The joint passes below are queued, like the contacts' passes: they run, in the order queued,
// when the queue runs (stage_queue::run), each colour's joints at once on the scheduler's
// threads; the result does not depend on the number of threads. The state and the bodies must
// outlive that run.

/// Measures every joint's pivots (`joint_anchor::pose`) and angles at the bodies' present
/// poses: queued before the first sub-step and after each sub-step's position projection, the
/// only times the bodies move, so that the velocity passes measure nothing themselves.
/// @param state The joints gathered this step.
/// @param bodies The step's solver bodies.
/// @param queue The queue the pass is added to.
void refresh_joint_geometry(constraint_solver_state &state, std::span<const solver_body> bodies,
                            stage_queue &queue);

/// Re-applies the accumulated impulses, at the start of each sub-step. Colour by colour.
/// @param state The joints gathered this step.
/// @param bodies The step's solver bodies.
/// @param queue The queue the pass is added to.
void warm_start_constraints(constraint_solver_state &state, std::span<solver_body> bodies,
                            stage_queue &queue);

/// One Gauss-Seidel pass over every joint row (biased or relax, as ctx says). Colour by colour.
/// Records `ctx.inv_h` for the projection.
/// @param state The joints gathered this step; their impulses accumulate.
/// @param bodies The step's solver bodies.
/// @param ctx The pass, from make_constraint_solve_context(); copied into the queue.
/// @param queue The queue the pass is added to.
void solve_joint_constraints(constraint_solver_state &state, std::span<solver_body> bodies,
                             const constraint_solve_context &ctx, stage_queue &queue);

/// Position projection of the joints that keep pivots together, after integrating positions.
/// Queues `position_projection_iterations` passes; queues nothing when `position_projection` is
/// not positive. Uses the sub-step of the last solve_joint_constraints() call.
/// @param state The joints gathered this step.
/// @param bodies The step's solver bodies: their positions and velocities change.
/// @param settings The joint settings.
/// @param queue The queue the passes are added to.
void project_joint_positions(constraint_solver_state &state, std::span<solver_body> bodies,
                             const constraint_solver_settings &settings, stage_queue &queue);

/// Stores the impulses in the components, for next step's warm start.
/// Also writes the hinge angle and CV joint twist reached. Called once at the end of the step.
/// @param registry The registry holding the constraint components.
/// @param state The joints solved this step.
void store_constraint_impulses(registry &registry, const constraint_solver_state &state);

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONSTRAINT_SOLVER_HPP
