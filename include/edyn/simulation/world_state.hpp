#ifndef EDYN_SIMULATION_WORLD_STATE_HPP
#define EDYN_SIMULATION_WORLD_STATE_HPP

#include "edyn/collision/broadphase.hpp"
#include "edyn/collision/collision_result.hpp"
#include "edyn/collision/manifold_update.hpp"
#include "edyn/constraints/constraint_colouring.hpp"
#include "edyn/constraints/constraint_solver.hpp"
#include "edyn/constraints/contact_solver.hpp"
#include "edyn/dynamics/solver_body.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include "edyn/simulation/island_manager.hpp"
#include <cstdint>
#include <memory>
#include <vector>

namespace edyn {

// The simulation's own state, in the registry's context: the broadphase, the islands, the
// clock and the scratch arrays the solver reuses from step to step (so that a step allocates
// nothing once the world stops growing).
struct world_state {
    edyn::broadphase broadphase;
    island_manager islands;

    // Clock.
    bool started{false};
    double last_time{0};
    double accumulator{0};
    double simulation_time{0};
    std::uint64_t step_count{0};
    bool paused{false};

    // Solver scratch: bodies[0] is the shared static body; body_entities[i] is bodies[i]'s
    // entity; body_index maps an entity's index to its solver body (0 when it has none).
    std::vector<solver_body> bodies;
    std::vector<entity> body_entities;
    std::vector<std::uint32_t> body_index;
    contact_solver_set contacts;
    // The manifolds solved this step, in the order found (a constraint's `source` indexes this),
    // with the colour each was given and its constraint's place in `contacts`.
    std::vector<entity> contact_manifolds;
    std::vector<std::uint32_t> contact_colours;
    std::vector<std::uint32_t> contact_slots;
    constraint_colouring colouring;
    constraint_solver_state joints;

    // Manifold entities in the order the narrowphase visits them, and what changed in each.
    std::vector<entity> manifolds;
    std::vector<contact_point_changes> manifold_changes;

    // Runs the step's parallel phases in execution_mode::sequential_multithreaded; null in the
    // other modes, where every phase runs on the calling thread.
    std::unique_ptr<task_scheduler> scheduler;
};

} // namespace edyn

#endif // EDYN_SIMULATION_WORLD_STATE_HPP
