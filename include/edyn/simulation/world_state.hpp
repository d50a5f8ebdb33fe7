#ifndef EDYN_SIMULATION_WORLD_STATE_HPP
#define EDYN_SIMULATION_WORLD_STATE_HPP

#include "edyn/collision/broadphase.hpp"
#include "edyn/collision/collision_result.hpp"
#include "edyn/collision/manifold_update.hpp"
#include "edyn/constraints/constraint_colouring.hpp"
#include "edyn/constraints/constraint_solver.hpp"
#include "edyn/constraints/contact_order.hpp"
#include "edyn/constraints/contact_solver.hpp"
#include "edyn/dynamics/material.hpp"
#include "edyn/dynamics/solver_body.hpp"
#include "edyn/dynamics/visit_shape.hpp"
#include "edyn/parallel/background_tasks.hpp"
#include "edyn/parallel/stage_queue.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include "edyn/shapes/aabb.hpp"
#include "edyn/simulation/island_manager.hpp"
#include <cstdint>
#include <memory>
#include <vector>

namespace edyn {

/// The simulation's own state, in the registry's context.
/// The broadphase, the islands, the clock and the scratch arrays the solver reuses from step to
/// step (so that a step allocates nothing once the world stops growing). Created by attach and
/// erased by detach; the step phases take it as a parameter. Programs use the functions of
/// world.hpp rather than this.
struct world_state {
    edyn::broadphase broadphase; ///< AABB trees of the bodies with a shape, and their manifolds.
    island_manager islands;      ///< Keeps the islands and puts them to sleep.

    // Clock.
    /// Whether update() has been called once (the first call only sets the start).
    bool started{false};
    /// The time given to the last update(), in seconds of the caller's clock.
    double last_time{0};
    /// Elapsed time not yet simulated, in seconds (less than a step after each update()).
    double accumulator{0};
    /// Simulated time of the last step, in seconds since attach (get_simulation_time).
    double simulation_time{0};
    /// Steps run since attach (get_step_count).
    std::uint64_t step_count{0};
    /// Bodies whose position, orientation, velocity, shape, material or gravity the program
    /// replaced, patched or gave since the last step began: checked before the next step uses
    /// them (check_written_bodies).
    std::vector<entity> written_bodies;
    /// Whether update() runs no steps (set_paused).
    bool paused{false};

    /// Solver scratch: the bodies being solved; bodies[0] is the shared static body.
    std::vector<solver_body> bodies;
    /// body_entities[i] is bodies[i]'s entity (null for index 0).
    std::vector<entity> body_entities;
    /// Scratch of gather_bodies: whether each candidate of its view (in the leading pool's
    /// order) is a body to solve.
    std::vector<std::uint8_t> body_candidates;
    /// Maps an entity's index to its solver body (0 when it has none).
    std::vector<std::uint32_t> body_index;
    /// The contact constraints and points being solved, in colour order.
    contact_solver_set contacts;
    /// The solver bodies and point count of the contact an island edge stands for (no points:
    /// not a contact to solve).
    struct edge_contact {
        std::uint32_t body[2]{0, 0}; ///< The manifold's two bodies' indices in `bodies`.
        std::uint32_t num_points{0}; ///< The manifold's points; 0 when it is not solved.
        std::uint32_t slot{0};       ///< Where the manifold lies in its pool (`storage::value_at`).
    };
    /// Scratch of wake_bodies_on_moving_kinematics: the bodies it wakes.
    std::vector<entity> kinematic_touching;
    /// The edges of the awake islands, island by island, as gather_contacts visits them.
    std::vector<entity> island_edges;
    /// The contact of each of island_edges.
    std::vector<edge_contact> edge_contacts;
    /// The index in edge_contacts of each contact solved this step, in island order.
    std::vector<std::uint32_t> solved_edges;
    /// Puts the contacts solved this step in the order they are solved in.
    contact_order ordering;
    /// The colour each contact solved this step was given, in solving order.
    std::vector<std::uint32_t> contact_colours;
    /// Where a contact's constraint and points go in `contacts`.
    struct contact_place {
        std::uint32_t constraint{0};       ///< Index of its constraint in contacts.constraints.
        std::uint32_t first_point{0};      ///< Index of its first point in contacts.points.
        std::uint32_t num_points{0};       ///< Its number of points.
        std::uint32_t slot{0};             ///< Where the manifold lies in its pool (`storage::value_at`).
        fixed_side held{fixed_side::none}; ///< See contact_solver_constraint::held.
    };
    /// The place of each contact solved this step, in solving order (a constraint's `source`
    /// indexes this), with its manifold's place in the pool.
    std::vector<contact_place> contact_places;
    /// Assigns colours to contacts, so that those of one colour share no moving body.
    constraint_colouring colouring;
    /// The joints (non-contact constraints) being solved.
    constraint_solver_state joints;

