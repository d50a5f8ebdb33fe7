#ifndef EDYN_SIMULATION_SOLVE_STEP_HPP
#define EDYN_SIMULATION_SOLVE_STEP_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/settings.hpp"
#include "edyn/simulation/world_state.hpp"

namespace edyn {

// Step phase 3: copies every awake dynamic and kinematic body into the solver's body array,
// with gravity as its acceleration (the external force, applied in each sub-step).
void gather_bodies(registry &registry, world_state &world, const settings &settings);

// Builds the contact constraints of every awake manifold in contact between bodies that both
// respond to collisions (sensors do not), with mixed materials and last step's impulses.
void gather_contacts(registry &registry, world_state &world);

// Phases 4 and 5: the restitution solver, then the soft-step sub-steps (integrate velocities,
// warm start, biased iteration, integrate positions, relax iterations).
void solve_constraints(world_state &world, const settings &settings);

// Phase 6: writes the solved velocities, positions and orientations back to the registry,
// refreshes world-space inertia and AABBs (swept over the next step of length dt), and stores
// impulses in the manifolds and constraints.
void write_back(registry &registry, world_state &world, scalar dt);

} // namespace edyn

#endif // EDYN_SIMULATION_SOLVE_STEP_HPP
