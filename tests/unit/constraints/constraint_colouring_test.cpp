#include "support/one_range_at_a_time.hpp"
#include "support/solver_bodies.hpp"
#include <algorithm>
#include <cstring>
#include <edyn/constraints/constraint_colouring.hpp>
#include <edyn/constraints/contact_solver.hpp>
#include <edyn/parallel/task_scheduler.hpp>
#include <gtest/gtest.h>
#include <map>
#include <random>
#include <utility>
#include <vector>

using namespace edyn;

namespace {

struct pair {
    solver_body_index a, b;
};

std::vector<pair> random_pairs(std::size_t count, std::size_t num_bodies, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<solver_body_index> body(0, solver_body_index(num_bodies - 1));
    std::vector<pair> pairs;
    while (pairs.size() < count) {
        auto a = body(rng), b = body(rng);
        if (a != b) pairs.push_back({a, b});
    }
    return pairs;
}

} // namespace

TEST(constraint_colouring,
     no_two_constraints_of_a_colour_share_a_moving_body_and_shared_ones_keep_their_order) {
    auto bodies = test::make_solver_bodies(200, 2);
    auto pairs = random_pairs(2000, bodies.size(), 3);
    constraint_colouring colouring;
    colouring.reset(bodies);
    std::vector<std::uint32_t> colour;
    for (auto [a, b] : pairs)
        colour.push_back(colouring.assign(a, b));

    for (std::size_t i = 0; i < pairs.size(); ++i) {
        for (std::size_t j = i + 1; j < pairs.size(); ++j) {
            auto shares = [&](solver_body_index x) {
                return moves(bodies[x]) && (x == pairs[j].a || x == pairs[j].b);
            };
            if (shares(pairs[i].a) || shares(pairs[i].b)) {
                // Sharing a moving body: a later colour, so the earlier one is solved first.
                ASSERT_LT(colour[i], colour[j]) << "constraints " << i << " and " << j;
            }
        }
    }
    EXPECT_EQ(colouring.num_colours(), *std::max_element(colour.begin(), colour.end()) + 1);
}

TEST(constraint_colouring, bodies_that_do_not_move_order_nothing) {
    auto bodies = test::make_solver_bodies(3, 2);
    solver_body_index kinematic = 4;
    constraint_colouring colouring;
    colouring.reset(bodies);
    // Three boxes on the ground and against a kinematic wall: every constraint is free to go
    // first, as none shares a body that moves with another.
    EXPECT_EQ(colouring.assign(1, static_solver_body), 0u);
    EXPECT_EQ(colouring.assign(static_solver_body, 2), 0u);
    EXPECT_EQ(colouring.assign(3, kinematic), 0u);
    EXPECT_EQ(colouring.assign(kinematic, static_solver_body), 0u);
    // A chain over them runs in its order.
    EXPECT_EQ(colouring.assign(1, 2), 1u);
    EXPECT_EQ(colouring.assign(2, 3), 2u);
    EXPECT_EQ(colouring.assign(3, 1), 3u);
    EXPECT_EQ(colouring.num_colours(), 4u);
}

TEST(constraint_colouring, places_each_colour_together_in_the_order_asked) {
    auto bodies = test::make_solver_bodies(5, 2);
    constraint_colouring colouring;
    colouring.reset(bodies);
    std::uint32_t points[] = {4, 2, 3, 1, 4};
    std::uint32_t colour[] = {colouring.assign(1, 2, 4), colouring.assign(2, 3, 2), colouring.assign(4, 5, 3),
                              colouring.assign(3, static_solver_body, 1), colouring.assign(5, 1, 4)};
    EXPECT_EQ(std::vector<std::uint32_t>(std::begin(colour), std::end(colour)),
              (std::vector<std::uint32_t>{0, 1, 0, 2, 1}));

    std::vector<std::uint32_t> begin{99}; // overwritten
    colouring.colour_ranges(begin);
    EXPECT_EQ(begin, (std::vector<std::uint32_t>{0, 2, 4, 5}));
    std::vector<constraint_colouring::place> places;
    for (int k = 0; k < 5; ++k)
        places.push_back(colouring.next_place(colour[k], points[k]));
    // Colour 0: constraints 0 and 2 (4 + 3 points); colour 1: 1 and 4 (2 + 4); colour 2: 3.
    std::pair<std::uint32_t, std::uint32_t> expected[] = {{0, 0}, {2, 7}, {1, 4}, {4, 13}, {3, 9}};
    for (int k = 0; k < 5; ++k) {
        EXPECT_EQ(places[k].constraint, expected[k].first) << "constraint " << k;
        EXPECT_EQ(places[k].first_point, expected[k].second) << "constraint " << k;
    }
}

