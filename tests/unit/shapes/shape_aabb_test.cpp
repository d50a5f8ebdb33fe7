#include "edyn/math/transform.hpp"
#include "edyn/shapes/convex_hull.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "unit/shapes/shape_test_util.hpp"
#include <cmath>
#include <vector>

using namespace edyn;
using edyn::test::str;
using edyn::test::surface_samples;

namespace {

// Every sample inside the AABB (to rounding) and the AABB no larger than the samples' bounds
// plus `tightness` on each side.
void expect_tight(const AABB &aabb, const std::vector<vector3> &world_points, scalar tightness,
                  const char *what) {
    auto lo = world_points[0], hi = world_points[0];
    for (auto &p : world_points) {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    for (int i = 0; i < 3; ++i) {
        EXPECT_LE(aabb.min[i], lo[i] + scalar(1e-5))
            << what << " axis " << i << " aabb " << str(aabb.min) << " samples " << str(lo);
        EXPECT_GE(aabb.max[i], hi[i] - scalar(1e-5))
            << what << " axis " << i << " aabb " << str(aabb.max) << " samples " << str(hi);
        EXPECT_NEAR(aabb.min[i], lo[i], tightness) << what << " axis " << i;
        EXPECT_NEAR(aabb.max[i], hi[i], tightness) << what << " axis " << i;
    }
}

template<typename Shape>
void check_shape(const Shape &shape, std::mt19937 &rng, const char *what) {
    auto local = surface_samples(shape);
    for (int trial = 0; trial < 4; ++trial) {
        auto orn = trial == 0 ? quaternion_identity : edyn::test::random_orientation(rng);
        auto pos = edyn::test::random_vector(rng, -5, 5);
        std::vector<vector3> world;
        world.reserve(local.size());
        for (auto &p : local)
            world.push_back(to_world_space(p, pos, orn));
        expect_tight(shape_aabb(shape, pos, orn), world, scalar(1e-4), what);
        // The variant gives the same box.
        EXPECT_EQ(shape_aabb(shapes_variant_t{shape}, pos, orn), shape_aabb(shape, pos, orn)) << what;
    }
}

} // namespace

TEST(shape_aabb_test, rotated_shapes_against_surface_samples) {
    std::mt19937 rng(17);
    check_shape(sphere_shape{scalar(0.7)}, rng, "sphere");
    check_shape(box_shape{scalar(0.5), scalar(1.2), scalar(0.3)}, rng, "box");
    for (auto axis : {coordinate_axis::x, coordinate_axis::y, coordinate_axis::z}) {
        check_shape(cylinder_shape{scalar(0.6), scalar(1.1), axis}, rng, "cylinder");
        check_shape(capsule_shape{scalar(0.4), scalar(0.9), axis}, rng, "capsule");
    }
    std::vector<vector3> cloud;
    for (int i = 0; i < 200; ++i)
        cloud.push_back(edyn::test::random_vector(rng, -1, 1) + vector3{scalar(0.5), 0, 0});
    check_shape(polyhedron_shape{cloud}, rng, "polyhedron");
}

TEST(shape_aabb_test, compound_is_union_of_children) {
    std::mt19937 rng(23);
    compound_shape compound;
    auto box = box_shape{scalar(0.5), scalar(0.2), scalar(0.3)};
    auto cyl = cylinder_shape{scalar(0.3), scalar(0.6), coordinate_axis::z};
    auto box_pos = vector3{1, 0, 0}, cyl_pos = vector3{-1, scalar(0.5), 0};
    auto box_orn = edyn::test::random_orientation(rng), cyl_orn = edyn::test::random_orientation(rng);
    compound.add_shape(box, box_pos, box_orn);
    compound.add_shape(cyl, cyl_pos, cyl_orn);
    compound.finish();
    for (int trial = 0; trial < 4; ++trial) {
        auto orn = edyn::test::random_orientation(rng);
        auto pos = edyn::test::random_vector(rng, -5, 5);
        std::vector<vector3> world;
        for (auto &p : surface_samples(box))
            world.push_back(to_world_space(to_world_space(p, box_pos, box_orn), pos, orn));
        for (auto &p : surface_samples(cyl))
            world.push_back(to_world_space(to_world_space(p, cyl_pos, cyl_orn), pos, orn));
        expect_tight(shape_aabb(compound, pos, orn), world, scalar(1e-4), "compound");
    }
}

TEST(shape_aabb_test, plane_is_tight_when_axis_aligned) {
    auto ground = shape_aabb(plane_shape{vector3_y, 0}, {3, 4, 5}, quaternion_axis_angle(vector3_x, 1));
    EXPECT_EQ(ground.max.y, 0);
    EXPECT_EQ(ground.min.y, -plane_aabb_half_size);
    EXPECT_EQ(ground.min.x, -plane_aabb_half_size);
    EXPECT_EQ(ground.max.z, plane_aabb_half_size);
    // Solid where -x <= 2, i.e. x >= -2.
    auto wall = shape_aabb(plane_shape{-vector3_x, 2}, vector3_zero, quaternion_identity);
    EXPECT_EQ(wall.min.x, -2);
    EXPECT_EQ(wall.max.x, plane_aabb_half_size);
    // A tilted plane cannot be bounded on any axis.
    auto n = normalize(vector3{1, 1, 0});
    auto tilted = shape_aabb(plane_shape{n, 1}, vector3_zero, quaternion_identity);
    EXPECT_EQ(tilted, (AABB{-vector3_one * plane_aabb_half_size, vector3_one * plane_aabb_half_size}));
    // Finite, so that areas stay finite.
    EXPECT_TRUE(std::isfinite(aabb_area(tilted)));
}
