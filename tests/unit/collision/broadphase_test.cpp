#include "edyn/collision/broadphase.hpp"
#include "edyn/collision/contact_manifold.hpp"
#include "edyn/collision/should_collide.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using edyn::AABB;
using edyn::broadphase;
using edyn::contact_manifold;
using edyn::entity;
using edyn::scalar;
using edyn::vector3;

AABB cube(vector3 center, scalar half = scalar(0.5)) {
    return {center - edyn::vector3_one * half, center + edyn::vector3_one * half};
}

std::pair<std::uint32_t, std::uint32_t> ordered(entity a, entity b) {
    auto x = edyn::to_integral(a), y = edyn::to_integral(b);
    return {std::min(x, y), std::max(x, y)};
}

struct broadphase_fixture : ::testing::Test {
    edyn::registry registry;
    broadphase bp{scalar(0.1)};

    entity make_body(const AABB &box, bool is_static = false) {
        auto e = registry.create();
        registry.emplace<AABB>(e, box);
        bp.insert(e, box, is_static);
        return e;
    }

    void move_to(entity e, const AABB &box) { registry.replace<AABB>(e, box); }

    std::size_t manifold_components() const { return registry.storage<contact_manifold>().size(); }
};

TEST_F(broadphase_fixture, overlapping_pair_gets_one_manifold) {
    auto a = make_body(cube({0, 0, 0}));
    auto b = make_body(cube({0.9f, 0, 0}));
    auto far = make_body(cube({5, 0, 0}));
    EXPECT_EQ(bp.num_manifolds(), 0u);

    bp.update(registry);
    ASSERT_EQ(bp.num_manifolds(), 1u);
    EXPECT_EQ(manifold_components(), 1u);
    auto m = bp.get_manifold(a, b);
    ASSERT_TRUE(registry.valid(m));
    EXPECT_EQ(bp.get_manifold(b, a), m);
    EXPECT_TRUE(bp.get_manifold(a, far) == edyn::null);
    auto &manifold = registry.get<contact_manifold>(m);
    EXPECT_EQ(manifold.body[0], a);
    EXPECT_EQ(manifold.body[1], b);
    EXPECT_EQ(manifold.num_points, 0u);

    for (int i = 0; i < 3; ++i) {
        // Moving within the margin changes nothing.
        move_to(b, cube({0.9f + scalar(0.02) * scalar(i), 0, 0}));
        bp.update(registry);
        EXPECT_EQ(bp.num_manifolds(), 1u);
        EXPECT_EQ(manifold_components(), 1u);
        EXPECT_EQ(bp.get_manifold(a, b), m);
    }
}

TEST_F(broadphase_fixture, manifold_lives_while_fat_aabbs_overlap) {
    auto a = make_body(cube({0, 0, 0}));
    // Tight boxes 15 cm apart, fat boxes (10 cm margin each) overlapping.
    auto b = make_body(cube({1.15f, 0, 0}));
    bp.update(registry);
    auto m = bp.get_manifold(a, b);
    ASSERT_TRUE(registry.valid(m));

    // Its fat box still holds it and another step like this one: no reinsertion, the pair stays.
    move_to(b, cube({1.19f, 0, 0}));
    bp.update(registry);
    EXPECT_EQ(bp.get_manifold(a, b), m);
    EXPECT_NEAR(bp.get_fat_aabb(b).min.x, 0.55, 1e-5);

    // Out of its fat box: reinserted at [0.9, ...], past a's fat box (max 0.6).
    move_to(b, cube({1.5f, 0, 0}));
    bp.update(registry);
    EXPECT_GT(bp.get_fat_aabb(b).min.x, bp.get_fat_aabb(a).max.x);
    EXPECT_TRUE(bp.get_manifold(a, b) == edyn::null);
    EXPECT_FALSE(registry.valid(m));
    EXPECT_EQ(manifold_components(), 0u);

    // Back again: a new manifold.
    move_to(b, cube({1.1f, 0, 0}));
    bp.update(registry);
    auto m2 = bp.get_manifold(a, b);
    EXPECT_TRUE(registry.valid(m2));
    EXPECT_EQ(manifold_components(), 1u);
}

