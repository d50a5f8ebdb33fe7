#ifndef EDYN_SRC_SIMULATION_CLOCK_HPP
#define EDYN_SRC_SIMULATION_CLOCK_HPP

#include "edyn/simulation/settings.hpp"
#include "edyn/simulation/world_state.hpp"
#include <cstdint>

namespace edyn {

// The fixed-step clock shared by update() and the asynchronous worker: takes the caller's
// `time`, returns how many fixed steps are due (none on the first call, which only sets the
// start, and none while paused), and leaves in the accumulator the time past the last of them.
std::uint64_t take_due_steps(world_state &world, const settings &settings, double time);

// After a step of an update's `run` so far, with `left` more due: what a step callback changed
// of the clock counts for the rest. Paused, none are left (their time is dropped, as a pause
// drops its time); with another fixed_dt, the time of those left is counted again in the new
// step, at most max_steps_per_update for the whole update. `dt_before` is the step's fixed_dt
// before it ran.
std::uint64_t recount_due_steps(world_state &world, const settings &settings, std::uint64_t run,
                                std::uint64_t left, scalar dt_before);

// Where the present lies between the last two steps, for interpolation.
scalar present_fraction(const world_state &world, const settings &settings);

} // namespace edyn

#endif // EDYN_SRC_SIMULATION_CLOCK_HPP
