#ifndef EDYN_SIMULATION_SOLVE_STEP_HPP
#define EDYN_SIMULATION_SOLVE_STEP_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/settings.hpp"
#include "edyn/simulation/world_state.hpp"

namespace edyn {

/// Step phase 3: copies every awake dynamic and kinematic body into the solver's body array.
/// Each dynamic body gets its gravity (its own, or the world's) as its acceleration, the
/// external force applied in each sub-step. Index 0 of world_state::bodies is the shared static
/// body; world_state::body_index maps each gathered entity to its index.
/// @param registry An attached registry.
/// @param world The registry's world_state, whose body arrays are refilled.
/// @param settings The step's settings (the world's gravity).
void gather_bodies(registry &registry, world_state &world, const settings &settings);

/// Builds the contact constraints of every awake manifold in contact between bodies that both
/// respond to collisions (sensors do not), with mixed materials and last step's impulses.
/// Manifolds are taken island by island, put in solving order outward from the bodies that do
/// not move (contact_order.hpp) and given colours for parallel solving. Bodies resting
/// on a moving kinematic body are woken first. Call after gather_bodies.
/// @param registry An attached registry.
/// @param world The registry's world_state, whose contact arrays are refilled.
void gather_contacts(registry &registry, world_state &world);

/// Phases 4 to 6 on the gathered arrays: the soft-step sub-steps.
/// Each sub-step integrates velocities, runs the restitution solver, warm starts, makes one
/// biased iteration over joints and contacts, integrates positions, projects the joints'
/// positions, then makes the relax iterations. Works on the arrays only, not the registry.
/// @param world The world_state with bodies, contacts and joints gathered.
/// @param settings The step's settings (fixed_dt, sub-steps, iterations, solver settings).
void solve_constraints(world_state &world, const settings &settings);

/// Phase 6: writes the solved velocities, positions and orientations back to the registry.
/// Also refreshes world-space inertia and AABBs (swept over the next step of length `dt`), and
/// stores impulses in the manifolds and constraints for warm starting and for listeners.
/// @param registry An attached registry.
/// @param world The world_state that was solved.
/// @param dt Length of the step, in seconds.
void write_back(registry &registry, world_state &world, scalar dt);

} // namespace edyn

#endif // EDYN_SIMULATION_SOLVE_STEP_HPP
