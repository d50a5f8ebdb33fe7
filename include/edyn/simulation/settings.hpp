#ifndef EDYN_SIMULATION_SETTINGS_HPP
#define EDYN_SIMULATION_SETTINGS_HPP

#include "edyn/constraints/constraint_solver.hpp"
#include "edyn/constraints/contact_solver.hpp"
#include "edyn/ecs/fwd.hpp"
#include "edyn/simulation/execution_mode.hpp"

namespace edyn {

using step_callback_t = void (*)(registry &);

// The ranges the setters of world.hpp accept (they throw std::invalid_argument outside them),
// and a network client accepts from its server. Beyond them a step costs without bound or its
// arithmetic leaves the range of a float.
// Seconds: from 10,000 steps per second to one.
inline constexpr scalar min_fixed_dt = scalar(1e-4);
inline constexpr scalar max_fixed_dt = scalar(1);
// Sub-steps per step, and relax, position, restitution and individual restitution iterations.
inline constexpr unsigned max_solver_substeps = 64;
inline constexpr unsigned max_solver_iterations = 64;
inline constexpr unsigned max_steps_per_update_limit = 1000;

// World-wide simulation settings, kept in the registry's context by attach().
struct settings {
    edyn::execution_mode execution_mode{edyn::execution_mode::sequential};
    scalar fixed_dt{scalar(1) / scalar(60)};
    vector3 gravity{0, scalar(-9.8), 0};
    // The soft-step solver splits each step into this many sub-steps, each with one biased
    // iteration; more sub-steps, stiffer and more accurate contacts and joints.
    unsigned num_substeps{6};
    // Relax iterations per sub-step: velocity-only passes removing the push-out velocity.
    unsigned num_relax_iterations{1};
    unsigned num_restitution_iterations{8};
    unsigned num_individual_restitution_iterations{3};
    // update() runs at most this many steps; the rest of a long pause is dropped so that a slow
    // frame cannot make the next one slower still.
    unsigned max_steps_per_update{10};
    contact_solver_settings contact{};
    constraint_solver_settings joint{};
    // A body whose speeds stay below these for time_to_sleep seconds may sleep with its island.
    scalar sleep_linear_velocity{scalar(0.05)};
    scalar sleep_angular_velocity{scalar(0.0872665)}; // 5 degrees per second
    scalar time_to_sleep{scalar(0.5)};
    step_callback_t pre_step_callback{nullptr};
    step_callback_t post_step_callback{nullptr};
};

} // namespace edyn

#endif // EDYN_SIMULATION_SETTINGS_HPP
