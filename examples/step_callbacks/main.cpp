// Air drag applied before every physics step. update() runs as many steps as the time since
// the last call asks for, so logic that must act once per step goes in a step callback, not
// beside update(). A drag that removes the fraction c dt of the velocity each step brings a
// falling body to the terminal speed g / c.
#include <atomic>
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>

namespace {

constexpr edyn::scalar drag_coefficient = 2; // 1/s

// Marks the bodies the wind acts on.
struct drag {};

// Callbacks are plain functions of a registry. In the asynchronous mode (the default) they run
// on the simulation worker's thread with the worker's registry, so what they share with the
// program lives outside both registries and is safe to touch from two threads.
std::atomic<int> pre_steps{0};
std::atomic<int> post_steps{0};

void apply_drag(edyn::registry &registry) {
    auto dt = edyn::get_fixed_dt(registry);
    for (auto entity : registry.view<drag, edyn::linvel>())
        registry.get<edyn::linvel>(entity) *= 1 - drag_coefficient * dt;
    ++pre_steps;
}

void count_step(edyn::registry &) { ++post_steps; }

} // namespace

int main() {
    edyn::registry registry;
    edyn::attach(registry);
    // The worker's registry gets the program's drag tags once edyn knows to send them.
    edyn::register_external_components<drag>(registry);
    edyn::set_pre_step_callback(registry, &apply_drag);
    edyn::set_post_step_callback(registry, &count_step);

    auto def = edyn::rigidbody_def();
    def.shape = edyn::sphere_shape{0.1};
    def.position = {0, 100, 0};
    auto leaf = edyn::make_rigidbody(registry, def);
    registry.emplace<drag>(leaf);

    // 30 frames per second for 4 s: two physics steps of 1/60 s per update. The first call
    // only starts the clock.
    // update() never waits for the worker, which steps meanwhile; frames made faster than it
    // steps would be merged (as a slow frame drops time in the sequential mode), so this
    // example, whose frames take no time at all, waits for each.
    for (int frame = 0; frame <= 120; ++frame) {
        edyn::update(registry, frame / 30.0);
        edyn::wait_for_simulation(registry);
    }

    auto speed = -registry.get<edyn::linvel>(leaf).y;
    auto expected = 9.8f / drag_coefficient;
    auto steps = int(edyn::get_step_count(registry));
    std::printf("120 updates ran %d steps (240, give or take one for rounding): pre-step callback called %d "
                "times, post-step %d times\n",
                steps, pre_steps.load(), post_steps.load());
    std::printf("falling at %.3f m/s after 4 s (expected terminal speed g / c = %.3f)\n", speed, expected);
    // Rounding in the clock may leave the last step to the next update.
    auto ok = pre_steps.load() == steps && post_steps.load() == steps && std::abs(steps - 240) <= 1 &&
              std::abs(speed - expected) < 0.01f * expected;
    edyn::detach(registry);
    return ok ? 0 : 1;
}
