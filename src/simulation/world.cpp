#include "edyn/simulation/world.hpp"
#include "../shapes/invalid_argument.hpp"
#include "async_execution.hpp"
#include "clock.hpp"
#include "edyn/collision/collision_filter.hpp"
#include "edyn/collision/contact_manifold.hpp"
#include "edyn/collision/should_collide.hpp"
#include "edyn/dynamics/body_limits.hpp"
#include "edyn/dynamics/material_mixing.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/dynamics/worker_calls.hpp"
#include "edyn/simulation/action_list.hpp"
#include "edyn/simulation/contact_events.hpp"
#include "edyn/simulation/interpolation.hpp"
#include "edyn/simulation/registry_listeners.hpp"
#include "edyn/simulation/step.hpp"
#include "edyn/simulation/world_state.hpp"
#include "pending_replies.hpp"
#include <chrono>
#include <cmath>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>

namespace edyn {

namespace {

using detail::concat;

[[noreturn]] void not_attached(const char *function) {
    throw std::invalid_argument(std::string(function) +
                                ": the registry is not attached (call edyn::attach first)");
}

// The world of an attached registry; `function`, the one called, is named in the error.
world_state &world(registry &registry, const char *function) {
    auto *w = registry.ctx().find<world_state>();
    if (!w) not_attached(function);
    return *w;
}

const world_state &attached_world(const registry &registry, const char *function) {
    auto *w = registry.ctx().find<world_state>();
    if (!w) not_attached(function);
    return *w;
}

settings &mutable_settings(registry &registry, const char *function) {
    world(registry, function);
    return registry.ctx().get<settings>();
}

const settings &settings_of(const registry &registry, const char *function) {
    attached_world(registry, function);
    return registry.ctx().get<settings>();
}

[[noreturn]] void invalid(const char *function, const std::string &what) {
    throw std::invalid_argument(std::string(function) + ": " + what);
}

void check_count(const char *function, const char *what, unsigned value, unsigned min, unsigned max) {
    if (value < min || value > max)
        invalid(function, std::string(what) + " must be in [" + std::to_string(min) + ", " +
                              std::to_string(max) + "], got " + std::to_string(value));
}

} // namespace

bool is_attached(const registry &registry) noexcept { return registry.ctx().contains<world_state>(); }

namespace {

void check_config(const char *function, const init_config &config) {
    if (config.execution_mode != execution_mode::sequential &&
        config.execution_mode != execution_mode::sequential_multithreaded &&
        config.execution_mode != execution_mode::asynchronous)
        invalid(function,
                "init_config::execution_mode is " + std::to_string(unsigned(config.execution_mode)) +
                    ", not an execution_mode (sequential, sequential_multithreaded or asynchronous)");
    if (config.execution_mode != execution_mode::sequential_multithreaded) return;
    if (config.scheduler) {
        auto &hooks = *config.scheduler;
        if (!hooks.enqueue) invalid(function, "init_config::scheduler: task_hooks::enqueue is null");
        if (!hooks.wait) invalid(function, "init_config::scheduler: task_hooks::wait is null");
        if (hooks.concurrency == 0) invalid(function, "init_config::scheduler: task_hooks::concurrency is 0");
    } else if (config.num_worker_threads > init_config::max_worker_threads) {
        invalid(function, "init_config::num_worker_threads is " + std::to_string(config.num_worker_threads) +
                              ", more than the " + std::to_string(init_config::max_worker_threads) +
                              " allowed");
    }
}

// What init() set, read by attach(registry); registries may be attached on several threads.
std::mutex default_config_mutex;
init_config default_config;

} // namespace

void init(const init_config &config) {
    check_config("init", config);
    std::lock_guard lock(default_config_mutex);
    default_config = config;
}

void attach(registry &registry) {
    init_config config;
    {
        std::lock_guard lock(default_config_mutex);
        config = default_config;
    }
    attach(registry, config);
}

void attach(registry &registry, const init_config &config) {
    if (is_attached(registry)) invalid("attach", "the registry is already attached");
    check_config("attach", config);
    // Made before anything is added to the registry, so that a rejected config leaves it as it was.
    std::unique_ptr<task_scheduler> scheduler;
    if (config.execution_mode == execution_mode::sequential_multithreaded) {
        try {
            scheduler = config.scheduler ? std::make_unique<task_scheduler>(*config.scheduler)
                                         : std::make_unique<task_scheduler>(config.num_worker_threads);
        } catch (const std::invalid_argument &e) {
            invalid("attach", std::string("init_config::scheduler: ") + e.what());
        }
    }
    auto background = config.scheduler && scheduler ? std::make_unique<background_tasks>(*config.scheduler)
                                                    : std::make_unique<background_tasks>();
    auto &s = registry.ctx().emplace<settings>();
    s.execution_mode = config.execution_mode;
    auto &state = registry.ctx().emplace<world_state>();
    state.scheduler = std::move(scheduler);
    state.min_parallel_bodies = config.min_parallel_bodies;
    state.background = std::move(background);
    registry.ctx().emplace<contact_events>();
    if (config.execution_mode == execution_mode::asynchronous) {
        // The simulation lives in the worker; this registry mirrors it.
        registry.ctx().emplace<async_execution>(registry).adopt_existing(registry);
        return;
    }
    connect_registry_listeners(registry);
    adopt_existing_bodies(registry);
}

void detach(registry &registry) {
    if (!is_attached(registry)) return;
    if (auto *async = registry.ctx().find<async_execution>()) {
        async->disconnect(registry);
        // Stops and joins the worker.
        registry.ctx().erase<async_execution>();
    } else {
        disconnect_registry_listeners(registry);
    }
    remove_edyn_components(registry);
    registry.ctx().erase<pending_replies>();
    registry.ctx().erase<world_state>();
    registry.ctx().erase<settings>();
    registry.ctx().erase<contact_events>();
    registry.ctx().erase<material_mix_table>();
    registry.ctx().erase<detail::action_types>();
    reset_should_collide(registry);
}

void step_simulation(registry &registry) {
    world(registry, "step_simulation");
    validate_settings(registry.ctx().get<settings>(), "step_simulation");
    if (auto *async = registry.ctx().find<async_execution>()) {
        async->step_simulation(registry);
        return;
    }
    save_previous_transforms(registry);
    run_step(registry);
    interpolate_present_transforms(registry, 1);
}

namespace {

// Takes from the accumulator the whole steps it holds, at most `most`, dropping the time of
// those beyond.
std::uint64_t take_whole_steps(world_state &w, const settings &s, std::uint64_t most) {
    double dt = s.fixed_dt;
    // Compared in floating point before converting: a long pause over a small dt is more steps
    // than an integer holds.
    auto due = std::floor(w.accumulator / dt);
    std::uint64_t steps;
    if (!(due <= double(most))) {
        // Drop the time that cannot be caught up with.
        auto fraction = std::isfinite(w.accumulator) ? std::fmod(w.accumulator, dt) : 0.0;
        w.accumulator = fraction + dt * double(most);
        steps = most;
    } else {
        steps = static_cast<std::uint64_t>(due);
    }
    // One subtraction per step, as the steps are run, so that the fraction left is the same.
    for (std::uint64_t i = 0; i < steps; ++i)
        w.accumulator -= dt;
    return steps;
}

} // namespace

std::uint64_t take_due_steps(world_state &w, const settings &s, double time) {
    if (!w.started) {
        w.started = true;
        w.last_time = time;
        return 0;
    }
    auto elapsed = std::max(time - w.last_time, 0.0);
    w.last_time = time;
    if (w.paused) return 0;
    w.accumulator += elapsed;
    return take_whole_steps(w, s, s.max_steps_per_update);
}

std::uint64_t recount_due_steps(world_state &w, const settings &s, std::uint64_t run, std::uint64_t left,
                                scalar dt_before) {
    if (w.paused) return 0;
    if (s.fixed_dt == dt_before) return left;
    for (std::uint64_t i = 0; i < left; ++i)
        w.accumulator += dt_before;
    return take_whole_steps(w, s, s.max_steps_per_update > run ? s.max_steps_per_update - run : 0);
}

scalar present_fraction(const world_state &w, const settings &s) {
    if (w.paused || !w.started) return 1;
    return static_cast<scalar>(std::clamp(w.accumulator / s.fixed_dt, 0.0, 1.0));
}

void update(registry &registry, double time) {
    if (!std::isfinite(time)) invalid("update", "time must be finite, got " + std::to_string(time));
    auto &w = world(registry, "update");
    validate_settings(registry.ctx().get<settings>(), "update");
    if (auto *async = registry.ctx().find<async_execution>()) {
        async->update(registry, time);
        return;
    }
    auto &s = registry.ctx().get<settings>();
    auto steps = take_due_steps(w, s, time);
    for (std::uint64_t i = 0; i < steps; ++i) {
        save_previous_transforms(registry);
        auto dt = s.fixed_dt;
        run_step(registry);
        // A step callback may have paused the world or changed its step.
        steps = i + 1 + recount_due_steps(w, s, i + 1, steps - i - 1, dt);
    }
    interpolate_present_transforms(registry, present_fraction(w, s));
    run_pending_replies(registry);
}

void wait_for_simulation(registry &registry) {
    world(registry, "wait_for_simulation");
    if (auto *async = registry.ctx().find<async_execution>()) {
        async->wait(registry);
        return;
    }
    run_pending_replies(registry);
}

void update(registry &registry) {
    auto now = std::chrono::steady_clock::now().time_since_epoch();
    update(registry, std::chrono::duration<double>(now).count());
}

void wake_up_entity(registry &registry, entity e) {
    if (!registry.valid(e))
        invalid("wake_up_entity", "entity " + std::to_string(to_index(e)) + " is not valid");
    call_here_and_in_worker(
        registry, e,
        [](edyn::registry &r, entity target) {
            if (auto *w = r.ctx().find<world_state>()) w->islands.wake_entity(r, target);
        },
        motion_parts::none);
}

void set_paused(registry &registry, bool paused) { world(registry, "set_paused").paused = paused; }
bool is_paused(const registry &registry) { return attached_world(registry, "is_paused").paused; }

void set_fixed_dt(registry &registry, scalar dt) {
    if (!(dt >= min_fixed_dt && dt <= max_fixed_dt))
        invalid("set_fixed_dt", "dt must be in [" + concat(min_fixed_dt) + ", " + concat(max_fixed_dt) +
                                    "] s, got " + concat(dt));
    mutable_settings(registry, "set_fixed_dt").fixed_dt = dt;
}
scalar get_fixed_dt(const registry &registry) { return settings_of(registry, "get_fixed_dt").fixed_dt; }

void set_gravity(registry &registry, const vector3 &gravity) {
    if (!isfinite(gravity)) invalid("set_gravity", concat("gravity must be finite, got ", gravity));
    if (!(length(gravity) <= max_gravity))
        invalid("set_gravity", concat("gravity must be at most ", max_gravity, " m/s^2 long, got ", gravity));
    mutable_settings(registry, "set_gravity").gravity = gravity;
    // Resting bodies must notice a new gravity (in asynchronous mode the worker wakes its own;
    // here they are shown awake at once, and the worker's say when they sleep again).
    if (auto *async = registry.ctx().find<async_execution>()) {
        registry.clear<sleeping_tag>();
        async->push_gravity(gravity);
        return;
    }
    auto &w = world(registry, "set_gravity");
    for (auto e : registry.view<dynamic_tag, sleeping_tag>())
        w.islands.wake_entity(registry, e);
}
vector3 get_gravity(const registry &registry) { return settings_of(registry, "get_gravity").gravity; }

void set_solver_substeps(registry &registry, unsigned substeps) {
    check_count("set_solver_substeps", "substeps", substeps, 1, max_solver_substeps);
    mutable_settings(registry, "set_solver_substeps").num_substeps = substeps;
}
unsigned get_solver_substeps(const registry &registry) {
    return settings_of(registry, "get_solver_substeps").num_substeps;
}

void set_solver_relax_iterations(registry &registry, unsigned iterations) {
    check_count("set_solver_relax_iterations", "iterations", iterations, 0, max_solver_iterations);
    mutable_settings(registry, "set_solver_relax_iterations").num_relax_iterations = iterations;
}
unsigned get_solver_relax_iterations(const registry &registry) {
    return settings_of(registry, "get_solver_relax_iterations").num_relax_iterations;
}

void set_solver_velocity_iterations(registry &registry, unsigned iterations) {
    check_count("set_solver_velocity_iterations", "iterations", iterations, 1, max_solver_substeps);
    mutable_settings(registry, "set_solver_velocity_iterations").num_substeps = iterations;
}
unsigned get_solver_velocity_iterations(const registry &registry) {
    return settings_of(registry, "get_solver_velocity_iterations").num_substeps;
}

void set_solver_position_iterations(registry &registry, unsigned iterations) {
    check_count("set_solver_position_iterations", "iterations", iterations, 0, max_solver_iterations);
    mutable_settings(registry, "set_solver_position_iterations").joint.position_projection_iterations =
        iterations;
}
unsigned get_solver_position_iterations(const registry &registry) {
    return settings_of(registry, "get_solver_position_iterations").joint.position_projection_iterations;
}

void set_solver_restitution_iterations(registry &registry, unsigned iterations) {
    check_count("set_solver_restitution_iterations", "iterations", iterations, 0, max_solver_iterations);
    mutable_settings(registry, "set_solver_restitution_iterations").num_restitution_iterations = iterations;
}
unsigned get_solver_restitution_iterations(const registry &registry) {
    return settings_of(registry, "get_solver_restitution_iterations").num_restitution_iterations;
}

void set_solver_individual_restitution_iterations(registry &registry, unsigned iterations) {
    check_count("set_solver_individual_restitution_iterations", "iterations", iterations, 0,
                max_solver_iterations);
    mutable_settings(registry, "set_solver_individual_restitution_iterations")
        .num_individual_restitution_iterations = iterations;
}
unsigned get_solver_individual_restitution_iterations(const registry &registry) {
    return settings_of(registry, "get_solver_individual_restitution_iterations")
        .num_individual_restitution_iterations;
}

void set_max_steps_per_update(registry &registry, unsigned steps) {
    check_count("set_max_steps_per_update", "steps", steps, 1, max_steps_per_update_limit);
    mutable_settings(registry, "set_max_steps_per_update").max_steps_per_update = steps;
}

void set_max_linear_speed(registry &registry, scalar speed) {
    if (!(speed > 0 && speed <= max_linear_speed_limit))
        invalid("set_max_linear_speed",
                "speed must be in (0, " + concat(max_linear_speed_limit) + "] m/s, got " + concat(speed));
    mutable_settings(registry, "set_max_linear_speed").max_linear_speed = speed;
}
scalar get_max_linear_speed(const registry &registry) {
    return settings_of(registry, "get_max_linear_speed").max_linear_speed;
}

void set_pre_step_callback(registry &registry, step_callback_t callback) {
    mutable_settings(registry, "set_pre_step_callback").pre_step_callback = callback;
}
void set_post_step_callback(registry &registry, step_callback_t callback) {
    mutable_settings(registry, "set_post_step_callback").post_step_callback = callback;
}

const settings &get_settings(const registry &registry) { return settings_of(registry, "get_settings"); }

double get_simulation_time(const registry &registry) {
    return attached_world(registry, "get_simulation_time").simulation_time;
}
std::uint64_t get_step_count(const registry &registry) {
    return attached_world(registry, "get_step_count").step_count;
}

} // namespace edyn
