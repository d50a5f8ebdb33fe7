// What a client does with values from its server that would hang or break its simulation:
// settings, times and playout delays out of range, bodies it cannot simulate, and bodies or
// constraints for entities that already have another role. Each is refused and counted; the
// client keeps running. Also what it does when the server reuses an entity's index: the
// earlier entity's local one goes.
#include "src/networking/extrapolation.hpp"
#include "src/networking/network_registry.hpp"
#include <chrono>
#include <cmath>
#include <edyn/edyn.hpp>
#include <edyn/networking/client.hpp>
#include <edyn/serialization/constraint_types.hpp>
#include <edyn/serialization/dynamics_types.hpp>
#include <edyn/serialization/shape_types.hpp>
#include <gtest/gtest.h>
#include <limits>

namespace {

using namespace edyn;

// A client with no server: the test plays the server, its packets going through bytes as a
// transport carries them.
struct lone_client {
    registry reg;
    double time{0};

    lone_client() {
        attach(reg, init_config{execution_mode::sequential});
        init_network_client(reg);
        set_network_client_round_trip_time(reg, 0);
    }
    ~lone_client() { deinit_network_client(reg); }
    lone_client(const lone_client &) = delete;
    lone_client &operator=(const lone_client &) = delete;

    void receive(const packet::edyn_packet &sent) {
        auto data = std::vector<std::uint8_t>{};
        auto out = memory_output_archive(data);
        out(sent);
        auto packet = packet::edyn_packet{};
        auto in = memory_input_archive(data.data(), data.size());
        in(packet);
        ASSERT_FALSE(in.failed());
        client_receive_packet(reg, packet);
    }

    void frame() {
        time += 1.0 / 60;
        update_network_client(reg);
        wait_for_network_client(reg);
        update(reg, time);
    }

