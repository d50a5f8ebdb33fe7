#include "edyn/collision/dynamic_tree.hpp"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace {

using edyn::AABB;
using edyn::dynamic_tree;
using edyn::scalar;
using edyn::vector3;
using node_id = dynamic_tree::node_id;

struct random_boxes {
    std::mt19937 rng{1234};

    scalar uniform(scalar lo, scalar hi) { return std::uniform_real_distribution<scalar>(lo, hi)(rng); }

    vector3 point(scalar extent) {
        return {uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)};
    }

    AABB box(scalar extent, scalar max_size) {
        auto c = point(extent);
        auto h = vector3{uniform(scalar(0.05), max_size), uniform(scalar(0.05), max_size),
                         uniform(scalar(0.05), max_size)};
        return {c - h, c + h};
    }
};

// Segment-box test written independently of the tree's slab test: the segment hits the box when
// it starts inside or crosses one of the six faces.
bool segment_hits_box(const AABB &box, const vector3 &p0, const vector3 &p1) {
    if (edyn::contains(box, p0)) return true;
    auto d = p1 - p0;
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0) continue;
        for (auto plane : {box.min[axis], box.max[axis]}) {
            auto t = (plane - p0[axis]) / d[axis];
            if (t < 0 || t > 1) continue;
            auto p = p0 + d * t;
            bool inside = true;
            for (int other = 0; other < 3; ++other) {
                if (other == axis) continue;
                inside = inside && p[other] >= box.min[other] && p[other] <= box.max[other];
            }
            if (inside) return true;
        }
    }
    return false;
}

// Entry fraction of the segment into the box (0 when it starts inside), or a value above 1.
scalar segment_entry_fraction(const AABB &box, const vector3 &p0, const vector3 &p1) {
    if (edyn::contains(box, p0)) return 0;
    auto best = scalar(2);
    auto d = p1 - p0;
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0) continue;
        for (auto plane : {box.min[axis], box.max[axis]}) {
            auto t = (plane - p0[axis]) / d[axis];
            if (t < 0 || t > 1) continue;
            auto p = p0 + d * t;
            bool inside = true;
            for (int other = 0; other < 3; ++other) {
                if (other == axis) continue;
                inside = inside && p[other] >= box.min[other] && p[other] <= box.max[other];
            }
            if (inside) best = std::min(best, t);
        }
    }
    return best;
}

struct tree_fixture {
    dynamic_tree tree;
    // Leaf id -> tight AABB for every live leaf.
    std::vector<std::pair<node_id, AABB>> leaves;

    std::set<node_id> brute_query(const AABB &q) const {
        std::set<node_id> out;
        for (auto &[id, box] : leaves) {
            if (edyn::intersect(tree.get_fat_aabb(id), q)) out.insert(id);
        }
        return out;
    }

    std::set<node_id> tree_query(const AABB &q) const {
        std::set<node_id> out;
        tree.query(
            q, [&](node_id id) { EXPECT_TRUE(out.insert(id).second) << "leaf " << id << " reported twice"; });
        return out;
    }
};

TEST(dynamic_tree_test, rejects_bad_margin) {
    EXPECT_THROW(dynamic_tree(scalar(-0.1)), std::invalid_argument);
    EXPECT_THROW(dynamic_tree{std::numeric_limits<scalar>::quiet_NaN()}, std::invalid_argument);
    EXPECT_NO_THROW(dynamic_tree(scalar(0)));
}

TEST(dynamic_tree_test, empty_tree) {
    dynamic_tree tree;
    EXPECT_EQ(tree.height(), -1);
    EXPECT_EQ(tree.size(), 0u);
    EXPECT_EQ(tree.validate(), "");
    int calls = 0;
    tree.query({{-10, -10, -10}, {10, 10, 10}}, [&](node_id) { ++calls; });
    tree.raycast({-10, 0, 0}, {10, 0, 0}, [&](node_id) { ++calls; });
    tree.query_pairs([&](node_id, node_id) { ++calls; });
    EXPECT_EQ(calls, 0);
}

TEST(dynamic_tree_test, fat_aabb_has_margin) {
    dynamic_tree tree(scalar(0.25));
    auto id = tree.create({{0, 0, 0}, {1, 2, 3}}, edyn::make_entity(7, 0));
    auto fat = tree.get_fat_aabb(id);
    EXPECT_NEAR(fat.min.x, -0.25, 1e-6);
    EXPECT_NEAR(fat.max.z, 3.25, 1e-6);
    EXPECT_EQ(tree.get_payload(id), edyn::make_entity(7, 0));
    EXPECT_EQ(tree.height(), 0);
}

