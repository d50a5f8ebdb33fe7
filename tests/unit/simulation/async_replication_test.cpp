// The asynchronous mode's two directions: what the main registry sends the worker (every kind of
// component operation, entity-valued members, external components and entities, settings,
// calls that read motion) and what comes back (motion, events, query replies), checked in the
// worker's own registry through a step callback.
#include <chrono>
#include <cmath>
#include <edyn/edyn.hpp>
#include <functional>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace edyn;

init_config async_config() { return init_config{execution_mode::asynchronous}; }

// Components of the program's own.
struct tag_value {
    int value;
};
struct link_to {
    entity target;
};
struct log_list {
    std::vector<int> items;
};

} // namespace

// link_to holds an entity: declared so that it is translated into the worker's.
template<>
struct edyn::entity_members<link_to> {
    template<typename Fn>
    static void each(link_to &link, Fn &&fn) {
        fn(link.target);
    }
};

// log_list grows in the worker instead of being replaced.
template<>
void edyn::merge_component<log_list>(log_list &current, const log_list &incoming) {
    current.items.insert(current.items.end(), incoming.items.begin(), incoming.items.end());
}

namespace {

// Runs in the worker after each step, on the worker's registry. The test thread sets it before
// a step and reads what it wrote after wait_for_simulation, which orders both.
std::function<void(registry &)> probe;
void run_probe(registry &worker) {
    if (probe) probe(worker);
}

struct async_world : ::testing::Test {
    registry reg;

