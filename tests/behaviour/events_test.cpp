// Collision events, sensors, destroying bodies in contact, and step callbacks.
#include "behaviour_support.hpp"
#include <algorithm>
#include <array>
#include <edyn_scenes/scenes.hpp>
#include <stdexcept>
#include <vector>

using namespace edyn;
using edyn::test::world_fixture;

namespace {

// What the listeners saw, kept in the registry's context.
struct event_log {
    enum class kind { started, ended, point_created, point_destroyed };
    struct record {
        kind type;
        entity manifold;
        unsigned id;
        std::uint64_t step;
        // Sum of the normal impulses (solver and restitution) of the manifold's points.
        scalar normal_impulse;
        std::uint32_t num_points;
        std::array<entity, 2> bodies;
        // Positions of the manifold's bodies when the event was delivered.
        std::array<vector3, 2> body_positions;
    };
    std::vector<record> records;

    std::size_t count(kind k, entity manifold = null) const {
        return std::size_t(std::count_if(records.begin(), records.end(), [&](const record &r) {
            return r.type == k && (manifold == null || r.manifold == manifold);
        }));
    }
};

void log_event(registry &reg, event_log::kind k, entity manifold, unsigned id) {
    event_log::record rec{k, manifold, id,           get_step_count(reg),
                          0, 0,        {null, null}, {vector3_zero, vector3_zero}};
    if (auto *m = reg.try_get<contact_manifold>(manifold)) {
        // As in the manual's example.
        for (unsigned i = 0; i < m->num_points; ++i) {
            auto &cp = m->point[m->ids[i]];
            rec.normal_impulse += cp.normal_impulse + cp.normal_restitution_impulse;
        }
        rec.num_points = m->num_points;
        rec.bodies = m->body;
        for (int i = 0; i < 2; ++i) {
            if (reg.valid(m->body[i]) && reg.all_of<position>(m->body[i]))
                rec.body_positions[i] = reg.get<position>(m->body[i]);
        }
    }
    reg.ctx().get<event_log>().records.push_back(rec);
}

void contact_started(registry &reg, entity e) { log_event(reg, event_log::kind::started, e, 0); }
void contact_ended(registry &reg, entity e) { log_event(reg, event_log::kind::ended, e, 0); }
void point_created(registry &reg, entity e, contact_manifold::id_type id) {
    log_event(reg, event_log::kind::point_created, e, id);
}
void point_destroyed(registry &reg, entity e, contact_manifold::id_type id) {
    log_event(reg, event_log::kind::point_destroyed, e, id);
}

struct events : world_fixture {
    void SetUp() override {
        world_fixture::SetUp();
        reg.ctx().emplace<event_log>();
        on_contact_started(reg).connect<&contact_started>(reg);
        on_contact_ended(reg).connect<&contact_ended>(reg);
        on_contact_point_created(reg).connect<&point_created>(reg);
        on_contact_point_destroyed(reg).connect<&point_destroyed>(reg);
    }

    event_log &log() { return reg.ctx().get<event_log>(); }

    std::vector<entity> manifolds_of(entity body) {
        std::vector<entity> result;
        for (auto e : reg.view<contact_manifold>()) {
            auto &m = reg.get<contact_manifold>(e);
            if (m.body[0] == body || m.body[1] == body) result.push_back(e);
        }
        return result;
    }
};

using kind = event_log::kind;

} // namespace