    const network_client_rejections &rejected() const { return get_network_client_rejections(reg); }
};

packet::server_settings default_settings() {
    auto s = settings{};
    return {s.fixed_dt,
            s.gravity,
            s.num_substeps,
            s.num_relax_iterations,
            s.num_restitution_iterations,
            s.num_individual_restitution_iterations,
            s.max_linear_speed,
            s.contact,
            s.joint};
}

// A pool of values of the networked type at `index`, each for an entity of the packet's list.
template<typename T>
packet::pool_snapshot make_pool(std::uint16_t index, const std::vector<std::pair<std::size_t, T>> &values) {
    auto pool = packet::pool_snapshot{index, {}};
    auto archive = memory_output_archive(pool.data);
    for (auto [position, value] : values) {
        archive.write_size(position);
        archive(value);
    }
    return pool;
}

template<typename T>
std::uint16_t network_index_of(registry &reg) {
    return std::uint16_t(ensure_network_registry(reg).index_of(type_index<T>()));
}

rigidbody_def box_at(const vector3 &pos) {
    auto def = rigidbody_def{};
    def.shape = box_shape{{0.5, 0.5, 0.5}};
    def.position = pos;
    return def;
}

// Remote entities: any entities of another registry will do.
std::vector<entity> remote_entities(std::size_t count) {
    static registry server;
    auto result = std::vector<entity>{};
    for (std::size_t i = 0; i < count; ++i)
        result.push_back(server.create());
    return result;
}

bool is_body(const lone_client &c, entity remote) {
    auto local = client_local_entity(c.reg, remote);
    return local != null && c.reg.valid(local) && c.reg.all_of<rigidbody_tag>(local);
}

TEST(network_bounds, server_settings_out_of_range_are_refused_whole) {
    auto bad = std::vector<std::pair<const char *, packet::server_settings>>{};
    auto add = [&](const char *what, auto change) {
        auto s = default_settings();
        change(s);
        bad.emplace_back(what, s);
    };
    // Counts a step would loop over for hours, and dts that overflow the step count.
    add("substeps", [](auto &s) { s.num_substeps = 4000000000u; });
    add("zero substeps", [](auto &s) { s.num_substeps = 0; });
    add("relax", [](auto &s) { s.num_relax_iterations = 4000000000u; });
    add("restitution", [](auto &s) { s.num_restitution_iterations = 4000000000u; });
    add("individual restitution", [](auto &s) { s.num_individual_restitution_iterations = 4000000000u; });
    add("tiny dt", [](auto &s) { s.fixed_dt = scalar(1e-21); });
    add("huge dt", [](auto &s) { s.fixed_dt = scalar(5.7e36); });
    add("NaN dt", [](auto &s) { s.fixed_dt = std::numeric_limits<scalar>::quiet_NaN(); });
    add("huge gravity", [](auto &s) { s.gravity = {0, scalar(-4e34), 0}; });
    add("NaN gravity", [](auto &s) { s.gravity = {std::numeric_limits<scalar>::quiet_NaN(), 0, 0}; });
    add("position iterations",
        [](auto &s) { s.joint.position_projection_iterations = max_solver_iterations + 1; });
    add("NaN contact frequency",
        [](auto &s) { s.contact.contact_hertz = std::numeric_limits<scalar>::quiet_NaN(); });
    add("negative push-out", [](auto &s) { s.contact.max_push_out_velocity = -3; });
    add("no frequency cap", [](auto &s) { s.joint.max_hertz_ratio = 0; });
    add("negative correction speed", [](auto &s) { s.joint.max_correction_speed = -3; });
    add("zero speed limit", [](auto &s) { s.max_linear_speed = 0; });
    add("negative speed limit", [](auto &s) { s.max_linear_speed = -400; });
    add("huge speed limit", [](auto &s) { s.max_linear_speed = max_linear_speed_limit * 2; });
    add("NaN speed limit", [](auto &s) { s.max_linear_speed = std::numeric_limits<scalar>::quiet_NaN(); });

    lone_client c;
    auto before = get_settings(c.reg);
    std::uint32_t refused = 0;
    for (auto &[what, s] : bad) {
        SCOPED_TRACE(what);
        c.receive({s});
        EXPECT_EQ(c.rejected().out_of_range, ++refused);
        // Nothing of a refused packet is applied, not even its valid fields.
        auto &now = get_settings(c.reg);
        ASSERT_EQ(now.num_substeps, before.num_substeps);
        ASSERT_EQ(now.num_relax_iterations, before.num_relax_iterations);
        ASSERT_EQ(now.num_restitution_iterations, before.num_restitution_iterations);
        ASSERT_EQ(now.num_individual_restitution_iterations, before.num_individual_restitution_iterations);
        ASSERT_EQ(now.fixed_dt, before.fixed_dt);
        ASSERT_EQ(now.gravity, before.gravity);
        ASSERT_EQ(now.max_linear_speed, before.max_linear_speed);
        ASSERT_EQ(now.contact, before.contact);
        ASSERT_EQ(now.joint, before.joint);
    }
    // The client still steps, at once.
    make_rigidbody(c.reg, box_at({0, 1, 0}));
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 30; ++i)
        c.frame();
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));

    // Settings within range are applied.
    auto good = default_settings();
    good.fixed_dt = scalar(1) / 120;
    good.gravity = {0, scalar(-1.62), 0};
    good.num_substeps = max_solver_substeps;
    good.num_relax_iterations = 2;
    good.joint.position_projection_iterations = 0;
    good.joint.max_projected_gap = std::numeric_limits<scalar>::infinity();
    good.contact.contact_hertz = 30;
    good.max_linear_speed = max_linear_speed_limit;
    c.receive({good});
    EXPECT_EQ(c.rejected().out_of_range, refused);
    EXPECT_EQ(get_fixed_dt(c.reg), scalar(1) / 120);
    EXPECT_EQ(get_gravity(c.reg).y, scalar(-1.62));
    EXPECT_EQ(get_solver_substeps(c.reg), max_solver_substeps);
    EXPECT_EQ(get_solver_relax_iterations(c.reg), 2u);
    EXPECT_EQ(get_solver_position_iterations(c.reg), 0u);
    EXPECT_EQ(get_settings(c.reg).joint.max_projected_gap, std::numeric_limits<scalar>::infinity());
    EXPECT_EQ(get_settings(c.reg).contact.contact_hertz, scalar(30));
    EXPECT_EQ(get_max_linear_speed(c.reg), max_linear_speed_limit);
}