namespace {

// A random pile-like contact set: each contact joins two bodies (half of them the static one, as
// A or as B, some a kinematic one) with up to four points, slightly overlapping, bodies moving at
// random.
struct random_contacts {
    std::vector<solver_body> bodies;
    contact_solver_set contacts;
};

random_contacts make_contacts(std::size_t num_contacts, unsigned seed, bool coloured) {
    random_contacts set;
    set.bodies = test::make_solver_bodies(num_contacts / 3, 2);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<scalar> unit(-1, 1);
    for (std::size_t i = 1; i < set.bodies.size(); ++i) {
        set.bodies[i].linvel = {unit(rng), unit(rng), unit(rng)};
        set.bodies[i].angvel = {unit(rng), unit(rng), unit(rng)};
    }
    auto pairs = random_pairs(num_contacts, set.bodies.size(), seed);
    // A quarter of the contacts against the static body as B and a quarter as A, as on the
    // ground: their rows leave the static side out (fixed_side).
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (k % 4 == 1 && pairs[k].a != static_solver_body) pairs[k].b = static_solver_body;
        if (k % 4 == 2 && pairs[k].b != static_solver_body) pairs[k].a = static_solver_body;
    }

    constraint_colouring colouring;
    colouring.reset(set.bodies);
    std::vector<std::uint32_t> colours, sizes;
    for (auto [a, b] : pairs) {
        sizes.push_back(1 + rng() % 4);
        colours.push_back(colouring.assign(a, b, sizes.back()));
    }
    std::vector<std::uint32_t> order(pairs.size());
    if (coloured) {
        colouring.colour_ranges(set.contacts.colour_begin);
        for (std::size_t k = 0; k < pairs.size(); ++k)
            order[colouring.next_place(colours[k], sizes[k]).constraint] = std::uint32_t(k);
    } else {
        for (std::size_t k = 0; k < pairs.size(); ++k)
            order[k] = std::uint32_t(k);
    }
    // Built in the solving order, each contact from its own seed so both sets hold the same ones.
    for (auto k : order) {
        std::mt19937 contact_rng(seed * 7919u + k);
        std::uniform_real_distribution<scalar> u(-1, 1);
        auto normal = normalize(vector3{scalar(0.3) * u(contact_rng), 1, scalar(0.3) * u(contact_rng)});
        contact_solver_constraint c;
        c.body[0] = pairs[k].a;
        c.body[1] = pairs[k].b;
        c.friction = scalar(0.6) + scalar(0.4) * u(contact_rng);
        c.normal = normal;
        // Most contacts have plain friction and are solved in bundles; some have spinning
        // and rolling friction or a material spring, and are solved one at a time.
        if (k % 5 == 1) {
            c.spin_friction = scalar(0.01);
            c.roll_friction = scalar(0.01);
            c.num_roll_axes = 2;
            plane_space(normal, c.roll_axis[0], c.roll_axis[1]);
        } else if (k % 7 == 2) {
            c.stiffness = 1e4;
        }
        auto *points = set.contacts.add(c, sizes[k]);
        for (std::uint32_t i = 0; i < sizes[k]; ++i) {
            auto &p = points[i];
            p.rA = {u(contact_rng) / 2, scalar(-0.5), u(contact_rng) / 2};
            p.rB = {u(contact_rng) / 2, scalar(0.5), u(contact_rng) / 2};
            p.normal = normal;
            p.adjusted_separation = scalar(0.01) * u(contact_rng) - dot(p.normal, p.rA - p.rB);
            // Surfaces slid by up to 2 mm from where they stuck, for the friction anchors.
            vector3 slid{scalar(0.002) * u(contact_rng), 0, scalar(0.002) * u(contact_rng)};
            p.adjusted_anchor_gap = slid - (p.rA - p.rB);
            p.normal_impulse = scalar(0.1) * (u(contact_rng) + 1);
        }
    }
    return set;
}