// An estimator that gives the bodies listed in `motion` their listed motion and leaves the others
// to the broadphase's own guess.
struct fixed_motions {
    std::vector<std::pair<entity, edyn::proxy_motion_estimate>> motion;
    bool operator()(const edyn::registry &, entity e, const AABB &, edyn::proxy_motion_estimate &out) const {
        for (auto &[body, estimate] : motion) {
            if (body != e) continue;
            out = estimate;
            return true;
        }
        return false;
    }
};

// Two new proxies 15 cm apart with 3 cm margins: their fat boxes lie apart, yet one closing in
// at 10 cm a step has a manifold before the step it may touch in, and a turning one reaching
// 13 cm out too. A proxy of the same box moving as fast but without an estimate has no history to
// go by, and gets none.
TEST(broadphase_test, a_proxy_covers_its_estimated_motion_from_its_first_update) {
    for (int mode = 0; mode < 3; ++mode) {
        edyn::registry registry;
        broadphase bp{scalar(0.03)};
        auto make_body = [&](const AABB &box) {
            auto e = registry.create();
            registry.emplace<AABB>(e, box);
            bp.insert(e, box, false);
            return e;
        };
        auto a = make_body(cube({0, 0, 0}));
        auto b = make_body(cube({1.15f, 0, 0}));
        fixed_motions motions;
        if (mode == 0) motions.motion.push_back({a, {{scalar(0.1), 0, 0}, 0}});
        if (mode == 1) motions.motion.push_back({a, {edyn::vector3_zero, scalar(0.13)}});
        bp.update(registry, nullptr,
                  edyn::motion_estimator{edyn::connect_arg<&fixed_motions::operator()>, motions});
        EXPECT_EQ(bp.get_manifold(a, b) != edyn::null, mode < 2) << "mode " << mode;
    }
}

// A proxy that sped up and stopped keeps its stretched box for shrink_patience updates (a
// swinging body slows down at each end of its swing), then is shrunk to its margin.
TEST(broadphase_test, an_oversized_box_is_shrunk_once_it_stays_oversized) {
    edyn::registry registry;
    broadphase bp{scalar(0.03)};
    auto e = registry.create();
    registry.emplace<AABB>(e, cube({0, 0, 0}));
    bp.insert(e, cube({0, 0, 0}), false);
    fixed_motions motions;
    motions.motion.push_back({e, {{scalar(0.5), 0, 0}, 0}});
    auto estimator = edyn::motion_estimator{edyn::connect_arg<&fixed_motions::operator()>, motions};
    bp.update(registry, nullptr, estimator);
    EXPECT_NEAR(bp.get_fat_aabb(e).max.x, 0.53 + 0.5 + edyn::dynamic_tree::max_lookahead, 1e-5);

    motions.motion[0].second = {};
    for (int i = 0; i < broadphase::shrink_patience; ++i) {
        bp.update(registry, nullptr, estimator);
        ASSERT_GT(bp.get_fat_aabb(e).max.x, scalar(1)) << "update " << i;
    }
    bp.update(registry, nullptr, estimator);
    EXPECT_NEAR(bp.get_fat_aabb(e).max.x, 0.53, 1e-5);
}

TEST_F(broadphase_fixture, static_pairs) {
    auto ground = make_body({{-10, -1, -10}, {10, 0, 10}}, true);
    auto wall = make_body({{-10, -1, -10}, {-9, 5, 10}}, true);
    auto box = make_body(cube({-9, 0.4f, 0}));
    bp.update(registry);

    EXPECT_TRUE(bp.get_manifold(ground, wall) == edyn::null);
    EXPECT_TRUE(registry.valid(bp.get_manifold(ground, box)));
    EXPECT_TRUE(registry.valid(bp.get_manifold(wall, box)));
    EXPECT_EQ(bp.num_manifolds(), 2u);

    // A static body added later pairs with the dynamic one only.
    auto ramp = make_body(cube({-9, 0.5f, 0}, 2), true);
    bp.update(registry);
    EXPECT_TRUE(registry.valid(bp.get_manifold(ramp, box)));
    EXPECT_TRUE(bp.get_manifold(ramp, ground) == edyn::null);
    EXPECT_EQ(bp.num_manifolds(), 3u);

    // Static proxies are not moved by update(), whatever their AABB component says.
    move_to(ground, {{100, 100, 100}, {101, 101, 101}});
    bp.update(registry);
    EXPECT_TRUE(registry.valid(bp.get_manifold(ground, box)));
}

