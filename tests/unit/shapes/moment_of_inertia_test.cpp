#include "edyn/math/transform.hpp"
#include "edyn/shapes/moment_of_inertia.hpp"
#include "unit/shapes/shape_test_util.hpp"
#include <cmath>
#include <limits>

using namespace edyn;
using edyn::test::expect_invalid_argument;
using edyn::test::expect_matrix_near;
using edyn::test::expect_vector_near;

namespace {

// Inertia of a solid of revolution about coordinate axis `axis`, integrated numerically over
// thin discs: a disc of mass dm and radius rho at height z contributes dm rho^2 / 2 about the
// axis and dm (rho^2 / 4 + z^2) across. Independent of the closed forms under test.
template<typename RadiusFn>
matrix3x3 inertia_of_revolution(RadiusFn radius_at, scalar z_min, scalar z_max, scalar mass,
                                coordinate_axis axis) {
    constexpr int slices = 200000;
    double dz = double(z_max - z_min) / slices;
    double volume = 0, axial = 0, transverse = 0;
    for (int i = 0; i < slices; ++i) {
        double z = z_min + (i + 0.5) * dz;
        double rho = radius_at(scalar(z));
        double dv = 3.14159265358979323846 * rho * rho * dz;
        volume += dv;
        axial += dv * rho * rho / 2;
        transverse += dv * (rho * rho / 4 + z * z);
    }
    auto density = double(mass) / volume;
    vector3 d{scalar(transverse * density), scalar(transverse * density), scalar(transverse * density)};
    d[coordinate_axis_index(axis)] = scalar(axial * density);
    return diagonal_matrix(d);
}

polyhedron_shape box_polyhedron(const vector3 &he, const vector3 &centre = vector3_zero) {
    auto vertices = edyn::test::cube_vertices(1);
    for (auto &v : vertices)
        v = v * he + centre;
    return {vertices, edyn::test::cube_faces()};
}

} // namespace

TEST(moment_of_inertia_test, closed_forms) {
    scalar m = 3, r = scalar(0.5);
    expect_matrix_near(moment_of_inertia(sphere_shape{r}, m),
                       diagonal_matrix(vector3_one * (scalar(0.4) * m * r * r)), 1e-6);
    // m/12 (b^2 + c^2) with full side lengths 1, 2, 3.
    auto box = moment_of_inertia(box_shape{scalar(0.5), 1, scalar(1.5)}, m);
    expect_matrix_near(box, diagonal_matrix(vector3{4 + 9, 1 + 9, 1 + 4} * (m / 12)), 1e-5);
    // Cylinder of radius r and length L = 2: m r^2 / 2 about the axis, m (3 r^2 + L^2) / 12 across.
    auto cyl = moment_of_inertia(cylinder_shape{r, 1, coordinate_axis::y}, m);
    auto across = m * (3 * r * r + 4) / 12;
    expect_matrix_near(cyl, diagonal_matrix({across, m * r * r / 2, across}), 1e-5);
}

TEST(moment_of_inertia_test, cylinder_and_capsule_against_integration) {
    scalar m = 2, r = scalar(0.4), h = scalar(0.7);
    for (auto axis : {coordinate_axis::x, coordinate_axis::y, coordinate_axis::z}) {
        auto cyl = inertia_of_revolution([&](scalar) { return r; }, -h, h, m, axis);
        expect_matrix_near(moment_of_inertia(cylinder_shape{r, h, axis}, m), cyl, 1e-5);
        auto capsule_radius = [&](scalar z) {
            auto beyond = std::max(std::abs(z) - h, scalar(0));
            return std::sqrt(std::max(r * r - beyond * beyond, scalar(0)));
        };
        auto cap = inertia_of_revolution(capsule_radius, -h - r, h + r, m, axis);
        expect_matrix_near(moment_of_inertia(capsule_shape{r, h, axis}, m), cap, 1e-5);
    }
    EXPECT_NEAR(shape_volume(capsule_shape{r, h}), pi * r * r * 2 * h + 4 * pi * r * r * r / 3, 1e-6);
}