    void SetUp() override {
        attach(reg, async_config());
        set_post_step_callback(reg, &run_probe);
    }
    void TearDown() override {
        probe = nullptr;
        detach(reg);
    }
    void step() {
        step_simulation(reg);
        wait_for_simulation(reg);
    }
    entity make_ground() {
        rigidbody_def def;
        def.kind = rigidbody_kind::rb_static;
        def.shape = plane_shape{vector3_y, 0};
        return make_rigidbody(reg, def);
    }
    entity make_ball(const vector3 &at, rigidbody_kind kind = rigidbody_kind::rb_dynamic) {
        rigidbody_def def;
        def.kind = kind;
        def.mass = 2;
        def.shape = sphere_shape{scalar(0.5)};
        def.position = at;
        return make_rigidbody(reg, def);
    }
    // The tag_value values the worker's registry holds, in view order.
    std::vector<int> worker_values() {
        std::vector<int> values;
        probe = [&](registry &worker) {
            values.clear();
            for (auto e : worker.view<tag_value>())
                values.push_back(worker.get<tag_value>(e).value);
        };
        step();
        probe = nullptr;
        return values;
    }
};

TEST_F(async_world, external_components_follow_emplace_replace_patch_remove_and_destroy) {
    register_external_components<tag_value>(reg);
    auto ball = make_ball({0, 5, 0});
    reg.emplace<tag_value>(ball, 7);
    EXPECT_EQ(worker_values(), std::vector<int>{7});
    reg.replace<tag_value>(ball, 8);
    EXPECT_EQ(worker_values(), std::vector<int>{8});
    reg.patch<tag_value>(ball, [](tag_value &t) { t.value = 9; });
    EXPECT_EQ(worker_values(), std::vector<int>{9});
    // Assigned in place, then announced with patch (the manual's way).
    reg.get<tag_value>(ball).value = 10;
    reg.patch<tag_value>(ball);
    EXPECT_EQ(worker_values(), std::vector<int>{10});
    reg.remove<tag_value>(ball);
    EXPECT_EQ(worker_values(), std::vector<int>{});
    reg.emplace<tag_value>(ball, 11);
    EXPECT_EQ(worker_values(), std::vector<int>{11});

    std::size_t bodies = 0;
    probe = [&](registry &worker) { bodies = worker.view<rigidbody_tag>().size(); };
    step();
    EXPECT_EQ(bodies, 1u);
    reg.destroy(ball);
    EXPECT_EQ(worker_values(), std::vector<int>{});
    probe = [&](registry &worker) { bodies = worker.view<rigidbody_tag>().size(); };
    step();
    EXPECT_EQ(bodies, 0u) << "the destroyed body is still in the worker";
}

TEST_F(async_world, components_on_entities_outside_the_simulation_stay_on_the_main_side) {
    register_external_components<tag_value>(reg);
    auto loose = reg.create();
    reg.emplace<tag_value>(loose, 99);
    // Held before the entity became a body: it travels when the entity does.
    auto early = reg.create();
    reg.emplace<tag_value>(early, 5);
    rigidbody_def def;
    def.shape = sphere_shape{1};
    make_rigidbody(early, reg, def);
    EXPECT_EQ(worker_values(), std::vector<int>{5});
}

TEST_F(async_world, components_registered_after_they_were_emplaced_are_sent) {
    auto ball = make_ball({0, 5, 0});
    reg.emplace<tag_value>(ball, 3);
    step();
    register_external_components<tag_value>(reg);
    // Twice is harmless: one copy, one value.
    register_external_components<tag_value>(reg);
    EXPECT_EQ(worker_values(), std::vector<int>{3});
}

TEST_F(async_world, entity_valued_members_name_the_workers_entities) {
    register_external_components<link_to>(reg);
    make_ground();
    auto anchor = make_ball({5, 1, 0}, rigidbody_kind::rb_static);
    auto ball = make_ball({0, 5, 0});
    reg.emplace<link_to>(ball, anchor);
    vector3 seen{0, 0, 0};
    bool found = false;
    probe = [&](registry &worker) {
        for (auto e : worker.view<link_to>()) {
            auto target = worker.get<link_to>(e).target;
            found = worker.valid(target) && worker.all_of<position>(target);
            if (found) seen = worker.get<position>(target);
        }
    };
    step();
    ASSERT_TRUE(found) << "link_to names no body in the worker";
    EXPECT_EQ(seen, (vector3{5, 1, 0})) << "link_to names another body in the worker";
}

// An exclusion list keeps naming a body the program destroyed. Sent again (a new exclusion),
// that stale entity must not take, in the worker, the place of the live body that now has its
// index: the live body's later changes would go to an empty entity of the worker's.
TEST_F(async_world, a_destroyed_entity_named_in_a_component_does_not_displace_the_one_with_its_index) {
    set_gravity(reg, vector3_zero);
    auto a = make_ball({0, 0, 0});
    auto gone = make_ball({5, 0, 0});
    exclude_collision(reg, a, gone);
    step();
    reg.destroy(gone);
    step();
    auto successor = make_ball({10, 0, 0});
    ASSERT_EQ(to_index(successor), to_index(gone)) << "the test needs the index reused";
    auto other = make_ball({-5, 0, 0});
    exclude_collision(reg, a, other); // sends a's list, which still names `gone`
    step();
    reg.replace<linvel>(successor, vector3{1, 0, 0});
    for (int i = 0; i < 30; ++i)
        step();
    EXPECT_NEAR(reg.get<position>(successor).x, scalar(10.5), scalar(1e-3))
        << "the successor's velocity went to another entity in the worker";
    std::size_t worker_entities_with_shape = 0;
    probe = [&](registry &worker) { worker_entities_with_shape = worker.view<shape_index>().size(); };
    step();
    probe = nullptr;
    EXPECT_EQ(worker_entities_with_shape, 3u);
}

TEST_F(async_world, merge_component_specialisations_decide_how_values_merge) {
    register_external_components<log_list>(reg);
    auto ball = make_ball({0, 5, 0});
    reg.emplace<log_list>(ball, log_list{{1, 2}});
    step();
    reg.replace<log_list>(ball, log_list{{3}});
    std::vector<int> items;
    probe = [&](registry &worker) {
        for (auto e : worker.view<log_list>())
            items = worker.get<log_list>(e).items;
    };
    step();
    EXPECT_EQ(items, (std::vector<int>{1, 2, 3}));
}

TEST_F(async_world, an_external_entity_joined_by_a_null_constraint_reaches_the_worker) {
    register_external_components<tag_value>(reg);
    auto ball = make_ball({0, 5, 0});
    auto external = reg.create();
    tag_external_entity(reg, external);
    reg.emplace<tag_value>(external, 42);
    make_constraint<null_constraint>(reg, ball, external);
    EXPECT_EQ(worker_values(), std::vector<int>{42});
    bool tagged = false;
    probe = [&](registry &worker) {
        for (auto e : worker.view<tag_value>())
            tagged = worker.all_of<external_tag>(e) && !worker.all_of<rigidbody_tag>(e);
    };
    step();
    EXPECT_TRUE(tagged);
}

TEST_F(async_world, settings_reach_the_worker) {
    auto ball = make_ball({0, 5, 0});
    set_gravity(reg, vector3_zero);
    set_fixed_dt(reg, scalar(1) / 120);
    set_solver_substeps(reg, 3);
    material_base mixed;
    mixed.friction = scalar(0.123);
    insert_material_mixing(reg, 4, 5, mixed);
    settings seen;
    scalar mixed_friction = 0;
    probe = [&](registry &worker) {
        seen = get_settings(worker);
        material a, b;
        a.id = 4;
        b.id = 5;
        mixed_friction = get_mixed_material(worker, a, b).friction;
    };
    step();
    EXPECT_EQ(seen.gravity, vector3_zero);
    EXPECT_EQ(seen.fixed_dt, scalar(1) / 120);
    EXPECT_EQ(seen.num_substeps, 3u);
    EXPECT_EQ(mixed_friction, scalar(0.123));
    EXPECT_EQ(reg.get<position>(ball), (vector3{0, 5, 0})) << "the ball fell without gravity";

    // The table is sent when it changes: the worker keeps it through batches that do not carry
    // it, and takes a changed entry and a new one.
    step();
    EXPECT_EQ(mixed_friction, scalar(0.123)) << "the worker lost the table it was sent before";
    mixed.friction = scalar(0.25);
    insert_material_mixing(reg, 4, 5, mixed);
    mixed.friction = scalar(0.75);
    insert_material_mixing(reg, 6, 4, mixed);
    scalar new_pair_friction = 0;
    probe = [&](registry &worker) {
        material a, b, c;
        a.id = 4;
        b.id = 5;
        c.id = 6;
        mixed_friction = get_mixed_material(worker, a, b).friction;
        new_pair_friction = get_mixed_material(worker, c, a).friction;
    };
    step();
    EXPECT_EQ(mixed_friction, scalar(0.25));
    EXPECT_EQ(new_pair_friction, scalar(0.75));
    step();
    EXPECT_EQ(new_pair_friction, scalar(0.75));

    // Paused, time passes and no step runs.
    update(reg, 0);
    wait_for_simulation(reg);
    auto steps = get_step_count(reg);
    set_paused(reg, true);
    update(reg, 1);
    wait_for_simulation(reg);
    EXPECT_EQ(get_step_count(reg), steps);
    set_paused(reg, false);
    update(reg, 1 + 6.5 / 120);
    wait_for_simulation(reg);
    EXPECT_EQ(get_step_count(reg), steps + 6) << "six and a half steps of time at 120 Hz";
}

// What a step callback changes in the worker's settings stays there, as in the sequential
// modes, and reaches the program's registry with the step; a change the program makes after
// the step ran, before it heard of the callback's, is the one that stands.
TEST_F(async_world, settings_a_step_callback_changes_stay_and_reach_the_program) {
    auto ball = make_ball({0, 50, 0});
    probe = [](registry &worker) {
        if (get_step_count(worker) != 2) return;
        set_gravity(worker, vector3_zero);
        set_solver_substeps(worker, 3);
    };
    for (int i = 0; i < 3; ++i)
        step();
    EXPECT_EQ(get_settings(reg).gravity, vector3_zero);
    EXPECT_EQ(get_settings(reg).num_substeps, 3u);
    auto coasting = reg.get<linvel>(ball);
    EXPECT_LT(coasting.y, 0) << "the ball fell for two steps";
    // Later batches leave the callback's settings alone: the ball keeps its speed.
    for (int i = 0; i < 10; ++i)
        step();
    EXPECT_EQ(reg.get<linvel>(ball), coasting) << "gravity came back with a later batch";

    // The program's own change afterwards reaches the worker and stays.
    set_gravity(reg, vector3{0, -1, 0});
    settings seen;
    probe = [&](registry &worker) { seen = get_settings(worker); };
    step();
    step();
    EXPECT_EQ(seen.gravity, (vector3{0, -1, 0}));
    EXPECT_EQ(seen.num_substeps, 3u);

    // The callback changes the substeps in a step; the program changes them before it hears of
    // that: the program's change came last, as in the sequential modes.
    probe = [](registry &worker) { set_solver_substeps(worker, 2); };
    step_simulation(reg);
    set_solver_substeps(reg, 5);
    wait_for_simulation(reg);
    EXPECT_EQ(get_settings(reg).num_substeps, 5u);
    probe = [&](registry &worker) { seen = get_settings(worker); };
    step();
    EXPECT_EQ(seen.num_substeps, 5u);
    EXPECT_EQ(get_settings(reg).num_substeps, 5u);

    // A callback that pauses the world: the program sees it paused, and no step runs until
    // the program resumes it.
    probe = [](registry &worker) { set_paused(worker, true); };
    step();
    probe = nullptr;
    EXPECT_TRUE(is_paused(reg));
    update(reg, 0);
    wait_for_simulation(reg);
    auto steps = get_step_count(reg);
    update(reg, 1);
    wait_for_simulation(reg);
    EXPECT_EQ(get_step_count(reg), steps) << "a step ran while the callback had paused the world";
    set_paused(reg, false);
    update(reg, 1 + 3.5 * double(get_fixed_dt(reg)));
    wait_for_simulation(reg);
    EXPECT_EQ(get_step_count(reg), steps + 3);
}

TEST_F(async_world, a_custom_collision_filter_runs_in_the_worker) {
    make_ground();
    auto ball = make_ball({0, scalar(0.6), 0});
    set_should_collide(reg, [](const registry &, entity, entity) { return false; });
    for (int i = 0; i < 30; ++i)
        step_simulation(reg);
    wait_for_simulation(reg);
    EXPECT_LT(reg.get<position>(ball).y, 0) << "the filter let the ball land";
}

TEST_F(async_world, impulses_add_to_the_workers_velocity_not_the_main_copy) {
    set_gravity(reg, vector3_zero);
    auto ball = make_ball({0, 5, 0});
    reg.replace<linvel>(ball, vector3{1, 0, 0});
    // Shown at once on this side...
    rigidbody_apply_impulse(reg, ball, {0, 4, 0}, vector3_zero);
    EXPECT_EQ(reg.get<linvel>(ball), (vector3{1, 2, 0}));
    // ...and applied once in the worker, on top of the velocity it has there.
    step();
    EXPECT_EQ(reg.get<linvel>(ball), (vector3{1, 2, 0}));
    rigidbody_apply_impulse(reg, ball, {-2, 0, 0}, vector3_zero);
    step();
    EXPECT_EQ(reg.get<linvel>(ball), (vector3{0, 2, 0}));
}

TEST_F(async_world, a_teleport_is_not_undone_by_steps_run_before_it_arrived) {
    auto ball = make_ball({0, 50, 0});
    update(reg, 0);
    // Steps asked for, then a teleport made before their results are back.
    update(reg, 0.5);
    reg.replace<position>(ball, vector3{10, 20, 0});
    wait_for_simulation(reg);
    // The worker may have run the steps before the teleport arrived (their motion is then
    // dropped) or, when it took both at once, after it (from the new place): never on the old
    // track.
    auto p = reg.get<position>(ball);
    EXPECT_EQ(p.x, 10) << "back on the old track at x = " << p.x;
    EXPECT_LE(p.y, 20);
    EXPECT_GT(p.y, scalar(19.8)) << "more than ten steps of fall from the new place";
    EXPECT_EQ(reg.get<present_position>(ball).x, 10);
    step();
    EXPECT_EQ(reg.get<position>(ball).x, 10);
    EXPECT_LT(reg.get<position>(ball).y, 20);
}

// Motion the worker computed before a change of the program reached it comes back for the parts
// of the motion the change did not set: a body whose input, velocity or sleep the program
// changes every frame still moves on the main side (it stood still there while the change was
// on its way, which for a change made every frame is always).
TEST_F(async_world, a_body_the_program_changes_every_frame_still_moves_here) {
    register_external_components<tag_value>(reg);
    set_gravity(reg, vector3_zero);
    std::vector<std::function<void(entity, int)>> changes{
        [&](entity e, int frame) { reg.patch<tag_value>(e, [&](tag_value &t) { t.value = frame; }); },
        [&](entity e, int) { wake_up_entity(reg, e); },
        [&](entity e, int) {
            reg.replace<linvel>(e, vector3{1, 0, 0});
        },
        [&](entity e, int) { rigidbody_apply_impulse(reg, e, vector3_zero, vector3_zero); },
    };
    for (std::size_t i = 0; i < changes.size(); ++i) {
        auto ball = make_ball({0, 5, scalar(i) * 2});
        reg.emplace<tag_value>(ball, 0);
        reg.replace<linvel>(ball, vector3{1, 0, 0});
        for (int frame = 0; frame < 30; ++frame) {
            // The step is asked for, the change made while it runs, and its motion applied with
            // the change still to reach the worker.
            step_simulation(reg);
            changes[i](ball, frame);
            wait_for_simulation(reg);
        }
        EXPECT_NEAR(reg.get<position>(ball).x, scalar(0.5), scalar(0.02))
            << "change " << i << ": the body did not move on the main side";
        EXPECT_EQ(reg.get<linvel>(ball), (vector3{1, 0, 0})) << "change " << i;
        reg.destroy(ball);
    }
    // A teleport every frame keeps the program's place, and its velocity still comes back.
    auto ball = make_ball({0, 5, 0});
    for (int frame = 0; frame < 10; ++frame) {
        step_simulation(reg);
        reg.replace<position>(ball, vector3{0, 5, 0});
        reg.patch<linvel>(ball, [](linvel &v) { v.x += 1; });
        wait_for_simulation(reg);
    }
    EXPECT_EQ(reg.get<position>(ball), (vector3{0, 5, 0}));
    EXPECT_EQ(reg.get<linvel>(ball).x, 10);
}

TEST_F(async_world, contact_events_fire_on_the_calling_thread_with_main_entities) {
    make_ground();
    auto ball = make_ball({0, 2, 0});
    struct seen_event {
        std::thread::id thread;
        bool valid;
        bool names_ball;
        std::uint32_t points;
    };
    static std::vector<seen_event> seen;
    seen.clear();
    on_contact_started(reg).connect<[](registry &r, entity m) {
        auto *manifold = r.try_get<contact_manifold>(m);
        seen.push_back({std::this_thread::get_id(), manifold != nullptr,
                        manifold && (manifold->body[0] == entity{1} || manifold->body[1] == entity{1}),
                        manifold ? manifold->num_points : 0u});
    }>(reg);
    ASSERT_EQ(ball, entity{1});
    for (int i = 0; i < 90; ++i)
        step_simulation(reg);
    wait_for_simulation(reg);
    ASSERT_EQ(seen.size(), 1u);
    EXPECT_EQ(seen[0].thread, std::this_thread::get_id());
    EXPECT_TRUE(seen[0].valid);
    EXPECT_TRUE(seen[0].names_ball);
    EXPECT_GT(seen[0].points, 0u);
}

TEST_F(async_world, step_callbacks_run_on_the_worker_and_may_cast_rays_there) {
    auto ground = make_ground();
    std::thread::id thread;
    bool hit = false;
    probe = [&](registry &worker) {
        thread = std::this_thread::get_id();
        hit = raycast(worker, {0, 5, 0}, {0, -5, 0}).hit();
    };
    step();
    EXPECT_NE(thread, std::this_thread::get_id());
    EXPECT_TRUE(hit) << "the ray missed the ground";
    (void)ground;
}

struct ray_catch {
    int calls{0};
    raycast_id_type id{0};
    raycast_result result;
};
void keep_ray(ray_catch &c, raycast_id_type id, const raycast_result &result, vector3, vector3) {
    ++c.calls;
    c.id = id;
    c.result = result;
}

// A reply that acts on what the ray hit: it throws a ball up, or destroys it.
struct ray_action {
    registry *reg;
    bool destroy;
};
void act_on_hit(ray_action &a, raycast_id_type, const raycast_result &result, vector3, vector3) {
    if (result.entity == null) return;
    if (a.destroy)
        a.reg->destroy(result.entity);
    else
        a.reg->replace<linvel>(result.entity, vector3{0, 5, 0});
}

// The program's listener puts a ball where a destroyed body was.
struct debris_maker {
    entity target{null}, made{null};
};
void make_debris(registry &reg, entity e) {
    auto &maker = reg.ctx().get<debris_maker>();
    if (e != maker.target) return;
    rigidbody_def def;
    def.mass = 1;
    def.shape = sphere_shape{scalar(0.25)};
    def.position = {5, 5, 0};
    maker.made = make_rigidbody(reg, def);
}

// A body the worker destroys (here, from a step callback) is destroyed in the program's registry
// at the next update. What the program's listeners do as it goes reaches the worker.
TEST_F(async_world, what_destroy_listeners_do_for_a_body_the_worker_destroyed_reaches_it) {
    make_ground();
    reg.ctx().emplace<debris_maker>().target = make_ball({0, 5, 0});
    reg.on_destroy<rigidbody_tag>().connect<&make_debris>();
    probe = [](registry &worker) {
        std::vector<entity> dynamic(worker.view<dynamic_tag>().begin(), worker.view<dynamic_tag>().end());
        for (auto e : dynamic)
            worker.destroy(e);
    };
    step();
    probe = nullptr;
    step();
    auto debris = reg.ctx().get<debris_maker>().made;
    ASSERT_NE(debris, entity{null}) << "the ball was not destroyed here";
    for (int i = 0; i < 30; ++i)
        step();
    EXPECT_LT(reg.get<position>(debris).y, 4) << "the debris never reached the worker";
    reg.on_destroy<rigidbody_tag>().disconnect<&make_debris>();
}

// A query's reply runs on the calling thread while the worker's results are applied; what it
// changes reaches the worker like any other change of the program's.
TEST_F(async_world, what_a_query_reply_changes_reaches_the_worker) {
    make_ground();
    auto thrown = make_ball({0, scalar(0.5), 0});
    auto destroyed = make_ball({5, scalar(0.5), 0});
    for (int i = 0; i < 30; ++i)
        step();
    ray_action throw_up{&reg, false}, destroy{&reg, true};
    raycast_delegate_type throw_delegate, destroy_delegate;
    throw_delegate.connect<&act_on_hit>(throw_up);
    destroy_delegate.connect<&act_on_hit>(destroy);
    raycast_async(reg, {0, 5, 0}, {0, -5, 0}, throw_delegate);
    raycast_async(reg, {5, 5, 0}, {5, -5, 0}, destroy_delegate);
    step();
    EXPECT_FALSE(reg.valid(destroyed));
    // 0.25 s after a throw at 5 m/s the ball is 0.94 m higher.
    for (int i = 0; i < 15; ++i)
        step();
    EXPECT_GT(reg.get<position>(thrown).y, scalar(1.2)) << "the worker never threw the ball";
    std::size_t worker_bodies = 0;
    probe = [&](registry &worker) { worker_bodies = worker.view<dynamic_tag>().size(); };
    step();
    probe = nullptr;
    EXPECT_EQ(worker_bodies, 1u) << "the worker still simulates the destroyed ball";
}

// One scene built the same way in two registries, entity for entity.
void build_scene(registry &r) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.shape = plane_shape{vector3_y, 0};
    make_rigidbody(r, def);
    def.shape = box_shape{scalar(0.5), scalar(0.5), scalar(0.5)};
    def.position = {0, scalar(0.5), 0};
    make_rigidbody(r, def);
    def.shape = sphere_shape{scalar(0.5)};
    def.position = {3, scalar(0.5), 0};
    make_rigidbody(r, def);
}

