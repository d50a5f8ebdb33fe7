// What the server's program changes in bodies and constraints after a client has them: each
// change reaches the client once, over the reliable channel, in both execution modes, and the
// client's view follows the changed world.
#include "network_harness.hpp"
#include <cmath>
#include <edyn/networking/remote_client.hpp>
#include <gtest/gtest.h>

namespace {

using namespace edyn;
using edyn::test::net_harness;

entity networked_body(registry &registry, rigidbody_def def) {
    auto e = make_rigidbody(registry, def);
    registry.emplace<networked_tag>(e);
    return e;
}

// A static slab whose top is at y = 0 (a plane ignores its body's position).
entity ground(registry &registry) {
    auto def = rigidbody_def{};
    def.kind = rigidbody_kind::rb_static;
    def.shape = box_shape{20, 0.5, 20};
    def.position = {0, -0.5, 0};
    return networked_body(registry, def);
}

entity box(registry &registry, const vector3 &pos, scalar half = 0.5) {
    auto def = rigidbody_def{};
    def.shape = box_shape{half, half, half};
    def.position = pos;
    return networked_body(registry, def);
}

// The program's components: a value and a tag, networked both.
struct hit_points {
    int value{100};
};
template<typename Archive>
void serialize(Archive &archive, hit_points &h) {
    archive(h.value);
}
struct on_fire {};
// A client's input.
struct throttle : network_input {
    int level{0};
};
template<typename Archive>
void serialize(Archive &archive, throttle &t) {
    archive(t.level);
}

void program_components(registry &registry) {
    register_external_components<hit_points, on_fire, throttle>(registry);
    register_networked_components<hit_points, on_fire, throttle>(registry);
}

// A box with hit points, resting on the ground.
entity box_with_hit_points(registry &server, int value) {
    ground(server);
    auto body = box(server, {0, 0.5, 0});
    server.emplace<hit_points>(body, hit_points{value});
    return body;
}

// Counts the create_entity packets the server sends, by client.
struct create_counter {
    std::map<entity, int> sent;
    static void on_packet(create_counter &c, entity client, const packet::edyn_packet &packet) {
        if (std::holds_alternative<packet::create_entity>(packet.var)) c.sent[client] += 1;
    }
};

struct network_changes : ::testing::TestWithParam<execution_mode> {};

INSTANTIATE_TEST_SUITE_P(modes, network_changes,
                         ::testing::Values(execution_mode::sequential, execution_mode::asynchronous),
                         [](const auto &info) {
                             return info.param == execution_mode::sequential ? "sequential" : "asynchronous";
                         });

TEST_P(network_changes, a_body_s_new_definition_reaches_the_client) {
    net_harness h({}, GetParam());
    auto &s = h.server;
    auto floor = ground(s);
    auto grown = box(s, {0, 0.5, 0});
    auto other = box(s, {3, 0.5, 0});
    auto &c = h.add_client({.latency = 0.05, .jitter = 0.01, .loss = 0.2, .seed = 3});
    h.run(1.5);
    auto local = [&](entity e) { return client_local_entity(c.reg, e); };
    ASSERT_TRUE(c.reg.valid(local(grown)));
    ASSERT_TRUE(c.reg.valid(local(other)));

    rigidbody_set_shape(s, grown, box_shape{1, 1, 1});
    s.patch<material>(other, [](material &m) {
        m.friction = scalar(0.05);
        m.restitution = scalar(0.7);
    });
    rigidbody_set_mass(s, other, 7);
    set_center_of_mass(s, other, {0.1, 0, 0});
    s.emplace<gravity>(other, vector3{0, -3, 0});
    s.patch<collision_filter>(grown, [](collision_filter &f) { f.group = 2; });
    h.run(1.5);

    auto &shape = c.reg.get<box_shape>(local(grown));
    EXPECT_EQ(shape.half_extents, (vector3{1, 1, 1}));
    EXPECT_EQ(c.reg.get<collision_filter>(local(grown)).group, 2u);
    // The grown box rests on its new faces on both ends.
    EXPECT_NEAR(s.get<position>(grown).y, 1, 0.01);
    EXPECT_NEAR(c.reg.get<position>(local(grown)).y, 1, 0.01);
    EXPECT_EQ(c.reg.get<material>(local(other)), s.get<material>(other));
    EXPECT_EQ(c.reg.get<mass>(local(other)).s, 7);
    EXPECT_EQ(static_cast<const matrix3x3 &>(c.reg.get<inertia>(local(other))),
              static_cast<const matrix3x3 &>(s.get<inertia>(other)));
    ASSERT_TRUE(c.reg.all_of<center_of_mass>(local(other)));
    EXPECT_EQ(c.reg.get<center_of_mass>(local(other)), s.get<center_of_mass>(other));
    ASSERT_TRUE(c.reg.all_of<gravity>(local(other)));
    EXPECT_EQ(c.reg.get<gravity>(local(other)), (vector3{0, -3, 0}));

    // A static body moved by the program sends no motion: its definition carries the move. A
    // kind change goes the same way.
    s.patch<position>(floor, [](position &p) { p.y = -0.75; });
    rigidbody_set_kind(s, other, rigidbody_kind::rb_kinematic);
    h.run(1.5);
    EXPECT_EQ(c.reg.get<position>(local(floor)).y, scalar(-0.75));
    EXPECT_TRUE(c.reg.all_of<kinematic_tag>(local(other)));
    EXPECT_NEAR(c.reg.get<position>(local(grown)).y, 0.75, 0.01)
        << "the client's box did not follow the floor";
    EXPECT_EQ(get_network_client_rejections(c.reg).invalid_value, 0u);
}

// A body the server's program makes a sensor (by removing its material) is one on the client,
// and solid again when the material comes back.
TEST_P(network_changes, a_body_made_a_sensor_or_solid_again_is_one_on_the_client) {
    net_harness h({}, GetParam());
    auto &s = h.server;
    auto floor = ground(s);
    auto body = box(s, {0, 0.5, 0});
    auto &c = h.add_client({.latency = 0.05, .jitter = 0.01, .loss = 0.2, .seed = 5});
    h.run(1.5);
    auto local_floor = client_local_entity(c.reg, floor), local_body = client_local_entity(c.reg, body);
    ASSERT_TRUE(c.reg.valid(local_floor));
    ASSERT_TRUE(c.reg.valid(local_body));

    s.remove<material>(floor);
    h.run(0.5);
    EXPECT_TRUE(c.reg.all_of<sensor_tag>(local_floor));
    EXPECT_FALSE(c.reg.all_of<material>(local_floor));
    // The box falls through the floor on both ends (0.5 s of free fall is 1.2 m).
    EXPECT_LT(s.get<position>(body).y, -0.5);
    EXPECT_LT(c.reg.get<present_position>(local_body).y, -0.5);

    s.emplace<material>(floor);
    h.run(0.5);
    EXPECT_FALSE(c.reg.all_of<sensor_tag>(local_floor));
    ASSERT_TRUE(c.reg.all_of<material>(local_floor));
    EXPECT_EQ(c.reg.get<material>(local_floor), s.get<material>(floor));
}

TEST_P(network_changes, constraints_made_or_changed_after_entry_reach_the_client) {
    net_harness h({}, GetParam());
    auto &s = h.server;
    ground(s);
    auto anchor_def = rigidbody_def{};
    anchor_def.kind = rigidbody_kind::rb_static;
    anchor_def.position = {0, 10, 0};
    auto anchor = networked_body(s, anchor_def);
    auto bob = box(s, {0, 0.25, 0}, 0.25);
    auto &c = h.add_client({.latency = 0.05, .loss = 0.2, .seed = 5});
    h.run(1);
    auto local = [&](entity e) { return client_local_entity(c.reg, e); };
    ASSERT_TRUE(c.reg.valid(local(bob)));

    // A rope made once both ends are on the client (its length 0 lifts the bob to the
    // shapeless anchor), then lengthened.
    auto rope = make_constraint<distance_constraint>(s, anchor, bob);
    s.emplace<networked_tag>(rope);
    h.run(1);
    ASSERT_TRUE(c.reg.valid(local(rope)));
    ASSERT_TRUE(c.reg.all_of<distance_constraint>(local(rope)));
    EXPECT_EQ(c.reg.get<distance_constraint>(local(rope)).body[1], local(bob));
    s.patch<distance_constraint>(rope, [](distance_constraint &d) { d.distance = 8; });
    h.run(3);
    EXPECT_EQ(c.reg.get<distance_constraint>(local(rope)).distance, 8);
    // The bob hangs 8 m below the anchor, on the server and in the client's view.
    EXPECT_NEAR(s.get<position>(bob).y, 2, 0.02);
    EXPECT_NEAR(c.reg.get<position>(local(bob)).y, 2, 0.02);
    EXPECT_EQ(get_network_client_rejections(c.reg).conflicting_role, 0u);
}

TEST_P(network_changes, a_change_goes_once_and_only_to_the_clients_that_have_the_body) {
    net_harness h({}, GetParam());
    auto &s = h.server;
    ground(s);
    auto near = box(s, {0, 0.5, 0});
    auto far = box(s, {200, 0.5, 0});
    auto counter = create_counter{};
    network_server_packet_sink(s).connect<&create_counter::on_packet>(counter);
    auto &a = h.add_client();
    auto &b = h.add_client();
    s.get<remote_client>(b.server_entity).aabb_of_interest = {{150, -50, -50}, {250, 50, 50}};
    h.run(2);
    ASSERT_TRUE(a.reg.valid(client_local_entity(a.reg, near)));
    ASSERT_FALSE(b.reg.valid(client_local_entity(b.reg, near)));
    ASSERT_TRUE(b.reg.valid(client_local_entity(b.reg, far)));
    // Once everything has entered and rests, the engine's own work changes no definition.
    auto before_a = counter.sent[a.server_entity];
    auto before_b = counter.sent[b.server_entity];
    h.run(1);
    EXPECT_EQ(counter.sent[a.server_entity], before_a);
    EXPECT_EQ(counter.sent[b.server_entity], before_b);

    s.patch<material>(near, [](material &m) { m.friction = 0.1; });
    s.patch<material>(near, [](material &m) { m.restitution = 0.2; });
    h.run(1);
    EXPECT_EQ(counter.sent[a.server_entity], before_a + 1) << "two changes in one update make one packet";
    EXPECT_EQ(counter.sent[b.server_entity], before_b) << "a client without the body heard of it";
    EXPECT_EQ(a.reg.get<material>(client_local_entity(a.reg, near)).restitution, scalar(0.2));
}

TEST_P(network_changes, components_the_server_removes_are_removed_in_the_client) {
    net_harness h(&program_components, GetParam());
    auto &s = h.server;
    auto body = box_with_hit_points(s, 42);
    s.emplace<on_fire>(body);
    auto &c = h.add_client({.latency = 0.05, .jitter = 0.02, .loss = 0.2, .reordering = 0.2, .seed = 11});
    h.run(1);
    auto local = client_local_entity(c.reg, body);
    ASSERT_TRUE(c.reg.valid(local));
    ASSERT_TRUE(c.reg.all_of<on_fire>(local));
    ASSERT_EQ(c.reg.get<hit_points>(local).value, 42);

    s.remove<on_fire>(body);
    s.patch<hit_points>(body, [](hit_points &hp) { hp.value = 7; });
    h.run(1);
    EXPECT_FALSE(c.reg.all_of<on_fire>(local));
    EXPECT_EQ(c.reg.get<hit_points>(local).value, 7);
    s.remove<hit_points>(body);
    s.emplace<on_fire>(body);
    h.run(1);
    EXPECT_FALSE(c.reg.all_of<hit_points>(local));
    EXPECT_TRUE(c.reg.all_of<on_fire>(local)) << "a component put back after its removal did not come back";
}

TEST_P(network_changes, a_late_snapshot_does_not_undo_a_newer_value) {
    // Snapshots held back longer than a change is repeated (three snapshots, 0.1 s at 30 a
    // second) arrive after copies of the newer value. The value only grows on the server, so
    // the client's must never go down.
    net_harness h(&program_components, GetParam());
    auto &s = h.server;
    auto body = box_with_hit_points(s, 0);
    auto &c = h.add_client({.latency = 0.05, .reordering = 0.2, .reorder_delay = 0.25, .seed = 2});
    h.run(0.5);
    auto local = client_local_entity(c.reg, body);
    ASSERT_TRUE(c.reg.all_of<hit_points>(local));
    auto frames = 0;
    auto highest = 0;
    auto went_down = 0;
    h.run(4, [&] {
        if (++frames % 7 == 0) s.patch<hit_points>(body, [](hit_points &hp) { hp.value += 1; });
        auto value = c.reg.get<hit_points>(local).value;
        if (value < highest) ++went_down;
        highest = std::max(highest, value);
    });
    h.run(1);
    EXPECT_EQ(went_down, 0);
    EXPECT_EQ(c.reg.get<hit_points>(local).value, s.get<hit_points>(body).value);
}

TEST_P(network_changes, a_changed_definition_does_not_undo_the_client_s_own_input) {
    net_harness h(&program_components, GetParam());
    auto &s = h.server;
    auto body = box_with_hit_points(s, 1);
    s.emplace<throttle>(body);
    auto &c = h.add_client({.latency = 0.05});
    s.get<remote_client>(c.server_entity).owned_entities.push_back(body);
    h.run(1);
    auto local = client_local_entity(c.reg, body);
    ASSERT_TRUE(c.reg.valid(local));
    c.reg.patch<throttle>(local, [](throttle &t) { t.level = 5; });
    // Changed on the server before the input reaches it: the body's definition goes to the
    // client with the server's values of the moment, the input's older one among them.
    s.patch<material>(body, [](material &m) { m.friction = scalar(0.2); });
    h.run(1);
    EXPECT_EQ(c.reg.get<material>(local).friction, scalar(0.2));
    EXPECT_EQ(c.reg.get<throttle>(local).level, 5) << "the client's input was put back";
    EXPECT_EQ(s.get<throttle>(body).level, 5);
}

} // namespace