TEST(network_bounds, playout_delays_and_times_out_of_range_are_refused) {
    lone_client c;
    for (double delay : {1e300, -1.0, std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::quiet_NaN(), 1e6}) {
        c.receive({packet::set_playout_delay{delay}});
    }
    EXPECT_EQ(c.rejected().out_of_range, 5u);
    // The client's first update asks for the time (request 1); an answer from a clock no server
    // has is refused, and the client stays unsynchronised.
    c.frame();
    c.receive({packet::time_response{1, 1e300}});
    EXPECT_EQ(c.rejected().out_of_range, 6u);
    c.frame();
    EXPECT_TRUE(std::isfinite(get_network_client_time(c.reg)));
    EXPECT_LT(std::abs(get_network_client_time(c.reg)), 1.0)
        << "the client's time follows its playout delay, which must not have taken a refused value";

    // A playout delay in range is applied: the client's time leads by it.
    c.receive({packet::set_playout_delay{0.1}});
    EXPECT_EQ(c.rejected().out_of_range, 6u);
    c.frame();
    EXPECT_NEAR(get_network_client_time(c.reg) - get_simulation_time(c.reg), 0.1, 1.0 / 60 + 1e-9);
}

// Gives the client one box at (0, 1, 0), made for `remote`, and the server's clock, which is
// the client's own.
void give_box_and_clock(lone_client &c, entity remote) {
    auto body_index = network_index_of<rigidbody_def>(c.reg);
    c.receive({packet::create_entity{
        0, {remote}, {make_pool<rigidbody_def>(body_index, {{0, box_at({0, 1, 0})}})}}});
    ASSERT_TRUE(is_body(c, remote));
    c.frame();
    c.receive({packet::time_response{1, get_simulation_time(c.reg)}});
    c.frame();
}

TEST(network_bounds, snapshots_from_far_in_the_past_or_future_are_refused) {
    lone_client c;
    auto remote = remote_entities(1);
    give_box_and_clock(c, remote[0]);
    auto motion = network_motion{{0, 2, 0}, quaternion_identity, vector3_zero, vector3_zero};
    for (double t : {-1e300, 1e300, -1e12, 1e12, get_network_client_time(c.reg) + 3600}) {
        auto snapshot = packet::registry_snapshot{};
        snapshot.timestamp = t;
        snapshot.entities = remote;
        snapshot.pools.push_back(make_pool<network_motion>(network_index::motion, {{0, motion}}));
        c.receive({std::move(snapshot)});
    }
    EXPECT_EQ(c.rejected().out_of_range, 5u);
    for (int i = 0; i < 10; ++i)
        c.frame();
    auto local = client_local_entity(c.reg, remote[0]);
    EXPECT_TRUE(isfinite(c.reg.get<position>(local)));
    EXPECT_TRUE(std::isfinite(get_network_client_time(c.reg)));
}

// Another client's input, as a server forwards it: a push along x, applied by a step callback.
struct push : network_input {
    vector3 force{vector3_zero};
};
template<typename Archive>
void serialize(Archive &archive, push &p) {
    archive(p.force);
}
void apply_push(registry &registry) {
    for (auto [e, p, v, m] : registry.view<push, linvel, mass>().each())
        v += p.force * (get_fixed_dt(registry) / m.s);
}

// A client whose world knows pushes and has no gravity, with one box made for `remote`.
void give_pushable_box(lone_client &c, entity remote) {
    register_external_components<push>(c.reg);
    register_networked_components<push>(c.reg);
    set_pre_step_callback(c.reg, &apply_push);
    set_gravity(c.reg, vector3_zero);
    give_box_and_clock(c, remote);
}

// A server snapshot at `time` with the box at rest at (0, 3, 0).
packet::registry_snapshot box_at_rest(const std::vector<entity> &remote, double time) {
    auto snapshot = packet::registry_snapshot{};
    snapshot.timestamp = time;
    snapshot.entities = remote;
    auto at_rest = network_motion{{0, 3, 0}, quaternion_identity, vector3_zero, vector3_zero};
    snapshot.pools.push_back(make_pool<network_motion>(network_index::motion, {{0, at_rest}}));
    return snapshot;
}

void run_frames(lone_client &c, int frames) {
    for (int i = 0; i < frames; ++i)
        c.frame();
}