TEST(async_attach, bodies_and_constraints_made_before_attach_join_the_worker) {
    registry reg;
    rigidbody_def def;
    def.mass = 1;
    def.shape = sphere_shape{scalar(0.5)};
    def.position = {0, 5, 0};
    auto a = make_rigidbody(reg, def);
    def.position = {2, 5, 0};
    auto b = make_rigidbody(reg, def);
    auto joint =
        make_constraint<distance_constraint>(reg, a, b, [](distance_constraint &d) { d.distance = 2; });
    attach(reg, async_config());
    for (int i = 0; i < 30; ++i)
        step_simulation(reg);
    wait_for_simulation(reg);
    EXPECT_LT(reg.get<position>(a).y, 5) << "the body made before attach did not fall";
    EXPECT_NEAR(distance(reg.get<position>(a), reg.get<position>(b)), 2, 1e-3);
    // The main side knows the joint belongs to its bodies.
    reg.destroy(a);
    EXPECT_FALSE(reg.valid(joint));
    detach(reg);
}

TEST(async_raycast, gives_the_hit_raycast_gives_in_the_sequential_mode) {
    registry sequential;
    attach(sequential, init_config{execution_mode::sequential});
    build_scene(sequential);
    registry async;
    attach(async, async_config());
    build_scene(async);

    struct ray {
        vector3 p0, p1;
        std::vector<entity> ignore;
    };
    std::vector<ray> rays{{{scalar(0.2), 5, scalar(0.1)}, {scalar(0.2), -5, scalar(0.1)}, {}},
                          {{-5, scalar(0.5), 0}, {5, scalar(0.5), 0}, {entity{1}}},
                          {{3, 3, 2}, {3, scalar(0.5), 0}, {}},
                          {{-3, 2, 0}, {-3, -2, 0}, {}},
                          {{0, 5, 0}, {0, 10, 0}, {}}};
    for (std::size_t i = 0; i < rays.size(); ++i) {
        auto expected = raycast(sequential, rays[i].p0, rays[i].p1, rays[i].ignore);
        ray_catch caught;
        raycast_delegate_type delegate;
        delegate.connect<&keep_ray>(caught);
        auto id = raycast_async(async, rays[i].p0, rays[i].p1, delegate, rays[i].ignore);
        EXPECT_EQ(caught.calls, 0) << "the reply came before an update";
        wait_for_simulation(async);
        ASSERT_EQ(caught.calls, 1) << "ray " << i;
        EXPECT_EQ(caught.id, id);
        EXPECT_EQ(caught.result.entity, expected.entity) << "ray " << i;
        EXPECT_EQ(caught.result.fraction, expected.fraction) << "ray " << i;
        EXPECT_EQ(caught.result.normal, expected.normal) << "ray " << i;
        EXPECT_EQ(caught.result.info_var.index(), expected.info_var.index()) << "ray " << i;
    }
    detach(async);
    detach(sequential);
}

