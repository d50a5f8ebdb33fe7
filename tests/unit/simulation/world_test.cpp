#include <chrono>
#include <cmath>
#include <edyn/edyn.hpp>
#include <functional>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

namespace edyn {
namespace {

entity make_ball(registry &reg, const vector3 &pos) {
    rigidbody_def def;
    def.shape = sphere_shape{0.5};
    def.position = pos;
    return make_rigidbody(reg, def);
}

TEST(world, attach_detach_attach_keeps_the_programs_entities) {
    registry reg;
    attach(reg);
    EXPECT_TRUE(is_attached(reg));
    EXPECT_THROW(attach(reg), std::invalid_argument);
    auto ball = make_ball(reg, {0, 0.45, 0});
    rigidbody_def ground;
    ground.kind = rigidbody_kind::rb_static;
    ground.shape = plane_shape{vector3_y, 0};
    make_rigidbody(reg, ground);
    struct user_data {
        int value;
    };
    reg.emplace<user_data>(ball, 7);
    step_simulation(reg); // a manifold entity now exists
    ASSERT_GT(reg.storage<contact_manifold>().size(), 0u);

    set_should_collide(reg, [](const registry &, entity, entity) { return true; });
    detach(reg);
    EXPECT_FALSE(is_attached(reg));
    EXPECT_TRUE(reg.ctx().empty()) << reg.ctx().size() << " context variables left after detach";
    EXPECT_EQ(get_should_collide(reg), &should_collide_default);
    EXPECT_TRUE(reg.valid(ball));
    EXPECT_EQ(reg.get<user_data>(ball).value, 7);
    EXPECT_FALSE(reg.any_of<position>(ball));
    EXPECT_EQ(reg.storage<contact_manifold>().size(), 0u);
    EXPECT_EQ(reg.storage<island>().size(), 0u);
    EXPECT_THROW(step_simulation(reg), std::invalid_argument);

    attach(reg);
    auto again = make_ball(reg, {0, 5, 0});
    for (int i = 0; i < 10; ++i)
        step_simulation(reg);
    EXPECT_LT(reg.get<position>(again).y, 5);
    detach(reg);
}

TEST(world, the_asynchronous_mode_is_the_default) {
    EXPECT_EQ(init_config{}.execution_mode, execution_mode::asynchronous);
    registry reg;
    attach(reg, init_config{});
    EXPECT_EQ(get_settings(reg).execution_mode, execution_mode::asynchronous);
    detach(reg);
    EXPECT_FALSE(is_attached(reg));
}

TEST(world, sequential_multithreaded_attaches_with_its_own_threads_or_the_programs_scheduler) {
    registry reg;
    init_config config;
    config.execution_mode = execution_mode::sequential_multithreaded;
    config.num_worker_threads = 2;
    attach(reg, config);
    EXPECT_EQ(get_settings(reg).execution_mode, execution_mode::sequential_multithreaded);
    detach(reg);

    // A configuration attach refuses, with a message that contains `expected`; nothing is
    // attached.
    auto expect_refused = [&reg](const init_config &refused, const char *what, const char *expected) {
        try {
            attach(reg, refused);
            ADD_FAILURE() << "attach accepted " << what;
        } catch (const std::invalid_argument &e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
        EXPECT_FALSE(is_attached(reg));
    };

    // A thread count no machine has is refused, naming the field.
    auto too_many = config;
    too_many.num_worker_threads = 100000;
    expect_refused(too_many, "100,000 worker threads", "init_config::num_worker_threads is 100000");

    // A mode outside the enumeration is refused, naming the field.
    auto unknown = config;
    unknown.execution_mode = static_cast<execution_mode>(9);
    expect_refused(unknown, "execution mode 9", "attach: init_config::execution_mode is 9");

    // Incomplete hooks are refused, naming the field.
    auto no_hooks = config;
    no_hooks.scheduler = task_hooks{};
    expect_refused(no_hooks, "task_hooks without enqueue", "init_config::scheduler");
}

// The manual's edyn::init(init_config): the configuration attach uses when given none.
TEST(world, init_sets_the_configuration_attach_uses_when_given_none) {
    init_config config;
    config.execution_mode = execution_mode::sequential_multithreaded;
    config.num_worker_threads = 2;
    init(config);
    registry reg;
    attach(reg);
    EXPECT_EQ(get_settings(reg).execution_mode, execution_mode::sequential_multithreaded);
    detach(reg);

    // Refused as attach would refuse it, naming the field; the previous configuration stays.
    auto bad = config;
    bad.num_worker_threads = 100000;
    try {
        init(bad);
        ADD_FAILURE() << "init accepted 100000 worker threads";
    } catch (const std::invalid_argument &e) {
        EXPECT_NE(std::string(e.what()).find("init: init_config::num_worker_threads"), std::string::npos)
            << e.what();
    }
    attach(reg);
    EXPECT_EQ(get_settings(reg).execution_mode, execution_mode::sequential_multithreaded);
    detach(reg);

    // A configuration given to attach wins; init() with none restores the default.
    attach(reg, init_config{execution_mode::sequential});
    EXPECT_EQ(get_settings(reg).execution_mode, execution_mode::sequential);
    detach(reg);
    init();
    attach(reg);
    EXPECT_EQ(get_settings(reg).execution_mode, execution_mode::asynchronous);
    detach(reg);
    // Back to what the other unit tests expect (support/sequential_default.cpp).
    init(init_config{execution_mode::sequential});
}

// The manual's main loop calls update(registry) with no time: it reads the clock itself, so
// steps follow the wall time that passes between calls.
TEST(world, update_without_a_time_steps_as_the_clock_moves) {
    registry reg;
    attach(reg, init_config{execution_mode::sequential});
    update(reg);
    auto start = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(150)) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        update(reg);
    }
    // 150 ms at 60 steps a second: about 9 steps (a slow machine may take longer between calls,
    // never fewer steps than the time passed allows).
    EXPECT_GE(get_step_count(reg), 8u);
    EXPECT_LE(double(get_step_count(reg)),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 60 + 2);
    detach(reg);
}

TEST(world, update_runs_as_many_fixed_steps_as_the_time_asks_for) {
    registry reg;
    attach(reg);
    auto dt = double(get_fixed_dt(reg));
    EXPECT_NEAR(dt, 1.0 / 60, 1e-7);
    update(reg, 100.0); // sets the start only
    EXPECT_EQ(get_step_count(reg), 0u);
    update(reg, 100.0 + 2.5 * dt);
    EXPECT_EQ(get_step_count(reg), 2u);
    update(reg, 100.0 + 3.6 * dt); // the half step left over plus 1.1 more
    EXPECT_EQ(get_step_count(reg), 3u);
    EXPECT_NEAR(get_simulation_time(reg), 3 * dt, 1e-6);
    update(reg, 99.0); // time going backwards is no time
    EXPECT_EQ(get_step_count(reg), 3u);
    EXPECT_THROW(update(reg, std::nan("")), std::invalid_argument);
}

TEST(world, steps_per_update_are_capped_and_the_rest_dropped) {
    registry reg;
    attach(reg);
    set_max_steps_per_update(reg, 4);
    EXPECT_THROW(set_max_steps_per_update(reg, 0), std::invalid_argument);
    auto dt = double(get_fixed_dt(reg));
    update(reg, 0.0);
    // A stall of 100.25 steps: 4 run, the quarter step stays in the accumulator and the 96
    // whole steps beyond the cap are dropped.
    update(reg, 100.25 * dt);
    EXPECT_EQ(get_step_count(reg), 4u);
    // 1.01 steps later the accumulator holds 1.26 steps: exactly one more step. Had the stall
    // been kept, it would be the cap again.
    update(reg, 101.26 * dt);
    EXPECT_EQ(get_step_count(reg), 5u) << "the stall was caught up with";
    // The 0.26 left over and 0.5 more make no whole step.
    update(reg, 101.76 * dt);
    EXPECT_EQ(get_step_count(reg), 5u);
    EXPECT_NEAR(get_simulation_time(reg), 5 * dt, 1e-6);
}

TEST(world, pause_stops_update_but_not_step_simulation) {
    registry reg;
    attach(reg);
    auto ball = make_ball(reg, {0, 10, 0});
    update(reg, 0.0);
    set_paused(reg, true);
    EXPECT_TRUE(is_paused(reg));
    update(reg, 1.0);
    EXPECT_EQ(get_step_count(reg), 0u);
    EXPECT_EQ(reg.get<position>(ball).y, 10);
    step_simulation(reg);
    EXPECT_EQ(get_step_count(reg), 1u);
    EXPECT_LT(reg.get<position>(ball).y, 10);
    set_paused(reg, false);
    update(reg, 1.0 + 3.5 * double(get_fixed_dt(reg)));
    EXPECT_EQ(get_step_count(reg), 4u);
}

// After update(), present_position lies between the last two steps, at the fraction of a step
// of time left over.
TEST(world, present_transforms_are_interpolated_between_the_last_two_steps) {
    registry reg;
    attach(reg);
    set_gravity(reg, vector3_zero);
    rigidbody_def def;
    def.shape = sphere_shape{0.5};
    def.linvel = {6, 0, 0};
    def.angvel = {0, 3, 0};
    auto ball = make_rigidbody(reg, def);
    auto dt = double(get_fixed_dt(reg));

    update(reg, 0.0);
    update(reg, 2.25 * dt); // two steps and a quarter
    ASSERT_EQ(get_step_count(reg), 2u);
    auto x = reg.get<position>(ball).x;
    EXPECT_NEAR(x, 6 * 2 * dt, 1e-5);
    auto present = reg.get<present_position>(ball).x;
    EXPECT_NEAR(present, 6 * 1.25 * dt, 1e-5) << "the present lags the last step by 3/4 of a step";
    EXPECT_GT(present, 6 * dt - 1e-6);
    EXPECT_LT(present, x);
    auto present_angle = 2 * std::asin(reg.get<present_orientation>(ball).y);
    EXPECT_NEAR(present_angle, 3 * 1.25 * dt, 1e-4);

    // step_simulation sets the present to the step it ran.
    step_simulation(reg);
    EXPECT_EQ(reg.get<present_position>(ball).x, reg.get<position>(ball).x);
}

// Each setter throws naming itself and the value it refused.
void expect_refused(const char *function, const std::string &value, const std::function<void()> &call) {
    try {
        call();
        ADD_FAILURE() << function << " accepted " << value;
    } catch (const std::invalid_argument &e) {
        auto what = std::string(e.what());
        EXPECT_NE(what.find(function), std::string::npos) << "\"" << what << "\" does not name " << function;
        EXPECT_NE(what.find(value), std::string::npos) << "\"" << what << "\" does not name " << value;
    }
}

// Values a network client once took from its server: a step count that overflows, a step that
// never ends, a gravity the solver cannot integrate.
TEST(world, settings_are_bounded) {
    registry reg;
    attach(reg);
    auto before = get_settings(reg);
    expect_refused("set_fixed_dt", "1e-21", [&] { set_fixed_dt(reg, scalar(1e-21)); });
    expect_refused("set_fixed_dt", "5.7e+36", [&] { set_fixed_dt(reg, scalar(5.7e36)); });
    expect_refused("set_fixed_dt", "inf",
                   [&] { set_fixed_dt(reg, std::numeric_limits<scalar>::infinity()); });
    expect_refused("set_gravity", "-4e+34", [&] { set_gravity(reg, {0, scalar(-4e34), 0}); });
    expect_refused("set_solver_substeps", "4000000000", [&] { set_solver_substeps(reg, 4000000000u); });
    expect_refused("set_solver_velocity_iterations", "65", [&] { set_solver_velocity_iterations(reg, 65); });
    expect_refused("set_solver_relax_iterations", "4000000000",
                   [&] { set_solver_relax_iterations(reg, 4000000000u); });
    expect_refused("set_solver_position_iterations", "4000000000",
                   [&] { set_solver_position_iterations(reg, 4000000000u); });
    expect_refused("set_solver_restitution_iterations", "4000000000",
                   [&] { set_solver_restitution_iterations(reg, 4000000000u); });
    expect_refused("set_solver_individual_restitution_iterations", "4000000000",
                   [&] { set_solver_individual_restitution_iterations(reg, 4000000000u); });
    expect_refused("set_max_steps_per_update", "4000000000",
                   [&] { set_max_steps_per_update(reg, 4000000000u); });
    expect_refused("set_max_linear_speed", "0", [&] { set_max_linear_speed(reg, 0); });
    expect_refused("set_max_linear_speed", "-3", [&] { set_max_linear_speed(reg, -3); });
    expect_refused("set_max_linear_speed", "100001", [&] { set_max_linear_speed(reg, 100001); });
    expect_refused("set_max_linear_speed", "nan",
                   [&] { set_max_linear_speed(reg, std::numeric_limits<scalar>::quiet_NaN()); });
    expect_refused("set_max_linear_speed", "inf",
                   [&] { set_max_linear_speed(reg, std::numeric_limits<scalar>::infinity()); });
    auto &after = get_settings(reg);
    EXPECT_EQ(after.fixed_dt, before.fixed_dt);
    EXPECT_EQ(after.gravity, before.gravity);
    EXPECT_EQ(after.num_substeps, before.num_substeps);
    EXPECT_EQ(after.num_relax_iterations, before.num_relax_iterations);
    EXPECT_EQ(after.max_steps_per_update, before.max_steps_per_update);
    EXPECT_EQ(after.max_linear_speed, before.max_linear_speed);

    // The bounds themselves are accepted.
    set_fixed_dt(reg, min_fixed_dt);
    set_fixed_dt(reg, max_fixed_dt);
    set_gravity(reg, {0, -max_gravity, 0});
    set_solver_substeps(reg, max_solver_substeps);
    set_solver_relax_iterations(reg, max_solver_iterations);
    set_max_steps_per_update(reg, max_steps_per_update_limit);
    set_max_linear_speed(reg, max_linear_speed_limit);
    EXPECT_EQ(get_max_linear_speed(reg), max_linear_speed_limit);
}

// Fields without a setter are changed in place; update() and step_simulation() refuse a value
// out of range before they step, naming the field, in every mode. A NaN stiffness or a negative
// push-out speed would otherwise reach the solver.
TEST(world, settings_changed_in_place_are_checked_before_a_step) {
    auto nan = std::numeric_limits<scalar>::quiet_NaN();
    auto inf = std::numeric_limits<scalar>::infinity();
    struct bad_value {
        const char *field;
        std::string value;
        std::function<void(settings &)> change;
    };
    auto bad = std::vector<bad_value>{
        {"settings::sleep_linear_velocity", "-1", [](settings &s) { s.sleep_linear_velocity = -1; }},
        {"settings::sleep_angular_velocity", "nan", [=](settings &s) { s.sleep_angular_velocity = nan; }},
        {"settings::time_to_sleep", "nan", [=](settings &s) { s.time_to_sleep = nan; }},
        {"settings::num_substeps", "0", [](settings &s) { s.num_substeps = 0; }},
        {"settings::max_linear_speed", "inf", [=](settings &s) { s.max_linear_speed = inf; }},
        {"settings::contact.contact_hertz", "nan", [=](settings &s) { s.contact.contact_hertz = nan; }},
        {"settings::contact.friction_anchor_hertz", "inf",
         [=](settings &s) { s.contact.friction_anchor_hertz = inf; }},
        {"settings::contact.contact_damping_ratio", "-2",
         [](settings &s) { s.contact.contact_damping_ratio = -2; }},
        {"settings::contact.max_hertz_ratio", "0", [](settings &s) { s.contact.max_hertz_ratio = 0; }},
        {"settings::contact.max_push_out_velocity", "-3",
         [](settings &s) { s.contact.max_push_out_velocity = -3; }},
        {"settings::contact.restitution_threshold", "nan",
         [=](settings &s) { s.contact.restitution_threshold = nan; }},
        {"settings::joint.joint_hertz", "-60", [](settings &s) { s.joint.joint_hertz = -60; }},
        {"settings::joint.joint_damping_ratio", "inf",
         [=](settings &s) { s.joint.joint_damping_ratio = inf; }},
        {"settings::joint.max_hertz_ratio", "2", [](settings &s) { s.joint.max_hertz_ratio = 2; }},
        {"settings::joint.restitution_threshold", "-0.1",
         [](settings &s) { s.joint.restitution_threshold = scalar(-0.1); }},
        {"settings::joint.position_projection", "1.5",
         [](settings &s) { s.joint.position_projection = scalar(1.5); }},
        {"settings::joint.position_projection_iterations", "65",
         [](settings &s) { s.joint.position_projection_iterations = 65; }},
        {"settings::joint.max_projected_gap", "nan", [=](settings &s) { s.joint.max_projected_gap = nan; }},
        {"settings::joint.max_correction_speed", "-3",
         [](settings &s) { s.joint.max_correction_speed = -3; }},
    };
    for (auto mode : {execution_mode::sequential, execution_mode::asynchronous}) {
        registry reg;
        attach(reg, init_config{mode});
        auto ball = make_ball(reg, {0, 10, 0});
        auto &in_place = reg.ctx().get<settings>();
        auto defaults = in_place;
        for (auto &[field, value, change] : bad) {
            SCOPED_TRACE(field);
            change(in_place);
            expect_refused("update", value, [&] { update(reg, 1.0); });
            expect_refused(field, value, [&] { update(reg, 1.0); });
            expect_refused("step_simulation", value, [&] { step_simulation(reg); });
            in_place = defaults;
        }
        wait_for_simulation(reg);
        EXPECT_EQ(get_step_count(reg), 0u) << "a step ran with a value out of range";
        EXPECT_EQ(reg.get<position>(ball).y, scalar(10));

        // The edges are accepted: infinities where they mean no bound, zeros that turn a force off.
        in_place.time_to_sleep = inf;
        in_place.joint.max_projected_gap = inf;
        in_place.joint.max_correction_speed = inf;
        in_place.contact.friction_anchor_hertz = 0;
        in_place.contact.max_hertz_ratio = 1;
        in_place.joint.position_projection = 0;
        step_simulation(reg);
        wait_for_simulation(reg);
        EXPECT_EQ(get_step_count(reg), 1u);
    }
}

void spoil_contact_hertz(registry &reg) {
    reg.ctx().get<settings>().contact.contact_hertz = std::numeric_limits<scalar>::quiet_NaN();
}

// A step callback may change the settings in place too, between two steps of one update(): the
// next step refuses them before it moves anything.
TEST(world, settings_a_step_callback_changes_are_checked_by_the_next_step) {
    for (auto mode : {execution_mode::sequential, execution_mode::sequential_multithreaded}) {
        registry reg;
        attach(reg, init_config{mode});
        make_ball(reg, {0, 10, 0});
        set_post_step_callback(reg, &spoil_contact_hertz);
        update(reg, 0.0);
        expect_refused("step: settings::contact.contact_hertz", "nan",
                       [&] { update(reg, 5 * double(get_fixed_dt(reg))); });
        EXPECT_EQ(get_step_count(reg), 1u) << "a step ran with a NaN contact stiffness";
    }
}

// A long pause over the smallest dt is more steps than an integer holds: the count is capped
// before it is converted, and update() runs max_steps_per_update steps.
TEST(world, a_pause_of_any_length_runs_at_most_max_steps_per_update) {
    registry reg;
    attach(reg);
    set_fixed_dt(reg, min_fixed_dt);
    set_max_steps_per_update(reg, 3);
    update(reg, 0.0);
    update(reg, 1e30); // 1e34 steps due: 2^64 is 1.8e19
    EXPECT_EQ(get_step_count(reg), 3u);
    update(reg, 1e300);
    EXPECT_EQ(get_step_count(reg), 6u);
    // Time going on normally after it steps as before.
    update(reg, 1e300);
    EXPECT_EQ(get_step_count(reg), 6u);
}

TEST(world, settings_are_validated_and_read_back) {
    registry reg;
    EXPECT_THROW(get_settings(reg), std::invalid_argument);
    attach(reg);
    EXPECT_THROW(set_fixed_dt(reg, 0), std::invalid_argument);
    EXPECT_THROW(set_fixed_dt(reg, -1), std::invalid_argument);
    EXPECT_THROW(set_fixed_dt(reg, std::numeric_limits<scalar>::quiet_NaN()), std::invalid_argument);
    set_fixed_dt(reg, scalar(0.01));
    EXPECT_EQ(get_fixed_dt(reg), scalar(0.01));
    EXPECT_EQ(get_gravity(reg), (vector3{0, scalar(-9.8), 0}));
    set_gravity(reg, {0, -1.62, 0});
    EXPECT_EQ(get_gravity(reg).y, scalar(-1.62));
    EXPECT_THROW(set_gravity(reg, {0, std::numeric_limits<scalar>::infinity(), 0}), std::invalid_argument);
    try {
        set_gravity(reg, {0, -20000, 0});
        ADD_FAILURE() << "gravity of 20000 m/s^2 accepted";
    } catch (const std::invalid_argument &e) {
        EXPECT_NE(std::string(e.what()).find("set_gravity: gravity must be at most "), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("long, got (0, -20000, 0)"), std::string::npos) << e.what();
    }
    EXPECT_EQ(get_gravity(reg).y, scalar(-1.62));
    EXPECT_THROW(set_solver_substeps(reg, 0), std::invalid_argument);
    set_solver_substeps(reg, 4);
    EXPECT_EQ(get_solver_substeps(reg), 4u);
    EXPECT_EQ(get_settings(reg).num_substeps, 4u);
    set_solver_relax_iterations(reg, 2);
    EXPECT_EQ(get_solver_relax_iterations(reg), 2u);
    EXPECT_EQ(get_settings(reg).num_relax_iterations, 2u);
    // The classic names: one velocity iteration per sub-step, position iterations are the
    // joints' projection passes.
    EXPECT_THROW(set_solver_velocity_iterations(reg, 0), std::invalid_argument);
    set_solver_velocity_iterations(reg, 5);
    EXPECT_EQ(get_solver_substeps(reg), 5u);
    EXPECT_EQ(get_solver_velocity_iterations(reg), 5u);
    set_solver_position_iterations(reg, 3);
    EXPECT_EQ(get_settings(reg).joint.position_projection_iterations, 3u);
    EXPECT_EQ(get_solver_position_iterations(reg), 3u);
    EXPECT_EQ(get_solver_relax_iterations(reg), 2u);
    set_solver_restitution_iterations(reg, 0);
    EXPECT_EQ(get_solver_restitution_iterations(reg), 0u);
    set_solver_individual_restitution_iterations(reg, 3);
    EXPECT_EQ(get_solver_individual_restitution_iterations(reg), 3u);

    // The new fixed dt is used by the next step.
    auto ball = make_ball(reg, {0, 10, 0});
    step_simulation(reg);
    EXPECT_NEAR(reg.get<linvel>(ball).y, -1.62 * 0.01, 1e-5);
}

} // namespace
} // namespace edyn