// Forwarded inputs must decode to inputs, at times within the longest playout delay the client
// accepts of the snapshot's; otherwise the whole snapshot is dropped (a time out of range is
// counted). Accepted ones act in the extrapolation only: the client's own copy of the body never
// gets the input.
TEST(network_bounds, forwarded_inputs_must_be_inputs_near_the_snapshot_s_time) {
    lone_client c;
    auto remote = remote_entities(1);
    give_pushable_box(c, remote[0]);
    auto body_index = network_index_of<rigidbody_def>(c.reg);
    auto push_index = network_index_of<push>(c.reg);
    auto local = client_local_entity(c.reg, remote[0]);
    auto snapshot_with = [&](packet::timed_inputs forwarded) {
        auto snapshot = box_at_rest(remote, get_network_client_time(c.reg) - 0.05);
        snapshot.inputs.push_back(std::move(forwarded));
        return snapshot;
    };
    auto pushed = make_pool<push>(push_index, {{0, push{{}, {100, 0, 0}}}});

    // A body instead of an input: dropped, so the body stays where it was made.
    auto time = get_network_client_time(c.reg) - 0.04;
    c.receive(
        {snapshot_with({time, remote, {make_pool<rigidbody_def>(body_index, {{0, box_at({0, 5, 0})}})}})});
    // Times an hour away, and not a time.
    for (auto t : {time + 3600, time - 3600, std::numeric_limits<double>::quiet_NaN()})
        c.receive({snapshot_with({t, remote, {pushed}})});
    EXPECT_EQ(c.rejected().out_of_range, 2u);
    run_frames(c, 10);
    EXPECT_NEAR(c.reg.get<position>(local).y, 1, 1e-4) << "a dropped snapshot moved the body";

    // Accepted: the extrapolation starts at the snapshot's motion and pushes from the input's time.
    c.receive({snapshot_with({get_network_client_time(c.reg) - 0.04, remote, {pushed}})});
    run_frames(c, 10);
    EXPECT_NEAR(c.reg.get<position>(local).y, 3, 1e-3);
    EXPECT_GT(c.reg.get<linvel>(local).x, scalar(1)) << "the forwarded push did not act";
    EXPECT_FALSE(c.reg.all_of<push>(local)) << "a forwarded input was applied to the client's registry";
}

// The server forwards each input in two snapshots: the client keeps it, so that it still acts in
// extrapolations from later snapshots that do not carry it, until a snapshot from after its time
// shows the server applied it.
TEST(network_bounds, forwarded_inputs_are_kept_until_a_snapshot_from_after_their_time) {
    lone_client c;
    auto remote = remote_entities(1);
    give_pushable_box(c, remote[0]);
    auto push_index = network_index_of<push>(c.reg);
    auto local = client_local_entity(c.reg, remote[0]);
    auto now = get_network_client_time(c.reg);
    auto forwarding = box_at_rest(remote, now - 0.1);
    auto input_time = now - 0.02;
    forwarding.inputs.push_back(
        {input_time, remote, {make_pool<push>(push_index, {{0, push{{}, {100, 0, 0}}}})}});
    c.receive({forwarding});
    c.receive({box_at_rest(remote, now - 0.08)});
    run_frames(c, 10);
    EXPECT_GT(c.reg.get<linvel>(local).x, scalar(1)) << "the input an earlier snapshot forwarded did not act";

    // After the input's time, the server's state holds it (here: no push at all), and the client
    // no longer applies it.
    c.receive({box_at_rest(remote, input_time + 0.05)});
    run_frames(c, 10);
    EXPECT_NEAR(c.reg.get<linvel>(local).x, 0, 1e-4) << "an input older than the newest snapshot acted again";
    EXPECT_NEAR(c.reg.get<position>(local).x, 0, 1e-3);
}

// The extrapolation's step count is capped before it is converted: a start far in the past is
// max_extrapolation_steps, not whatever an overflowing conversion gives.
TEST(network_bounds, an_extrapolation_from_far_in_the_past_runs_its_most_steps) {
    registry reg;
    attach(reg, init_config{execution_mode::sequential});
    auto input = extrapolation_input{};
    input.settings = get_settings(reg);
    input.settings.fixed_dt = scalar(1) / 64;
    input.types.types = ensure_network_registry(reg).types;
    auto dt = double(input.settings.fixed_dt);
    // 2^32 steps back: exactly the count that wraps to zero in 32 bits.
    input.start_time = -std::ldexp(1.0, 32) * dt;
    input.end_time = 0;
    auto result = extrapolation_result{};
    run_extrapolation(input, result);
    EXPECT_EQ(result.end_time, input.start_time + max_extrapolation_steps * dt);

    for (double start : {-1e300, -std::numeric_limits<double>::infinity()}) {
        SCOPED_TRACE(start);
        input.start_time = start;
        run_extrapolation(input, result);
        EXPECT_EQ(result.end_time, start + max_extrapolation_steps * dt);
    }
    // Ahead of its end, or not a time: no steps.
    input.start_time = 1e300;
    run_extrapolation(input, result);
    EXPECT_EQ(result.end_time, input.start_time);
    input.start_time = std::numeric_limits<double>::quiet_NaN();
    run_extrapolation(input, result);
    EXPECT_TRUE(std::isnan(result.end_time));
}