TEST(async_raycast, replies_in_the_sequential_mode_at_the_next_update) {
    registry reg;
    attach(reg, init_config{execution_mode::sequential});
    build_scene(reg);
    ray_catch caught;
    raycast_delegate_type delegate;
    delegate.connect<&keep_ray>(caught);
    raycast_async(reg, {0, 5, 0}, {0, -5, 0}, delegate);
    EXPECT_EQ(caught.calls, 0);
    update(reg, 0);
    ASSERT_EQ(caught.calls, 1);
    EXPECT_EQ(caught.result.entity, entity{1}) << "the box";
}

// An empty delegate would be called with the reply: refused up front, in every mode, and the
// world steps on.
TEST(async_raycast, an_empty_delegate_is_refused_naming_the_function) {
    for (auto mode : {execution_mode::sequential, execution_mode::asynchronous}) {
        registry reg;
        attach(reg, init_config{mode});
        build_scene(reg);
        try {
            raycast_async(reg, {0, 5, 0}, {0, -5, 0}, raycast_delegate_type{});
            ADD_FAILURE() << "raycast_async took an empty delegate";
        } catch (const std::invalid_argument &e) {
            EXPECT_NE(std::string(e.what()).find("raycast_async: delegate is empty"), std::string::npos)
                << e.what();
        }
        try {
            query_aabb_async(reg, AABB{{-1, -1, -1}, {1, 1, 1}}, query_aabb_delegate_type{});
            ADD_FAILURE() << "query_aabb_async took an empty delegate";
        } catch (const std::invalid_argument &e) {
            EXPECT_NE(std::string(e.what()).find("query_aabb_async: delegate is empty"), std::string::npos)
                << e.what();
        }
        update(reg, 0);
        wait_for_simulation(reg);
        detach(reg);
    }
}