    /// How a body's shape resists rolling in a contact (see contact_solver_constraint's roll
    /// axes): not at all, about both tangents (a sphere, a capsule), or about its main axis only
    /// (a cylinder along x, y or z).
    enum class rolling : std::uint8_t { none, both_tangents, about_x, about_y, about_z };
    /// What the narrowphase reads of a body with a broadphase proxy, gathered once a step so
    /// that its loop over the manifolds looks nothing up in the registry. One cache line each
    /// (in single precision): the loop reads two per manifold, in no predictable order.
    struct alignas(64) collision_body {
        vector3 origin{vector3_zero};                ///< get_rigidbody_origin (m).
        quaternion orientation{quaternion_identity}; ///< The body's orientation.
        vector3 linvel{vector3_zero};                ///< Zero unless it has both velocities (m/s).
        scalar spin_reach{0};                        ///< |angvel| × its reach from its centre of mass (m/s).
        scalar bounding_radius{large_scalar};        ///< shape_bounding_radius of its shape (m).
        std::uint32_t shape_epoch{0};                ///< Its shape_epoch, 0 without one.
        std::uint8_t dynamic : 1 {0};                ///< Whether it has a dynamic_tag.
        std::uint8_t resting : 1 {0};                ///< Whether it is static or asleep.
        /// Whether its points may have materials of their own (has_point_materials).
        std::uint8_t point_materials : 1 {0};
        std::uint8_t shape_kind : 5 {0};      ///< Its shape's index in shapes_variant_t (shape_ref::index).
        const void *shape_component{nullptr}; ///< Its shape component; null without a shape_index.

        /// Its shape, for visit_shape (the body must have one).
        shape_ref shape() const { return {shape_component, shape_kind}; }
    };
    static_assert(num_shapes <= 32, "collision_body::shape_kind must hold every shape's index");
    /// The collision_body of every body with a proxy, by entity index (others are stale).
    std::vector<collision_body> collision_bodies;
    /// What the contacts' gathering reads of a body besides its collision_body, and what the
    /// narrowphase reads to give new points their materials: apart from collision_body because
    /// most manifolds do not read it in the narrowphase.
    struct contact_body {
        vector3 centre{vector3_zero}; ///< Its position (centre of mass).
        rolling rolls{rolling::none}; ///< How its shape resists rolling.
        const material *mat{nullptr}; ///< Its material; null without one (a sensor).
    };
    /// The contact_body of every body with a proxy, by entity index as `collision_bodies`.
    std::vector<contact_body> contact_bodies;
    /// The AABB component of every body with a proxy, by entity index as `collision_bodies`:
    /// apart from it because only pairs without points read it.
    std::vector<AABB> collision_aabbs;
    /// Manifold entities in the order the narrowphase visits them.
    std::vector<entity> manifolds;
    /// Where each of `manifolds` lies in the contact_manifold pool (`storage::value_at`), for
    /// the narrowphase's loop to reach it without a look-up.
    std::vector<std::uint32_t> manifold_slots;
    /// Where the narrowphase's listing of `manifolds` puts the first awake manifold of each
    /// block of the contact_manifold pool, and then how many there are in all.
    std::vector<std::uint32_t> manifold_block_first;
    /// What changed in each of `manifolds` this step.
    std::vector<contact_point_changes> manifold_changes;
    /// Which point slots of each of `manifolds` are live once it is collided this step, a bit
    /// per slot, and points_changed_bit if a point was made or dropped (its entry in
    /// `manifold_changes` then has something to say), written by the thread that collided it.
    std::vector<std::uint8_t> manifold_live_slots;
    /// The bit of a `manifold_live_slots` entry that says its manifold's points changed.
    static constexpr std::uint8_t points_changed_bit = 0x80;
    static_assert(contact_manifold::max_contacts < 8, "a live slot's bit must not be points_changed_bit");
    /// `manifold_live_slots` by slot of the contact_manifold pool as the last narrowphase left
    /// them, copied on the calling thread, for the narrowphase to ask ahead only for the point
    /// slots a manifold is likely to use. Only a hint (a manifold changes slots when another is
    /// destroyed), never read for results.
    std::vector<std::uint8_t> pool_live_slots;

    /// Runs the step's parallel phases in execution_mode::sequential_multithreaded; null in the
    /// other modes, where every phase runs on the calling thread.
    std::unique_ptr<task_scheduler> scheduler;
    /// init_config::min_parallel_bodies: the fewest bodies a step must move for its phases to go
    /// to `scheduler`.
    std::uint32_t min_parallel_bodies{0};
    /// The scheduler the phases of the step under way use: `scheduler`, or null when the world
    /// is too small for worker threads to pay (its phases then run on the calling thread).
    /// Set by run_step.
    task_scheduler *step_scheduler{nullptr};
    /// The solver's passes queued to be handed to `scheduler` together (see solve_constraints);
    /// empty between steps.
    stage_queue solver_stages;
    /// Runs the work that must not hold up the step (paged meshes' page loads): through the
    /// program's scheduler when init_config::scheduler gives one (sequential_multithreaded),
    /// otherwise on a background thread made when the first task comes. Never null once
    /// attached.
    std::unique_ptr<background_tasks> background;
};

} // namespace edyn

#endif // EDYN_SIMULATION_WORLD_STATE_HPP