TEST_F(events, a_landing_box_starts_contact_once_with_its_impulse_and_points) {
    scenes::make_ground(reg, scalar(0.5), 0);
    const scalar m = 2;
    // 1 cm above the ground, falling at 3 m/s: it lands during the first step.
    auto def = edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, {0, scalar(0.51), 0}, m);
    def.linvel = {0, -3, 0};
    auto box = make_rigidbody(reg, def);

    auto v_before = vel(box).y;
    auto start = pos(box);
    edyn::test::step(reg);
    auto v_after = vel(box).y;

    ASSERT_EQ(log().count(kind::started), 1u) << "contact_started events in the landing step";
    auto started = *std::find_if(log().records.begin(), log().records.end(),
                                 [](auto &r) { return r.type == kind::started; });
    // Delivered at the end of the step: the body already sits where the step left it.
    EXPECT_EQ(started.step, 1u);
    // The box is the body that moved in the step (the ground stays at the origin), so its
    // position tells when the event was delivered.
    auto box_index = started.bodies[0] == box ? 0 : 1;
    ASSERT_EQ(started.bodies[box_index], box);
    ASSERT_NE(pos(box), start) << "the box did not move in the step";
    auto seen = started.body_positions[box_index];
    EXPECT_EQ(seen, pos(box)) << "event delivered before the step finished: box at y = " << seen.y
                              << ", after the step at y = " << pos(box).y << ", before it at y = " << start.y;
    // One point_created per point in the manifold (a face on a plane: 4).
    EXPECT_EQ(started.num_points, 4u);
    EXPECT_EQ(log().count(kind::point_created, started.manifold), started.num_points);
    EXPECT_EQ(log().count(kind::point_destroyed) + log().count(kind::ended), 0u);

    // The box stopped in this step, so the solver's impulses are in the manifold.
    EXPECT_GT(v_after - v_before, -v_before / 2) << "the box did not land in the first step";
    EXPECT_GT(started.normal_impulse, 0) << "impulses not filled in when contact_started is delivered";

    // Resting: no more events.
    run_for(1);
    EXPECT_EQ(log().count(kind::started), 1u);
    EXPECT_EQ(log().count(kind::ended), 0u);
    EXPECT_EQ(log().count(kind::point_destroyed), 0u);
}

TEST_F(events, the_impulse_reported_at_contact_started_is_the_collision_impulse) {
    scenes::make_ground(reg, scalar(0.5), 0);
    const scalar m = 2;
    auto def = edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, {0, scalar(0.51), 0}, m);
    def.linvel = {0, -3, 0};
    auto box = make_rigidbody(reg, def);
    auto v_before = vel(box).y;
    edyn::test::step(reg);
    auto v_after = vel(box).y;
    ASSERT_EQ(log().count(kind::started), 1u);
    auto started = *std::find_if(log().records.begin(), log().records.end(),
                                 [](auto &r) { return r.type == kind::started; });
    // The impulse the contact gave in this step: m (dv - g dt).
    auto applied = m * (v_after - v_before + test::earth_g * get_fixed_dt(reg));
    EXPECT_NEAR(started.normal_impulse, applied, scalar(0.1) * applied)
        << "reported normal impulse " << started.normal_impulse << " N s, applied m dv = " << applied
        << " N s (velocity " << v_before << " -> " << v_after << " m/s)";
}

TEST_F(events, lifting_a_box_away_ends_contact_once_and_landing_again_starts_it_once) {
    scenes::make_ground(reg, scalar(0.5), 0);
    auto box = make_rigidbody(
        reg, edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, {0, scalar(0.5), 0}));
    run_for(1);
    ASSERT_EQ(log().count(kind::started), 1u);
    auto manifold = log().records.front().manifold;
    auto points = reg.get<contact_manifold>(manifold).num_points;
    ASSERT_GT(points, 0u);

    // Lift it 30 cm: the points separate beyond the breaking threshold.
    reg.replace<position>(box, vector3{0, scalar(0.8), 0});
    reg.replace<linvel>(box, vector3_zero);
    auto steps_before = get_step_count(reg);
    edyn::test::step(reg);
    EXPECT_EQ(log().count(kind::ended), 1u) << "contact_ended after lifting the box";
    EXPECT_EQ(log().count(kind::point_destroyed), points) << "one point_destroyed per point";
    // Within that step: at its end when the narrowphase drops the points, or at once when the
    // broadphase destroys the manifold (the entity is still valid then, see contact_events.hpp).
    for (auto &r : log().records) {
        if (r.type == kind::ended) {
            EXPECT_TRUE(r.step == steps_before || r.step == steps_before + 1)
                << "ended delivered in step " << r.step;
        }
    }
    // It falls back: exactly one new start, no second end.
    run_for(1);
    EXPECT_EQ(log().count(kind::started), 2u);
    EXPECT_EQ(log().count(kind::ended), 1u);
    EXPECT_NEAR(pos(box).y, scalar(0.5), scalar(0.01));

    // Teleported far away: the manifold goes with the AABB overlap, the end is reported once.
    reg.replace<position>(box, vector3{0, 50, 0});
    reg.replace<linvel>(box, vector3_zero);
    edyn::test::step(reg);
    EXPECT_EQ(log().count(kind::ended), 2u);
    EXPECT_TRUE(manifolds_of(box).empty());
}