TEST_F(broadphase_fixture, filtered_pairs_get_no_manifold) {
    auto a = make_body(cube({0, 0, 0}));
    auto b = make_body(cube({0.5f, 0, 0}));
    auto c = make_body(cube({0, 0.5f, 0}));
    auto d = make_body(cube({0, 0, 0.5f}));
    registry.emplace<edyn::collision_filter>(a, edyn::collision_filter{1ull, ~(1ull << 1)});
    registry.emplace<edyn::collision_filter>(b, edyn::collision_filter{1ull << 1, ~1ull});
    edyn::exclude_collision(registry, a, c);

    for (int i = 0; i < 3; ++i)
        bp.update(registry);
    EXPECT_TRUE(bp.get_manifold(a, b) == edyn::null);
    EXPECT_TRUE(bp.get_manifold(a, c) == edyn::null);
    EXPECT_TRUE(registry.valid(bp.get_manifold(a, d)));
    EXPECT_TRUE(registry.valid(bp.get_manifold(b, c)));
    EXPECT_TRUE(registry.valid(bp.get_manifold(b, d)));
    EXPECT_TRUE(registry.valid(bp.get_manifold(c, d)));
    EXPECT_EQ(bp.num_manifolds(), 4u);
    EXPECT_EQ(manifold_components(), 4u);
}

struct body_tag {};

int custom_calls = 0;
bool only_tagged(const edyn::registry &registry, entity a, entity b) {
    ++custom_calls;
    return registry.all_of<body_tag>(a) && registry.all_of<body_tag>(b);
}

TEST_F(broadphase_fixture, custom_should_collide_is_asked_once_per_new_pair) {
    edyn::set_should_collide(registry, &only_tagged);
    custom_calls = 0;
    auto a = make_body(cube({0, 0, 0}));
    auto b = make_body(cube({0.5f, 0, 0}));
    auto c = make_body(cube({0, 0.5f, 0}));
    registry.emplace<body_tag>(a);
    registry.emplace<body_tag>(b);

    bp.update(registry);
    EXPECT_EQ(custom_calls, 3);
    EXPECT_TRUE(registry.valid(bp.get_manifold(a, b)));
    EXPECT_TRUE(bp.get_manifold(a, c) == edyn::null);
    EXPECT_TRUE(bp.get_manifold(b, c) == edyn::null);

    // Nothing moved: no pair is new, nobody is asked.
    bp.update(registry);
    EXPECT_EQ(custom_calls, 3);
}

bool never(const edyn::registry &, entity, entity) { return false; }

TEST_F(broadphase_fixture, a_new_should_collide_is_asked_about_every_overlapping_pair) {
    auto a = make_body(cube({0, 0, 0}));
    auto b = make_body(cube({0.5f, 0, 0}));
    auto c = make_body(cube({0, 0.5f, 0}));
    auto ground = make_body(cube({0, -0.5f, 0}), true);
    bp.update(registry);
    ASSERT_EQ(bp.num_manifolds(), 6u);
    auto ab = bp.get_manifold(a, b);

    // Nothing moves. The new function keeps a-b (the same manifold) and drops the rest.
    registry.emplace<body_tag>(a);
    registry.emplace<body_tag>(b);
    edyn::set_should_collide(registry, &only_tagged);
    custom_calls = 0;
    bp.update(registry);
    EXPECT_EQ(bp.num_manifolds(), 1u);
    EXPECT_EQ(manifold_components(), 1u);
    EXPECT_EQ(bp.get_manifold(a, b), ab);
    EXPECT_EQ(bp.get_manifold(c, ground), entity{edyn::null});
    EXPECT_GE(custom_calls, 6);
    // The same function again asks nobody.
    edyn::set_should_collide(registry, &only_tagged);
    custom_calls = 0;
    bp.update(registry);
    EXPECT_EQ(custom_calls, 0);

    edyn::set_should_collide(registry, &never);
    bp.update(registry);
    EXPECT_EQ(bp.num_manifolds(), 0u);

    // Back to the default: the pairs both functions refused are found again, static ones too.
    edyn::reset_should_collide(registry);
    bp.update(registry);
    EXPECT_EQ(bp.num_manifolds(), 6u);
    EXPECT_EQ(manifold_components(), 6u);
    EXPECT_TRUE(registry.valid(bp.get_manifold(c, ground)));
}