TEST(dynamic_tree_test, move_reinserts_only_when_leaving_fat_aabb) {
    dynamic_tree tree(scalar(0.1));
    auto id = tree.create({{0, 0, 0}, {1, 1, 1}}, edyn::make_entity(1, 0));
    tree.create({{5, 5, 5}, {6, 6, 6}}, edyn::make_entity(2, 0));

    // Inside the margin: no change.
    EXPECT_FALSE(tree.move(id, {{0.05f, 0, 0}, {1.05f, 1, 1}}));
    EXPECT_NEAR(tree.get_fat_aabb(id).max.x, 1.1, 1e-6);

    // Leaves it: reinserted around the new box.
    EXPECT_TRUE(tree.move(id, {{0.2f, 0, 0}, {1.2f, 1, 1}}));
    EXPECT_NEAR(tree.get_fat_aabb(id).min.x, 0.1, 1e-6);
    EXPECT_NEAR(tree.get_fat_aabb(id).max.x, 1.3, 1e-6);
    EXPECT_EQ(tree.validate(), "");
}

// needs_move() answers what move() would do, without doing it.
TEST(dynamic_tree_test, needs_move_tells_whether_move_reinserts) {
    dynamic_tree tree(scalar(0.1));
    std::mt19937 rng(5);
    std::uniform_real_distribution<scalar> step(-0.06f, 0.06f);
    std::vector<std::pair<dynamic_tree::node_id, AABB>> leaves;
    for (int i = 0; i < 50; ++i) {
        AABB box{{scalar(i), 0, 0}, {scalar(i) + 1, 1, 1}};
        leaves.emplace_back(tree.create(box, edyn::make_entity(std::uint32_t(i + 1), 0)), box);
    }
    int reinserted = 0, kept = 0;
    for (int round = 0; round < 20; ++round) {
        for (auto &[id, box] : leaves) {
            vector3 d{step(rng), step(rng), step(rng)};
            // Now and then a leaf stops, so that its fat box is too large for its motion.
            if (round % 5 == 4) d = edyn::vector3_zero;
            box = {box.min + d, box.max + d};
            auto fat = tree.get_fat_aabb(id);
            auto needs = tree.needs_move(id, box, d);
            EXPECT_EQ(tree.get_fat_aabb(id).min, fat.min) << "needs_move changed the tree";
            EXPECT_EQ(tree.move(id, box, d), needs);
            (needs ? reinserted : kept) += 1;
        }
    }
    EXPECT_GT(reinserted, 100);
    EXPECT_GT(kept, 100);
    EXPECT_EQ(tree.validate(), "");
}

TEST(dynamic_tree_test, move_stretches_along_displacement) {
    dynamic_tree tree(scalar(0.1));
    auto id = tree.create({{0, 0, 0}, {1, 1, 1}}, edyn::make_entity(1, 0));
    // A slow body's box reaches ahead by displacement_multiplier of its steps.
    ASSERT_TRUE(tree.move(id, {{0.5f, 0, 0}, {1.5f, 1, 1}}, {0.02f, 0, -0.01f}));
    auto fat = tree.get_fat_aabb(id);
    auto k = dynamic_tree::displacement_multiplier;
    EXPECT_NEAR(fat.max.x, 1.6 + 0.02 * k, 1e-5);
    EXPECT_NEAR(fat.min.x, 0.4, 1e-5);
    EXPECT_NEAR(fat.min.z, -0.1 - 0.01 * k, 1e-5);
    EXPECT_NEAR(fat.max.z, 1.1, 1e-5);

    // A fast one's by its step and max_lookahead more.
    ASSERT_TRUE(tree.move(id, {{3, 0, 0}, {4, 1, 1}}, {2, 0, 0}));
    EXPECT_NEAR(tree.get_fat_aabb(id).max.x, 4.1 + 2 + dynamic_tree::max_lookahead, 1e-5);

    // Once the body stops, the stretched box is far too large and gets shrunk back.
    EXPECT_TRUE(tree.move(id, {{3, 0, 0}, {4, 1, 1}}, {0, 0, 0}));
    EXPECT_NEAR(tree.get_fat_aabb(id).max.x, 4.1, 1e-5);
}

