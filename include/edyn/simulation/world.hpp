#ifndef EDYN_SIMULATION_WORLD_HPP
#define EDYN_SIMULATION_WORLD_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/settings.hpp"

namespace edyn {

// Sets the configuration that attach(registry), given none, uses from then on (until init is
// called, a default init_config). Registries already attached keep theirs. Throws
// std::invalid_argument, keeping the previous configuration, for one attach would refuse.
void init(const init_config &config = {});

// Makes `registry` ready for physics: settings, the broadphase and the listeners that keep the
// simulation in step with the registry. Bodies made before attach() join the simulation too.
// Without a configuration, the one given to init() applies. Throws std::invalid_argument for
// an execution mode that is not available, a bad thread count or incomplete scheduler hooks
// (naming the init_config field), or if the registry is already attached.
void attach(registry &registry);
void attach(registry &registry, const init_config &config);

// Removes every edyn component, context variable and internal entity (manifolds, islands);
// the program's own entities and components stay. attach() may be called again afterwards.
void detach(registry &registry);

bool is_attached(const registry &registry) noexcept;

// Advances the simulation to `time` (seconds, from the caller's clock; the first call only
// sets the start) in fixed steps, then interpolates present_position / present_orientation
// between the last two steps. update(registry) uses the steady clock.
//
// In asynchronous mode update() never waits: it applies what the worker has finished since the
// last call (motion, sleeping, manifolds; collision events and query replies are delivered to
// their listeners here, on the calling thread), sends the changes made to the main registry
// and the new time, and presents the transforms one update behind the sequential mode's. An
// exception thrown in the worker by a step callback, or by a listener or delegate during this
// call, is rethrown from here once the rest is applied; the worker keeps running.
void update(registry &registry, double time);
void update(registry &registry);

// Runs exactly one fixed step now, paused or not, and sets the present transforms to it. In
// asynchronous mode the worker runs it as soon as it can; its result arrives with a later
// update() or wait_for_simulation().
void step_simulation(registry &registry);

// Asynchronous mode: sends everything done to the main registry so far, waits until the worker
// has applied it (and run the steps already asked for), then applies the worker's results to
// the main registry as update() does, without advancing time. Tools and tests use it, with
// set_paused and step_simulation, to run the worker step by step. In the other modes there is
// nothing to wait for and it returns at once.
void wait_for_simulation(registry &registry);

// Wakes the island of `entity` (a rigid body or a constraint) if it sleeps: for changes the
// simulation cannot see, such as a component a step callback reads to push the body.
void wake_up_entity(registry &registry, entity entity);

void set_paused(registry &registry, bool paused);
bool is_paused(const registry &registry);

// The setters below throw std::invalid_argument, naming the function and the value, for one
// outside the ranges of settings.hpp (min_fixed_dt to max_fixed_dt, at most max_gravity long,
// at most max_solver_substeps and max_solver_iterations, max_steps_per_update_limit).
void set_fixed_dt(registry &registry, scalar dt);
scalar get_fixed_dt(const registry &registry);

void set_gravity(registry &registry, const vector3 &gravity);
vector3 get_gravity(const registry &registry);

// The solver runs a soft step: each fixed step is split into sub-steps, and each sub-step
// integrates velocities, runs the restitution solver, warm starts, makes one biased velocity
// iteration over every contact and joint row, integrates positions, projects the joints'
// positions, then makes the relax iterations (velocity iterations without position bias).
// Defaults: 6 sub-steps, 1 relax iteration, 4 position projection passes (settings.hpp).
void set_solver_substeps(registry &registry, unsigned substeps);
unsigned get_solver_substeps(const registry &registry);
void set_solver_relax_iterations(registry &registry, unsigned iterations);
unsigned get_solver_relax_iterations(const registry &registry);
// A velocity iteration is one biased pass over every row; the soft step makes one per
// sub-step, so these set and get the number of sub-steps (same as set_solver_substeps).
void set_solver_velocity_iterations(registry &registry, unsigned iterations);
unsigned get_solver_velocity_iterations(const registry &registry);
// A position iteration is one projection pass over the joints that keep pivots together,
// after each sub-step's integration (settings.joint.position_projection_iterations); 0 leaves
// joint drift to the soft velocity correction alone. Contacts have no position iterations.
void set_solver_position_iterations(registry &registry, unsigned iterations);
unsigned get_solver_position_iterations(const registry &registry);
void set_solver_restitution_iterations(registry &registry, unsigned iterations);
unsigned get_solver_restitution_iterations(const registry &registry);
void set_solver_individual_restitution_iterations(registry &registry, unsigned iterations);
unsigned get_solver_individual_restitution_iterations(const registry &registry);
void set_max_steps_per_update(registry &registry, unsigned steps);

void set_pre_step_callback(registry &registry, step_callback_t callback);
void set_post_step_callback(registry &registry, step_callback_t callback);

const settings &get_settings(const registry &registry);

// Simulated time of the last step, in seconds since attach().
double get_simulation_time(const registry &registry);
// Steps run since attach().
std::uint64_t get_step_count(const registry &registry);

} // namespace edyn

#endif // EDYN_SIMULATION_WORLD_HPP
