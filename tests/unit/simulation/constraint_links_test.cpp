#include <edyn/edyn.hpp>
#include <gtest/gtest.h>
#include <vector>

using namespace edyn;

namespace {

struct constraint_links_fixture : ::testing::Test {
    registry reg;
    void SetUp() override { attach(reg); }
    void TearDown() override { detach(reg); }

    entity body(scalar x) {
        rigidbody_def def;
        def.shape = sphere_shape{scalar(0.1)};
        def.position = {x, 0, 0};
        def.gravity = vector3_zero;
        return make_rigidbody(reg, def);
    }

    std::vector<entity> of(entity e) {
        std::vector<constraint_ref> refs;
        constraints_of(reg, e, refs);
        std::vector<entity> result;
        for (auto &r : refs)
            result.push_back(r.constraint);
        return result;
    }
};

std::size_t count_point_and_hinge(registry &reg) {
    return reg.view<point_constraint>().size() + reg.view<hinge_constraint>().size();
}

} // namespace

TEST_F(constraint_links_fixture, each_body_lists_exactly_its_constraints) {
    auto a = body(0), b = body(1), c = body(2);
    auto ab = make_constraint<point_constraint>(reg, a, b);
    auto bc = make_constraint<hinge_constraint>(reg, b, c);
    auto ca = make_constraint<point_constraint>(reg, c, a);
    EXPECT_EQ(of(a), (std::vector<entity>{ca, ab}));
    EXPECT_EQ(of(b), (std::vector<entity>{bc, ab}));
    EXPECT_EQ(of(c), (std::vector<entity>{ca, bc}));

    reg.destroy(bc);
    EXPECT_EQ(of(b), (std::vector<entity>{ab}));
    EXPECT_EQ(of(c), (std::vector<entity>{ca}));
    EXPECT_EQ(of(a), (std::vector<entity>{ca, ab}));
}

TEST_F(constraint_links_fixture, destroying_a_body_destroys_its_constraints_and_only_those) {
    auto a = body(0), b = body(1), c = body(2), d = body(3);
    auto ab = make_constraint<point_constraint>(reg, a, b);
    auto bc = make_constraint<point_constraint>(reg, b, c);
    auto cd = make_constraint<point_constraint>(reg, c, d);
    reg.destroy(b);
    EXPECT_FALSE(reg.valid(ab));
    EXPECT_FALSE(reg.valid(bc));
    EXPECT_TRUE(reg.valid(cd));
    EXPECT_EQ(of(a), std::vector<entity>{});
    EXPECT_EQ(of(c), std::vector<entity>{cd});
    for (int i = 0; i < 10; ++i)
        step_simulation(reg);
}

TEST_F(constraint_links_fixture, a_constraint_to_an_external_entity_goes_with_it) {
    auto a = body(0);
    auto outside = reg.create();
    tag_external_entity(reg, outside);
    auto c = make_constraint<null_constraint>(reg, a, outside);
    EXPECT_EQ(of(a), std::vector<entity>{c});
    reg.destroy(outside);
    EXPECT_FALSE(reg.valid(c));
    EXPECT_EQ(of(a), std::vector<entity>{});
}

// Building and clearing a scene costs as much as its size: 10,000 bodies joined in a ring by
// 10,000 constraints are made and destroyed (the time is recorded by the constraint_links
// micro-benchmark; this checks the counts).
TEST_F(constraint_links_fixture, ten_thousand_bodies_and_constraints_are_built_and_destroyed) {
    constexpr int n = 10000;
    std::vector<entity> bodies;
    for (int i = 0; i < n; ++i)
        bodies.push_back(body(scalar(i)));
    for (int i = 0; i < n; ++i)
        make_constraint<point_constraint>(reg, bodies[i], bodies[(i + 1) % n]);
    EXPECT_EQ(count_point_and_hinge(reg), std::size_t(n));
    for (int i = 0; i < n; i += 97)
        ASSERT_EQ(of(bodies[i]).size(), 2u) << "body " << i;

    // Every other body first: each takes its two constraints with it.
    for (int i = 0; i < n; i += 2)
        reg.destroy(bodies[i]);
    EXPECT_EQ(count_point_and_hinge(reg), 0u);
    for (int i = 1; i < n; i += 2) {
        ASSERT_TRUE(of(bodies[i]).empty()) << "body " << i;
        reg.destroy(bodies[i]);
    }
    EXPECT_EQ(reg.view<rigidbody_tag>().size(), 0u);
    EXPECT_EQ(reg.view<constraint_links>().size(), 0u);
    EXPECT_EQ(reg.view<constraint_list>().size(), 0u);
}