namespace events_test_listeners {

struct live_ids {
    std::vector<std::uint32_t> ids; // one bit per slot, per manifold index
};
struct tracker {
    static void created(registry &reg, entity m, contact_manifold::id_type id) {
        bits(reg, m) |= std::uint32_t{1} << id;
    }
    static void destroyed(registry &reg, entity m, contact_manifold::id_type id) {
        bits(reg, m) &= ~(std::uint32_t{1} << id);
    }
    static std::uint32_t &bits(registry &reg, entity m) {
        auto &ids = reg.ctx().get<live_ids>().ids;
        if (ids.size() <= to_index(m)) ids.resize(to_index(m) + 1, 0);
        return ids[to_index(m)];
    }
};

struct thrower {
    static void created(registry &reg, entity, contact_manifold::id_type) {
        if (++reg.ctx().get<int>() == 2) throw std::runtime_error("listener");
    }
};

} // namespace events_test_listeners

// A box sliding on its face renews its four points most steps, a new point often taking the
// slot of one removed in the same step. The ids the point events leave alive are the manifold's
// own after every step (with the points created first, a slot renewed in a step was announced
// created, then destroyed, and the listener lost a live point: 22 of 60 steps went wrong).
TEST_F(events, the_point_events_name_the_live_points_of_a_sliding_box) {
    reg.ctx().emplace<events_test_listeners::live_ids>();
    on_contact_point_created(reg).connect<&events_test_listeners::tracker::created>(reg);
    on_contact_point_destroyed(reg).connect<&events_test_listeners::tracker::destroyed>(reg);
    scenes::make_ground(reg, 1, 0);
    auto def = edyn::test::box_def({scalar(0.2), scalar(0.15), scalar(0.25)}, {0, scalar(0.15), 0});
    def.linvel = {3, 0, 0};
    make_rigidbody(reg, def);
    int renewed_steps = 0;
    for (int step = 1; step <= 60; ++step) {
        auto before = log().count(kind::point_destroyed);
        edyn::test::step(reg);
        if (log().count(kind::point_destroyed) > before) ++renewed_steps;
        for (auto [m, manifold] : reg.view<contact_manifold>().each()) {
            std::uint32_t actual = 0;
            for (unsigned i = 0; i < manifold.num_points; ++i)
                actual |= std::uint32_t{1} << manifold.ids[i];
            ASSERT_EQ(events_test_listeners::tracker::bits(reg, m), actual) << "step " << step;
        }
    }
    EXPECT_GT(renewed_steps, 10) << "the box should renew its points while it slides";
}

// A listener that throws: the exception reaches the program, and the step's other events come
// with the next step, each once (they were all delivered again, the contact started twice).
TEST_F(events, a_listener_that_throws_leaves_the_other_events_for_the_next_step) {
    reg.ctx().emplace<int>(0);
    on_contact_point_created(reg).connect<&events_test_listeners::thrower::created>(reg);
    scenes::make_ground(reg, 1, 0);
    make_rigidbody(reg, edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, {0, scalar(0.6), 0}));
    int caught = 0;
    for (int i = 0; i < 60; ++i) {
        try {
            edyn::test::step(reg);
        } catch (const std::runtime_error &) {
            ++caught;
        }
    }
    EXPECT_EQ(caught, 1);
    EXPECT_EQ(log().count(kind::started), 1u);
    EXPECT_EQ(log().count(kind::ended), 0u);
    auto manifolds = reg.view<contact_manifold>();
    ASSERT_EQ(manifolds.size(), 1u);
    auto &manifold = reg.get<contact_manifold>(*manifolds.begin());
    EXPECT_EQ(manifold.num_points, 4u);
    EXPECT_EQ(log().count(kind::point_created) - log().count(kind::point_destroyed), 4u)
        << "each point announced once";
}