TEST(network_bounds, bodies_the_client_cannot_simulate_are_refused) {
    auto bad = std::vector<std::pair<const char *, rigidbody_def>>{};
    auto add = [&](const char *what, auto change) {
        auto def = box_at({0, 1, 0});
        change(def);
        bad.emplace_back(what, def);
    };
    add("position far beyond the snapshots' range", [](auto &d) { d.position = {scalar(1.7e38), 0, 0}; });
    add("position past the snapshots' range", [](auto &d) {
        d.position = {0, 0, -2 * max_quantized_coordinate};
    });
    add("velocity past the snapshots' range", [](auto &d) { d.linvel = {scalar(3e37), 0, 0}; });
    add("shape reaching past the snapshots' range", [](auto &d) {
        d.shape = box_shape{{scalar(1e30), 1, 1}};
    });
    add("huge gravity", [](auto &d) { d.gravity = vector3{0, scalar(-4e34), 0}; });
    add("tiny inertia", [](auto &d) {
        d.inertia = diagonal_matrix(vector3{scalar(1e-13), scalar(1e-13), scalar(1e-13)});
    });
    add("huge inertia", [](auto &d) { d.inertia = diagonal_matrix(vector3{scalar(1e32), 1, 1}); });
    add("non-symmetric inertia", [](auto &d) {
        auto I = matrix3x3_identity;
        I[0][1] = scalar(0.9);
        I[1][0] = scalar(-0.9);
        d.inertia = I;
    });
    add("inertia with positive diagonal and determinant, not positive definite", [](auto &d) {
        d.inertia = matrix3x3{{vector3{1, 2, 2}, vector3{2, 1, 2}, vector3{2, 2, 1}}};
    });
    add("tiny mass", [](auto &d) { d.mass = scalar(1e-30); });

    lone_client c;
    auto remote = remote_entities(bad.size() + 3);
    auto values = std::vector<std::pair<std::size_t, rigidbody_def>>{};
    for (std::size_t i = 0; i < bad.size(); ++i)
        values.emplace_back(i, bad[i].second);
    // Bodies that can be simulated, in the same packet, with a constraint to one of them.
    auto good = bad.size();
    values.emplace_back(good, box_at({2, 1, 0}));
    values.emplace_back(good + 1, box_at({4, 1, 0}));
    auto body_index = network_index_of<rigidbody_def>(c.reg);
    auto create = packet::create_entity{0, remote, {make_pool(body_index, values)}};
    // Constraints to every refused body, and between the good ones.
    auto constraints = std::vector<std::pair<std::size_t, distance_constraint>>{};
    auto tether = distance_constraint{};
    tether.body[0] = remote[good];
    tether.body[1] = remote[good + 1];
    tether.distance = 2;
    constraints.emplace_back(good + 2, tether);
    create.pools.push_back(make_pool(network_index_of<distance_constraint>(c.reg), constraints));
    c.receive({create});

    for (std::size_t i = 0; i < bad.size(); ++i) {
        SCOPED_TRACE(bad[i].first);
        EXPECT_FALSE(is_body(c, remote[i]));
    }
    EXPECT_EQ(c.rejected().invalid_value, bad.size());
    EXPECT_TRUE(is_body(c, remote[good]));
    EXPECT_TRUE(is_body(c, remote[good + 1]));
    EXPECT_TRUE(c.reg.all_of<distance_constraint>(client_local_entity(c.reg, remote[good + 2])));

    // A constraint to a refused body is refused too.
    auto to_refused = tether;
    to_refused.body[1] = remote[0];
    auto more = remote_entities(1);
    auto entities = remote;
    entities.push_back(more[0]);
    c.receive(
        {packet::create_entity{0,
                               entities,
                               {make_pool<distance_constraint>(network_index_of<distance_constraint>(c.reg),
                                                               {{entities.size() - 1, to_refused}})}}});
    EXPECT_FALSE(c.reg.all_of<distance_constraint>(client_local_entity(c.reg, more[0])));
    EXPECT_EQ(c.rejected().invalid_value, bad.size() + 1);

    for (int i = 0; i < 30; ++i)
        c.frame();
    for (auto [e, p, o] : c.reg.view<position, orientation>().each()) {
        EXPECT_TRUE(isfinite(p));
        EXPECT_TRUE(isfinite(o));
    }
}

