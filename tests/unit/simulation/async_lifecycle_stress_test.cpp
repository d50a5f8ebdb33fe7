// The asynchronous mode's lifecycle under stress: bodies and constraints made and destroyed at
// random while the worker steps, attach/detach cycles with work in flight, and a registry
// dropped without detach while the worker is busy.
#include "unit/simulation/async_lifecycle_support.hpp"

using namespace edyn;
using namespace edyn::async_lifecycle_support;

// 10,000 bodies (dynamic, static and kinematic spheres and boxes) and 2,000 constraints (point,
// distance, hinge, null, between random existing bodies) are made and destroyed at random in
// batches, with an update() between batches that sends them while the worker steps the
// previous ones; only at the end is the worker waited for. The main registry must then hold
// exactly the bodies and constraints the test thinks exist, every constraint joining live
// bodies, every manifold between live bodies (or gone after one more wait), no NaN, and the
// worker must have the same bodies.
TEST_F(async_lifecycle,
       random_bodies_and_constraints_made_and_destroyed_while_stepping_leave_main_consistent) {
    const int total_bodies = 10000;
    const int total_constraints = 2000;
    start();

    std::mt19937 rng(20240607);
    auto uniform = [&](double lo, double hi) {
        return scalar(std::uniform_real_distribution<double>(lo, hi)(rng));
    };
    auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };

    struct joint {
        entity e;
        entity body[2];
    };
    std::vector<entity> bodies;
    std::vector<joint> joints;
    int made_bodies = 0, made_joints = 0, batches = 0, explicit_steps = 0;
    // Constraints still valid on the main side right after one of their bodies was destroyed.
    int joints_left_behind = 0;

    auto make_random_body = [&] {
        rigidbody_def def;
        auto roll = uniform(0, 1);
        def.kind = roll < 0.8   ? rigidbody_kind::rb_dynamic
                   : roll < 0.9 ? rigidbody_kind::rb_static
                                : rigidbody_kind::rb_kinematic;
        def.position = {uniform(-40, 40), uniform(0.5, 15), uniform(-40, 40)};
        def.orientation = quaternion_axis_angle(
            normalize(vector3{uniform(-1, 1), uniform(-1, 1), uniform(0.1, 1)}), uniform(0, 3));
        if (uniform(0, 1) < 0.5)
            def.shape = sphere_shape{uniform(0.2, 0.6)};
        else
            def.shape = box_shape{uniform(0.2, 0.6), uniform(0.2, 0.6), uniform(0.2, 0.6)};
        if (def.kind == rigidbody_kind::rb_kinematic) def.linvel = {uniform(-1, 1), 0, uniform(-1, 1)};
        bodies.push_back(make_rigidbody(reg, def));
        ++made_bodies;
    };

    auto destroy_random_body = [&] {
        auto i = pick(bodies.size());
        auto e = bodies[i];
        bodies[i] = bodies.back();
        bodies.pop_back();
        reg.destroy(e);
        for (std::size_t j = 0; j < joints.size();) {
            if (joints[j].body[0] == e || joints[j].body[1] == e) {
                if (reg.valid(joints[j].e)) ++joints_left_behind;
                joints[j] = joints.back();
                joints.pop_back();
            } else {
                ++j;
            }
        }
    };

    auto make_random_joint = [&] {
        auto a = bodies[pick(bodies.size())], b = bodies[pick(bodies.size())];
        if (a == b) return;
        // Pivots at the midpoint as the main side sees the bodies now, so that the joint starts
        // nearly satisfied.
        vector3 pa = reg.get<position>(a), pb = reg.get<position>(b);
        quaternion qa = reg.get<orientation>(a), qb = reg.get<orientation>(b);
        auto mid = (pa + pb) * scalar(0.5);
        auto local_a = rotate(conjugate(qa), mid - pa);
        auto local_b = rotate(conjugate(qb), mid - pb);
        // The main side sees moving bodies some steps late: rows built on such poses between a
        // body and two immovable ones could be impossible to satisfy (a fight for the solver,
        // not what this test is about). So joints with rows join two dynamic bodies, and null
        // constraints join any two.
        auto type = pick(4);
        if (!reg.all_of<dynamic_tag>(a) || !reg.all_of<dynamic_tag>(b)) type = 3;
        entity e;
        switch (type) {
        case 0:
            e = make_constraint<point_constraint>(reg, a, b, [&](point_constraint &c) {
                c.pivot[0] = local_a;
                c.pivot[1] = local_b;
            });
            break;
        case 1:
            e = make_constraint<distance_constraint>(
                reg, a, b, [&](distance_constraint &c) { c.distance = distance(pa, pb); });
            break;
        case 2:
            e = make_constraint<hinge_constraint>(reg, a, b, [&](hinge_constraint &c) {
                c.pivot[0] = local_a;
                c.pivot[1] = local_b;
                c.set_axes(rotate(conjugate(qa), vector3_z), rotate(conjugate(qb), vector3_z));
            });
            break;
        default:
            e = make_constraint<null_constraint>(reg, a, b);
            break;
        }
        joints.push_back({e, {a, b}});
        ++made_joints;
    };

    auto destroy_random_joint = [&] {
        auto i = pick(joints.size());
        reg.destroy(joints[i].e);
        joints[i] = joints.back();
        joints.pop_back();
    };

    while (made_bodies < total_bodies || made_joints < total_constraints) {
        // About 60 bodies made, 25 destroyed, 12 constraints made and 4 destroyed per batch,
        // interleaved: some die in the batch that made them, before the worker ever saw them.
        for (int op = 0; op < 100; ++op) {
            auto roll = uniform(0, 100);
            if (roll < 59) {
                if (made_bodies < total_bodies) make_random_body();
            } else if (roll < 84) {
                if (bodies.size() > 2) destroy_random_body();
            } else if (roll < 96) {
                if (made_joints < total_constraints && bodies.size() >= 2) make_random_joint();
            } else if (!joints.empty()) {
                destroy_random_joint();
            }
        }
        t += frame;
        update(reg, t);
        ++batches;
        // A worker that falls behind drops time (and so steps): these steps it runs anyway.
        if (batches % 8 == 0) {
            step_simulation(reg);
            ++explicit_steps;
        }
    }
    wait_for_simulation(reg);

    EXPECT_EQ(joints_left_behind, 0) << "constraints not destroyed on the main side with their body";

    // Bodies: exactly those the test made and did not destroy, with finite transforms.
    EXPECT_EQ(reg.view<rigidbody_tag>().size(), bodies.size() + 1) << "rigid bodies on the main side (ground "
                                                                      "included) vs the test's count";
    int missing = 0, not_finite = 0;
    for (auto e : bodies) {
        if (!reg.valid(e) || !reg.all_of<rigidbody_tag>(e)) ++missing;
    }
    reg.view<rigidbody_tag, position, orientation>().each(
        [&](entity e, const position &p, const orientation &q) {
            bool finite = isfinite(p) && isfinite(q);
            if (auto *pp = reg.try_get<present_position>(e)) finite = finite && isfinite(*pp);
            if (auto *pq = reg.try_get<present_orientation>(e)) finite = finite && isfinite(*pq);
            if (!finite) ++not_finite;
        });
    EXPECT_EQ(missing, 0) << "bodies the test kept that are gone from the main registry";
    EXPECT_EQ(not_finite, 0) << "bodies with a NaN or infinite position or orientation";

    // Constraints: exactly the test's, each joining two live bodies.
    EXPECT_EQ(count_constraints(reg), joints.size()) << "constraint components vs the test's count";
    int joints_missing = 0, joints_dangling = 0;
    for (auto &j : joints) {
        if (!reg.valid(j.e)) ++joints_missing;
    }
    auto check_bodies = [&](auto &&view) {
        view.each([&](entity, const auto &con) {
            for (auto body : con.body) {
                if (!reg.valid(body) || !reg.all_of<rigidbody_tag>(body)) ++joints_dangling;
            }
        });
    };
    check_bodies(reg.view<point_constraint>());
    check_bodies(reg.view<distance_constraint>());
    check_bodies(reg.view<hinge_constraint>());
    check_bodies(reg.view<null_constraint>());
    EXPECT_EQ(joints_missing, 0) << "constraints the test kept that are gone from the main registry";
    EXPECT_EQ(joints_dangling, 0) << "constraint bodies that are not live rigid bodies";

    // Manifolds: between live bodies, or gone after one more wait.
    std::vector<entity> stale;
    reg.view<contact_manifold>().each([&](entity m, const contact_manifold &manifold) {
        if (!reg.valid(manifold.body[0]) || !reg.valid(manifold.body[1])) stale.push_back(m);
    });
    wait_for_simulation(reg);
    int stale_left = 0, dangling_manifolds = 0;
    for (auto m : stale) {
        if (reg.valid(m)) ++stale_left;
    }
    reg.view<contact_manifold>().each([&](entity, const contact_manifold &manifold) {
        if (!reg.valid(manifold.body[0]) || !reg.valid(manifold.body[1])) ++dangling_manifolds;
    });
    EXPECT_EQ(stale_left, 0) << "of " << stale.size()
                             << " manifolds with a destroyed body after the first wait";
    EXPECT_EQ(dangling_manifolds, 0) << "manifolds with a destroyed body after two waits";
    EXPECT_GT(reg.view<contact_manifold>().size(), 0u)
        << "the bodies touched nothing: the scene tests no contacts";

    // The worker has exactly the same bodies.
    auto expected = bodies;
    std::sort(expected.begin(), expected.end());
    auto in_worker = worker_bodies(reg, ground);
    std::vector<entity> only_main, only_worker;
    std::set_difference(expected.begin(), expected.end(), in_worker.begin(), in_worker.end(),
                        std::back_inserter(only_main));
    std::set_difference(in_worker.begin(), in_worker.end(), expected.begin(), expected.end(),
                        std::back_inserter(only_worker));
    EXPECT_EQ(in_worker.size(), expected.size()) << "bodies in the worker vs on the main side";
    EXPECT_EQ(only_main.size(), 0u) << "bodies on the main side that the worker lacks";
    EXPECT_EQ(only_worker.size(), 0u) << "bodies in the worker that the main side destroyed";

    // The steps asked for with step_simulation() at least (updates add those their time asks
    // for, less what a worker left behind drops).
    EXPECT_GE(get_step_count(reg), std::uint64_t(explicit_steps))
        << "steps run for " << batches << " updates";
}

