#include "edyn/shapes/validate_shape.hpp"
#include "unit/shapes/shape_test_util.hpp"
#include <limits>

using namespace edyn;
using edyn::test::expect_invalid_argument;

namespace {
constexpr auto nan_value = std::numeric_limits<scalar>::quiet_NaN();
constexpr auto inf_value = std::numeric_limits<scalar>::infinity();
} // namespace

TEST(validate_shape_test, valid_shapes_pass) {
    EXPECT_NO_THROW(validate_shape(plane_shape{vector3_y, 0}));
    EXPECT_NO_THROW(validate_shape(sphere_shape{scalar(0.5)}));
    EXPECT_NO_THROW(validate_shape(box_shape{1, 2, 3}));
    EXPECT_NO_THROW(validate_shape(cylinder_shape{1, 2, coordinate_axis::z}));
    EXPECT_NO_THROW(validate_shape(capsule_shape{1, 2, coordinate_axis::y}));
    EXPECT_NO_THROW(validate_shape(polyhedron_shape(edyn::test::cube_vertices(), edyn::test::cube_faces())));
    compound_shape compound;
    compound.add_shape(sphere_shape{1});
    compound.finish();
    EXPECT_NO_THROW(validate_shape(compound));
    EXPECT_NO_THROW(validate_shape(shapes_variant_t{compound}));
}

TEST(validate_shape_test, sphere) {
    expect_invalid_argument([] { validate_shape(sphere_shape{0}); },
                            {"sphere_shape: radius", "positive", "got 0"});
    expect_invalid_argument([] { validate_shape(sphere_shape{-2}); }, {"sphere_shape: radius", "got -2"});
    expect_invalid_argument([] { validate_shape(sphere_shape{nan_value}); },
                            {"sphere_shape: radius", "got nan"});
    expect_invalid_argument([] { validate_shape(sphere_shape{inf_value}); },
                            {"sphere_shape: radius", "got inf"});
}

TEST(validate_shape_test, box) {
    expect_invalid_argument(
        [] {
            validate_shape(box_shape{0, 1, 1});
        },
        {"box_shape: half_extents.x", "got 0"});
    expect_invalid_argument(
        [] {
            validate_shape(box_shape{1, -1, 1});
        },
        {"box_shape: half_extents.y", "got -1"});
    expect_invalid_argument(
        [] {
            validate_shape(box_shape{1, 1, nan_value});
        },
        {"box_shape: half_extents.z", "got nan"});
}

TEST(validate_shape_test, cylinder_and_capsule) {
    expect_invalid_argument(
        [] {
            validate_shape(cylinder_shape{0, 1});
        },
        {"cylinder_shape: radius", "got 0"});
    expect_invalid_argument(
        [] {
            validate_shape(cylinder_shape{1, -3});
        },
        {"cylinder_shape: half_length", "got -3"});
    expect_invalid_argument(
        [] {
            validate_shape(cylinder_shape{1, nan_value});
        },
        {"cylinder_shape: half_length", "nan"});
    expect_invalid_argument(
        [] {
            validate_shape(cylinder_shape{1, 1, static_cast<coordinate_axis>(7)});
        },
        {"cylinder_shape: axis", "got 7"});
    expect_invalid_argument(
        [] {
            validate_shape(capsule_shape{-1, 1});
        },
        {"capsule_shape: radius", "got -1"});
    expect_invalid_argument(
        [] {
            validate_shape(capsule_shape{1, 0});
        },
        {"capsule_shape: half_length", "got 0"});
    expect_invalid_argument(
        [] {
            validate_shape(capsule_shape{1, 1, static_cast<coordinate_axis>(3)});
        },
        {"capsule_shape: axis", "got 3"});
}

TEST(validate_shape_test, plane) {
    expect_invalid_argument(
        [] {
            validate_shape(plane_shape{vector3_zero, 0});
        },
        {"plane_shape: normal", "unit", "(0, 0, 0)", "length 0"});
    expect_invalid_argument(
        [] {
            validate_shape(plane_shape{{0, 2, 0}, 0});
        },
        {"plane_shape: normal", "unit", "(0, 2, 0)", "length 2"});
    expect_invalid_argument(
        [] {
            validate_shape(plane_shape{{nan_value, 1, 0}, 0});
        },
        {"plane_shape: normal", "finite", "nan"});
    expect_invalid_argument(
        [] {
            validate_shape(plane_shape{vector3_y, inf_value});
        },
        {"plane_shape: constant", "inf"});
    // Rounding of a user's normalisation is accepted.
    EXPECT_NO_THROW(validate_shape(plane_shape{{0, scalar(1.0004), 0}, 1}));
}

TEST(validate_shape_test, variant_dispatches) {
    expect_invalid_argument(
        [] {
            validate_shape(shapes_variant_t{box_shape{1, 0, 1}});
        },
        {"box_shape: half_extents.y"});
    expect_invalid_argument(
        [] {
            validate_shape(shapes_variant_t{plane_shape{vector3_zero, 0}});
        },
        {"plane_shape"});
    expect_invalid_argument(
        [] {
            validate_shape(compound_child_shape_t{capsule_shape{1, -1}});
        },
        {"capsule_shape: half_length"});
    expect_invalid_argument([] { validate_shape(shapes_variant_t{polyhedron_shape{}}); },
                            {"polyhedron_shape"});
    expect_invalid_argument([] { validate_shape(shapes_variant_t{mesh_shape{}}); },
                            {"mesh_shape: trimesh is null"});
    expect_invalid_argument(
        [] { validate_shape(shapes_variant_t{mesh_shape{std::make_shared<triangle_mesh>()}}); },
        {"mesh_shape: trimesh is not initialized"});
    expect_invalid_argument([] { validate_shape(shapes_variant_t{paged_mesh_shape{}}); },
                            {"paged_mesh_shape: trimesh is null"});
}

TEST(validate_shape_test, shape_index) {
    static_assert(get_shape_index<plane_shape>() == 0);
    static_assert(get_shape_index<compound_shape>() == num_shapes - 3);
    static_assert(get_shape_index<mesh_shape>() == num_shapes - 2);
    static_assert(get_shape_index<paged_mesh_shape>() == num_shapes - 1);
    EXPECT_EQ((shapes_variant_t{box_shape{1, 1, 1}}.index()), get_shape_index<box_shape>());
    EXPECT_EQ((shapes_variant_t{polyhedron_shape{}}.index()), get_shape_index<polyhedron_shape>());
}
