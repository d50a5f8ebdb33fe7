#ifndef EDYN_SIMULATION_NARROWPHASE_HPP
#define EDYN_SIMULATION_NARROWPHASE_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/world_state.hpp"

namespace edyn {

/// Wakes the bodies touching a kinematic body that moves (a nonzero linvel or angvel), or joined
/// to it by a constraint, and resets their sleep timers: a kinematic body is in no island, so
/// nothing else tells what rests on it that it must move, nor keeps it from falling asleep
/// there. Called by run_step after the broadphase and before paged meshes load their pages and
/// the narrowphase runs, so that the bodies it wakes hold their pages, and are collided and
/// solved, in the same step.
/// @param registry An attached registry.
/// @param world The registry's world_state.
void wake_bodies_on_moving_kinematics(registry &registry, world_state &world);

/// Step phase 2: updates the contact points of every awake manifold.
/// Closest points for every awake manifold whose pair has a dynamic body, merged into the
/// manifold (points matched across steps for warm starting), with each point's mixed material;
/// contact events recorded (when someone listens); manifolds that start touching join (and
/// wake) their bodies' islands, those that stop leave. The collision of each manifold runs on
/// the world's scheduler threads when there is one. Called by run_step.
/// @param registry An attached registry.
/// @param world The registry's world_state.
void run_narrowphase(registry &registry, world_state &world);

} // namespace edyn

#endif // EDYN_SIMULATION_NARROWPHASE_HPP
