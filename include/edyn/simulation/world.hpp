#ifndef EDYN_SIMULATION_WORLD_HPP
#define EDYN_SIMULATION_WORLD_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/settings.hpp"

namespace edyn {

/// Sets the configuration that attach(registry), given none, uses from then on.
/// Until init is called, a default init_config applies (asynchronous mode). Registries already
/// attached keep theirs. It may be called from any thread.
/// @param config The configuration for later attach() calls.
/// @throws std::invalid_argument Keeping the previous configuration, for one attach would
/// refuse: in sequential_multithreaded mode, `num_worker_threads` above `max_worker_threads`,
/// or a `scheduler` whose `enqueue` or `wait` hook is null or whose `concurrency` is 0.
void init(const init_config &config = {});

/// Makes `registry` ready for physics, with the configuration given to init().
/// Puts the settings, the broadphase and the listeners that keep the simulation in step with
/// the registry in it; bodies and constraints made before attach() join the simulation too.
/// In asynchronous mode it starts the simulation worker thread. Different registries may be
/// attached on different threads.
/// @param registry The registry to attach.
/// @throws std::invalid_argument When the registry is already attached, or for a bad
/// configuration (see the other overload); the registry is left as it was.
void attach(registry &registry);
/// Makes `registry` ready for physics with the configuration `config`.
/// As attach(registry), with `config` instead of the one given to init().
/// @param registry The registry to attach.
/// @param config Execution mode and threads.
/// @throws std::invalid_argument When the registry is already attached; in
/// sequential_multithreaded mode, when `num_worker_threads` is above `max_worker_threads` or
/// the `scheduler` hooks are incomplete (a null `enqueue` or `wait`, a `concurrency` of 0) or
/// refused by the task scheduler, naming the init_config field. The registry is left as it was.
void attach(registry &registry, const init_config &config);

/// Removes every edyn component, context variable and internal entity (manifolds, islands).
/// The program's own entities and components stay. In asynchronous mode the simulation worker
/// is stopped and joined. attach() may be called again afterwards. Does nothing on a registry
/// that is not attached.
/// @param registry The registry to detach.
void detach(registry &registry);

/// Whether attach() was called on `registry` (and detach() not since).
/// @param registry The registry.
/// @return True when the registry is attached.
bool is_attached(const registry &registry) noexcept;

/// Advances the simulation to `time` in fixed steps, then interpolates present_position /
/// present_orientation between the last two steps.
/// `time` is in seconds from the caller's clock; the first call only sets the start. Time that
/// goes backwards counts as none, and at most settings::max_steps_per_update steps run per call
/// (the rest of a long pause is dropped). While paused no step runs and the paused time is not
/// made up later. Pending raycast_async and query_aabb_async replies are delivered here.
///
/// In asynchronous mode update() never waits: it applies what the worker has finished since the
/// last call (motion, sleeping, manifolds; collision events and query replies are delivered to
/// their listeners here, on the calling thread), sends the changes made to the main registry
/// and the new time, and presents the transforms one update behind the sequential mode's. An
/// exception thrown in the worker by a step callback, or by a listener or delegate during this
/// call, is rethrown from here once the rest is applied; the worker keeps running.
/// @param registry An attached registry (the main one, in asynchronous mode).
/// @param time The current time, in seconds.
/// @throws std::invalid_argument When `time` is not finite or the registry is not attached.
void update(registry &registry, double time);
/// Advances the simulation to the current time of the steady clock.
/// As update(registry, time), with `std::chrono::steady_clock` as the clock.
/// @param registry An attached registry (the main one, in asynchronous mode).
/// @throws std::invalid_argument When the registry is not attached.
void update(registry &registry);

/// Runs exactly one fixed step now, paused or not, and sets the present transforms to it.
/// In asynchronous mode the worker runs it as soon as it can; its result arrives with a later
/// update() or wait_for_simulation(). The clock of update() is not changed.
/// @param registry An attached registry.
/// @throws std::invalid_argument When the registry is not attached.
void step_simulation(registry &registry);

/// Asynchronous mode: waits until the simulation worker has caught up, then applies its
/// results.
/// Sends everything done to the main registry so far, waits until the worker has applied it
/// (and run the steps already asked for), then applies the worker's results to the main
/// registry as update() does, without advancing time. Tools and tests use it, with set_paused
/// and step_simulation, to run the worker step by step. In the other modes there is nothing to
/// wait for: it hands the pending raycast_async and query_aabb_async replies to their delegates,
/// as update() would, and returns.
/// @param registry An attached registry.
/// @throws std::invalid_argument When the registry is not attached. An exception thrown in
/// the worker, or by a listener or delegate, is rethrown as in update().
void wait_for_simulation(registry &registry);

/// Wakes the island of `entity` (a rigid body or a constraint) if it sleeps.
/// For changes the simulation cannot see, such as a component a step callback reads to push
/// the body. Its sleep timer starts again, so it stays awake at least settings::time_to_sleep.
/// In asynchronous mode the worker wakes its copy at the start of its next step. Nothing
/// happens for an entity in no island, or on a registry that is not attached.
/// @param registry The registry the entity lives in.
/// @param entity The body or constraint to wake.
/// @throws std::invalid_argument When `entity` is not valid.
void wake_up_entity(registry &registry, entity entity);

/// Pauses or resumes the simulation.
/// While paused update() runs no step and time passes without being made up later;
/// step_simulation still runs one step. A step callback that pauses stops the update() that
/// ran it after the step under way. In asynchronous mode the worker learns it with the next
/// update().
/// @param registry An attached registry.
/// @param paused True to pause, false to resume.
/// @throws std::invalid_argument When the registry is not attached.
void set_paused(registry &registry, bool paused);
/// Whether the simulation is paused (set_paused).
/// @param registry An attached registry.
/// @return True when paused.
/// @throws std::invalid_argument When the registry is not attached.
bool is_paused(const registry &registry);

/// Sets the length of a fixed step.
/// @param registry An attached registry.
/// @param dt The step, in seconds, in [`min_fixed_dt`, `max_fixed_dt`]; default 1/60.
/// @throws std::invalid_argument Naming the function and the value, when `dt` is outside that
/// range or NaN, or when the registry is not attached.
void set_fixed_dt(registry &registry, scalar dt);
/// The length of a fixed step.
/// @param registry An attached registry.
/// @return The step, in seconds.
/// @throws std::invalid_argument When the registry is not attached.
scalar get_fixed_dt(const registry &registry);

/// Sets the world's gravitational acceleration, which every dynamic body without its own
/// gravity component falls with.
/// Sleeping dynamic bodies are woken, so that they fall the new way.
/// @param registry An attached registry.
/// @param gravity The acceleration, world space, in m/s²; default (0, -9.8, 0).
/// @throws std::invalid_argument Naming the function and the value, when `gravity` is not
/// finite or longer than `max_gravity`, or when the registry is not attached.
void set_gravity(registry &registry, const vector3 &gravity);
/// The world's gravitational acceleration.
/// @param registry An attached registry.
/// @return The acceleration, world space, in m/s².
/// @throws std::invalid_argument When the registry is not attached.
vector3 get_gravity(const registry &registry);

/// Sets the number of sub-steps per fixed step.
/// The solver runs a soft step: each fixed step is split into sub-steps, and each sub-step
/// integrates velocities, runs the restitution solver, warm starts, makes one biased velocity
/// iteration over every contact and joint row, integrates positions, projects the joints'
/// positions, then makes the relax iterations (velocity iterations without position bias).
/// Defaults: 6 sub-steps, 1 relax iteration, 3 position projection passes (settings.hpp).
/// More sub-steps give stiffer, more accurate contacts and joints, at a proportional cost.
/// @param registry An attached registry.
/// @param substeps Sub-steps per step, in [1, `max_solver_substeps`].
/// @throws std::invalid_argument Naming the function and the value, when `substeps` is outside
/// that range, or when the registry is not attached.
void set_solver_substeps(registry &registry, unsigned substeps);
/// The number of sub-steps per fixed step (set_solver_substeps).
/// @param registry An attached registry.
/// @return Sub-steps per step.
/// @throws std::invalid_argument When the registry is not attached.
unsigned get_solver_substeps(const registry &registry);
/// Sets the number of relax iterations per sub-step: velocity passes without position bias,
/// which remove the push-out velocity.
/// @param registry An attached registry.
/// @param iterations Relax iterations, in [0, `max_solver_iterations`]; default 1.
/// @throws std::invalid_argument Naming the function and the value, when `iterations` is
/// outside that range, or when the registry is not attached.
void set_solver_relax_iterations(registry &registry, unsigned iterations);
/// The number of relax iterations per sub-step (set_solver_relax_iterations).
/// @param registry An attached registry.
/// @return Relax iterations per sub-step.
/// @throws std::invalid_argument When the registry is not attached.
unsigned get_solver_relax_iterations(const registry &registry);
/// Sets the number of velocity iterations, which is the number of sub-steps.
/// A velocity iteration is one biased pass over every row; the soft step makes one per
/// sub-step, so this sets the number of sub-steps (same as set_solver_substeps).
/// @param registry An attached registry.
/// @param iterations Velocity iterations (sub-steps) per step, in [1, `max_solver_substeps`].
/// @throws std::invalid_argument Naming the function and the value, when `iterations` is
/// outside that range, or when the registry is not attached.
void set_solver_velocity_iterations(registry &registry, unsigned iterations);
/// The number of velocity iterations per step, which is the number of sub-steps.
/// @param registry An attached registry.
/// @return Velocity iterations (sub-steps) per step.
/// @throws std::invalid_argument When the registry is not attached.
unsigned get_solver_velocity_iterations(const registry &registry);
/// Sets the number of position iterations: projection passes over the joints that keep
/// pivots together, after each sub-step's integration.
/// Stored in settings.joint.position_projection_iterations; 0 leaves joint drift to the soft
/// velocity correction alone. Contacts have no position iterations.
/// @param registry An attached registry.
/// @param iterations Projection passes per sub-step, in [0, `max_solver_iterations`]; default 3.
/// @throws std::invalid_argument Naming the function and the value, when `iterations` is
/// outside that range, or when the registry is not attached.
void set_solver_position_iterations(registry &registry, unsigned iterations);
/// The number of joint position projection passes per sub-step
/// (set_solver_position_iterations).
/// @param registry An attached registry.
/// @return Projection passes per sub-step.
/// @throws std::invalid_argument When the registry is not attached.
unsigned get_solver_position_iterations(const registry &registry);
/// Sets the number of iterations of the restitution solver, which propagates the shock of
/// bouncing contacts through chains of bodies.
/// 0 turns the restitution solver off: restitution then only acts on contact points that
/// approach in the step, each manifold alone and once, at the end of the step (shocks do not
/// travel along chains of touching bodies), and is cheaper.
/// @param registry An attached registry.
/// @param iterations Iterations per sub-step, in [0, `max_solver_iterations`]; default 8.
/// @throws std::invalid_argument Naming the function and the value, when `iterations` is
/// outside that range, or when the registry is not attached.
void set_solver_restitution_iterations(registry &registry, unsigned iterations);
/// The number of restitution solver iterations (set_solver_restitution_iterations).
/// @param registry An attached registry.
/// @return Iterations per sub-step.
/// @throws std::invalid_argument When the registry is not attached.
unsigned get_solver_restitution_iterations(const registry &registry);
/// Sets the most iterations the restitution solver spends on each small group of contacts it
/// solves in isolation; it stops sooner once no impulse of the group changes by more than 1e-4
/// of the largest.
/// @param registry An attached registry.
/// @param iterations Iterations per group, in [0, `max_solver_iterations`]; default 32.
/// @throws std::invalid_argument Naming the function and the value, when `iterations` is
/// outside that range, or when the registry is not attached.
void set_solver_individual_restitution_iterations(registry &registry, unsigned iterations);
/// The number of restitution iterations per group of contacts
/// (set_solver_individual_restitution_iterations).
/// @param registry An attached registry.
/// @return Iterations per group.
/// @throws std::invalid_argument When the registry is not attached.
unsigned get_solver_individual_restitution_iterations(const registry &registry);
/// Sets the most steps one update() runs.
/// The rest of a long pause (a slow frame, a debugger stop) is dropped, so that a slow frame
/// cannot make the next one slower still.
/// @param registry An attached registry.
/// @param steps Steps per update, in [1, `max_steps_per_update_limit`]; default 10.
/// @throws std::invalid_argument Naming the function and the value, when `steps` is outside
/// that range, or when the registry is not attached.
void set_max_steps_per_update(registry &registry, unsigned steps);
/// Sets the fastest a body moves (settings::max_linear_speed): the solver lowers a faster
/// body's velocity to it, keeping its direction, so that constraints that cannot all hold, or a
/// huge impulse, cannot drive a body out of the range of a float.
/// @param registry An attached registry.
/// @param speed The speed in m/s, in (0, `max_linear_speed_limit`]; default 400.
/// @throws std::invalid_argument Naming the function and the value, when `speed` is outside
/// that range (or not a number), or when the registry is not attached.
void set_max_linear_speed(registry &registry, scalar speed);
/// The fastest a body moves (set_max_linear_speed).
/// @param registry An attached registry.
/// @return The speed in m/s.
/// @throws std::invalid_argument When the registry is not attached.
scalar get_max_linear_speed(const registry &registry);

/// Sets a function to run at the start of every step, before the broadphase.
/// In asynchronous mode it runs in the simulation worker's thread, with the worker's registry,
/// not the main one: take the usual care with data shared between threads.
/// @param registry An attached registry.
/// @param callback The function, or null to remove it.
/// @throws std::invalid_argument When the registry is not attached.
void set_pre_step_callback(registry &registry, step_callback_t callback);
/// Sets a function to run at the end of every step, after collision events are delivered.
/// In asynchronous mode it runs in the simulation worker's thread, with the worker's registry,
/// not the main one: take the usual care with data shared between threads.
/// @param registry An attached registry.
/// @param callback The function, or null to remove it.
/// @throws std::invalid_argument When the registry is not attached.
void set_post_step_callback(registry &registry, step_callback_t callback);

/// The world-wide settings of an attached registry.
/// @param registry An attached registry.
/// @return The settings in the registry's context; change them with the setters above.
/// @throws std::invalid_argument When the registry is not attached.
const settings &get_settings(const registry &registry);

/// Simulated time of the last step, in seconds since attach().
/// In asynchronous mode, that of the last step whose results the main registry has applied.
/// @param registry An attached registry.
/// @return Seconds of simulated time.
/// @throws std::invalid_argument When the registry is not attached.
double get_simulation_time(const registry &registry);
/// Steps run since attach().
/// In asynchronous mode, as of the last results the main registry has applied.
/// @param registry An attached registry.
/// @return The number of steps.
/// @throws std::invalid_argument When the registry is not attached.
std::uint64_t get_step_count(const registry &registry);

} // namespace edyn

#endif // EDYN_SIMULATION_WORLD_HPP