namespace {

// A component of the program's own, which detach() leaves alone.
struct cycle_mark {
    int cycle;
};

} // namespace

// attach() and detach() 1,000 times, each cycle with steps queued
// and not waited for, and bodies and a constraint made (and a body destroyed) after the last
// update, so that they are still in flight when detach() stops the worker. Each detach must
// leave the program's entities and components and no edyn component; every hundredth cycle
// waits and checks that bodies made after and before attach() (which the simulation adopts)
// were simulated.
TEST_F(async_lifecycle, detach_and_attach_repeatedly_with_bodies_in_flight) {
    const int cycles = 1000;
    int early_bodies_not_simulated = 0;
    for (int cycle = 0; cycle < cycles; ++cycle) {
        // Made before attach(): the simulation adopts it.
        auto early = make_box(reg, {0, 3, 0});
        attach(reg, async_config());
        ground = make_ground(reg);
        auto a = make_box(reg, {2, 1, 0});
        auto b = make_ball(reg, {3, 1, 0}, scalar(0.25));
        auto ab =
            make_constraint<distance_constraint>(reg, a, b, [](distance_constraint &c) { c.distance = 1; });
        reg.emplace<cycle_mark>(a, cycle);
        update(reg, t);
        t += frame;
        update(reg, t);
        step_simulation(reg);
        if (cycle % 100 == 0) {
            wait_for_simulation(reg);
            ASSERT_GE(get_step_count(reg), 1u) << "cycle " << cycle;
            ASSERT_LT(pos(b).y, 1) << "cycle " << cycle << ": a body made after attach() did not fall";
            if (!(pos(early).y < 3)) ++early_bodies_not_simulated;
        }
        // In flight: made or destroyed after the last batch was sent.
        auto late = make_ball(reg, {0, 5, 0}, scalar(0.25));
        auto late_joint = make_constraint<hinge_constraint>(reg, late, a);
        reg.destroy(b);
        ASSERT_FALSE(reg.valid(ab)) << "cycle " << cycle << ": the constraint outlived its body";
        ASSERT_TRUE(reg.valid(late_joint)) << "cycle " << cycle;

        detach(reg);
        ASSERT_FALSE(is_attached(reg)) << "cycle " << cycle;
        ASSERT_EQ(reg.view<rigidbody_tag>().size(), 0u) << "cycle " << cycle;
        ASSERT_EQ(reg.view<position>().size(), 0u) << "cycle " << cycle;
        ASSERT_EQ(reg.view<contact_manifold>().size(), 0u) << "cycle " << cycle;
        ASSERT_EQ(count_constraints(reg), 0u) << "cycle " << cycle;
        ASSERT_TRUE(reg.valid(a) && reg.valid(late) && reg.valid(early)) << "cycle " << cycle;
        ASSERT_TRUE(reg.all_of<cycle_mark>(a)) << "cycle " << cycle;
        ASSERT_EQ(reg.get<cycle_mark>(a).cycle, cycle);

        // The program clears its entities before the next cycle.
        std::vector<entity> entities;
        reg.each([&](entity e) { entities.push_back(e); });
        for (auto e : entities)
            reg.destroy(e);
    }

    EXPECT_EQ(early_bodies_not_simulated, 0)
        << "of " << (cycles + 99) / 100
        << " checks, a body made before attach() had not moved after the steps";

    // Attached once more, the simulation works as before.
    start();
    auto box = make_box(reg, {0, 3, 0});
    run_frames(120);
    EXPECT_NEAR(pos(box).y, 0.5, 0.02) << "a box dropped after the cycles rests on the ground";
}