// Tools that step one step at a time (step_simulation, wait_for_simulation) get their replies in
// every mode, without an update() that would move the clock.
TEST(async_raycast, wait_for_simulation_hands_over_the_replies_in_every_mode) {
    for (auto mode : {execution_mode::sequential, execution_mode::sequential_multithreaded,
                      execution_mode::asynchronous}) {
        registry reg;
        attach(reg, init_config{mode});
        build_scene(reg);
        step_simulation(reg);
        wait_for_simulation(reg);
        ray_catch caught;
        raycast_delegate_type delegate;
        delegate.connect<&keep_ray>(caught);
        raycast_async(reg, {0, 5, 0}, {0, -5, 0}, delegate);
        wait_for_simulation(reg);
        ASSERT_EQ(caught.calls, 1) << "mode " << int(mode);
        EXPECT_EQ(caught.result.entity, entity{1}) << "the box, mode " << int(mode);
        wait_for_simulation(reg);
        EXPECT_EQ(caught.calls, 1) << "each reply once, mode " << int(mode);
    }
}

void throw_from_delegate(ray_catch &c, raycast_id_type, const raycast_result &, vector3, vector3) {
    ++c.calls;
    throw std::runtime_error("delegate failed");
}

TEST(async_raycast, a_delegate_that_throws_is_reported_by_update_and_the_others_still_reply) {
    for (auto mode : {execution_mode::sequential, execution_mode::asynchronous}) {
        registry reg;
        attach(reg, init_config{mode});
        build_scene(reg);
        ray_catch thrower, keeper;
        raycast_delegate_type throwing, keeping;
        throwing.connect<&throw_from_delegate>(thrower);
        keeping.connect<&keep_ray>(keeper);
        raycast_async(reg, {0, 5, 0}, {0, -5, 0}, throwing);
        raycast_async(reg, {0, 5, 0}, {0, -5, 0}, keeping);
        try {
            update(reg, 0);
            wait_for_simulation(reg);
            update(reg, 0);
            ADD_FAILURE() << "the delegate's exception was swallowed";
        } catch (const std::runtime_error &e) {
            EXPECT_STREQ(e.what(), "delegate failed");
        }
        EXPECT_EQ(thrower.calls, 1);
        EXPECT_EQ(keeper.calls, 1) << "the reply after the one that threw was lost";
        // Reported once.
        EXPECT_NO_THROW(update(reg, 0));
        detach(reg);
    }
}