// A box that reaches past what the motion asks for by less than the slack is kept: a body
// slowing down a little is not reinserted; one that reaches further is.
TEST(dynamic_tree_test, a_slowing_leaf_is_shrunk_only_past_the_slack) {
    const auto margin = scalar(0.1);
    const auto slack = dynamic_tree::shrink_slack;
    const auto k = dynamic_tree::displacement_multiplier;
    dynamic_tree tree(margin);
    auto id = tree.create({{0, 0, 0}, {1, 1, 1}}, edyn::make_entity(1, 0));
    tree.create({{9, 9, 9}, {10, 10, 10}}, edyn::make_entity(2, 0));

    // Moved out of its fat box at speed d: stretched by k d along +x; then the body stops.
    auto near = slack / k * scalar(0.9);
    auto box = AABB{{2, 0, 0}, {3, 1, 1}};
    ASSERT_TRUE(tree.move(id, box, {near, 0, 0}));
    EXPECT_NEAR(tree.get_fat_aabb(id).max.x, 3 + margin + k * near, 1e-5);
    EXPECT_FALSE(tree.needs_move(id, box, edyn::vector3_zero)) << "within the slack";
    EXPECT_FALSE(tree.oversized(id, box, edyn::vector3_zero, 0));

    auto far = slack / k * scalar(1.1);
    box = AABB{{5, 0, 0}, {6, 1, 1}};
    ASSERT_TRUE(tree.move(id, box, {far, 0, 0}));
    EXPECT_TRUE(tree.covers(id, box, edyn::vector3_zero, 0));
    EXPECT_TRUE(tree.oversized(id, box, edyn::vector3_zero, 0));
    EXPECT_TRUE(tree.move(id, box, edyn::vector3_zero)) << "past the slack";
    EXPECT_FALSE(tree.oversized(id, box, edyn::vector3_zero, 0));
    EXPECT_NEAR(tree.get_fat_aabb(id).max.x, 6 + margin, 1e-5);
    EXPECT_EQ(tree.validate(), "");
}

// The fat box must hold the coming step's motion, not only the body as it is now: a leaf well
// inside its box is reinserted once its expected displacement or turning reaches out of it.
TEST(dynamic_tree_test, a_leaf_is_reinserted_when_its_box_does_not_hold_its_next_step) {
    const auto margin = scalar(0.03);
    dynamic_tree tree(margin);
    AABB box{{0, 0, 0}, {1, 1, 1}};
    auto id = tree.create(box, edyn::make_entity(1, 0));

    // Moving 2 cm or turning by 2 cm a step fits in the 3 cm margin; 5 cm does not.
    EXPECT_TRUE(tree.covers(id, box, {0, scalar(-0.02), 0}, 0));
    EXPECT_TRUE(tree.covers(id, box, edyn::vector3_zero, scalar(0.02)));
    EXPECT_FALSE(tree.covers(id, box, {0, scalar(-0.05), 0}, 0));
    EXPECT_FALSE(tree.covers(id, box, edyn::vector3_zero, scalar(0.05)));
    EXPECT_FALSE(tree.covers(id, box, {0, scalar(-0.02), 0}, scalar(0.02)))
        << "together they reach 4 cm down";
    EXPECT_FALSE(tree.move(id, box, {0, scalar(-0.02), 0}, 0));

    // Reinserted, it is stretched along the motion by the multiplier and grown by the reach
    // where the reach exceeds the margin.
    ASSERT_TRUE(tree.move(id, box, {0, scalar(-0.05), 0}, scalar(0.04)));
    auto fat = tree.get_fat_aabb(id);
    auto ahead =
        std::min((dynamic_tree::displacement_multiplier - 1) * scalar(0.05), dynamic_tree::max_lookahead);
    EXPECT_NEAR(fat.min.y, -0.04 - 0.05 - ahead, 1e-6);
    EXPECT_NEAR(fat.max.y, 1.04, 1e-6);
    EXPECT_NEAR(fat.min.x, -0.04, 1e-6);
    EXPECT_TRUE(tree.covers(id, box, {0, scalar(-0.05), 0}, scalar(0.04)));
    EXPECT_EQ(tree.validate(), "");
}