// A packet must not make a body of a constraint's entity, nor a constraint of a body's: the
// islands would hold one entity as a node and an edge, and destroying it corrupts them.
TEST(network_bounds, bodies_and_constraints_are_not_put_on_entities_with_another_role) {
    lone_client c;
    auto remote = remote_entities(4); // three bodies and a constraint
    auto body_index = network_index_of<rigidbody_def>(c.reg);
    auto distance_index = network_index_of<distance_constraint>(c.reg);
    auto point_index = network_index_of<point_constraint>(c.reg);
    auto tether = distance_constraint{};
    tether.body[0] = remote[0];
    tether.body[1] = remote[1];
    tether.distance = 2;
    c.receive({packet::create_entity{
        0,
        remote,
        {make_pool<rigidbody_def>(body_index,
                                  {{0, box_at({0, 1, 0})}, {1, box_at({2, 1, 0})}, {2, box_at({4, 1, 0})}}),
         make_pool<distance_constraint>(distance_index, {{3, tether}})}}});
    ASSERT_TRUE(is_body(c, remote[2]));
    auto body = client_local_entity(c.reg, remote[2]);
    auto constraint = client_local_entity(c.reg, remote[3]);
    ASSERT_TRUE(c.reg.all_of<distance_constraint>(constraint));
    for (int i = 0; i < 3; ++i)
        c.frame();

    // A constraint for the body's entity, in a snapshot and in a repeated create_entity.
    auto onto_body = tether;
    auto snapshot = packet::registry_snapshot{};
    snapshot.timestamp = 0;
    snapshot.entities = remote;
    snapshot.pools.push_back(make_pool<distance_constraint>(distance_index, {{2, onto_body}}));
    c.receive({snapshot});
    auto point = point_constraint{};
    point.body[0] = remote[0];
    point.body[1] = remote[1];
    c.receive({packet::create_entity{0, remote, {make_pool<point_constraint>(point_index, {{2, point}})}}});
    EXPECT_FALSE((c.reg.any_of<distance_constraint, point_constraint>(body)));
    // A body, and a constraint of another type, for the constraint's entity.
    c.receive({packet::create_entity{0,
                                     remote,
                                     {make_pool<rigidbody_def>(body_index, {{3, box_at({6, 1, 0})}}),
                                      make_pool<point_constraint>(point_index, {{3, point}})}}});
    EXPECT_FALSE(c.reg.all_of<rigidbody_tag>(constraint));
    EXPECT_FALSE(c.reg.all_of<point_constraint>(constraint));
    EXPECT_EQ(c.rejected().conflicting_role, 4u);

    // The same body and constraint sent again are already there: nothing to refuse.
    c.receive({packet::create_entity{0,
                                     remote,
                                     {make_pool<rigidbody_def>(body_index, {{2, box_at({4, 1, 0})}}),
                                      make_pool<distance_constraint>(distance_index, {{3, tether}})}}});
    EXPECT_EQ(c.rejected().conflicting_role, 4u);

    // Destroying them leaves the islands whole.
    for (int i = 0; i < 3; ++i)
        c.frame();
    c.receive({packet::destroy_entity{0, {remote[2], remote[3]}}});
    for (int i = 0; i < 30; ++i)
        c.frame();
    EXPECT_FALSE(c.reg.valid(body));
    EXPECT_FALSE(c.reg.valid(constraint));
    EXPECT_TRUE(is_body(c, remote[0]));
}

} // namespace