TEST_F(broadphase_fixture, refilter_applies_filter_changes) {
    auto a = make_body(cube({0, 0, 0}));
    auto b = make_body(cube({0.5f, 0, 0}));
    bp.update(registry);
    auto m = bp.get_manifold(a, b);
    ASSERT_TRUE(registry.valid(m));

    // A mask of zero: a collides with nothing.
    registry.emplace<edyn::collision_filter>(a, edyn::collision_filter{1ull, 0ull});
    bp.refilter(registry, a);
    EXPECT_FALSE(registry.valid(m));
    EXPECT_EQ(bp.num_manifolds(), 0u);
    bp.update(registry);
    EXPECT_EQ(bp.num_manifolds(), 0u);

    registry.remove<edyn::collision_filter>(a);
    bp.update(registry);
    EXPECT_EQ(bp.num_manifolds(), 0u) << "a rejected pair is not asked again until refilter or motion";
    bp.refilter(registry, a);
    bp.update(registry);
    EXPECT_TRUE(registry.valid(bp.get_manifold(a, b)));
}

TEST_F(broadphase_fixture, refiltered_body_moving_away_loses_its_manifold) {
    auto a = make_body(cube({0, 0, 0}));
    auto b = make_body(cube({0.5f, 0, 0}));
    bp.update(registry);
    auto m = bp.get_manifold(a, b);
    ASSERT_TRUE(registry.valid(m));

    // Queued for a pair search by refilter, then moved away in the same update.
    bp.refilter(registry, b);
    move_to(b, cube({5, 0, 0}));
    bp.update(registry);
    EXPECT_FALSE(registry.valid(m));
    EXPECT_EQ(bp.num_manifolds(), 0u);
}

TEST_F(broadphase_fixture, remove_destroys_manifolds) {
    auto a = make_body(cube({0, 0, 0}));
    auto b = make_body(cube({0.5f, 0, 0}));
    auto c = make_body(cube({-0.5f, 0, 0}));
    auto ground = make_body({{-5, -1, -5}, {5, -0.45f, 5}}, true);
    bp.update(registry);
    ASSERT_EQ(bp.num_manifolds(), 6u); // ab ac bc (touching counts) and each with the ground
    auto ab = bp.get_manifold(a, b);
    auto bc = bp.get_manifold(b, c);
    auto a_ground = bp.get_manifold(a, ground);

    bp.remove(registry, a);
    EXPECT_FALSE(bp.contains(a));
    EXPECT_FALSE(registry.valid(ab));
    EXPECT_FALSE(registry.valid(a_ground));
    EXPECT_TRUE(registry.valid(bc));
    EXPECT_EQ(bp.num_manifolds(), 3u);
    EXPECT_EQ(manifold_components(), 3u);
    EXPECT_THROW(bp.remove(registry, a), std::invalid_argument);

    bp.remove(registry, ground);
    EXPECT_EQ(bp.num_manifolds(), 1u);
    bp.update(registry);
    EXPECT_EQ(bp.num_manifolds(), 1u);
    EXPECT_EQ(bp.get_manifold(b, c), bc);

    // Removed before its first update: never pairs.
    auto d = make_body(cube({0.5f, 0, 0}));
    bp.remove(registry, d);
    bp.update(registry);
    EXPECT_EQ(bp.num_manifolds(), 1u);
}

TEST_F(broadphase_fixture, manifold_destroyed_by_user_is_forgotten) {
    auto a = make_body(cube({0, 0, 0}));
    auto b = make_body(cube({0.5f, 0, 0}));
    bp.update(registry);
    registry.destroy(bp.get_manifold(a, b));
    move_to(b, cube({5, 0, 0}));
    bp.update(registry);
    EXPECT_EQ(bp.num_manifolds(), 0u);
}

TEST_F(broadphase_fixture, insert_validates) {
    auto e = registry.create();
    EXPECT_THROW(bp.insert(edyn::null, cube({0, 0, 0}), false), std::invalid_argument);
    EXPECT_THROW(bp.insert(e, {{0, 0, 0}, {1, -1, 1}}, false), std::invalid_argument);
    auto nan = std::numeric_limits<scalar>::quiet_NaN();
    EXPECT_THROW(bp.insert(e, {{0, 0, 0}, {1, nan, 1}}, false), std::invalid_argument);
    EXPECT_FALSE(bp.contains(e));
    bp.insert(e, cube({0, 0, 0}), false);
    EXPECT_TRUE(bp.contains(e));
    EXPECT_THROW(bp.insert(e, cube({0, 0, 0}), true), std::invalid_argument);
    EXPECT_EQ(bp.num_proxies(), 1u);
    auto other = registry.create();
    EXPECT_THROW(bp.refilter(registry, other), std::invalid_argument);
    EXPECT_THROW((void)bp.get_fat_aabb(other), std::invalid_argument);

    try {
        bp.insert(other, {{0, 2, 0}, {1, 1, 1}}, false);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument &error) {
        EXPECT_NE(std::string(error.what()).find("aabb.min.y"), std::string::npos) << error.what();
    }
}