TEST(dynamic_tree_test, random_operations_match_brute_force) {
    random_boxes rnd;
    tree_fixture f;
    std::uint32_t next_entity = 0;

    for (int batch = 0; batch < 60; ++batch) {
        for (int op = 0; op < 40; ++op) {
            auto choice = rnd.uniform(0, 1);
            if (choice < 0.45f || f.leaves.size() < 5) {
                auto box = rnd.box(20, 1);
                auto id = f.tree.create(box, edyn::make_entity(next_entity++, 0));
                f.leaves.emplace_back(id, box);
            } else if (choice < 0.8f) {
                auto idx = static_cast<std::size_t>(rnd.uniform(0, scalar(f.leaves.size()) - scalar(0.01)));
                auto &[id, box] = f.leaves[idx];
                auto delta = rnd.point(scalar(0.3));
                box = {box.min + delta, box.max + delta};
                f.tree.move(id, box, delta);
                ASSERT_TRUE(edyn::contains(f.tree.get_fat_aabb(id), box));
            } else {
                auto idx = static_cast<std::size_t>(rnd.uniform(0, scalar(f.leaves.size()) - scalar(0.01)));
                f.tree.destroy(f.leaves[idx].first);
                f.leaves.erase(f.leaves.begin() + static_cast<std::ptrdiff_t>(idx));
            }
        }

        ASSERT_EQ(f.tree.validate(), "") << "after batch " << batch;
        ASSERT_EQ(f.tree.size(), f.leaves.size());

        for (int q = 0; q < 10; ++q) {
            auto query = rnd.box(20, 4);
            ASSERT_EQ(f.tree_query(query), f.brute_query(query)) << "batch " << batch;
        }

        for (int r = 0; r < 10; ++r) {
            auto p0 = rnd.point(25);
            auto p1 = rnd.point(25);
            std::set<node_id> expected, got;
            for (auto &[id, box] : f.leaves) {
                if (segment_hits_box(f.tree.get_fat_aabb(id), p0, p1)) expected.insert(id);
            }
            f.tree.raycast(p0, p1, [&](node_id id) { got.insert(id); });
            ASSERT_EQ(got, expected) << "batch " << batch;
        }
    }
}

TEST(dynamic_tree_test, raycast_shrinking_finds_closest) {
    random_boxes rnd;
    tree_fixture f;
    for (std::uint32_t i = 0; i < 500; ++i) {
        auto box = rnd.box(20, 1);
        f.leaves.emplace_back(f.tree.create(box, edyn::make_entity(i, 0)), box);
    }

    int rays_with_hits = 0;
    for (int r = 0; r < 200; ++r) {
        auto p0 = rnd.point(25);
        auto p1 = rnd.point(25);
        // Closest hit on the tight boxes by brute force.
        auto expected = scalar(2);
        for (auto &[id, box] : f.leaves)
            expected = std::min(expected, segment_entry_fraction(box, p0, p1));

        auto best = scalar(2);
        int calls = 0;
        f.tree.raycast(p0, p1, [&](node_id id) {
            ++calls;
            auto it = std::find_if(f.leaves.begin(), f.leaves.end(), [&](auto &l) { return l.first == id; });
            auto t = segment_entry_fraction(it->second, p0, p1);
            if (t <= 1) best = std::min(best, t);
            // Keep going when the exact box was missed; zero would stop the query.
            return t <= 1 ? std::max(t, scalar(1e-6)) : scalar(1);
        });
        if (expected <= 1) ++rays_with_hits;
        EXPECT_NEAR(best, expected, 1e-5) << "ray " << r << " after " << calls << " callbacks";
    }
    EXPECT_GT(rays_with_hits, 20);
}

TEST(dynamic_tree_test, raycast_stops_when_callback_returns_zero) {
    dynamic_tree tree;
    for (std::uint32_t i = 0; i < 10; ++i) {
        auto x = scalar(i) * 3;
        tree.create({{x, -1, -1}, {x + 1, 1, 1}}, edyn::make_entity(i, 0));
    }
    int calls = 0;
    tree.raycast({-5, 0, 0}, {40, 0, 0}, [&](node_id) {
        ++calls;
        return scalar(0);
    });
    EXPECT_EQ(calls, 1);

    calls = 0;
    tree.query({{-100, -100, -100}, {100, 100, 100}}, [&](node_id) { return ++calls < 3; });
    EXPECT_EQ(calls, 3);
}

TEST(dynamic_tree_test, axis_parallel_raycast) {
    dynamic_tree tree(0);
    auto id = tree.create({{0, 0, 0}, {1, 1, 1}}, edyn::make_entity(0, 0));
    std::vector<node_id> hits;
    auto collect = [&](node_id n) { hits.push_back(n); };
    tree.raycast({0.5f, 0.5f, -2}, {0.5f, 0.5f, 2}, collect);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0], id);
    hits.clear();
    tree.raycast({1.5f, 0.5f, -2}, {1.5f, 0.5f, 2}, collect);
    EXPECT_TRUE(hits.empty());
    // Ends before reaching the box.
    tree.raycast({0.5f, 0.5f, -2}, {0.5f, 0.5f, -0.5f}, collect);
    EXPECT_TRUE(hits.empty());
}

