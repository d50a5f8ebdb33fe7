#ifndef EDYN_TESTS_BEHAVIOUR_SUPPORT_HPP
#define EDYN_TESTS_BEHAVIOUR_SUPPORT_HPP

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <edyn/edyn.hpp>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <string_view>

namespace edyn::test {

// Gravity's pull in the tests' worked figures (the worlds' default gravity is 9.8 m/s^2 down).
constexpr scalar earth_g = scalar(9.8);

// Half extents of a 1 m cube.
inline const vector3 unit_half{scalar(0.5), scalar(0.5), scalar(0.5)};

// The configuration every behaviour test attaches with: sequential, or, when
// EDYN_TEST_EXECUTION_MODE says so (CTest runs the suite in each mode), the multithreaded step
// on two worker threads or the asynchronous worker. The behaviour must hold in all three.
inline init_config test_config() {
    init_config config;
    config.execution_mode = execution_mode::sequential;
    auto *mode = std::getenv("EDYN_TEST_EXECUTION_MODE");
    if (mode && std::string_view(mode) == "sequential_multithreaded") {
        config.execution_mode = execution_mode::sequential_multithreaded;
        config.num_worker_threads = 2;
        // The scenes are small: every step goes to the threads all the same.
        config.min_parallel_bodies = 0;
    } else if (mode && std::string_view(mode) == "asynchronous") {
        config.execution_mode = execution_mode::asynchronous;
    } else if (mode && std::string_view(mode) != "sequential") {
        throw std::invalid_argument(std::string("EDYN_TEST_EXECUTION_MODE: unknown mode ") + mode);
    }
    return config;
}

// Whether the simulation's own state (islands, contact reuse marks) lives in this registry: in
// the asynchronous mode it lives in the worker's, and tests of it run in the other modes.
inline bool simulates_here(const registry &reg) {
    return get_settings(reg).execution_mode != execution_mode::asynchronous;
}

// One fixed step, its results in the registry on return in every mode (in the asynchronous
// one, the worker runs it and the main registry receives it before this returns).
inline void step(registry &reg) {
    step_simulation(reg);
    wait_for_simulation(reg);
}

// update(reg, time), likewise with its results in the registry on return.
inline void advance_to(registry &reg, double time) {
    update(reg, time);
    wait_for_simulation(reg);
}

// A world with default settings in the tests' execution mode, attached on construction,
// detached on exit.
struct world_fixture : ::testing::Test {
    registry reg;

    void SetUp() override { attach(reg, test_config()); }
    void TearDown() override { detach(reg); }

    // Runs whole fixed steps covering `seconds` of simulated time; returns the step count.
    int run_for(double seconds) {
        auto steps = int(std::lround(seconds / double(get_fixed_dt(reg))));
        for (int i = 0; i < steps; ++i)
            step_simulation(reg);
        wait_for_simulation(reg);
        return steps;
    }

    vector3 pos(entity e) const { return reg.get<position>(e); }
    vector3 vel(entity e) const { return reg.get<linvel>(e); }
    vector3 angular(entity e) const { return reg.get<angvel>(e); }
};

// What rigidbody_def::sleeping_disabled does, for every dynamic body a scene builder made: a
// stack that falls asleep stands whatever the solver does, so stability is measured awake.
inline void disable_sleeping(registry &reg) {
    for (auto e : reg.view<dynamic_tag>())
        reg.emplace_or_replace<sleeping_disabled_tag>(e);
}

inline rigidbody_def sphere_def(scalar radius, const vector3 &position, scalar mass = 1) {
    rigidbody_def def;
    def.mass = mass;
    def.shape = sphere_shape{radius};
    def.position = position;
    return def;
}

inline rigidbody_def box_def(const vector3 &half_extents, const vector3 &position, scalar mass = 1) {
    rigidbody_def def;
    def.mass = mass;
    def.shape = box_shape{half_extents};
    def.position = position;
    return def;
}

// How far a body falls freely from rest in `seconds` under the world's gravity: sub-stepped
// semi-implicit Euler falls g h^2 n (n + 1) / 2 after n sub-steps of h, 0.3% more than
// g t^2 / 2 after 1 s at the default 6 sub-steps of a 60 Hz step. `seconds` is a whole number
// of fixed steps.
inline scalar fall(const registry &reg, scalar seconds) {
    auto g = length(get_gravity(reg));
    auto n = std::round(seconds / get_fixed_dt(reg)) * scalar(get_solver_substeps(reg));
    auto h = seconds / n;
    return g * h * h * n * (n + 1) / 2;
}

// Steps until `ball` has bounced and reached its peak (at most `max_steps`); returns the peak
// height of its centre less `radius`, or a negative value if it never bounced.
inline scalar rebound_peak(registry &reg, entity ball, scalar radius, int max_steps = 300) {
    bool bounced = false;
    scalar peak = 0;
    for (int i = 0; i < max_steps; ++i) {
        step(reg);
        auto v = reg.get<linvel>(ball).y;
        if (!bounced && v > 0) bounced = true;
        if (bounced) {
            peak = std::max(peak, reg.get<position>(ball).y - radius);
            if (v < 0) break;
        }
    }
    return bounced ? peak : scalar(-1);
}

// How far above the closed form a bounce's peak may be: a bounce starts when contact happens
// within the coming sub-step, so up to one sub-step of travel above the ground, plus 1%.
inline scalar rebound_tolerance(const registry &reg, scalar drop_height, scalar expected) {
    auto impact_speed = std::sqrt(2 * length(get_gravity(reg)) * drop_height);
    auto substep = get_fixed_dt(reg) / scalar(get_solver_substeps(reg));
    return impact_speed * substep + scalar(0.01) * expected;
}

} // namespace edyn::test

#endif // EDYN_TESTS_BEHAVIOUR_SUPPORT_HPP
