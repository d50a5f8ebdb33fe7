#include "edyn/simulation/step.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/simulation/action_list.hpp"
#include "edyn/simulation/body_motion_estimate.hpp"
#include "edyn/simulation/contact_events.hpp"
#include "edyn/simulation/narrowphase.hpp"
#include "edyn/simulation/paged_mesh_loading.hpp"
#include "edyn/simulation/registry_listeners.hpp"
#include "edyn/simulation/solve_step.hpp"
#include "edyn/simulation/world.hpp"
#include "edyn/simulation/world_state.hpp"

namespace edyn {

// The spine of the engine: one fixed step, in the manual's order.
void run_step(registry &registry) {
    auto &world = registry.ctx().get<world_state>();
    // A copy: callbacks may change the settings, which then apply from the next step. Checked
    // here too, not only by update(), for what a step callback changed in place.
    auto settings = get_settings(registry);
    validate_settings(settings, "step");

    if (settings.pre_step_callback) settings.pre_step_callback(registry);
    // What the program wrote into bodies since the last step is checked first: a NaN would
    // spread through contacts to every body it touches.
    check_written_bodies(registry);

    // 0. The worker threads take the step's phases only when the world is big enough for them to
    //    pay; otherwise it is stepped on the calling thread, to the same result.
    auto moving = world.bodies.empty() ? registry.storage<dynamic_tag>().size() : world.bodies.size() - 1;
    world.step_scheduler = moving >= world.min_parallel_bodies ? world.scheduler.get() : nullptr;

    // 1. Broadphase: manifolds created for new overlapping pairs, destroyed for separated ones;
    //    every body's fat box covers where its velocities take it in this step.
    const body_motion_estimate estimate(settings, registry);
    world.broadphase.update(registry, world.step_scheduler, estimate.estimator());
    //    Bodies touching a kinematic body that moves, or joined to it, wake to move with it.
    wake_bodies_on_moving_kinematics(registry, world);
    //    Paged meshes load the pages bodies are over and near, and unload those left behind.
    update_paged_meshes(registry, world);
    // 2. Narrowphase: closest points, contact points created and destroyed, events recorded.
    run_narrowphase(registry, world);
    // 3. External forces: gravity becomes each body's acceleration for the sub-steps.
    gather_bodies(registry, world, settings);
    gather_contacts(registry, world);
    gather_constraints(registry, world.joints, world.body_index, world.bodies,
                       settings.joint.max_projected_gap);
    // 4. Restitution solver, then the constraint solver's sub-steps, which apply the impulses
    //    (5) and integrate velocities into positions and orientations (6).
    solve_constraints(world, settings);
    write_back(registry, world, settings.fixed_dt);
    // Islands that came to rest go to sleep.
    world.islands.update_sleeping(registry, settings, settings.fixed_dt);

    world.simulation_time += settings.fixed_dt;
    ++world.step_count;
    // Collision events, with this step's impulses.
    registry.ctx().emplace<contact_events>().deliver(registry);

    if (settings.post_step_callback) settings.post_step_callback(registry);
    // The step's callbacks have seen the actions: each is seen by one step only.
    detail::consume_actions(registry);
}

} // namespace edyn