TEST_F(events, a_sensor_reports_a_ball_passing_through_without_touching_its_motion) {
    rigidbody_def sensor_def;
    sensor_def.kind = rigidbody_kind::rb_static;
    sensor_def.shape = box_shape{1, 1, 1};
    sensor_def.position = {0, 5, 0};
    sensor_def.material.reset();
    auto sensor = make_rigidbody(reg, sensor_def);
    EXPECT_TRUE(reg.all_of<sensor_tag>(sensor));
    EXPECT_FALSE(reg.all_of<material>(sensor));

    auto ball = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.25), {0, 10, 0}));
    // The same ball far from everything: the reference free fall.
    auto twin = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.25), {50, 10, 0}));

    run_for(2);
    EXPECT_EQ(log().count(kind::started), 1u) << "contact_started while passing through";
    EXPECT_EQ(log().count(kind::ended), 1u) << "contact_ended after leaving";
    EXPECT_GT(log().count(kind::point_created), 0u);
    for (auto &r : log().records) {
        if (r.type == kind::started) {
            EXPECT_GT(r.num_points, 0u);
            EXPECT_EQ(r.normal_impulse, 0) << "a sensor contact applied an impulse";
        }
    }
    // Bitwise the same motion as the free ball.
    EXPECT_EQ(vel(ball).y, vel(twin).y);
    EXPECT_EQ(pos(ball).y, pos(twin).y);
    EXPECT_EQ(vel(ball).x, 0);
    EXPECT_EQ(vel(ball).z, 0);
    EXPECT_EQ(angular(ball), vector3_zero);
    // And that is free fall.
    EXPECT_NEAR(vel(ball).y, -test::earth_g * 2, scalar(1e-3))
        << "velocity " << vel(ball).y << ", expected " << -test::earth_g * 2;
}

TEST_F(events, a_dynamic_sensor_falls_through_the_ground_reporting_the_contact) {
    scenes::make_ground(reg, scalar(0.5), 0);
    auto def = edyn::test::sphere_def(scalar(0.25), {0, 1, 0});
    def.material.reset();
    auto ball = make_rigidbody(reg, def);
    auto steps = run_for(1);
    // Free fall for 1 s. Sub-stepped semi-implicit Euler falls g h^2 n (n + 1) / 2 after n
    // sub-steps of h, 0.3% more than g t^2 / 2 here.
    auto n = scalar(steps * int(get_solver_substeps(reg)));
    auto h = 1 / n;
    auto expected = 1 - test::earth_g * h * h * n * (n + 1) / 2;
    EXPECT_NEAR(pos(ball).y, expected, scalar(1e-3)) << "the sensor was held by the ground";
    EXPECT_EQ(log().count(kind::started), 1u);
}

