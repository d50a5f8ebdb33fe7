#include "unit/shapes/shape_test_util.hpp"
#include <edyn/edyn.hpp>
#include <edyn/shapes/shape_bounding_radius.hpp>
#include <edyn/shapes/shape_extent.hpp>
#include <gtest/gtest.h>
#include <random>
#include <variant>

// The step's narrowphase rules a pair without points out by its bounding spheres, its AABBs and
// its shapes' extents along the line between their origins before it calls collide(). Pairs of
// spheres, boxes, capsules and cylinders, turned at random and placed about where they begin to
// touch along a random line: a pair must get points in the step exactly when collide() finds one
// within the contact threshold.

namespace edyn {
namespace {

using test_shape = std::variant<sphere_shape, box_shape, capsule_shape, cylinder_shape>;

struct trial_counts {
    int touching{0};      // collide() found a point within the threshold
    int apart{0};         // it found none
    int by_extents{0};    // apart, and only the extents along the line between the origins show it
    int beyond_bounds{0}; // apart, though no bound shows it: collide() decided
};

void run_trial(const test_shape &shape_a, const test_shape &shape_b, std::mt19937 &rng,
               trial_counts &counts) {
    auto orn_a = test::random_orientation(rng), orn_b = test::random_orientation(rng);
    auto dir = test::random_direction(rng);
    // Where the shapes' reaches along `dir` meet: they touch there or nearer.
    auto meet = std::visit([&](auto &s) { return shape_extent(s, orn_a, dir); }, shape_a) +
                std::visit([&](auto &s) { return shape_extent(s, orn_b, -dir); }, shape_b);
    auto offset = std::uniform_real_distribution<scalar>(scalar(-0.25), scalar(0.06))(rng);
    auto pos_a = vector3{scalar(0.3), 2, scalar(-0.1)};
    auto pos_b = pos_a + dir * (meet + offset);

    auto result = collision_result{};
    auto ctx = collision_context{pos_a, orn_a, pos_b, orn_b, contact_breaking_threshold};
    std::visit([&](auto &a, auto &b) { collide(a, b, ctx, result); }, shape_a, shape_b);
    auto touching = false;
    for (std::size_t i = 0; i < result.num_points; ++i)
        touching |= result.point[i].distance <= contact_breaking_threshold;

    registry reg;
    attach(reg, init_config{execution_mode::sequential});
    set_gravity(reg, vector3_zero);
    auto make = [&](const test_shape &shape, const vector3 &pos, const quaternion &orn) {
        auto def = rigidbody_def{};
        std::visit([&](auto &s) { def.shape = s; }, shape);
        def.position = pos;
        def.orientation = orn;
        return make_rigidbody(reg, def);
    };
    auto a = make(shape_a, pos_a, orn_a);
    auto b = make(shape_b, pos_b, orn_b);
    step_simulation(reg);
    auto points = std::size_t{0};
    for (auto [e, manifold] : reg.view<contact_manifold>().each())
        points += manifold.num_points;
    EXPECT_EQ(points > 0, touching) << "offset " << offset << " from where the reaches meet";

    if (touching) {
        ++counts.touching;
        return;
    }
    ++counts.apart;
    auto radius_a = std::visit([](auto &s) { return shape_bounding_radius(s); }, shape_a);
    auto radius_b = std::visit([](auto &s) { return shape_bounding_radius(s); }, shape_b);
    auto spheres_overlap = length(pos_b - pos_a) <= radius_a + radius_b + contact_breaking_threshold;
    auto aabbs_overlap =
        intersect(inset(reg.get<AABB>(a), vector3_one * contact_breaking_threshold), reg.get<AABB>(b));
    // The shapes are `meet + offset` apart along `dir`, and reach `meet` towards each other.
    auto extents_overlap = offset <= contact_breaking_threshold;
    counts.by_extents += spheres_overlap && aabbs_overlap && !extents_overlap;
    counts.beyond_bounds += spheres_overlap && aabbs_overlap && extents_overlap;
}

TEST(narrowphase, rules_out_only_pairs_that_collide_would_give_no_point) {
    auto shapes = std::vector<test_shape>{
        sphere_shape{scalar(0.4)},
        box_shape{vector3{scalar(0.5), scalar(0.3), scalar(0.2)}},
        capsule_shape{scalar(0.2), scalar(0.5), coordinate_axis::y},
        cylinder_shape{scalar(0.35), scalar(0.45), coordinate_axis::x},
    };
    std::mt19937 rng(3);
    auto counts = trial_counts{};
    for (auto &a : shapes)
        for (auto &b : shapes)
            for (int trial = 0; trial < 40; ++trial)
                run_trial(a, b, rng, counts);
    // Both outcomes come up often, and so do pairs that only the extents or only collide() tell
    // apart.
    EXPECT_GT(counts.touching, 100);
    EXPECT_GT(counts.apart, 100);
    EXPECT_GT(counts.by_extents, 25);
    EXPECT_GT(counts.beyond_bounds, 50);
}

// Points are looked for as far as the bodies can close in within a step: their relative speed
// and each body's spin times the farthest its shape reaches from its centre of mass. That reach
// is the bounding sphere's radius (plus the centre's offset from the shape's origin) where that
// is less than the AABB's half diagonal, as for this box, turned about a slanted axis.
const box_shape spinning_box{vector3{scalar(0.5), scalar(0.3), scalar(0.2)}};
constexpr scalar spin_rate = 3; // rad/s

// The box's pair's separation threshold after one step beside a static slab `gap` below the box's
// lowest corner, and the reach the AABB's half diagonal would give.
scalar spinning_box_threshold(const vector3 &com_offset, scalar gap, scalar &aabb_reach) {
    auto orn = quaternion_axis_angle(normalize(vector3{1, 1, 1}), scalar(0.9));
    auto origin = vector3{0, 1, 0};
    registry reg;
    attach(reg, init_config{execution_mode::sequential});
    set_gravity(reg, vector3_zero);
    auto def = rigidbody_def{};
    def.shape = spinning_box;
    def.position = origin;
    def.orientation = orn;
    // About one of the box's principal axes, so that the spin stays as it is.
    def.angvel = rotate(orn, vector3{0, 0, spin_rate});
    if (com_offset != vector3_zero) def.center_of_mass = com_offset;
    make_rigidbody(reg, def);
    // A static slab near enough for the broadphase to pair them (the box's fat AABB reaches out
    // by its turn in a step, the slab's by the 3 cm margin), too far for a contact point while
    // that corner turns.
    auto aabb = shape_aabb(spinning_box, origin, orn);
    auto ground = rigidbody_def{};
    ground.kind = rigidbody_kind::rb_static;
    ground.shape = box_shape{vector3{2, scalar(0.1), 2}};
    ground.position = vector3{0, aabb.min.y - scalar(0.1) - gap, 0};
    make_rigidbody(reg, ground);
    step_simulation(reg);

    auto centre = origin + rotate(orn, com_offset);
    aabb_reach = length(aabb_half_extents(aabb)) + length(aabb_center(aabb) - centre);
    auto manifolds = reg.view<contact_manifold>();
    EXPECT_EQ(manifolds.size(), 1u);
    if (manifolds.size() != 1) return 0;
    auto &manifold = reg.get<contact_manifold>(*manifolds.begin());
    EXPECT_EQ(manifold.num_points, 0u);
    return manifold.separation_threshold;
}

TEST(narrowphase, a_spinning_body_reaches_as_far_as_its_bounding_sphere) {
    auto radius = shape_bounding_radius(spinning_box);
    auto per_metre = spin_rate * settings{}.fixed_dt; // m the spin carries a point 1 m out in a step
    auto aabb_reach = scalar(0);
    // The threshold is about 5.1 cm, the fat boxes reach 3.1 + 3 cm.
    auto threshold = spinning_box_threshold(vector3_zero, scalar(0.056), aabb_reach);
    // The AABB's half diagonal would give a threshold at least 3 mm wider: the test tells them apart.
    ASSERT_GT(aabb_reach - radius, scalar(0.06));
    EXPECT_NEAR(threshold, contact_breaking_threshold + radius * per_metre, scalar(1e-6));

    // Off the origin, the centre of mass reaches farther from one side of the shape.
    auto offset = vector3{scalar(0.25), 0, 0};
    // The threshold is about 6.3 cm, the fat boxes reach 4.3 + 3 cm.
    threshold = spinning_box_threshold(offset, scalar(0.068), aabb_reach);
    auto reach = std::min(radius + length(offset), aabb_reach);
    EXPECT_NEAR(threshold, contact_breaking_threshold + reach * per_metre, scalar(1e-6));
}

} // namespace
} // namespace edyn