std::set<std::pair<node_id, node_id>> brute_pairs(const dynamic_tree &a, const std::vector<node_id> &ids_a,
                                                  const dynamic_tree &b, const std::vector<node_id> &ids_b,
                                                  bool same) {
    std::set<std::pair<node_id, node_id>> out;
    for (std::size_t i = 0; i < ids_a.size(); ++i) {
        for (std::size_t j = same ? i + 1 : 0; j < ids_b.size(); ++j) {
            if (!edyn::intersect(a.get_fat_aabb(ids_a[i]), b.get_fat_aabb(ids_b[j]))) continue;
            auto p = std::pair{ids_a[i], ids_b[j]};
            if (same && p.first > p.second) std::swap(p.first, p.second);
            out.insert(p);
        }
    }
    return out;
}

TEST(dynamic_tree_test, pair_queries_match_brute_force) {
    random_boxes rnd;
    dynamic_tree a, b;
    std::vector<node_id> ids_a, ids_b;
    for (std::uint32_t i = 0; i < 400; ++i)
        ids_a.push_back(a.create(rnd.box(8, 1), edyn::make_entity(i, 0)));
    for (std::uint32_t i = 0; i < 150; ++i)
        ids_b.push_back(b.create(rnd.box(8, 2), edyn::make_entity(i, 0)));
    // Some removals so that node ids are not contiguous.
    for (int i = 0; i < 50; ++i) {
        a.destroy(ids_a.back());
        ids_a.pop_back();
    }

    std::set<std::pair<node_id, node_id>> self;
    a.query_pairs([&](node_id x, node_id y) {
        EXPECT_NE(x, y);
        auto p = std::pair{std::min(x, y), std::max(x, y)};
        EXPECT_TRUE(self.insert(p).second) << "pair reported twice";
    });
    auto expected_self = brute_pairs(a, ids_a, a, ids_a, true);
    EXPECT_GT(expected_self.size(), 50u);
    EXPECT_EQ(self, expected_self);

    std::set<std::pair<node_id, node_id>> cross;
    a.query_pairs(b, [&](node_id x, node_id y) { EXPECT_TRUE(cross.insert({x, y}).second); });
    auto expected_cross = brute_pairs(a, ids_a, b, ids_b, false);
    EXPECT_GT(expected_cross.size(), 50u);
    EXPECT_EQ(cross, expected_cross);
}

TEST(dynamic_tree_test, height_is_logarithmic_for_sorted_insertion) {
    dynamic_tree tree;
    constexpr int n = 4096;
    std::vector<node_id> ids;
    for (int i = 0; i < n; ++i) {
        auto x = scalar(i) * scalar(1.5);
        ids.push_back(tree.create({{x, 0, 0}, {x + 1, 1, 1}}, edyn::make_entity(std::uint32_t(i), 0)));
    }
    ASSERT_EQ(tree.validate(), "");
    // A perfectly balanced tree has height 12; rotations keep it within a small factor.
    EXPECT_LE(tree.height(), 2 * 12) << "height " << tree.height();
    EXPECT_GE(tree.height(), 12);

    // Removing every other leaf in order must keep it shallow too.
    for (int i = 0; i < n; i += 2)
        tree.destroy(ids[std::size_t(i)]);
    ASSERT_EQ(tree.validate(), "");
    EXPECT_LE(tree.height(), 2 * 11) << "height " << tree.height();

    // And a diagonal line of boxes, sorted along all axes at once.
    dynamic_tree diagonal;
    for (int i = 0; i < n; ++i) {
        auto x = scalar(i);
        diagonal.create({{x, x, x}, {x + 1, x + 1, x + 1}}, edyn::make_entity(std::uint32_t(i), 0));
    }
    ASSERT_EQ(diagonal.validate(), "");
    EXPECT_LE(diagonal.height(), 2 * 12) << "height " << diagonal.height();
}

TEST(dynamic_tree_test, node_storage_is_reused) {
    dynamic_tree tree;
    random_boxes rnd;
    std::vector<node_id> ids;
    for (std::uint32_t i = 0; i < 100; ++i)
        ids.push_back(tree.create(rnd.box(10, 1), edyn::make_entity(i, 0)));
    for (auto id : ids)
        tree.destroy(id);
    EXPECT_EQ(tree.validate(), "");
    EXPECT_EQ(tree.height(), -1);
    // All 199 nodes (100 leaves, 99 internal) came back to the free list: new leaves reuse them.
    for (std::uint32_t i = 0; i < 100; ++i) {
        auto id = tree.create(rnd.box(10, 1), edyn::make_entity(i, 0));
        EXPECT_LT(id, 199);
    }
    EXPECT_EQ(tree.validate(), "");
}

} // namespace
