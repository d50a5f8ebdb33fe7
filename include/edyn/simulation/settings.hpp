#ifndef EDYN_SIMULATION_SETTINGS_HPP
#define EDYN_SIMULATION_SETTINGS_HPP

#include "edyn/constraints/constraint_solver.hpp"
#include "edyn/constraints/contact_solver.hpp"
#include "edyn/ecs/fwd.hpp"
#include "edyn/simulation/execution_mode.hpp"

namespace edyn {

/// A function run before or after every step: set_pre_step_callback, set_post_step_callback.
/// It gets the registry the step runs in: in asynchronous mode the simulation worker's, on the
/// worker thread.
using step_callback_t = void (*)(registry &);

/// Shortest fixed step set_fixed_dt accepts, in seconds (10,000 steps per second).
/// This and the constants below are the ranges the setters of world.hpp accept (they throw
/// std::invalid_argument outside them), and a network client accepts from its server. Beyond
/// them a step costs without bound or its arithmetic leaves the range of a float.
inline constexpr scalar min_fixed_dt = scalar(1e-4);
/// Longest fixed step set_fixed_dt accepts, in seconds (one step per second).
inline constexpr scalar max_fixed_dt = scalar(1);
/// Most sub-steps per step set_solver_substeps (and set_solver_velocity_iterations) accepts.
inline constexpr unsigned max_solver_substeps = 64;
/// Most relax, position, restitution and individual restitution iterations their setters
/// accept.
inline constexpr unsigned max_solver_iterations = 64;
/// Fastest speed set_max_linear_speed accepts, in m/s (a hundred kilometres per second).
inline constexpr scalar max_linear_speed_limit = scalar(1e5);
/// Most steps per update() set_max_steps_per_update accepts.
inline constexpr unsigned max_steps_per_update_limit = 1000;

/// World-wide simulation settings, kept in the registry's context by attach().
/// Read them with get_settings and change them with the setters of world.hpp, which validate
/// the values; fields without a setter are changed in place
/// (`registry.ctx().get<edyn::settings>()`), and update() and step_simulation() check every
/// field (validate_settings) before they step. In asynchronous mode the changes reach the
/// simulation worker with the next update(), and a step callback's changes on the worker reach
/// the program's registry with the step's results (a change the program made in between
/// replaces them). A step works on a copy made when it starts, so a step callback's changes
/// apply from the next step, which checks them first.
struct settings {
    /// The mode the registry was attached with (init_config::execution_mode); fixed by attach.
    edyn::execution_mode execution_mode{edyn::execution_mode::sequential};
    /// Length of a step, in seconds; default 1/60 (set_fixed_dt).
    scalar fixed_dt{scalar(1) / scalar(60)};
    /// The world's gravitational acceleration, in m/s²; default (0, -9.8, 0) (set_gravity).
    vector3 gravity{0, scalar(-9.8), 0};
    /// Sub-steps per step; default 6 (set_solver_substeps).
    /// The soft-step solver splits each step into this many sub-steps, each with one biased
    /// iteration; more sub-steps, stiffer and more accurate contacts and joints.
    unsigned num_substeps{6};
    /// Relax iterations per sub-step; default 1 (set_solver_relax_iterations).
    /// Velocity-only passes removing the push-out velocity.
    unsigned num_relax_iterations{1};
    /// Iterations of the restitution solver per sub-step; default 8; 0 turns it off
    /// (set_solver_restitution_iterations).
    unsigned num_restitution_iterations{8};
    /// Most iterations the restitution solver spends on each group of contacts, which it stops
    /// once their impulses settle; default 32 (set_solver_individual_restitution_iterations).
    unsigned num_individual_restitution_iterations{32};
    /// update() runs at most this many steps; default 10 (set_max_steps_per_update).
    /// The rest of a long pause is dropped so that a slow frame cannot make the next one slower
    /// still.
    unsigned max_steps_per_update{10};
    /// Contact solver settings: stiffness, damping, push-out speed, restitution threshold.
    /// No setter of world.hpp changes them.
    contact_solver_settings contact{};
    /// Joint solver settings, including the position projection passes
    /// (set_solver_position_iterations).
    constraint_solver_settings joint{};
    /// The fastest a body moves, in m/s; default 400 (set_max_linear_speed).
    /// The solver lowers a faster body's velocity to it, keeping its direction, at the start of
    /// every sub-step and at the end of the step; a body's rotation is likewise held to a quarter
    /// turn per sub-step. Contacts and joints that cannot all hold (a bridge whose
    /// anchors lie farther apart than its length) can throw bodies about, and a huge impulse
    /// can be applied: the limits keep such bodies within the range of a float.
    scalar max_linear_speed{400};
    /// Linear speed below which a body counts as at rest, in m/s; default 0.05.
    /// A body whose speeds stay below these for time_to_sleep seconds may sleep with its island.
    scalar sleep_linear_velocity{scalar(0.05)};
    /// Angular speed below which a body counts as at rest, in rad/s; default 5 degrees per
    /// second.
    scalar sleep_angular_velocity{scalar(0.0872665)};
    /// Seconds a whole island's bodies must stay below the sleep speeds before it sleeps;
    /// default 0.5.
    scalar time_to_sleep{scalar(0.5)};
    /// Run at the start of every step, or null (the default); set_pre_step_callback.
    step_callback_t pre_step_callback{nullptr};
    /// Run at the end of every step, after collision events, or null (the default);
    /// set_post_step_callback.
    step_callback_t post_step_callback{nullptr};

    /// Field by field: whether every setting, callbacks included, is the same.
    bool operator==(const settings &) const = default;
};

/// Checks every field of `s`: those with a setter against the ranges their setters accept, and
/// the others against theirs: speeds, frequencies, damping ratios, thresholds and time_to_sleep
/// finite and not negative (max_projected_gap, max_correction_speed and time_to_sleep may be
/// infinite, for no bound), the frequency caps (max_hertz_ratio) in (0, 1] and
/// joint.position_projection in [0, 1]. update(), step_simulation() and every step call it,
/// and so does a network client on the settings its server sends.
/// @param s The settings to check.
/// @param function The name the error message starts with: the function that checks them.
/// @throws std::invalid_argument naming `function` and the first field out of range, with its
/// value.
void validate_settings(const settings &s, const char *function);

} // namespace edyn

#endif // EDYN_SIMULATION_SETTINGS_HPP