struct aabb_catch {
    int calls{0};
    query_aabb_result result;
};
void keep_aabb(aabb_catch &c, query_aabb_id_type, const query_aabb_result &result) {
    ++c.calls;
    c.result = result;
}

TEST(async_query_aabb, lists_the_bodies_whose_boxes_overlap_it) {
    for (auto mode : {execution_mode::sequential, execution_mode::asynchronous}) {
        registry reg;
        attach(reg, init_config{mode});
        build_scene(reg);
        aabb_catch caught;
        query_aabb_delegate_type delegate;
        delegate.connect<&keep_aabb>(caught);
        // Around the sphere only, then around everything above the ground's surface.
        query_aabb_async(reg, AABB{{2, 0, -1}, {4, 1, 1}}, delegate);
        update(reg, 0);
        wait_for_simulation(reg);
        ASSERT_EQ(caught.calls, 1);
        EXPECT_EQ(caught.result.entities, (std::vector<entity>{entity{0}, entity{2}})) << "ground and sphere";
        query_aabb_async(reg, AABB{{-10, 2, -10}, {10, 3, 10}}, delegate);
        update(reg, 0);
        wait_for_simulation(reg);
        ASSERT_EQ(caught.calls, 2);
        EXPECT_EQ(caught.result.entities, std::vector<entity>{}) << "nothing is that high";
        detach(reg);
    }
}