// Removing a body's material makes it a sensor at run time, and emplacing one makes it solid
// again; bodies asleep on it, or it asleep on them, wake to respond.
TEST_F(events, removing_or_emplacing_the_material_makes_a_body_a_sensor_or_solid_at_run_time) {
    scenes::make_ground(reg, scalar(0.5), 0);
    auto half = vector3{scalar(0.5), scalar(0.5), scalar(0.5)};
    auto box = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(0.5), 0}));
    // A static platform 2 m up with a box on it, far from the first.
    auto platform_def = edyn::test::box_def(vector3{2, scalar(0.25), 2}, {10, scalar(1.75), 0});
    platform_def.kind = rigidbody_kind::rb_static;
    auto platform = make_rigidbody(reg, platform_def);
    auto rider = make_rigidbody(reg, edyn::test::box_def(half, {10, scalar(2.5), 0}));
    run_for(3);
    ASSERT_TRUE(reg.all_of<sleeping_tag>(box));
    ASSERT_TRUE(reg.all_of<sleeping_tag>(rider));
    ASSERT_NEAR(pos(rider).y, scalar(2.5), scalar(0.01));

    // The sleeping box becomes a sensor: it wakes and falls freely through the ground.
    reg.remove<material>(box);
    EXPECT_TRUE(reg.all_of<sensor_tag>(box));
    run_for(1);
    EXPECT_NEAR(pos(box).y, scalar(0.5) - fall(reg, 1), scalar(0.02)) << "the ground still held the sensor";

    // The static platform becomes a sensor: the box asleep on it wakes and falls through it onto
    // the ground, where it rests.
    reg.remove<material>(platform);
    EXPECT_TRUE(reg.all_of<sensor_tag>(platform));
    run_for(2);
    EXPECT_NEAR(pos(rider).y, scalar(0.5), scalar(0.01)) << "the rider did not fall through the platform";

    // Solid again: a ball dropped on it rests on it.
    reg.emplace<material>(platform);
    EXPECT_FALSE(reg.all_of<sensor_tag>(platform));
    auto ball = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.25), {10, 3, 0}));
    run_for(2);
    EXPECT_NEAR(pos(ball).y, scalar(2.25), scalar(0.01)) << "the ball fell through the solid platform";

    // A dynamic sensor made solid while it falls lands on the ground and rests there.
    auto def = edyn::test::sphere_def(scalar(0.25), {-10, 3, 0});
    def.material.reset();
    auto ghost = make_rigidbody(reg, def);
    run_for(0.5);
    reg.emplace<material>(ghost);
    EXPECT_FALSE(reg.all_of<sensor_tag>(ghost));
    run_for(2);
    EXPECT_NEAR(pos(ghost).y, scalar(0.25), scalar(0.01)) << "the ball made solid fell through the ground";
}

namespace {
// The stacks below settle in 0.25 s and fall asleep after 0.5 s more at rest.
constexpr scalar settle_awake = scalar(0.25);
constexpr scalar settle_asleep = 2;
} // namespace

namespace {
// Bodies a contact_started listener destroys when they touch anything (a projectile that hits).
struct doomed_bodies {
    std::vector<entity> bodies;
    int destroyed{0};
};
void destroy_doomed_on_contact(registry &reg, entity manifold) {
    auto &doomed = reg.ctx().get<doomed_bodies>();
    for (auto body : reg.get<contact_manifold>(manifold).body) {
        if (reg.valid(body) &&
            std::find(doomed.bodies.begin(), doomed.bodies.end(), body) != doomed.bodies.end()) {
            reg.destroy(body);
            ++doomed.destroyed;
        }
    }
}
} // namespace

// A body a contact listener destroys leaves the simulation (in asynchronous mode the listener
// runs on the calling thread while the worker's results are applied: the destruction must reach
// the worker all the same). No event names it after, no manifold outlives it, and a ball dropped
// where it lay falls to the ground instead of landing on what is left of it.
TEST_F(events, bodies_destroyed_by_a_contact_listener_leave_the_simulation) {
    auto ground = scenes::make_ground(reg, scalar(0.5), 0);
    auto &doomed = reg.ctx().emplace<doomed_bodies>();
    for (int i = 0; i < 3; ++i)
        doomed.bodies.push_back(
            make_rigidbody(reg, edyn::test::sphere_def(scalar(0.25), {scalar(i) * 2, 1, 0})));
    on_contact_started(reg).connect<&destroy_doomed_on_contact>(reg);
    run_for(1);
    EXPECT_EQ(doomed.destroyed, 3);
    for (auto body : doomed.bodies)
        EXPECT_FALSE(reg.valid(body));
    // Every contact that started ended once, and none is left (the asynchronous worker hears of
    // a destruction made while its results were applied at the next update).
    run_for(0.25);
    EXPECT_EQ(log().count(kind::started), 3u);
    EXPECT_EQ(log().count(kind::ended), 3u);
    EXPECT_TRUE(reg.view<contact_manifold>().empty());
    // The listeners are told the end of no point they were not told of: the points created with
    // the contact were still to be told when the body went (a listener counting live points went
    // below zero).
    EXPECT_EQ(log().count(kind::point_destroyed), log().count(kind::point_created));

    on_contact_started(reg).disconnect<&destroy_doomed_on_contact>(reg);
    std::vector<entity> dropped;
    for (int i = 0; i < 3; ++i)
        dropped.push_back(make_rigidbody(reg, edyn::test::sphere_def(scalar(0.25), {scalar(i) * 2, 2, 0})));
    run_for(2);
    for (auto ball : dropped) {
        EXPECT_NEAR(pos(ball).y, scalar(0.25), scalar(0.01)) << "the ball landed on a destroyed body";
        for (auto manifold : manifolds_of(ball))
            for (auto body : reg.get<contact_manifold>(manifold).body)
                EXPECT_TRUE(body == ball || body == ground) << "a manifold with a destroyed body";
    }
}