TEST_F(broadphase_fixture, query_and_raycast_cover_both_trees) {
    auto ground = make_body({{-10, -1, -10}, {10, 0, 10}}, true);
    auto box = make_body(cube({0, 3, 0}));
    auto side = make_body(cube({6, 3, 0}));

    std::set<std::uint32_t> found;
    bp.query(cube({0, 1.5f, 0}, 2), [&](entity e) { found.insert(edyn::to_integral(e)); });
    EXPECT_EQ(found, (std::set<std::uint32_t>{edyn::to_integral(ground), edyn::to_integral(box)}));

    // Straight down through the box onto the ground; the callback clips to the exact boxes.
    auto p0 = vector3{0, 10, 0}, p1 = vector3{0, -10, 0};
    entity closest = edyn::null;
    std::vector<entity> visited;
    bp.raycast(p0, p1, [&](entity e) {
        visited.push_back(e);
        auto &box_aabb = registry.get<AABB>(e);
        auto t = (p0.y - box_aabb.max.y) / (p0.y - p1.y);
        closest = e;
        return t;
    });
    EXPECT_EQ(closest, box);
    // The ground lies past the box's hit fraction and is never offered.
    EXPECT_EQ(std::count(visited.begin(), visited.end(), ground), 0);

    // Without clipping every fat AABB on the way is reported, side never.
    std::set<std::uint32_t> all;
    bp.raycast(p0, p1, [&](entity e) { all.insert(edyn::to_integral(e)); });
    EXPECT_EQ(all, (std::set<std::uint32_t>{edyn::to_integral(ground), edyn::to_integral(box)}));
    EXPECT_EQ(all.count(edyn::to_integral(side)), 0u);

    // Returning zero stops everything.
    int calls = 0;
    bp.raycast(p0, p1, [&](entity) {
        ++calls;
        return scalar(0);
    });
    EXPECT_EQ(calls, 1);
}

// A random scene run for a number of steps: bodies random-walk, some are removed and others
// inserted. Records every manifold created, in order, and checks the manifold set against brute
// force after every update.
struct random_scene {
    edyn::registry registry;
    broadphase bp{scalar(0.1)};
    edyn::task_scheduler *scheduler{nullptr}; // the threads bp.update() reads on, if any
    std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> created;
    std::vector<std::size_t> created_per_update;
    std::vector<std::pair<entity, bool>> bodies;

    void on_manifold(edyn::registry &reg, entity m) {
        auto &manifold = reg.get<contact_manifold>(m);
        created.emplace_back(edyn::to_integral(m), edyn::to_integral(manifold.body[0]),
                             edyn::to_integral(manifold.body[1]));
    }

    // Fills the broadphase's containers and trees with unrelated history first (in a scratch
    // registry), so that two scenes with different `warmup` share inputs but not internal state.
    void warm_up(int count) {
        edyn::registry scratch;
        std::vector<entity> tmp;
        for (int i = 0; i < count; ++i) {
            auto e = scratch.create();
            auto box = cube({scalar(i % 7) * scalar(0.3), scalar(i / 7) * scalar(0.3), 0});
            scratch.emplace<AABB>(e, box);
            bp.insert(e, box, i % 5 == 0);
            tmp.push_back(e);
        }
        bp.update(scratch);
        for (auto e : tmp)
            bp.remove(scratch, e);
        EXPECT_EQ(bp.num_manifolds(), 0u);
    }