TEST(async_present, is_what_the_sequential_mode_presents_at_the_same_time) {
    std::vector<vector3> presented[2];
    std::vector<std::uint64_t> steps[2];
    for (int m = 0; m < 2; ++m) {
        registry reg;
        attach(reg, init_config{m == 0 ? execution_mode::sequential : execution_mode::asynchronous});
        build_scene(reg);
        rigidbody_def def;
        def.mass = 1;
        def.shape = box_shape{scalar(0.3), scalar(0.3), scalar(0.3)};
        def.position = {0, 4, 0};
        def.angvel = {1, 2, 0};
        auto box = make_rigidbody(reg, def);
        // Uneven frames: 7, 23 and 41 ms.
        double t = 10, frames[3] = {0.007, 0.023, 0.041};
        for (int i = 0; i < 120; ++i) {
            update(reg, t);
            wait_for_simulation(reg);
            presented[m].push_back(reg.get<present_position>(box));
            steps[m].push_back(get_step_count(reg));
            t += frames[i % 3];
        }
        detach(reg);
    }
    EXPECT_EQ(steps[0], steps[1]);
    for (std::size_t i = 0; i < presented[0].size(); ++i) {
        ASSERT_EQ(presented[0][i], presented[1][i])
            << "frame " << i << ": sequential y = " << presented[0][i].y
            << ", asynchronous y = " << presented[1][i].y;
    }
}