TEST_F(events, destroying_the_top_box_of_a_stack_cleans_its_manifolds) {
    scenes::make_ground(reg, scalar(0.6), 0);
    auto half = vector3{scalar(0.5), scalar(0.5), scalar(0.5)};
    auto bottom = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(0.5), 0}));
    auto top = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(1.5), 0}));
    run_for(settle_awake);
    ASSERT_FALSE(reg.all_of<sleeping_tag>(top));
    auto top_manifolds = manifolds_of(top);
    ASSERT_EQ(top_manifolds.size(), 1u);
    auto manifold = top_manifolds.front();
    auto points = reg.get<contact_manifold>(manifold).num_points;
    ASSERT_GT(points, 0u);
    log().records.clear();

    reg.destroy(top);
    // In the asynchronous mode the worker applies it: its results are back after this.
    wait_for_simulation(reg);
    EXPECT_TRUE(manifolds_of(top).empty()) << "a manifold still refers to the destroyed body";
    EXPECT_FALSE(reg.valid(manifold));
    for (int i = 0; i < 60; ++i)
        edyn::test::step(reg);
    EXPECT_EQ(log().count(kind::ended, manifold), 1u) << "contact_ended for the destroyed body's manifold";
    EXPECT_EQ(log().count(kind::point_destroyed, manifold), points);
    EXPECT_EQ(log().count(kind::started), 0u);
    // The bottom box rests where it was, still touching the ground.
    EXPECT_NEAR(pos(bottom).y, scalar(0.5), scalar(0.01));
    EXPECT_EQ(manifolds_of(bottom).size(), 1u);
}

TEST_F(events, destroying_the_top_box_of_a_sleeping_stack_cleans_its_manifolds) {
    scenes::make_ground(reg, scalar(0.6), 0);
    auto half = vector3{scalar(0.5), scalar(0.5), scalar(0.5)};
    auto bottom = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(0.5), 0}));
    auto top = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(1.5), 0}));
    run_for(settle_asleep);
    ASSERT_TRUE(reg.all_of<sleeping_tag>(top));
    auto top_manifolds = manifolds_of(top);
    ASSERT_EQ(top_manifolds.size(), 1u);
    auto manifold = top_manifolds.front();
    auto points = reg.get<contact_manifold>(manifold).num_points;
    ASSERT_GT(points, 0u);
    log().records.clear();

    reg.destroy(top);
    // In the asynchronous mode the worker applies it: its results are back after this.
    wait_for_simulation(reg);
    EXPECT_TRUE(manifolds_of(top).empty()) << "a manifold still refers to the destroyed body";
    EXPECT_FALSE(reg.valid(manifold));
    for (int i = 0; i < 60; ++i)
        edyn::test::step(reg);
    EXPECT_EQ(log().count(kind::ended, manifold), 1u) << "contact_ended for the destroyed body's manifold";
    EXPECT_EQ(log().count(kind::point_destroyed, manifold), points);
    EXPECT_EQ(log().count(kind::started), 0u);
    // The bottom box rests where it was, still touching the ground.
    EXPECT_NEAR(pos(bottom).y, scalar(0.5), scalar(0.01));
    EXPECT_EQ(manifolds_of(bottom).size(), 1u);
}