    void run(unsigned seed, int num_dynamic = 150) {
        registry.on_construct<contact_manifold>().connect<&random_scene::on_manifold>(*this);
        std::mt19937 rng(seed);
        auto uni = [&](scalar lo, scalar hi) { return std::uniform_real_distribution<scalar>(lo, hi)(rng); };
        auto add = [&](bool is_static) {
            auto e = registry.create();
            auto box = cube({uni(-6, 6), uni(-6, 6), uni(-6, 6)}, uni(0.2f, 0.8f));
            registry.emplace<AABB>(e, box);
            bp.insert(e, box, is_static);
            bodies.emplace_back(e, is_static);
        };
        for (int i = 0; i < 25; ++i)
            add(true);
        for (int i = 0; i < num_dynamic; ++i)
            add(false);

        for (int step = 0; step < 40; ++step) {
            for (auto &[e, is_static] : bodies) {
                if (is_static) continue;
                auto d = vector3{uni(-0.15f, 0.15f), uni(-0.15f, 0.15f), uni(-0.15f, 0.15f)};
                registry.patch<AABB>(e, [&](AABB &box) { box = {box.min + d, box.max + d}; });
            }
            if (step % 5 == 4) {
                auto idx = static_cast<std::size_t>(uni(0, scalar(bodies.size()) - 1));
                bp.remove(registry, bodies[idx].first);
                registry.destroy(bodies[idx].first);
                bodies.erase(bodies.begin() + static_cast<std::ptrdiff_t>(idx));
                add(uni(0, 1) < 0.2f);
            }

            auto before = created.size();
            bp.update(registry, scheduler);
            created_per_update.push_back(created.size() - before);
            check_sorted(before);
            check_brute_force();
        }
    }

    void check_sorted(std::size_t from) const {
        for (auto i = from; i + 1 < created.size(); ++i) {
            auto [m0, a0, b0] = created[i];
            auto [m1, a1, b1] = created[i + 1];
            EXPECT_LT(a0, b0);
            EXPECT_TRUE(std::pair(a0, b0) < std::pair(a1, b1)) << "creation out of order at " << i;
        }
    }

    void check_brute_force() const {
        std::set<std::pair<std::uint32_t, std::uint32_t>> expected, actual;
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            for (std::size_t j = i + 1; j < bodies.size(); ++j) {
                auto [a, sa] = bodies[i];
                auto [b, sb] = bodies[j];
                if (sa && sb) continue;
                if (!edyn::intersect(bp.get_fat_aabb(a), bp.get_fat_aabb(b))) continue;
                expected.insert(ordered(a, b));
            }
        }
        for (auto [m, manifold] : registry.view<contact_manifold>().each()) {
            EXPECT_TRUE(actual.insert(ordered(manifold.body[0], manifold.body[1])).second)
                << "duplicate manifold";
            EXPECT_EQ(bp.get_manifold(manifold.body[0], manifold.body[1]), m);
        }
        EXPECT_EQ(actual, expected);
        EXPECT_EQ(bp.num_manifolds(), expected.size());

        // Fat boxes contain the tight ones, so touching bodies always have a manifold.
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            for (std::size_t j = i + 1; j < bodies.size(); ++j) {
                auto [a, sa] = bodies[i];
                auto [b, sb] = bodies[j];
                if (sa && sb) continue;
                if (edyn::intersect(registry.get<AABB>(a), registry.get<AABB>(b))) {
                    EXPECT_EQ(expected.count(ordered(a, b)), 1u) << "touching bodies without a manifold";
                }
            }
        }
    }
};

TEST(broadphase_test, matches_brute_force_and_is_deterministic) {
    random_scene first;
    first.run(42);
    random_scene second;
    second.warm_up(60);
    second.run(42);

    EXPECT_GT(first.created.size(), 100u);
    // Manifolds were created in later steps too, not only the first.
    EXPECT_GT(std::count_if(first.created_per_update.begin() + 1, first.created_per_update.end(),
                            [](std::size_t n) { return n > 0; }),
              10);
    EXPECT_EQ(first.created, second.created);
}

// The scheduler's threads only read (which proxies left their fat boxes, which pairs separated,
// which are new): updated on four threads, the broadphase creates the same manifolds in the same
// order, and destroys the same ones (their entities are reused in the order they were freed), as
// on the calling thread alone.
TEST(broadphase_test, an_update_on_threads_matches_one_on_the_calling_thread) {
    random_scene alone;
    alone.run(7, 1200);
    edyn::task_scheduler scheduler(4);
    random_scene threaded;
    threaded.scheduler = &scheduler;
    threaded.run(7, 1200);

    EXPECT_GT(alone.created.size(), 2000u);
    EXPECT_EQ(alone.created, threaded.created);
}

} // namespace