TEST(moment_of_inertia_test, box_as_polyhedron_and_as_compound) {
    scalar m = 5;
    auto he = vector3{scalar(0.5), 1, scalar(1.5)};
    auto solid = moment_of_inertia(box_shape{he}, m);

    auto poly = box_polyhedron(he);
    EXPECT_NEAR(shape_volume(poly), 6, 1e-5);
    expect_vector_near(shape_centroid(poly), vector3_zero, 1e-6);
    expect_matrix_near(moment_of_inertia(poly, m), solid, 1e-5);

    // The same box as a hull of its corners, rotated points merged into quads.
    expect_matrix_near(moment_of_inertia(polyhedron_shape{poly.mesh->vertices}, m), solid, 1e-5);

    // Two half boxes side by side along x.
    compound_shape halves;
    auto half = box_shape{{he.x / 2, he.y, he.z}};
    halves.add_shape(half, {-he.x / 2, 0, 0});
    halves.add_shape(half, {he.x / 2, 0, 0});
    halves.finish();
    EXPECT_NEAR(shape_volume(halves), 6, 1e-5);
    expect_vector_near(shape_centroid(halves), vector3_zero, 1e-6);
    expect_matrix_near(moment_of_inertia(halves, m), solid, 1e-5);

    // A child rotated by 90 degrees about z swaps its x and y extents.
    compound_shape rotated;
    rotated.add_shape(box_shape{{he.y, he.x, he.z}}, vector3_zero, quaternion_axis_angle(vector3_z, half_pi));
    rotated.finish();
    expect_matrix_near(moment_of_inertia(rotated, m), solid, 1e-5);
}

TEST(moment_of_inertia_test, off_centre_tetrahedron) {
    // Unit right tetrahedron moved to (2, 3, 4): centroid at the vertex mean, volume 1/6; about its
    // centroid I_xx = 3m/40 and I_xy = m/80 (from the integrals over the unit tetrahedron:
    // integral of x^2 = 1/60, of xy = 1/120, per unit volume 6).
    auto offset = vector3{2, 3, 4};
    std::vector<vector3> vertices{offset, offset + vector3_x, offset + vector3_y, offset + vector3_z};
    auto tetra = polyhedron_shape{vertices};
    EXPECT_NEAR(shape_volume(tetra), scalar(1) / 6, 1e-6);
    expect_vector_near(shape_centroid(tetra), offset + vector3_one * scalar(0.25), 1e-5);
    scalar m = 2;
    auto diagonal = 3 * m / 40, off_diagonal = m / 80;
    matrix3x3 expected{{{diagonal, off_diagonal, off_diagonal},
                        {off_diagonal, diagonal, off_diagonal},
                        {off_diagonal, off_diagonal, diagonal}}};
    expect_matrix_near(moment_of_inertia(tetra, m), expected, 1e-5);

    // An off-centre box polyhedron: the centroid is its centre, the inertia the centred box's.
    auto box = box_polyhedron({1, 2, 3}, {5, -1, 2});
    expect_vector_near(shape_centroid(box), {5, -1, 2}, 1e-5);
    expect_matrix_near(moment_of_inertia(box, 1), moment_of_inertia(box_shape{1, 2, 3}, 1), 1e-4);
}

TEST(moment_of_inertia_test, compound_centroid_weights_by_volume) {
    compound_shape compound;
    compound.add_shape(sphere_shape{1}, {3, 0, 0});
    compound.add_shape(sphere_shape{2}, {0, 0, 0});
    compound.finish();
    // Volumes 1 : 8.
    expect_vector_near(shape_centroid(compound), {scalar(3) / 9, 0, 0}, 1e-6);
    auto m = scalar(9);
    auto expected = moment_of_inertia(sphere_shape{1}, 1) + moment_of_inertia(sphere_shape{2}, 8);
    // Parallel axis: masses 1 and 8 at distances 8/3 and 1/3 from the centroid along x.
    auto shift = scalar(1) * (scalar(64) / 9) + scalar(8) * (scalar(1) / 9);
    expected[1][1] += shift;
    expected[2][2] += shift;
    expect_matrix_near(moment_of_inertia(compound, m), expected, 1e-4);
}

TEST(moment_of_inertia_test, shift_against_point_masses) {
    // Point masses: inertia about any point p is sum m_i (|r_i|^2 E - r_i r_i^T), r_i = x_i - p.
    std::mt19937 rng(9);
    std::vector<std::pair<vector3, scalar>> masses;
    std::uniform_real_distribution<scalar> u(scalar(0.1), 2);
    for (int i = 0; i < 20; ++i)
        masses.push_back({edyn::test::random_vector(rng, -2, 2), u(rng)});
    auto about = [&](const vector3 &p) {
        auto inertia = matrix3x3_zero;
        for (auto &[x, m] : masses) {
            auto r = x - p;
            inertia += (matrix3x3_identity * dot(r, r) - matrix3x3_rows(r * r.x, r * r.y, r * r.z)) * m;
        }
        return inertia;
    };
    scalar total = 0;
    auto centre = vector3_zero;
    for (auto &[x, m] : masses) {
        total += m;
        centre += x * m;
    }
    centre /= total;
    auto offset = vector3{scalar(0.3), scalar(-1.2), scalar(0.7)};
    expect_matrix_near(shift_moment_of_inertia(about(centre), total, offset), about(centre + offset), 1e-4);
}