TEST_F(events, destroying_the_bottom_box_of_a_stack_lets_the_top_fall) {
    scenes::make_ground(reg, scalar(0.6), 0);
    auto half = vector3{scalar(0.5), scalar(0.5), scalar(0.5)};
    auto bottom = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(0.5), 0}));
    auto top = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(1.5), 0}));
    run_for(settle_awake);
    auto bottom_manifolds = manifolds_of(bottom);
    ASSERT_EQ(bottom_manifolds.size(), 2u);
    log().records.clear();

    reg.destroy(bottom);
    // In the asynchronous mode the worker applies it: its results are back after this.
    wait_for_simulation(reg);
    for (auto e : bottom_manifolds)
        EXPECT_FALSE(reg.valid(e));
    EXPECT_EQ(log().count(kind::ended), 2u) << "contact_ended for both of the bottom box's manifolds";
    EXPECT_FALSE(reg.all_of<sleeping_tag>(top)) << "the top box sleeps in mid-air";

    // It falls 1 m (0.45 s) and lands on the ground.
    run_for(1);
    EXPECT_NEAR(pos(top).y, scalar(0.5), scalar(0.01))
        << "top box at " << pos(top).y << ", expected on the ground";
    EXPECT_EQ(log().count(kind::started), 1u);
}

TEST_F(events, destroying_the_bottom_box_of_a_sleeping_stack_lets_the_top_fall) {
    scenes::make_ground(reg, scalar(0.6), 0);
    auto half = vector3{scalar(0.5), scalar(0.5), scalar(0.5)};
    auto bottom = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(0.5), 0}));
    auto top = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(1.5), 0}));
    run_for(settle_asleep);
    ASSERT_TRUE(reg.all_of<sleeping_tag>(top));
    auto bottom_manifolds = manifolds_of(bottom);
    ASSERT_EQ(bottom_manifolds.size(), 2u);
    log().records.clear();

    reg.destroy(bottom);
    // In the asynchronous mode the worker applies it: its results are back after this.
    wait_for_simulation(reg);
    for (auto e : bottom_manifolds)
        EXPECT_FALSE(reg.valid(e));
    EXPECT_EQ(log().count(kind::ended), 2u) << "contact_ended for both of the bottom box's manifolds";
    EXPECT_FALSE(reg.all_of<sleeping_tag>(top)) << "the top box sleeps in mid-air";

    // It falls 1 m (0.45 s) and lands on the ground.
    run_for(1);
    EXPECT_NEAR(pos(top).y, scalar(0.5), scalar(0.01))
        << "top box at " << pos(top).y << ", expected on the ground";
    EXPECT_EQ(log().count(kind::started), 1u);
}

// Step callbacks.
namespace {

struct callback_log {
    struct call {
        bool pre;
        std::uint64_t step_count;
        registry *reg;
        scalar y;
    };
    std::vector<call> calls;
    entity body{null};
};

void log_call(registry &reg, bool pre) {
    auto &log = reg.ctx().get<callback_log>();
    log.calls.push_back({pre, get_step_count(reg), &reg, reg.get<position>(log.body).y});
}
void pre_step(registry &reg) { log_call(reg, true); }
void post_step(registry &reg) { log_call(reg, false); }

// Pushes the body up at 1 m/s before every step.
void push_up(registry &reg) {
    auto &log = reg.ctx().get<callback_log>();
    reg.replace<linvel>(log.body, vector3{0, 1, 0});
}

// Pauses the world at the start of its fourth step.
void pause_at_fourth_step(registry &reg) {
    if (get_step_count(reg) == 3) set_paused(reg, true);
}

// Halves the fixed step at the start of the third.
void halve_step_at_third(registry &reg) {
    if (get_step_count(reg) == 2) set_fixed_dt(reg, get_fixed_dt(reg) / 2);
}

} // namespace

using step_callbacks = world_fixture;