// Two sub-steps of the contact passes the step runs.
void solve(random_contacts &set, task_scheduler *scheduler) {
    contact_solver_settings settings;
    auto h = scalar(1) / scalar(360);
    prepare_contacts(set.contacts, set.bodies, scheduler);
    stage_queue queue;
    for (int i = 0; i < 2; ++i) {
        warm_start_contacts(set.contacts, set.bodies, queue);
        solve_contacts(set.contacts, set.bodies, h, 0, settings, true, queue);
        solve_contacts(set.contacts, set.bodies, h, 0, settings, false, queue);
        accumulate_contact_impulses(set.contacts, queue);
    }
    queue.run(scheduler);
    unpack_contact_impulses(set.contacts, scheduler);
}

bool same_bits(const std::vector<solver_body> &a, const std::vector<solver_body> &b) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::memcmp(&a[i].linvel, &b[i].linvel, sizeof(vector3)) != 0 ||
            std::memcmp(&a[i].angvel, &b[i].angvel, sizeof(vector3)) != 0)
            return false;
    }
    return true;
}

// Every contact's impulses and totals, found by its bodies (the two sets order them apart).
bool same_impulses(const random_contacts &x, const random_contacts &y) {
    auto key = [](const contact_solver_constraint &c) { return std::pair(c.body[0], c.body[1]); };
    std::map<std::pair<solver_body_index, solver_body_index>, std::vector<const contact_solver_constraint *>>
        of_y;
    for (auto &c : y.contacts.constraints)
        of_y[key(c)].push_back(&c);
    std::map<std::pair<solver_body_index, solver_body_index>, std::size_t> used;
    for (auto &c : x.contacts.constraints) {
        auto &d = *of_y.at(key(c)).at(used[key(c)]++);
        if (c.num_points != d.num_points ||
            std::memcmp(&c.spin_impulse, &d.spin_impulse, sizeof(scalar)) != 0)
            return false;
        for (std::uint32_t i = 0; i < c.num_points; ++i) {
            auto &p = x.contacts.points[c.first_point + i];
            auto &q = y.contacts.points[d.first_point + i];
            auto &t = x.contacts.totals[c.first_point + i];
            auto &u = y.contacts.totals[d.first_point + i];
            if (std::memcmp(&p.normal_impulse, &q.normal_impulse, sizeof(scalar)) != 0 ||
                std::memcmp(&p.tangent_impulse, &q.tangent_impulse, sizeof(p.tangent_impulse)) != 0 ||
                std::memcmp(&t.normal_impulse, &u.normal_impulse, sizeof(scalar)) != 0 ||
                std::memcmp(&t.tangent_impulse, &u.tangent_impulse, sizeof(t.tangent_impulse)) != 0)
                return false;
        }
    }
    return true;
}

} // namespace

// The reason for the colouring: solved colour by colour on any number of threads, the contacts
// give bit for bit what solving them one after another in the order they were found gives.
TEST(constraint_colouring, coloured_contacts_solve_to_the_same_bits_as_in_order_on_any_thread_count) {
    auto in_order = make_contacts(3000, 11, false);
    solve(in_order, nullptr);
    ASSERT_NE(in_order.bodies[1].linvel, make_contacts(3000, 11, false).bodies[1].linvel) << "nothing solved";

    for (unsigned threads : {1u, 2u, 4u}) {
        task_scheduler scheduler(threads);
        auto coloured = make_contacts(3000, 11, true);
        ASSERT_GT(coloured.contacts.colour_begin.size(), 2u);
        solve(coloured, &scheduler);
        EXPECT_GT(coloured.contacts.bundles.size(), 1200u / contact_bundle_lanes)
            << "the plain contacts go " << contact_bundle_lanes << " at a time";
        EXPECT_GT(coloured.contacts.singles.size(), 500u) << "the others one at a time";
        EXPECT_TRUE(same_bits(in_order.bodies, coloured.bodies)) << threads << " threads";
        EXPECT_TRUE(same_impulses(in_order, coloured)) << threads << " threads";
    }
}

// Every colour is one task whose ranges wait for the earlier colours' work: whichever range runs
// first claims that work, so a scheduler that runs the ranges one at a time, in any order,
// neither stalls the passes nor changes a bit.
TEST(constraint_colouring, colours_solve_to_the_same_bits_on_a_scheduler_that_runs_one_range_at_a_time) {
    auto in_order = make_contacts(3000, 11, false);
    solve(in_order, nullptr);

    test::one_range_at_a_time program;
    task_scheduler scheduler(program.hooks());
    auto coloured = make_contacts(3000, 11, true);
    solve(coloured, &scheduler);
    EXPECT_GT(program.tasks, 0u);
    EXPECT_TRUE(same_bits(in_order.bodies, coloured.bodies));
    EXPECT_TRUE(same_impulses(in_order, coloured));
}