TEST(moment_of_inertia_test, invalid_mass_throws) {
    auto nan = std::numeric_limits<scalar>::quiet_NaN();
    auto inf = std::numeric_limits<scalar>::infinity();
    expect_invalid_argument([] { moment_of_inertia(sphere_shape{1}, -1); },
                            {"moment_of_inertia", "mass", "got -1"});
    expect_invalid_argument([] { moment_of_inertia(box_shape{1, 1, 1}, 0); }, {"mass", "got 0"});
    expect_invalid_argument([&] { moment_of_inertia(capsule_shape{1, 1}, nan); }, {"mass", "got nan"});
    expect_invalid_argument(
        [&] {
            moment_of_inertia(shapes_variant_t{cylinder_shape{1, 1}}, inf);
        },
        {"mass", "inf"});
    expect_invalid_argument(
        [] {
            moment_of_inertia(shapes_variant_t{plane_shape{vector3_y, 0}}, 1);
        },
        {"moment_of_inertia", "static"});
    EXPECT_EQ(shape_volume(shapes_variant_t{plane_shape{vector3_y, 0}}),
              std::numeric_limits<scalar>::infinity());
}

TEST(moment_of_inertia_test, invalid_dimensions_and_shifts_throw) {
    auto nan = std::numeric_limits<scalar>::quiet_NaN();
    auto inf = std::numeric_limits<scalar>::infinity();
    expect_invalid_argument([] { moment_of_inertia_solid_sphere(1, 0); },
                            {"moment_of_inertia_solid_sphere", "radius", "got 0"});
    expect_invalid_argument([&] { moment_of_inertia_solid_sphere(1, nan); }, {"radius", "got nan"});
    expect_invalid_argument(
        [] {
            moment_of_inertia_solid_box(1, {1, -2, 1});
        },
        {"moment_of_inertia_solid_box", "half_extents.y", "got -2"});
    expect_invalid_argument([&] { moment_of_inertia_solid_box(1, {1, 1, inf}); }, {"half_extents.z", "inf"});
    expect_invalid_argument([] { moment_of_inertia_solid_cylinder(1, -1, 1, coordinate_axis::x); },
                            {"moment_of_inertia_solid_cylinder", "radius", "got -1"});
    expect_invalid_argument([] { moment_of_inertia_solid_cylinder(1, 1, 0, coordinate_axis::x); },
                            {"moment_of_inertia_solid_cylinder", "half_length", "got 0"});
    expect_invalid_argument([&] { moment_of_inertia_solid_capsule(1, inf, 1, coordinate_axis::y); },
                            {"moment_of_inertia_solid_capsule", "radius", "inf"});
    expect_invalid_argument([&] { moment_of_inertia_solid_capsule(1, 1, nan, coordinate_axis::y); },
                            {"moment_of_inertia_solid_capsule", "half_length", "nan"});
    auto I = moment_of_inertia_solid_sphere(2, 1);
    expect_invalid_argument(
        [&] {
            shift_moment_of_inertia(I, -1, {1, 0, 0});
        },
        {"shift_moment_of_inertia", "mass", "got -1"});
    expect_invalid_argument([&] { shift_moment_of_inertia(I, nan, {1, 0, 0}); }, {"mass", "nan"});
    expect_invalid_argument([&] { shift_moment_of_inertia(I, inf, {1, 0, 0}); }, {"mass", "inf"});
    expect_invalid_argument(
        [&] {
            shift_moment_of_inertia(I, 2, {0, nan, 0});
        },
        {"shift_moment_of_inertia", "offset", "nan"});
    // A zero mass or offset moves nothing.
    expect_matrix_near(shift_moment_of_inertia(I, 0, {1, 2, 3}), I, 0);
    expect_matrix_near(shift_moment_of_inertia(I, 2, vector3_zero), I, 0);
}

TEST(moment_of_inertia_test, variant_matches_direct_calls) {
    auto shape = capsule_shape{scalar(0.3), scalar(0.8), coordinate_axis::z};
    EXPECT_EQ(moment_of_inertia(shapes_variant_t{shape}, 2), moment_of_inertia(shape, 2));
    EXPECT_EQ(shape_volume(shapes_variant_t{shape}), shape_volume(shape));
    EXPECT_EQ(shape_centroid(shapes_variant_t{shape}), vector3_zero);
}