// A callback's pause or new fixed step rules the rest of the update() that ran it: a paused
// world runs no more of its steps, and the time left is stepped with the new step, so that the
// simulation keeps up with the program's clock. Before, the steps counted at the start of the
// update all ran: four after the pause, and three of the new half length where seven were due.
TEST_F(step_callbacks, a_pause_or_a_new_step_from_a_callback_rules_the_rest_of_the_update) {
    make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {0, 10, 0}));
    auto dt = double(get_fixed_dt(reg));
    set_pre_step_callback(reg, &pause_at_fourth_step);
    edyn::test::advance_to(reg, 0);
    edyn::test::advance_to(reg, 8.5 * dt);
    EXPECT_TRUE(is_paused(reg));
    EXPECT_EQ(get_step_count(reg), 4u) << "steps ran after a callback paused the world";
    // Resumed, the steps the pause cut off are not made up.
    set_pre_step_callback(reg, nullptr);
    set_paused(reg, false);
    edyn::test::advance_to(reg, 9.5 * dt);
    EXPECT_EQ(get_step_count(reg), 5u);

    registry other;
    attach(other, edyn::test::test_config());
    make_rigidbody(other, edyn::test::sphere_def(scalar(0.5), {0, 10, 0}));
    set_pre_step_callback(other, &halve_step_at_third);
    edyn::test::advance_to(other, 0);
    edyn::test::advance_to(other, 6.5 * dt);
    // Three steps of dt (the third was already under way), then the 3.5 dt of time left as
    // seven steps of dt / 2: the simulation reaches the clock.
    EXPECT_EQ(get_step_count(other), 10u);
    EXPECT_NEAR(get_simulation_time(other), 6.5 * dt, 1e-9) << "the simulation fell behind the clock";
    EXPECT_EQ(get_fixed_dt(other), scalar(dt / 2));
    detach(other);
}

TEST_F(step_callbacks, pre_and_post_run_once_per_step_in_order_with_the_registry) {
    if (get_settings(reg).execution_mode == execution_mode::asynchronous)
        GTEST_SKIP() << "callbacks get the worker's registry there (tests/unit/simulation/async_*)";
    auto &log = reg.ctx().emplace<callback_log>();
    log.body = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {0, 10, 0}));
    set_pre_step_callback(reg, &pre_step);
    set_post_step_callback(reg, &post_step);

    update(reg, 0.0);
    EXPECT_TRUE(log.calls.empty()) << "the first update only sets the start time";
    // Three and a half steps of time: three steps.
    auto dt = double(get_fixed_dt(reg));
    update(reg, 3.5 * dt);
    ASSERT_EQ(log.calls.size(), 6u);
    for (std::size_t i = 0; i < log.calls.size(); ++i) {
        auto &c = log.calls[i];
        EXPECT_EQ(c.pre, i % 2 == 0) << "call " << i;
        EXPECT_EQ(c.reg, &reg);
        // Pre sees the step about to run, post the step just finished.
        EXPECT_EQ(c.step_count, i / 2 + (c.pre ? 0 : 1)) << "call " << i;
    }
    // Post runs after integration: it sees the step's new position.
    EXPECT_LT(log.calls[1].y, log.calls[0].y);
    EXPECT_EQ(log.calls[5].y, pos(log.body).y);

    edyn::test::step(reg);
    EXPECT_EQ(log.calls.size(), 8u) << "step_simulation runs the callbacks too";
}

TEST_F(step_callbacks, changes_made_in_the_pre_step_callback_apply_to_that_step) {
    if (get_settings(reg).execution_mode == execution_mode::asynchronous)
        GTEST_SKIP() << "callbacks get the worker's registry there (tests/unit/simulation/async_*)";
    auto &log = reg.ctx().emplace<callback_log>();
    auto def = edyn::test::sphere_def(scalar(0.5), {0, 10, 0});
    def.gravity = vector3_zero;
    log.body = make_rigidbody(reg, def);
    set_pre_step_callback(reg, &push_up);
    run_for(1);
    EXPECT_NEAR(pos(log.body).y, 11, scalar(1e-3)) << "the body should have moved up 1 m at 1 m/s";

    // Cleared callbacks are not called.
    set_pre_step_callback(reg, nullptr);
    reg.replace<linvel>(log.body, vector3_zero);
    run_for(1);
    EXPECT_NEAR(pos(log.body).y, 11, scalar(1e-3));
}
