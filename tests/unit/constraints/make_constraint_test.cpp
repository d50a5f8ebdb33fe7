// make_constraint: bodies and fields are validated before anything is created.
#include <edyn/edyn.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <utility>

using namespace edyn;

namespace {

struct make_constraint_test : ::testing::Test {
    registry reg;
    entity a, b;

    void SetUp() override {
        attach(reg);
        rigidbody_def def;
        def.shape = sphere_shape{scalar(0.5)};
        a = make_rigidbody(reg, def);
        def.position = {2, 0, 0};
        b = make_rigidbody(reg, def);
    }
    void TearDown() override { detach(reg); }

    // Runs `fn`, expecting std::invalid_argument whose message contains every fragment, and
    // that no entity was created.
    template<typename Fn>
    void expect_rejected(Fn fn, std::initializer_list<const char *> fragments) {
        auto alive = reg.alive();
        try {
            fn();
            ADD_FAILURE() << "expected std::invalid_argument";
        } catch (const std::invalid_argument &e) {
            std::string what = e.what();
            for (auto *fragment : fragments) {
                EXPECT_NE(what.find(fragment), std::string::npos)
                    << "message: " << what << "\nmissing: " << fragment;
            }
        }
        EXPECT_EQ(reg.alive(), alive) << "a rejected call created entities";
    }
};

} // namespace

TEST_F(make_constraint_test, creates_the_component_with_its_bodies) {
    auto e = make_constraint<point_constraint>(reg, a, b, [](point_constraint &c) {
        c.pivot[0] = {1, 0, 0};
    });
    ASSERT_TRUE(reg.all_of<point_constraint>(e));
    auto &c = reg.get<point_constraint>(e);
    EXPECT_EQ(c.body[0], a);
    EXPECT_EQ(c.body[1], b);
    EXPECT_EQ(c.pivot[0], (vector3{1, 0, 0}));
    EXPECT_TRUE(reg.all_of<island_resident>(e));
}

TEST_F(make_constraint_test, rejects_a_body_constrained_to_itself) {
    expect_rejected([&] { make_constraint<point_constraint>(reg, a, a); },
                    {"make_constraint<point_constraint>", "body[1]", "must differ"});
}

TEST_F(make_constraint_test, rejects_entities_that_are_not_rigid_bodies) {
    auto plain = reg.create();
    expect_rejected([&] { make_constraint<distance_constraint>(reg, a, plain); },
                    {"make_constraint<distance_constraint>", "body[1]", "rigid body"});
    expect_rejected([&] { make_constraint<point_constraint>(reg, null, b); }, {"body[0]", "valid entity"});
}

TEST_F(make_constraint_test, only_null_constraints_accept_external_entities) {
    auto external = reg.create();
    tag_external_entity(reg, external);
    expect_rejected([&] { make_constraint<point_constraint>(reg, a, external); }, {"body[1]", "rigid body"});
    auto e = make_constraint<null_constraint>(reg, a, external);
    EXPECT_TRUE(reg.all_of<null_constraint>(e));
    EXPECT_THROW(tag_external_entity(reg, a), std::invalid_argument);
}

TEST_F(make_constraint_test, rejects_negative_stiffness_and_damping) {
    expect_rejected(
        [&] {
            make_constraint<soft_distance_constraint>(reg, a, b,
                                                      [](soft_distance_constraint &c) { c.stiffness = -1; });
        },
        {"make_constraint<soft_distance_constraint>", "stiffness", "-1"});
    expect_rejected(
        [&] {
            make_constraint<soft_distance_constraint>(reg, a, b,
                                                      [](soft_distance_constraint &c) { c.damping = -2; });
        },
        {"damping", "-2"});
    expect_rejected(
        [&] {
            make_constraint<point_constraint>(reg, a, b, [](point_constraint &c) { c.friction_torque = -3; });
        },
        {"friction_torque", "-3"});
}

TEST_F(make_constraint_test, rejects_non_finite_pivots_and_negative_distance) {
    expect_rejected(
        [&] {
            make_constraint<distance_constraint>(reg, a, b, [](distance_constraint &c) {
                c.pivot[0].x = std::numeric_limits<scalar>::quiet_NaN();
            });
        },
        {"pivot[0]", "finite"});
    expect_rejected(
        [&] {
            make_constraint<distance_constraint>(reg, a, b, [](distance_constraint &c) { c.distance = -1; });
        },
        {"distance", "-1"});
}