namespace bounds_versions {

using namespace edyn;

std::size_t body_count(lone_client &c) { return c.reg.view<rigidbody_tag>().size(); }

// The server reuses an entity's index once it has destroyed it. A create_entity for the new
// version may reach the client before the old one's destroy_entity (or with none: the old one
// may have left the client's interest while the packet saying so was lost): the old local body
// goes, rather than staying as a body no packet can name. A packet for the old version that
// arrives after the new one's is late, and makes nothing.
TEST(network_bounds, a_later_version_of_a_remote_index_replaces_the_earlier_one) {
    lone_client c;
    auto body_index = network_index_of<rigidbody_def>(c.reg);
    registry server;
    auto first = server.create();
    server.destroy(first);
    auto second = server.create();
    ASSERT_EQ(to_index(first), to_index(second));
    ASSERT_NE(first, second);

    c.receive({packet::create_entity{
        0, {first}, {make_pool<rigidbody_def>(body_index, {{0, box_at({0, 1, 0})}})}}});
    ASSERT_TRUE(is_body(c, first));
    auto first_local = client_local_entity(c.reg, first);
    c.frame();

    c.receive({packet::create_entity{
        0, {second}, {make_pool<rigidbody_def>(body_index, {{0, box_at({5, 1, 0})}})}}});
    ASSERT_TRUE(is_body(c, second));
    EXPECT_FALSE(c.reg.valid(first_local)) << "the earlier version's body stayed";
    EXPECT_EQ(client_local_entity(c.reg, first), null);
    EXPECT_EQ(body_count(c), 1u);
    auto second_local = client_local_entity(c.reg, second);
    EXPECT_NEAR(c.reg.get<position>(second_local).x, 5, 1e-4);

    // The earlier version, late: its create_entity and its destroy_entity change nothing.
    c.receive({packet::create_entity{
        0, {first}, {make_pool<rigidbody_def>(body_index, {{0, box_at({0, 1, 0})}})}}});
    c.receive({packet::destroy_entity{0, {first}}});
    for (int i = 0; i < 3; ++i)
        c.frame();
    EXPECT_EQ(client_local_entity(c.reg, second), second_local);
    EXPECT_EQ(client_local_entity(c.reg, first), null);
    EXPECT_TRUE(c.reg.valid(second_local));
    EXPECT_EQ(body_count(c), 1u);

    // Versions wrap round: the version after the last is later than it.
    auto index = to_index(first);
    auto last =
        entity(entity_traits::value_type(index) | (entity_traits::version_mask << entity_traits::index_bits));
    auto wrapped = entity(entity_traits::value_type(index));
    lone_client d;
    d.receive(
        {packet::create_entity{0, {last}, {make_pool<rigidbody_def>(body_index, {{0, box_at({0, 1, 0})}})}}});
    d.receive({packet::create_entity{
        0, {wrapped}, {make_pool<rigidbody_def>(body_index, {{0, box_at({5, 1, 0})}})}}});
    EXPECT_TRUE(is_body(d, wrapped));
    EXPECT_EQ(client_local_entity(d.reg, last), null);
    EXPECT_EQ(body_count(d), 1u);

    // An asset entering under a later version of a body's index takes the body's place too.
    lone_client e;
    e.receive({packet::create_entity{
        0, {first}, {make_pool<rigidbody_def>(body_index, {{0, box_at({0, 1, 0})}})}}});
    ASSERT_EQ(body_count(e), 1u);
    e.receive({packet::entity_entered{{packet::entered_asset{second, 7, {}}}}});
    EXPECT_EQ(body_count(e), 0u);
    auto asset = client_local_entity(e.reg, second);
    ASSERT_NE(asset, null);
    EXPECT_TRUE(e.reg.all_of<asset_ref>(asset));
    EXPECT_EQ(e.reg.get<asset_ref>(asset).id, 7u);

    // A member named by a later version of the asset's own index does not take the asset's
    // place when the program links the asset (which would destroy it while it is linked).
    lone_client f;
    f.receive({packet::entity_entered{{packet::entered_asset{first, 9, {{0, second}}}}}});
    auto own = client_local_entity(f.reg, first);
    ASSERT_NE(own, null);
    auto member = f.reg.create();
    assign_to_asset<>(f.reg, own, 0, member);
    client_link_asset(f.reg, own);
    EXPECT_TRUE(f.reg.valid(own));
    EXPECT_EQ(client_local_entity(f.reg, first), own);
    EXPECT_EQ(client_local_entity(f.reg, second), null);
    f.frame();
}

} // namespace bounds_versions