// Updates as fast as the program can call them, without waiting, while the worker's steps take
// 1.5 ms (a step callback sleeps): a body moving at a steady 6 m/s is never presented behind
// where it was. The worker sent each batch's fraction apart from its last step's motion, and an
// update() that took the motion with the last batch's fraction, near 1, put the present a step
// ahead, which the next update() took back (some 20 times a second here).
TEST(async_present, never_steps_back_while_updates_race_the_worker) {
    registry reg;
    attach(reg, init_config{execution_mode::asynchronous});
    set_gravity(reg, vector3_zero);
    set_pre_step_callback(reg,
                          [](registry &) { std::this_thread::sleep_for(std::chrono::microseconds(1500)); });
    rigidbody_def def;
    def.shape = sphere_shape{scalar(0.5)};
    def.linvel = {6, 0, 0};
    def.sleeping_disabled = true;
    auto ball = make_rigidbody(reg, def);
    auto start = std::chrono::steady_clock::now();
    scalar last = 0, worst = 0;
    int frames = 0;
    while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(1500)) {
        update(reg, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        auto x = reg.get<present_position>(ball).x;
        worst = std::max(worst, last - x);
        last = x;
        ++frames;
    }
    detach(reg);
    EXPECT_GT(last, 0) << "the ball never moved: nothing was tested";
    EXPECT_LE(worst, scalar(1e-5)) << "the present stepped back by up to " << worst << " m in " << frames
                                   << " frames";
}

TEST(async_bad_input, calls_that_need_attach_name_themselves) {
    registry reg;
    raycast_delegate_type ray_delegate;
    query_aabb_delegate_type aabb_delegate;
    auto expect_named = [](auto &&call, const std::string &name) {
        try {
            call();
            ADD_FAILURE() << name << " accepted a registry that is not attached";
        } catch (const std::invalid_argument &e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    };
    expect_named([&] { raycast_async(reg, vector3_zero, vector3_y, ray_delegate); }, "raycast_async");
    expect_named([&] { query_aabb_async(reg, AABB{}, aabb_delegate); }, "query_aabb_async");
    expect_named([&] { register_external_components<tag_value>(reg); }, "register_external_components");
    auto loose = reg.create();
    expect_named([&] { tag_external_entity(reg, loose); }, "tag_external_entity");
    EXPECT_FALSE(reg.all_of<external_tag>(loose));

    attach(reg, async_config());
    expect_named([&] { raycast(reg, vector3_zero, vector3_y); }, "raycast_async");
    auto nan = std::numeric_limits<scalar>::quiet_NaN();
    expect_named([&] { raycast_async(reg, {nan, 0, 0}, vector3_y, ray_delegate); }, "raycast_async");
    expect_named(
        [&] {
            query_aabb_async(reg, AABB{{1, 1, 1}, {0, 0, 0}}, aabb_delegate);
        },
        "query_aabb_async");
    detach(reg);
}

} // namespace