// A zero or non-finite axis has no frame: set_axes says so, naming itself and the argument,
// in every build (normalising it would assert, or give NaN frames).
TEST_F(make_constraint_test, set_axes_refuses_a_zero_or_non_finite_axis) {
    expect_rejected(
        [&] {
            make_constraint<hinge_constraint>(
                reg, a, b, [](hinge_constraint &c) { c.set_axes(vector3_zero, vector3_x); });
        },
        {"hinge_constraint::set_axes", "axisA", "(0, 0, 0)"});
    expect_rejected(
        [&] {
            make_constraint<cvjoint_constraint>(reg, a, b, [](cvjoint_constraint &c) {
                c.set_axes(vector3_y, vector3{std::numeric_limits<scalar>::infinity(), 0, 0});
            });
        },
        {"cvjoint_constraint::set_axes", "axisB", "finite"});
    // A short axis that is not zero is normalised.
    auto hinge = hinge_constraint{};
    hinge.set_axes(vector3{0, 0, scalar(1e-3)}, vector3_z);
    EXPECT_EQ(hinge.frame[0].column(0), vector3_z);
}

TEST_F(make_constraint_test, destroying_or_clearing_a_body_destroys_its_constraints) {
    auto c0 = make_constraint<point_constraint>(reg, a, b);
    auto c1 = make_constraint<distance_constraint>(reg, b, a);
    clear_rigidbody(reg, b);
    EXPECT_FALSE(reg.valid(c0));
    EXPECT_FALSE(reg.valid(c1));
    EXPECT_TRUE(reg.valid(b));
}

TEST_F(make_constraint_test, detach_removes_constraint_components_and_attach_adopts_them) {
    auto c = make_constraint<point_constraint>(reg, a, b);
    detach(reg);
    EXPECT_TRUE(reg.valid(c));
    EXPECT_FALSE(reg.all_of<point_constraint>(c));
    EXPECT_FALSE(reg.all_of<island_resident>(c));
    attach(reg);
}

TEST_F(make_constraint_test, constraints_made_before_attach_join_islands) {
    registry r;
    rigidbody_def def;
    def.shape = sphere_shape{scalar(0.5)};
    auto x = make_rigidbody(r, def);
    def.position = {5, 0, 0};
    auto y = make_rigidbody(r, def);
    auto c = make_constraint<null_constraint>(r, x, y);
    attach(r);
    EXPECT_EQ(r.get<island_resident>(x).island_entity, r.get<island_resident>(y).island_entity);
    EXPECT_TRUE(r.all_of<island_resident>(c));
    detach(r);
}

TEST_F(make_constraint_test, cvjoint_refuses_a_twist_locked_at_infinity) {
    const auto inf = std::numeric_limits<scalar>::infinity();
    for (auto limit : {inf, -inf}) {
        expect_rejected(
            [&] {
                make_constraint<cvjoint_constraint>(reg, a, b, [&](cvjoint_constraint &c) {
                    c.twist_min = limit;
                    c.twist_max = limit;
                });
            },
            {"make_constraint<cvjoint_constraint>", "twist_min", "finite", limit > 0 ? "inf" : "-inf"});
    }
    // Apart, infinite limits are simply not enforced: free, or limited on one side only.
    for (auto limits : {std::pair{-inf, inf}, std::pair{-inf, scalar(0.5)}, std::pair{scalar(-0.5), inf}}) {
        const scalar lo = limits.first, hi = limits.second;
        auto e = make_constraint<cvjoint_constraint>(reg, a, b, [&](cvjoint_constraint &c) {
            c.twist_min = lo;
            c.twist_max = hi;
        });
        EXPECT_TRUE(reg.all_of<cvjoint_constraint>(e)) << "limits " << lo << ", " << hi;
    }
}

TEST_F(make_constraint_test, gravity_refuses_bodies_that_are_not_dynamic) {
    rigidbody_def def;
    def.shape = sphere_shape{scalar(0.5)};
    def.position = {0, 5, 0};
    def.kind = rigidbody_kind::rb_static;
    auto ground = make_rigidbody(reg, def);
    def.position = {0, -5, 0};
    def.kind = rigidbody_kind::rb_kinematic;
    auto mover = make_rigidbody(reg, def);
    expect_rejected([&] { make_constraint<gravity_constraint>(reg, ground, a); },
                    {"make_constraint<gravity_constraint>", "body[0]", "dynamic"});
    expect_rejected([&] { make_constraint<gravity_constraint>(reg, a, mover); },
                    {"make_constraint<gravity_constraint>", "body[1]", "dynamic"});
    auto e = make_constraint<gravity_constraint>(reg, a, b);
    EXPECT_TRUE(reg.all_of<gravity_constraint>(e));
    // Other constraints still accept static bodies.
    EXPECT_NO_THROW(make_constraint<point_constraint>(reg, ground, a));
}
