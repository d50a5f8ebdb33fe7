#ifndef EDYN_DYNAMICS_INTEGRATION_HPP
#define EDYN_DYNAMICS_INTEGRATION_HPP

#include "edyn/dynamics/solver_body.hpp"
#include "edyn/parallel/stage_queue.hpp"
#include <span>

namespace edyn {

/// The fastest a body may turn in one sub-step of length `h`, in rad/s: a quarter turn per
/// sub-step (π/4 radians), beyond which its orientation would alias.
/// @param h Length of the sub-step, in seconds.
scalar max_angular_speed(scalar h) noexcept;

/// A free body's angular velocity after `h` seconds of its gyroscopic torque, `-ω × Iω`.
/// Euler's equation for a body turning with no torque, `I dω/dt + ω × Iω = 0` in its own
/// frame, taken one implicit Euler step with one Newton iteration from `angvel`. The angular
/// momentum then keeps its direction in the world while the body turns, as it must: a body
/// spinning about no principal axis wobbles and precesses, one spinning near its intermediate
/// axis tumbles, and a spinning wheel on an axle precesses under gravity's torque instead of
/// falling. Implicit Euler loses a little energy and never adds any (a result with more kinetic
/// energy than `angvel`'s, which the single Newton iteration could give when `h |ω|` is large,
/// is scaled back to `angvel`'s energy). A body whose inertia is the same about every axis has
/// no gyroscopic torque and gets `angvel` back unchanged, as does one spinning exactly about a
/// principal axis; the result does not depend on the inertia's scale.
/// @param angvel Angular velocity, world space, in rad/s.
/// @param inertia The body's inertia about its centre of mass, object space (positive
/// definite), in kg·m²; a matrix that is not, or a result that is not finite, gives `angvel`.
/// @param orn The body's orientation.
/// @param h The time step, in seconds.
/// @return The new angular velocity, world space, in rad/s.
vector3 gyroscopic_step(const vector3 &angvel, const matrix3x3 &inertia, const quaternion &orn,
                        scalar h) noexcept;

/// Lowers a body's speeds to the limits, keeping their directions: its linear speed to
/// `max_linear_speed` and its angular speed to `max_angular`.
/// @param body A solver body.
/// @param max_linear_speed The fastest linear speed, in m/s (settings::max_linear_speed).
/// @param max_angular The fastest angular speed, in rad/s (max_angular_speed()).
void limit_speed(solver_body &body, scalar max_linear_speed, scalar max_angular) noexcept;

/// Queues adding each body's acceleration (gravity) over the sub-step `h` to its linear velocity,
/// then lowering its speeds to the limits (limit_speed(): `max_linear_speed`, and
/// max_angular_speed(h)). Index 0, the shared static body, is left alone. Each integration is
/// queued as one stage (see stage_queue), whose blocks of bodies may run on different threads;
/// each body's result is the same either way. The step queues it at the start of every
/// sub-step, before the constraints are solved: the limits apply to the velocities a sub-step
/// starts from, not to the passing push of the biased pass, which the relax pass takes back.
/// The storage behind `bodies` must outlive the queue's run.
/// @param bodies The solver's body array, as gathered for this step (index 0 is the static body).
/// @param h Length of the sub-step, in seconds.
/// @param max_linear_speed The fastest linear speed, in m/s (settings::max_linear_speed).
/// @param queue Where the work is queued.
void integrate_velocities(std::span<solver_body> bodies, scalar h, scalar max_linear_speed,
                          stage_queue &queue);

/// Queues advancing each body's accumulated motion over the sub-step `h`.
/// Semi-implicit Euler: the velocities just solved move the bodies, adding to
/// `solver_body::delta_position` and `solver_body::delta_rotation` (the registry is written
/// later, by write_back). Index 0, the shared static body, is left alone. Angular speed is
/// capped so that no body turns more than π/4 radians in one sub-step, which would alias its
/// orientation; the cap lowers the body's `angvel` itself.
/// @param bodies The solver's body array, as gathered for this step (index 0 is the static body).
/// @param h Length of the sub-step, in seconds.
/// @param queue Where the work is queued.
void integrate_positions(std::span<solver_body> bodies, scalar h, stage_queue &queue);

/// Queues lowering every body's speeds to the limits (limit_speed), as integrate_positions
/// does. The step queues it last, so that no body leaves a step faster than the limits.
/// @param bodies The solver's body array, as gathered for this step (index 0 is the static body).
/// @param h Length of the sub-step, in seconds.
/// @param max_linear_speed The fastest linear speed, in m/s (settings::max_linear_speed).
/// @param queue Where the work is queued.
void limit_speeds(std::span<solver_body> bodies, scalar h, scalar max_linear_speed, stage_queue &queue);

} // namespace edyn

#endif // EDYN_DYNAMICS_INTEGRATION_HPP
