#ifndef EDYN_CONSTRAINTS_JOINT_PATHS_HPP
#define EDYN_CONSTRAINTS_JOINT_PATHS_HPP

#include "edyn/constraints/constraint_colouring.hpp"
#include "edyn/constraints/constraint_row.hpp"
#include "edyn/parallel/parallel_for_stages.hpp"
#include "edyn/parallel/stage_queue.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <cstdint>
#include <span>
#include <vector>

namespace edyn {

/// A 3x3 block of a path's factors, each row padded to four scalars, so that the recursion along a
/// path handles a row as one SIMD register.
struct alignas(4 * sizeof(scalar)) path_block {
    /// The block's rows, each followed by a zero.
    scalar row[3][4];
};

/// The joints whose pivots position projection brings together, cut into paths: runs of joints
/// one after another, each sharing with the next a moving body that no other projected joint
/// touches (the links of a chain, a rope, a limb). A path's pivots are projected at once, by an
/// exact solve of its block-tridiagonal system: what a chain's Gauss-Seidel passes spread along
/// it a little per pass (the error of a 100-link chain's far end moves one link a pass), one
/// solve removes. Joints meet other paths at their ends only, at bodies with three or more
/// joints (a rag doll's pelvis) or at the static world, and the passes settle those meetings.
///
/// Built once per step by build_joint_paths() from the joints gathered for the solver; its arrays
/// keep their capacity from step to step. A path of one joint is projected as project_point()
/// projects it.
struct joint_path_set {
    /// The pivots, path after path, the paths in colour order (see colour_block_begin).
    std::vector<joint_anchor *> anchors;
    /// For each anchor after the first of its path, where the body it shares with the one before
    /// lies: bit 0 set when it is this anchor's second body (body[1]), bit 1 set when it is the
    /// previous anchor's second body.
    std::vector<std::uint8_t> shared_side;
    /// Path p is anchors [path_begin[p], path_begin[p + 1]).
    std::vector<std::uint32_t> path_begin;
    /// Paths in blocks of a few for the scheduler's threads: block b holds the paths
    /// [block_begin[b], block_begin[b + 1]).
    std::vector<std::uint32_t> block_begin;
    /// The blocks of colour k are [colour_block_begin[k], colour_block_begin[k + 1]): no two
    /// paths of one colour share a moving body, and a path comes after every earlier one it
    /// shares a body with, so that the passes give the same result on any number of threads.
    std::vector<std::uint32_t> colour_block_begin;

    /// The poses the present pass measured, one per anchor (indexed as `anchors`).
    std::vector<joint_pose> poses;
    /// Per anchor, the inverse of its pivot block's Schur complement D_k, from the factors of the
    /// sub-step's first pass, which its other passes reuse. While a path is factored, its K_kk.
    std::vector<path_block> inverse_pivot;
    /// Per anchor after the first of its path, D_k-1^-1 K_k-1,k: its coupling to the anchor before
    /// it, folded into the factors. While a path is factored, K_k-1,k.
    std::vector<path_block> coupling;
    std::vector<vector3> work; ///< Right-hand side, then the position impulses, of a solve.
    /// Per path: whether both its ends are bodies that do not move or that nothing else the
    /// projection moves touches (a chain hanging from the world). The first pass of a sub-step
    /// solves such a path of two or more joints to within the second order of its turning: the
    /// other passes leave it unless its gaps were wide (see widest_gap).
    std::vector<std::uint8_t> isolated;
    /// Per path: the square of its widest pivot gap at the latest pass (m²).
    std::vector<scalar> widest_gap;
    /// Per path: whether its factors are valid this sub-step; a path whose system cannot be
    /// factored (bodies that do not move) falls back to one joint at a time.
    std::vector<std::uint8_t> factored;

    /// Scratch for building, reused from step to step.
    struct scratch {
        std::vector<std::uint32_t> degree;       ///< Per solver body: projected joints touching it.
        std::vector<std::uint32_t> pivot_degree; ///< Per solver body: how many of them are pivots.
        /// Per solver body: the first two of those pivots (indices into the pivots given).
        std::vector<std::uint32_t> incident;
        std::vector<std::uint8_t> visited;       ///< Per pivot: whether a path holds it yet.
        std::vector<joint_anchor *> anchors;     ///< The paths' anchors, paths in the order found.
        std::vector<std::uint8_t> shared_side;   ///< As joint_path_set::shared_side, in that order.
        std::vector<std::uint32_t> path_begin;   ///< The paths in that order, as `anchors` holds them.
        std::vector<std::uint32_t> path_colour;  ///< Per path in that order: its colour.
        std::vector<std::uint32_t> colour_begin; ///< The first path of each colour, in colour order.
        std::vector<std::uint8_t> path_isolated; ///< Per path in that order: see `isolated`.
        constraint_colouring colouring;          ///< Colours the paths by their end bodies.
    };
    scratch build;   ///< Scratch for building, reused from step to step.
    stage_sync sync; ///< Shared by the threads of a pass.
};

/// Cuts the step's projected pivots into paths and colours them (see joint_path_set).
/// @param set Overwritten.
/// @param pivots Every joint anchor whose pivots the projection brings together, in the order
/// the joints are solved; they must stay in place until the next build.
/// @param other_projected The bodies of the other joints that the projection moves (distance
/// joints), two per joint: a body one of them touches ends every path there.
/// @param bodies The step's solver bodies.
void build_joint_paths(joint_path_set &set, std::span<joint_anchor *const> pivots,
                       std::span<const solver_body_index> other_projected,
                       std::span<const solver_body> bodies);

/// One projection pass over every path, colour by colour, each colour's paths at once on the
/// scheduler's threads.
/// @param set The paths, from build_joint_paths().
/// @param bodies The step's solver bodies: their `delta_position`, `delta_rotation` and velocities
/// change as project_point() changes them.
/// @param fraction Share of the separation removed, in [0, 1].
/// @param inv_h 1 / h of the sub-step just integrated (1/s).
/// @param refactor True at a sub-step's first pass: the paths' systems are factored at the
/// present poses; later passes reuse those factors.
/// @param scheduler The threads to use, or null for the calling thread alone.
void project_joint_paths(joint_path_set &set, std::span<solver_body> bodies, scalar fraction, scalar inv_h,
                         bool refactor, task_scheduler *scheduler);

/// The same pass queued: each colour of paths a stage of `queue`, run by stage_queue::run().
/// The set and the bodies must outlive that run.
/// @param set The paths, from build_joint_paths().
/// @param bodies The step's solver bodies.
/// @param fraction Share of the separation removed, in [0, 1].
/// @param inv_h 1 / h of the sub-step just integrated (1/s).
/// @param refactor True at a sub-step's first pass (see above).
/// @param queue The queue the stages are added to.
void project_joint_paths(joint_path_set &set, std::span<solver_body> bodies, scalar fraction, scalar inv_h,
                         bool refactor, stage_queue &queue);

} // namespace edyn

#endif // EDYN_CONSTRAINTS_JOINT_PATHS_HPP
