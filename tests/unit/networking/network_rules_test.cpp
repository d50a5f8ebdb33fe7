// What the server accepts from a client and what it sends it: actions exactly once under loss,
// ownership and malformed packets, entities entering and leaving the AABB of interest, and
// destroyed entities.
#include "network_harness.hpp"
#include <edyn/networking/networked_components.hpp>
#include <edyn/networking/remote_client.hpp>
#include <gtest/gtest.h>
#include <map>
#include <mutex>

namespace {

using namespace edyn;
using edyn::test::net_client;
using edyn::test::net_harness;

struct steering : network_input {
    scalar angle{0};
};
template<typename Archive>
void serialize(Archive &archive, steering &s) {
    archive(s.angle);
}

// A health value only the server changes: networked, not an input.
struct health {
    int value{100};
};
template<typename Archive>
void serialize(Archive &archive, health &h) {
    archive(h.value);
}

struct jump {
    int id{0};
};
template<typename Archive>
void serialize(Archive &archive, jump &j) {
    archive(j.id);
}

// Every jump the steps consumed, by id: on the server, and on the client. Written by the
// stepping thread (a worker in asynchronous mode), read after wait_for_simulation.
struct jump_log {
    std::mutex mutex;
    std::vector<int> ids;
    std::vector<int> taken() {
        std::lock_guard lock(mutex);
        return ids;
    }
};
jump_log server_jumps, client_jumps;

void log_jumps(registry &registry, jump_log &log) {
    std::lock_guard lock(log.mutex);
    for (auto [e, list] : registry.view<action_list<jump>>().each())
        for (auto &j : list.actions)
            log.ids.push_back(j.id);
}
void consume_server_jumps(registry &registry) { log_jumps(registry, server_jumps); }
void consume_client_jumps(registry &registry) { log_jumps(registry, client_jumps); }

void rules_setup(registry &registry) {
    register_external_components<steering, health>(registry, std::tuple<jump>{});
    register_networked_components<steering, health>(registry, std::tuple<jump>{});
}

entity rules_box(registry &registry, const vector3 &pos) {
    auto def = rigidbody_def{};
    def.shape = box_shape{{0.5, 0.5, 0.5}};
    def.position = pos;
    def.gravity = vector3_zero;
    auto e = make_rigidbody(registry, def);
    registry.emplace<networked_tag>(e);
    return e;
}

// Jumps made on the client, a few per second, some two at once, each added either after
// update() or between the network update and update(); the server's steps and the client's own
// see each exactly once.
void check_actions_once_each(execution_mode mode, double frame_dt) {
    net_harness h(&rules_setup, mode);
    h.frame_dt = frame_dt;
    server_jumps.ids.clear();
    client_jumps.ids.clear();
    set_pre_step_callback(h.server, &consume_server_jumps);
    auto box = rules_box(h.server, {0, 0, 0});
    auto &c = h.add_client({.latency = 0.05, .jitter = 0.02, .loss = 0.25, .duplication = 0.1, .seed = 3});
    set_pre_step_callback(c.reg, &consume_client_jumps);
    h.server.get<remote_client>(c.server_entity).owned_entities.push_back(box);
    h.run(1);
    auto local = client_local_entity(c.reg, box);
    ASSERT_NE(local, entity{null});
    auto next_id = 0, frame = 0;
    auto add_jumps = [&] {
        auto &list = c.reg.get_or_emplace<action_list<jump>>(local);
        list.actions.push_back({next_id++});
        if (next_id % 7 == 0) list.actions.push_back({next_id++});
    };
    h.before_client_update = [&](net_client &) {
        if (frame % 5 == 2) add_jumps();
    };
    h.run(3, [&] {
        if (frame++ % 5 == 0) add_jumps();
    });
    h.before_client_update = {};
    h.run(1.5);
    auto expected = std::vector<int>(std::size_t(next_id));
    for (int i = 0; i < next_id; ++i)
        expected[std::size_t(i)] = i;
    EXPECT_GT(next_id, 20);
    EXPECT_EQ(server_jumps.taken(), expected)
        << server_jumps.taken().size() << " jumps seen by the server, " << next_id << " made";
    EXPECT_EQ(client_jumps.taken(), expected)
        << client_jumps.taken().size() << " jumps seen by the client's steps, " << next_id << " made";
    // The client's own lists are emptied by its steps too.
    EXPECT_TRUE(c.reg.get<action_list<jump>>(local).actions.empty());
}

TEST(network_rules, actions_reach_the_server_once_each_under_loss) {
    check_actions_once_each(execution_mode::sequential, 1.0 / 60);
}

TEST(network_rules, actions_are_seen_once_when_an_update_runs_several_steps) {
    check_actions_once_each(execution_mode::sequential, 1.0 / 20);
}

TEST(network_rules, actions_reach_the_servers_worker_once_each_in_asynchronous_mode) {
    check_actions_once_each(execution_mode::asynchronous, 1.0 / 30);
}

// When the round trip gets shorter, the playout delay and the client's lead shrink, and the
// client's time goes back over steps it has stamped inputs and actions with: what it stamps then
// still reaches the server (it was taken for copies of what the server had, or as older than what
// it applied: an input's last change and some actions were lost for good).
void check_a_shorter_round_trip(execution_mode mode) {
    net_harness h(&rules_setup, mode);
    server_jumps.ids.clear();
    client_jumps.ids.clear();
    set_pre_step_callback(h.server, &consume_server_jumps);
    auto box = rules_box(h.server, {0, 0, 0});
    auto &c = h.add_client({.latency = 0.05});
    auto set_rtt = [&](double rtt) {
        server_set_client_round_trip_time(h.server, c.server_entity, rtt);
        set_network_client_round_trip_time(c.reg, rtt);
    };
    set_rtt(0.4);
    h.server.get<remote_client>(c.server_entity).owned_entities.push_back(box);
    h.run(2);
    auto local = client_local_entity(c.reg, box);
    ASSERT_NE(local, entity{null});
    c.reg.emplace<steering>(local, steering{{}, 0});
    auto next_id = 0;
    scalar angle = 0;
    auto play = [&] {
        angle += scalar(0.01);
        c.reg.replace<steering>(local, steering{{}, angle});
        c.reg.get_or_emplace<action_list<jump>>(local).actions.push_back({next_id++});
    };
    h.run(1, play);
    auto lead_before = get_network_client_time(c.reg) - get_simulation_time(c.reg);
    set_rtt(0.1);
    h.run(0.1, play);
    c.reg.replace<steering>(local, steering{{}, 5});
    h.run(2);
    auto lead_after = get_network_client_time(c.reg) - get_simulation_time(c.reg);
    EXPECT_LT(lead_after, lead_before) << "the client's lead did not move down";
    ASSERT_TRUE(h.server.all_of<steering>(box));
    EXPECT_EQ(h.server.get<steering>(box).angle, 5) << "the client's last input did not reach the server";
    auto expected = std::vector<int>(std::size_t(next_id));
    for (int i = 0; i < next_id; ++i)
        expected[std::size_t(i)] = i;
    EXPECT_EQ(server_jumps.taken(), expected)
        << server_jumps.taken().size() << " jumps seen by the server, " << next_id << " made";
    EXPECT_EQ(h.server.get<remote_client>(c.server_entity).rejected.total(), 0u);
}

TEST(network_rules, inputs_and_actions_reach_the_server_when_the_round_trip_gets_shorter) {
    check_a_shorter_round_trip(execution_mode::sequential);
}

TEST(network_rules, inputs_and_actions_reach_the_servers_worker_when_the_round_trip_gets_shorter) {
    check_a_shorter_round_trip(execution_mode::asynchronous);
}

TEST(network_rules, the_server_refuses_what_the_client_does_not_own) {
    net_harness h(&rules_setup);
    auto mine = rules_box(h.server, {0, 0, 0});
    auto theirs = rules_box(h.server, {2, 0, 0});
    auto gone = rules_box(h.server, {4, 0, 0});
    h.server.emplace<health>(mine);
    auto &c = h.add_client({.latency = 0.01});
    auto &rc = h.server.get<remote_client>(c.server_entity);
    rc.owned_entities.push_back(mine);
    h.run(0.5);
    ASSERT_NE(client_local_entity(c.reg, gone), entity{null});
    h.server.destroy(gone);
    h.run(0.1);

    auto send_raw = [&](const packet::edyn_packet &p) {
        server_receive_packet(h.server, c.server_entity, p);
        return h.server.get<remote_client>(c.server_entity).rejected;
    };
    // Builds a one-entity snapshot of `value` at network index `index`.
    auto snapshot_of = [&](entity e, std::uint16_t index, auto value) {
        auto snap = packet::registry_snapshot{};
        snap.timestamp = get_simulation_time(h.server) + 0.05;
        snap.entities = {e};
        auto bytes = std::vector<std::uint8_t>{};
        auto archive = memory_output_archive(bytes);
        archive.write_size(0);
        archive(value);
        snap.pools.push_back({index, bytes});
        return packet::edyn_packet{snap};
    };
    // The program's types follow edyn's own: steering is the first of them.
    auto steering_index = std::uint16_t(0);
    for (auto e : {mine}) {
        // Find the index by sending the input on the owned entity: accepted.
        for (std::uint16_t i = 0; i < 64 && steering_index == 0; ++i) {
            auto before = h.server.get<remote_client>(c.server_entity).rejected;
            auto after = send_raw(snapshot_of(e, i, steering{{}, 0.25f}));
            if (after.total() == before.total()) steering_index = i;
        }
    }
    ASSERT_NE(steering_index, 0) << "no index accepted a steering input";
    h.run(0.2);
    ASSERT_TRUE(h.server.all_of<steering>(mine));
    EXPECT_FLOAT_EQ(h.server.get<steering>(mine).angle, 0.25f);

    auto before = h.server.get<remote_client>(c.server_entity).rejected;
    // An input on an entity it does not own.
    auto r = send_raw(snapshot_of(theirs, steering_index, steering{{}, 1.0f}));
    EXPECT_EQ(r.not_owned, before.not_owned + 1);
    // A component that is not an input (health follows steering).
    r = send_raw(snapshot_of(mine, std::uint16_t(steering_index + 1), health{1}));
    EXPECT_EQ(r.not_input, before.not_input + 1);
    // An entity the server never sent it.
    r = send_raw(snapshot_of(entity{0xABCDE}, steering_index, steering{{}, 1.0f}));
    EXPECT_EQ(r.unknown_entity, before.unknown_entity + 1);
    // Malformed values: a truncated pool, and an unknown component index.
    auto bad = snapshot_of(mine, steering_index, steering{{}, 1.0f});
    std::get<packet::registry_snapshot>(bad.var).pools[0].data.pop_back();
    r = send_raw(bad);
    EXPECT_EQ(r.malformed, before.malformed + 1);
    r = send_raw(snapshot_of(mine, 9999, steering{{}, 1.0f}));
    EXPECT_EQ(r.malformed, before.malformed + 2);
    // Inputs forwarded as the server forwards other clients' ones: the server's to send.
    auto forwarding = snapshot_of(mine, steering_index, steering{{}, 1.0f});
    auto &forwarded = std::get<packet::registry_snapshot>(forwarding.var);
    forwarded.inputs.push_back({forwarded.timestamp, forwarded.entities, forwarded.pools});
    r = send_raw(forwarding);
    EXPECT_EQ(r.malformed, before.malformed + 3);
    // Times no client can be at, further from the server's than the longest playout delay: the
    // other clients would refuse such an input, forwarded, and with it whole snapshots.
    for (auto off : {100.0, -100.0, 10.5, -10.5}) {
        auto far = snapshot_of(mine, steering_index, steering{{}, 1.0f});
        std::get<packet::registry_snapshot>(far.var).timestamp = get_simulation_time(h.server) + off;
        auto malformed = h.server.get<remote_client>(c.server_entity).rejected.malformed;
        r = send_raw(far);
        EXPECT_EQ(r.malformed, malformed + 1) << "an input stamped " << off << " s from the server's time";
    }
    // Entity requests: an entity the client heard of before it was destroyed is no refusal (a
    // client asks for what a packet sent before the destroy_entity named); an id the server
    // never issued is, at an index it never used or as a version of a known index still to come.
    r = send_raw({packet::entity_request{{gone}}});
    EXPECT_EQ(r.unknown_entity, before.unknown_entity + 1);
    r = send_raw({packet::entity_request{{entity{0xABCDE}}}});
    EXPECT_EQ(r.unknown_entity, before.unknown_entity + 2);
    auto next_version = entity(to_integral(theirs) + (2u << entity_traits::index_bits));
    r = send_raw({packet::entity_request{{next_version}}});
    EXPECT_EQ(r.unknown_entity, before.unknown_entity + 3);
    // Packets only the server sends.
    r = send_raw({packet::create_entity{}});
    r = send_raw({packet::server_settings{}});
    EXPECT_EQ(r.not_input, before.not_input + 3);
    EXPECT_EQ(r.malformed, before.malformed + 7);

    h.run(0.5);
    EXPECT_FLOAT_EQ(h.server.get<steering>(mine).angle, 0.25f) << "a refused packet changed the server";
    EXPECT_FALSE(h.server.all_of<steering>(theirs));
    EXPECT_EQ(h.server.get<health>(mine).value, 100);
}

// The snapshots sent to one client that forward each input of the others, by the input's time.
struct forwarded_count {
    entity client{null};
    std::map<double, int> snapshots;
    static void on_packet(forwarded_count &f, entity client, const packet::edyn_packet &packet) {
        if (client != f.client) return;
        if (auto *snapshot = std::get_if<packet::registry_snapshot>(&packet.var))
            for (auto &entry : snapshot->inputs)
                f.snapshots[entry.timestamp] += 1;
    }
};

// A client's input waits in the server's jitter buffer for the playout delay less its way there,
// several snapshot periods here, but goes to each other client in two snapshots only: one lost
// packet loses none, and the clients keep what they were forwarded.
TEST(network_rules, each_input_is_forwarded_to_the_other_clients_in_two_snapshots) {
    net_harness h(&rules_setup);
    auto theirs = rules_box(h.server, {0, 0, 0});
    auto &viewer = h.add_client({.latency = 0.05});
    auto &driver = h.add_client({.latency = 0.05});
    h.server.get<remote_client>(driver.server_entity).owned_entities.push_back(theirs);
    h.server.get<remote_client>(viewer.server_entity).snapshot_rate = 60;
    h.run(1);
    auto driven = client_local_entity(driver.reg, theirs);
    ASSERT_NE(driven, entity{null});
    auto count = forwarded_count{viewer.server_entity, {}};
    network_server_packet_sink(h.server).connect<&forwarded_count::on_packet>(count);
    driver.reg.emplace<steering>(driven);
    auto frame = 0;
    h.run(1, [&] {
        if (++frame % 6 == 0) driver.reg.replace<steering>(driven, steering{{}, scalar(frame)});
    });
    h.run(0.5);
    network_server_packet_sink(h.server).disconnect<&forwarded_count::on_packet>(count);
    auto period = 1 / h.server.get<remote_client>(viewer.server_entity).snapshot_rate;
    ASSERT_GT(h.server.get<remote_client>(driver.server_entity).playout_delay - 0.05, 3 * period)
        << "the inputs wait for fewer snapshots than the test needs";
    EXPECT_GE(count.snapshots.size(), 10u);
    for (auto [time, snapshots] : count.snapshots)
        EXPECT_EQ(snapshots, 2) << "the input of time " << time;
}

TEST(network_rules, random_bytes_never_crash_the_server) {
    net_harness h(&rules_setup);
    auto mine = rules_box(h.server, {0, 0, 0});
    auto &c = h.add_client({.latency = 0.01});
    h.server.get<remote_client>(c.server_entity).owned_entities.push_back(mine);
    h.run(0.3);
    auto rng = std::uint64_t{12345};
    auto next = [&] {
        rng = rng * 6364136223846793005ull + 1442695040888963407ull;
        return std::uint8_t(rng >> 56);
    };
    auto accepted = 0;
    for (int i = 0; i < 20000; ++i) {
        auto data = std::vector<std::uint8_t>(std::size_t(next() % 64));
        for (auto &b : data)
            b = next();
        // Mostly snapshots, so that the pool decoding is reached.
        if (!data.empty() && i % 2 == 0) data[0] = 0;
        packet::edyn_packet p;
        auto archive = memory_input_archive(data.data(), data.size());
        archive(p);
        if (archive.failed()) continue;
        ++accepted;
        server_receive_packet(h.server, c.server_entity, p);
        if (i % 100 == 0) h.frame();
    }
    EXPECT_GT(accepted, 100);
    h.run(0.5);
    EXPECT_TRUE(h.server.valid(mine));
}

TEST(network_rules, islands_enter_and_leave_the_aabb_of_interest) {
    net_harness h(&rules_setup);
    auto near_box = rules_box(h.server, {0, 0, 0});
    auto far_box = rules_box(h.server, {100, 0, 5});
    auto &c = h.add_client({.latency = 0.02});
    auto &rc = h.server.get<remote_client>(c.server_entity);
    rc.aabb_of_interest = {{-10, -10, -10}, {10, 10, 10}};
    h.run(0.5);
    EXPECT_NE(client_local_entity(c.reg, near_box), entity{null});
    EXPECT_EQ(client_local_entity(c.reg, far_box), entity{null}) << "a body outside the AABB was sent";

    // The far box flies in; the near one flies out (on another line).
    h.server.replace<linvel>(far_box, vector3{-95, 0, 0});
    h.server.replace<linvel>(near_box, vector3{100, 0, 0});
    h.run(1.1);
    EXPECT_NE(client_local_entity(c.reg, far_box), entity{null})
        << "a body entering the AABB was not created";
    auto near_local = client_local_entity(c.reg, near_box);
    EXPECT_EQ(near_local, entity{null}) << "a body leaving the AABB was not destroyed";
    auto bodies = 0;
    for (auto e : c.reg.view<rigidbody_tag>())
        bodies += e != null;
    EXPECT_EQ(bodies, 1);
}

// Bodies are in where their bounding boxes overlap the AABB of interest, not their centres;
// static bodies likewise (a plane everywhere), in both the sequential and asynchronous modes.
void check_boxes_of_interest(execution_mode mode) {
    net_harness h(&rules_setup, mode);
    auto ground = [&](shapes_variant_t shape, const vector3 &pos) {
        auto def = rigidbody_def{};
        def.kind = rigidbody_kind::rb_static;
        def.shape = shape;
        def.position = pos;
        auto e = make_rigidbody(h.server, def);
        h.server.emplace<networked_tag>(e);
        return e;
    };
    auto plane = ground(plane_shape{vector3_y, -20}, vector3_zero);
    auto far_wall = ground(box_shape{{1, 5, 1}}, {200, 0, 0});
    auto edge_wall = ground(box_shape{{5, 1, 1}}, {14, 0, 0}); // centre outside, box reaching in
    // A long plank whose centre lies outside the box but whose ends reach into it.
    auto plank_def = rigidbody_def{};
    plank_def.shape = box_shape{{6, 0.2, 0.2}};
    plank_def.position = {0, 0, 15};
    plank_def.orientation = quaternion_axis_angle(vector3_y, to_radians(90));
    plank_def.gravity = vector3_zero;
    auto plank = make_rigidbody(h.server, plank_def);
    h.server.emplace<networked_tag>(plank);
    auto &c = h.add_client({.latency = 0.02});
    h.server.get<remote_client>(c.server_entity).aabb_of_interest = {{-10, -10, -10}, {10, 10, 10}};
    h.run(0.5);
    EXPECT_NE(client_local_entity(c.reg, plane), entity{null}) << "a plane is everyone's";
    EXPECT_NE(client_local_entity(c.reg, edge_wall), entity{null}) << "a wall reaching into the box";
    EXPECT_NE(client_local_entity(c.reg, plank), entity{null}) << "a plank reaching into the box";
    EXPECT_EQ(client_local_entity(c.reg, far_wall), entity{null}) << "a static body far outside was sent";

    // The plank moves away: it leaves when its box no longer overlaps, not before.
    h.server.replace<linvel>(plank, vector3{0, 0, 4});
    wake_up_entity(h.server, plank);
    h.run(0.1); // near end near 9.4: still in
    EXPECT_NE(client_local_entity(c.reg, plank), entity{null});
    h.run(1.5); // near end near 15.4: out
    EXPECT_EQ(client_local_entity(c.reg, plank), entity{null}) << "a plank that left was not destroyed";

    // The box of interest moves to the far wall: it comes in, the edge wall leaves.
    h.server.get<remote_client>(c.server_entity).aabb_of_interest = {{190, -10, -10}, {210, 10, 10}};
    h.run(0.5);
    EXPECT_NE(client_local_entity(c.reg, far_wall), entity{null});
    EXPECT_EQ(client_local_entity(c.reg, edge_wall), entity{null});
    EXPECT_NE(client_local_entity(c.reg, plane), entity{null});
}

TEST(network_rules, bodies_and_static_bodies_are_in_where_their_boxes_overlap_the_aabb_of_interest) {
    check_boxes_of_interest(execution_mode::sequential);
}

TEST(network_rules, boxes_of_interest_follow_the_workers_motion_in_asynchronous_mode) {
    check_boxes_of_interest(execution_mode::asynchronous);
}

TEST(network_rules, destroyed_entities_are_destroyed_in_the_client) {
    net_harness h(&rules_setup);
    auto a = rules_box(h.server, {0, 0, 0});
    auto b = rules_box(h.server, {3, 0, 0});
    h.server.emplace<health>(b, health{42});
    auto &c = h.add_client({.latency = 0.02, .loss = 0.2, .seed = 9});
    h.run(0.5);
    auto local_a = client_local_entity(c.reg, a);
    auto local_b = client_local_entity(c.reg, b);
    ASSERT_NE(local_a, entity{null});
    ASSERT_NE(local_b, entity{null});
    EXPECT_EQ(c.reg.get<health>(local_b).value, 42);
    h.server.patch<health>(b, [](health &hp) { hp.value = 7; });
    h.server.destroy(a);
    h.run(0.5);
    EXPECT_FALSE(c.reg.valid(local_a));
    EXPECT_EQ(c.reg.get<health>(local_b).value, 7) << "a change of a networked component did not arrive";
}

} // namespace