// A falling body made static while the worker runs a step the main side has not seen stops in
// the worker after that step and stays there, and the main side shows it where the worker has
// it (a ray cast in the worker hits its top where the main side has it). Made dynamic again,
// it falls to the ground.
TEST_F(async_lifecycle,
       a_registry_destroyed_without_detach_while_the_worker_is_busy_neither_crashes_nor_hangs) {
    const int rounds = 20;
    for (int round = 0; round < rounds; ++round) {
        std::uint64_t steps_seen = 0;
        auto seconds = run_with_deadline(
            [&] {
                // Outlives the registry: the worker may still hold a delegate that points to it.
                reply_catcher catcher;
                registry doomed;
                attach(doomed, async_config());
                make_ground(doomed);
                std::vector<entity> column;
                for (int x = 0; x < 10; ++x) {
                    for (int z = 0; z < 10; ++z) {
                        entity below = null;
                        for (int y = 0; y < 4; ++y) {
                            auto e = make_box(doomed, {scalar(x * 1.5), scalar(0.5 + y), scalar(z * 1.5)});
                            if (below != null && (x + z) % 3 == 0)
                                make_constraint<point_constraint>(doomed, below, e, [](point_constraint &c) {
                                    c.pivot[0] = {0, 0.5, 0};
                                    c.pivot[1] = {0, -0.5, 0};
                                });
                            below = e;
                        }
                    }
                }
                if (round % 2 == 1) {
                    callback_calls = 0;
                    throw_on_call = 1;
                    set_pre_step_callback(doomed, &throwing_pre_step);
                }
                update(doomed, 0);
                wait_for_simulation(doomed);
                steps_seen = get_step_count(doomed);
                // Ten steps due at once, then more asked for, none waited for.
                update(doomed, 10 * frame);
                for (int i = 0; i < 5; ++i)
                    step_simulation(doomed);
                raycast_async(doomed, {0, 10, 0}, {0, -10, 0},
                              raycast_delegate_type{connect_arg<&reply_catcher::on_ray>, catcher});
                try {
                    update(doomed, 20 * frame);
                } catch (const std::runtime_error &) {
                    // The callback's exception, if the worker got that far.
                }
                // Never sent.
                for (int i = 0; i < 50; ++i)
                    make_box(doomed, {scalar(i), 10, -5});
            },
            std::chrono::seconds(60), "destroying an attached registry");
        EXPECT_EQ(steps_seen, 0u) << "round " << round;
        EXPECT_LT(seconds, 20.0) << "round " << round << ": seconds to build, run and destroy";
    }
    throw_on_call = -1;
}
