#include "support/solver_bodies.hpp"
#include <algorithm>
#include <cstdlib>
#include <edyn/constraints/contact_order.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <utility>
#include <vector>

using namespace edyn;

namespace {

using contact = std::pair<solver_body_index, solver_body_index>;

std::vector<std::uint32_t> order_of(contact_order &ordering, const std::vector<solver_body> &bodies,
                                    const std::vector<contact> &contacts) {
    ordering.reset(bodies);
    for (auto [a, b] : contacts)
        ordering.add(a, b);
    auto sorted = ordering.sorted();
    return {sorted.begin(), sorted.end()};
}

// Each body's depth by repeated relaxation (not breadth first): 0 for bodies that do not move,
// else one more than the least depth of a neighbour; -1 where no resting body is reached.
std::vector<int> depths_by_relaxation(const std::vector<solver_body> &bodies,
                                      const std::vector<contact> &contacts) {
    std::vector<int> depth(bodies.size(), -1);
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (!moves(bodies[i])) depth[i] = 0;
    for (bool changed = true; changed;) {
        changed = false;
        for (auto [a, b] : contacts) {
            for (auto [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
                if (depth[from] < 0 || !moves(bodies[to])) continue;
                if (depth[to] < 0 || depth[from] + 1 < depth[to]) {
                    depth[to] = depth[from] + 1;
                    changed = true;
                }
            }
        }
    }
    return depth;
}

} // namespace

TEST(contact_order, a_stack_is_solved_from_the_ground_up_whatever_the_order_added) {
    // Bodies 1 to 5 stacked on the ground (body 0), added top first.
    auto bodies = test::make_solver_bodies(5);
    std::vector<contact> contacts{{5, 4}, {4, 3}, {3, 2}, {2, 1}, {1, 0}};
    contact_order ordering;
    EXPECT_EQ(order_of(ordering, bodies, contacts), (std::vector<std::uint32_t>{4, 3, 2, 1, 0}));
}

TEST(contact_order, a_layer_rests_before_its_neighbours_push_on_each_other) {
    // Bodies 1, 2 and 3 side by side on the ground, touching each other; body 4 on 1 and 2;
    // body 5 beside 4 on 3.
    auto bodies = test::make_solver_bodies(5);
    std::vector<contact> contacts{
        {1, 2}, // 0: side, depth 1
        {4, 1}, // 1: depth 1 to 2
        {0, 1}, // 2: ground
        {2, 3}, // 3: side, depth 1
        {4, 5}, // 4: side, depth 2
        {3, 0}, // 5: ground
        {2, 4}, // 6: depth 1 to 2
        {0, 2}, // 7: ground
        {5, 3}, // 8: depth 1 to 2
    };
    contact_order ordering;
    // The ground's contacts; those from the first layer up to the second, then those within the
    // first layer; then those within the second; each group in the order added.
    EXPECT_EQ(order_of(ordering, bodies, contacts), (std::vector<std::uint32_t>{2, 5, 7, 1, 6, 8, 0, 3, 4}));
}

TEST(contact_order, kinematic_bodies_carry_like_the_ground_and_a_clump_in_mid_air_comes_last) {
    // Body 4 is kinematic. Bodies 1 and 2 touch each other in mid-air; body 3 rests on body 4.
    auto bodies = test::make_solver_bodies(3, 1);
    std::vector<contact> contacts{{1, 2}, {3, 4}, {2, 1}};
    contact_order ordering;
    EXPECT_EQ(order_of(ordering, bodies, contacts), (std::vector<std::uint32_t>{1, 0, 2}));
}

TEST(contact_order, random_heaps_are_ordered_by_depth_groups_and_keep_the_order_added_within_each) {
    contact_order ordering; // reused, as a world reuses it from step to step
    for (unsigned seed = 1; seed <= 20; ++seed) {
        std::mt19937 rng(seed);
        auto num_moving = std::uniform_int_distribution<std::size_t>(1, 120)(rng);
        auto bodies = test::make_solver_bodies(num_moving, seed % 3);
        std::uniform_int_distribution<solver_body_index> body(0, solver_body_index(bodies.size() - 1));
        std::vector<contact> contacts;
        auto num_contacts = std::uniform_int_distribution<std::size_t>(0, 3 * num_moving)(rng);
        while (contacts.size() < num_contacts) {
            auto a = body(rng), b = body(rng);
            // Two bodies that do not move have no contact to solve.
            if (a != b && (moves(bodies[a]) || moves(bodies[b]))) contacts.push_back({a, b});
        }

        auto depth = depths_by_relaxation(bodies, contacts);
        auto group = [&](std::uint32_t k) {
            auto da = depth[contacts[k].first], db = depth[contacts[k].second];
            if (da < 0) return std::numeric_limits<int>::max();
            EXPECT_LE(std::abs(da - db), 1);
            return 2 * std::min(da, db) + (da == db ? 1 : 0);
        };
        std::vector<std::uint32_t> expected(contacts.size());
        for (std::uint32_t k = 0; k < contacts.size(); ++k)
            expected[k] = k;
        std::stable_sort(expected.begin(), expected.end(),
                         [&](std::uint32_t x, std::uint32_t y) { return group(x) < group(y); });
        ASSERT_EQ(order_of(ordering, bodies, contacts), expected) << "seed " << seed;
    }
}

TEST(contact_order, no_contacts_give_an_empty_order) {
    auto bodies = test::make_solver_bodies(3);
    contact_order ordering;
    EXPECT_TRUE(order_of(ordering, bodies, {}).empty());
}