namespace edyn {
namespace {

// The manual's components read and write like the vector or quaternion they hold.
TEST(world, state_getters_refuse_a_registry_that_is_not_attached) {
    registry reg;
    auto expect_refused = [](auto fn, const char *function) {
        try {
            fn();
            ADD_FAILURE() << function << ": expected std::invalid_argument";
        } catch (const std::invalid_argument &e) {
            std::string what = e.what();
            EXPECT_NE(what.find(function), std::string::npos) << what;
            EXPECT_NE(what.find("not attached"), std::string::npos) << what;
        }
    };
    expect_refused([&] { (void)is_paused(reg); }, "is_paused");
    expect_refused([&] { (void)get_simulation_time(reg); }, "get_simulation_time");
    expect_refused([&] { (void)get_step_count(reg); }, "get_step_count");
    // The setters and the step functions name themselves too.
    expect_refused([&] { update(reg); }, "update");
    expect_refused([&] { update(reg, 1.0); }, "update");
    expect_refused([&] { step_simulation(reg); }, "step_simulation");
    expect_refused([&] { set_pre_step_callback(reg, nullptr); }, "set_pre_step_callback");
    expect_refused([&] { set_gravity(reg, {0, -1, 0}); }, "set_gravity");
    expect_refused([&] { (void)get_fixed_dt(reg); }, "get_fixed_dt");
    expect_refused([&] { (void)get_settings(reg); }, "get_settings");
    attach(reg);
    EXPECT_FALSE(is_paused(reg));
    EXPECT_EQ(get_step_count(reg), 0u);
    detach(reg);
    EXPECT_THROW((void)get_step_count(reg), std::invalid_argument);
}

TEST(components, take_braced_coordinates_and_plain_vectors) {
    registry reg;
    auto e = reg.create();
    reg.emplace<linvel>(e, 1, 2, 3);
    reg.get<linvel>(e) = {0, 5, 0};
    EXPECT_EQ(reg.get<linvel>(e), (vector3{0, 5, 0}));
    vector3 v{4, 5, 6};
    reg.get<linvel>(e) = v;
    reg.get<linvel>(e) += vector3{1, 1, 1};
    EXPECT_EQ(reg.get<linvel>(e), (vector3{5, 6, 7}));
    reg.emplace_or_replace<angvel>(e, vector3{0, 0, 2});
    reg.patch<angvel>(e, [](angvel &w) { w = {0, 0, 1}; });
    EXPECT_EQ(reg.get<angvel>(e).z, 1);
    reg.emplace<position>(e, vector3{1, 0, 0});
    reg.replace<position>(e, 2, 0, 0);
    EXPECT_EQ(reg.get<position>(e).x, 2);
    reg.emplace<orientation>(e) = {0, 0, 0, 1};
    reg.get<orientation>(e) = quaternion_axis_angle(vector3_y, scalar(0.5));
    EXPECT_NEAR(reg.get<orientation>(e).y, std::sin(scalar(0.25)), 1e-6);
    linvel zero{};
    EXPECT_EQ(zero, vector3_zero);
}

} // namespace
} // namespace edyn
