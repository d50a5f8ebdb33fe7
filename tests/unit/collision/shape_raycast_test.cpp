#include "edyn/collision/shape_raycast.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"
#include "edyn/math/transform.hpp"
#include "unit/shapes/shape_test_util.hpp"
#include <algorithm>
#include <cmath>
#include <optional>

using namespace edyn;
using edyn::test::expect_vector_near;
using edyn::test::str;

namespace {

// Independent geometry for the randomised checks: point containment (closed shape grown by
// `tol`) and support distance (largest dot(n, x) over the shape), both in object space.

bool inside(const sphere_shape &s, const vector3 &p, scalar tol) { return length(p) <= s.radius + tol; }

bool inside(const box_shape &b, const vector3 &p, scalar tol) {
    return std::abs(p.x) <= b.half_extents.x + tol && std::abs(p.y) <= b.half_extents.y + tol &&
           std::abs(p.z) <= b.half_extents.z + tol;
}

bool inside(const cylinder_shape &c, const vector3 &p, scalar tol) {
    auto k = coordinate_axis_index(c.axis);
    auto radial = p;
    radial[k] = 0;
    return std::abs(p[k]) <= c.half_length + tol && length(radial) <= c.radius + tol;
}

bool inside(const capsule_shape &c, const vector3 &p, scalar tol) {
    auto k = coordinate_axis_index(c.axis);
    auto on_axis = vector3_zero;
    on_axis[k] = std::clamp(p[k], -c.half_length, c.half_length);
    return distance(p, on_axis) <= c.radius + tol;
}

bool inside(const polyhedron_shape &s, const vector3 &p, scalar tol) {
    for (std::size_t f = 0; f < s.mesh->num_faces(); ++f) {
        if (dot(s.mesh->normals[f], p) - s.mesh->plane_constants[f] > tol) return false;
    }
    return true;
}

bool inside(const compound_child_shape_t &s, const vector3 &p, scalar tol) {
    return std::visit([&](const auto &shape) { return inside(shape, p, tol); }, s);
}

bool inside(const compound_shape &c, const vector3 &p, scalar tol) {
    return std::any_of(c.children.begin(), c.children.end(), [&](const compound_shape::child &child) {
        return inside(child.shape, to_object_space(p, child.position, child.orientation), tol);
    });
}

scalar support(const sphere_shape &s, const vector3 &) { return s.radius; }
scalar support(const box_shape &b, const vector3 &n) { return dot(abs(n), b.half_extents); }

scalar support(const cylinder_shape &c, const vector3 &n) {
    auto k = coordinate_axis_index(c.axis);
    return std::abs(n[k]) * c.half_length + c.radius * length_across_axis(n, k);
}

scalar support(const capsule_shape &c, const vector3 &n) {
    return std::abs(n[coordinate_axis_index(c.axis)]) * c.half_length + c.radius;
}

scalar support(const polyhedron_shape &s, const vector3 &n) {
    return dot(s.mesh->vertices[s.mesh->support_vertex(n)], n);
}

scalar support(const compound_child_shape_t &s, const vector3 &n) {
    return std::visit([&](const auto &shape) { return support(shape, n); }, s);
}

// Support distance of what the ray hit: the shape, or for a compound (possibly concave) the
// child it reports.
template<typename Shape>
scalar hit_support(const Shape &shape, const vector3 &n, const shape_raycast_result &) {
    return support(shape, n);
}

scalar hit_support(const compound_shape &c, const vector3 &n, const shape_raycast_result &result) {
    const auto &child = c.children.at(std::get<compound_raycast_info>(result.info_var).child_index);
    return dot(n, child.position) + support(child.shape, rotate(conjugate(child.orientation), n));
}

// Casts random rays at `shape` placed at random transforms and checks each result against
// dense sampling of the segment with the containment test.
template<typename Shape>
void check_random_rays(const Shape &shape, std::mt19937 &rng, const char *what) {
    constexpr int samples = 4000;
    constexpr scalar tol = scalar(1e-4);
    int hits = 0, inside_starts = 0;
    for (int trial = 0; trial < 300; ++trial) {
        auto pos = edyn::test::random_vector(rng, -2, 2);
        auto orn = edyn::test::random_orientation(rng);
        auto p0 = pos + edyn::test::random_vector(rng, -3, 3) * (trial % 4 == 0 ? scalar(0.3) : scalar(1));
        auto p1 = pos + edyn::test::random_vector(rng, -3, 3);
        auto d = p1 - p0;
        auto is_inside = [&](scalar t, scalar grow) {
            return inside(shape, to_object_space(p0 + d * t, pos, orn), grow);
        };
        std::optional<scalar> first_inside;
        for (int j = 0; j <= samples && !first_inside; ++j) {
            auto t = scalar(j) / samples;
            if (is_inside(t, -tol)) first_inside = t;
        }
        auto result = shape_raycast(shape, raycast_context{pos, orn, p0, p1});
        std::string ctx = std::string(what) + " trial " + std::to_string(trial);
        if (!result.hit()) {
            EXPECT_FALSE(first_inside)
                << ctx << ": missed, but the segment is inside at t = " << *first_inside;
            EXPECT_EQ(result.fraction, raycast_miss_fraction) << ctx;
            continue;
        }
        ++hits;
        EXPECT_NEAR(length(result.normal), 1, 1e-4) << ctx;
        if (first_inside) {
            EXPECT_LE(result.fraction, *first_inside + scalar(1e-6)) << ctx;
        }
        if (is_inside(0, -tol)) {
            ++inside_starts;
            EXPECT_EQ(result.fraction, 0) << ctx;
            expect_vector_near(result.normal, -normalize(d), 1e-5, ctx + " inside normal");
            continue;
        }
        if (result.fraction == 0) continue;
        auto q = p0 + d * result.fraction;
        // On the surface: in the grown shape, not in the shrunk one, nothing inside before it.
        EXPECT_TRUE(is_inside(result.fraction, tol)) << ctx << " hit point " << str(q);
        EXPECT_FALSE(is_inside(result.fraction, -tol)) << ctx << " hit point " << str(q);
        if (first_inside) {
            EXPECT_GE(*first_inside, result.fraction - scalar(1e-5)) << ctx;
        }
        // The normal faces the ray and is a supporting plane at the hit point.
        EXPECT_LE(dot(result.normal, d), tol) << ctx;
        auto n_local = rotate(conjugate(orn), result.normal);
        auto gap = dot(result.normal, pos) + hit_support(shape, n_local, result) - dot(result.normal, q);
        EXPECT_NEAR(gap, 0, 1e-3) << ctx << " normal " << str(result.normal);
    }
    // The rays are spread so that all cases occur.
    EXPECT_GT(hits, 40) << what;
    EXPECT_GT(inside_starts, 5) << what;
}

raycast_context ray(const vector3 &p0, const vector3 &p1, const vector3 &pos = vector3_zero,
                    const quaternion &orn = quaternion_identity) {
    return {pos, orn, p0, p1};
}

} // namespace

TEST(shape_raycast_test, sphere) {
    auto sphere = sphere_shape{1};
    auto pos = vector3{1, 2, 3};
    auto r =
        shape_raycast(sphere, ray(pos + vector3{-5, scalar(0.5), 0}, pos + vector3{5, scalar(0.5), 0}, pos));
    auto x = std::sqrt(scalar(0.75));
    EXPECT_NEAR(r.fraction, (5 - x) / 10, 1e-6);
    expect_vector_near(r.normal, {-x, scalar(0.5), 0}, 1e-5);
    EXPECT_TRUE(std::holds_alternative<std::monostate>(r.info_var));
    // Tangent: a grazing ray hits.
    r = shape_raycast(sphere, ray({-5, 1, 0}, {5, 1, 0}));
    EXPECT_NEAR(r.fraction, scalar(0.5), 1e-6);
    expect_vector_near(r.normal, vector3_y, 1e-5);
    EXPECT_FALSE(shape_raycast(sphere, ray({-5, scalar(1.01), 0}, {5, scalar(1.01), 0})).hit());
    // Ends before the sphere; zero length.
    EXPECT_FALSE(shape_raycast(sphere, ray({-5, 0, 0}, {-2, 0, 0})).hit());
    EXPECT_FALSE(shape_raycast(sphere, ray({0, 0, 0}, {0, 0, 0})).hit());
    // Inside: fraction 0, normal against the ray.
    r = shape_raycast(sphere, ray({scalar(0.2), 0, 0}, {5, 0, 0}));
    EXPECT_EQ(r.fraction, 0);
    expect_vector_near(r.normal, -vector3_x, 1e-6);
    // On the surface: leaving misses, entering hits at 0.
    EXPECT_FALSE(shape_raycast(sphere, ray({1, 0, 0}, {5, 0, 0})).hit());
    r = shape_raycast(sphere, ray({1, 0, 0}, {-5, 0, 0}));
    EXPECT_EQ(r.fraction, 0);
    expect_vector_near(r.normal, vector3_x, 1e-6);
}

TEST(shape_raycast_test, box_faces) {
    auto box = box_shape{1, 2, 3};
    for (std::size_t face = 0; face < 6; ++face) {
        auto axis = int(face / 2);
        auto sign = face % 2 == 0 ? scalar(1) : scalar(-1);
        auto dir = coordinate_axis_vector(static_cast<coordinate_axis>(axis)) * sign;
        auto r = shape_raycast(box, ray(dir * 10, -dir * 10));
        EXPECT_NEAR(r.fraction, (10 - box.half_extents[axis]) / 20, 1e-6) << "face " << face;
        expect_vector_near(r.normal, dir, 1e-6, "face " + std::to_string(face));
        ASSERT_TRUE(std::holds_alternative<box_raycast_info>(r.info_var));
        EXPECT_EQ(std::get<box_raycast_info>(r.info_var).face_index, face);
    }
}

TEST(shape_raycast_test, rotated_box) {
    auto box = box_shape{1, 2, 3};
    // Rotating 90 degrees about z takes the box's +x face to world +y.
    auto orn = quaternion_axis_angle(vector3_z, half_pi);
    auto pos = vector3{0, 1, 0};
    auto r = shape_raycast(box, ray({scalar(0.5), 10, 0}, {scalar(0.5), -10, 0}, pos, orn));
    EXPECT_NEAR(r.fraction, (10 - 2) / scalar(20), 1e-6);
    expect_vector_near(r.normal, vector3_y, 1e-6);
    EXPECT_EQ(std::get<box_raycast_info>(r.info_var).face_index, 0u);
}

TEST(shape_raycast_test, box_parallel_grazing_and_inside) {
    auto box = box_shape{1, 2, 3};
    // Parallel to the +y face, outside it: miss. Sliding along it: hit through the -x face.
    EXPECT_FALSE(shape_raycast(box, ray({-5, scalar(2.5), 0}, {5, scalar(2.5), 0})).hit());
    auto r = shape_raycast(box, ray({-5, 2, 0}, {5, 2, 0}));
    EXPECT_NEAR(r.fraction, scalar(0.4), 1e-6);
    EXPECT_EQ(std::get<box_raycast_info>(r.info_var).face_index, 1u);
    expect_vector_near(r.normal, -vector3_x, 1e-6);
    // Inside: fraction 0, normal against the ray, the face the line enters by (-x, behind).
    r = shape_raycast(box, ray({0, 0, 0}, {4, 0, 0}));
    EXPECT_EQ(r.fraction, 0);
    expect_vector_near(r.normal, -vector3_x, 1e-6);
    EXPECT_EQ(std::get<box_raycast_info>(r.info_var).face_index, 1u);
    // Leaving from a face: miss.
    EXPECT_FALSE(shape_raycast(box, ray({1, 0, 0}, {4, 0, 0})).hit());
}

TEST(shape_raycast_test, cylinder) {
    auto cyl = cylinder_shape{scalar(0.5), 1, coordinate_axis::x};
    auto pos = vector3{1, 0, 0};
    auto r = shape_raycast(cyl, ray({6, 0, 0}, {-4, 0, 0}, pos));
    EXPECT_NEAR(r.fraction, scalar(0.4), 1e-6);
    expect_vector_near(r.normal, vector3_x, 1e-6);
    auto info = std::get<cylinder_raycast_info>(r.info_var);
    EXPECT_EQ(info.feature, cylinder_feature::face);
    EXPECT_EQ(info.face_index, 0u);

    r = shape_raycast(cyl, ray({-4, 0, 0}, {6, 0, 0}, pos));
    EXPECT_NEAR(r.fraction, scalar(0.4), 1e-6);
    expect_vector_near(r.normal, -vector3_x, 1e-6);
    EXPECT_EQ(std::get<cylinder_raycast_info>(r.info_var).face_index, 1u);

    r = shape_raycast(cyl, ray({scalar(1.3), 5, 0}, {scalar(1.3), -5, 0}, pos));
    EXPECT_NEAR(r.fraction, scalar(0.45), 1e-6);
    expect_vector_near(r.normal, vector3_y, 1e-6);
    EXPECT_EQ(std::get<cylinder_raycast_info>(r.info_var).feature, cylinder_feature::side_edge);

    // Along the side surface: enters through the cap rim, which counts as the cap.
    r = shape_raycast(cyl, ray({6, scalar(0.5), 0}, {-4, scalar(0.5), 0}, pos));
    EXPECT_NEAR(r.fraction, scalar(0.4), 1e-6);
    EXPECT_EQ(std::get<cylinder_raycast_info>(r.info_var).feature, cylinder_feature::face);
    EXPECT_FALSE(shape_raycast(cyl, ray({6, scalar(0.6), 0}, {-4, scalar(0.6), 0}, pos)).hit());

    // A y-axis cylinder rotated 90 degrees about x: its +y cap faces world +z.
    auto upright = cylinder_shape{scalar(0.5), 1, coordinate_axis::y};
    r = shape_raycast(upright,
                      ray({0, 0, 5}, {0, 0, -5}, vector3_zero, quaternion_axis_angle(vector3_x, half_pi)));
    EXPECT_NEAR(r.fraction, scalar(0.4), 1e-6);
    expect_vector_near(r.normal, vector3_z, 1e-6);
    EXPECT_EQ(std::get<cylinder_raycast_info>(r.info_var).face_index, 0u);

    r = shape_raycast(cyl, ray(pos, {1, 5, 0}, pos));
    EXPECT_EQ(r.fraction, 0);
    expect_vector_near(r.normal, -vector3_y, 1e-6);
}

TEST(shape_raycast_test, capsule) {
    auto cap = capsule_shape{scalar(0.5), 1, coordinate_axis::x};
    auto r = shape_raycast(cap, ray({5, 0, 0}, {-5, 0, 0}));
    EXPECT_NEAR(r.fraction, scalar(0.35), 1e-6);
    expect_vector_near(r.normal, vector3_x, 1e-6);
    auto info = std::get<capsule_raycast_info>(r.info_var);
    EXPECT_EQ(info.feature, capsule_feature::hemisphere);
    EXPECT_EQ(info.hemisphere_index, 0u);

    r = shape_raycast(cap, ray({-5, 0, 0}, {5, 0, 0}));
    EXPECT_NEAR(r.fraction, scalar(0.35), 1e-6);
    EXPECT_EQ(std::get<capsule_raycast_info>(r.info_var).hemisphere_index, 1u);

    r = shape_raycast(cap, ray({scalar(0.3), 5, 0}, {scalar(0.3), -5, 0}));
    EXPECT_NEAR(r.fraction, scalar(0.45), 1e-6);
    expect_vector_near(r.normal, vector3_y, 1e-6);
    EXPECT_EQ(std::get<capsule_raycast_info>(r.info_var).feature, capsule_feature::side);

    // Off the axis over the +x hemisphere: hits at height sqrt(0.25 - 0.09) = 0.4.
    r = shape_raycast(cap, ray({scalar(1.3), 5, 0}, {scalar(1.3), -5, 0}));
    EXPECT_NEAR(r.fraction, scalar(0.46), 1e-6);
    expect_vector_near(r.normal, {scalar(0.6), scalar(0.8), 0}, 1e-5);
    EXPECT_EQ(std::get<capsule_raycast_info>(r.info_var).feature, capsule_feature::hemisphere);

    // Rotated to stand along world y: the +x hemisphere is on top.
    auto orn = quaternion_axis_angle(vector3_z, half_pi);
    r = shape_raycast(cap, ray({0, 5, 0}, {0, -5, 0}, vector3_zero, orn));
    EXPECT_NEAR(r.fraction, scalar(0.35), 1e-6);
    expect_vector_near(r.normal, vector3_y, 1e-6);
    EXPECT_EQ(std::get<capsule_raycast_info>(r.info_var).hemisphere_index, 0u);

    EXPECT_FALSE(shape_raycast(cap, ray({-5, scalar(0.51), 0}, {5, scalar(0.51), 0})).hit());
    r = shape_raycast(cap, ray({scalar(1.2), 0, 0}, {scalar(1.2), 0, 3}));
    EXPECT_EQ(r.fraction, 0);
    expect_vector_near(r.normal, -vector3_z, 1e-6);
}

TEST(shape_raycast_test, polyhedron) {
    auto cube = polyhedron_shape(edyn::test::cube_vertices(1), edyn::test::cube_faces());
    auto r = shape_raycast(cube, ray({0, 0, 5}, {0, 0, -5}));
    EXPECT_NEAR(r.fraction, scalar(0.4), 1e-6);
    expect_vector_near(r.normal, vector3_z, 1e-6);
    EXPECT_EQ(std::get<polyhedron_raycast_info>(r.info_var).face_index, 1u);

    // Rotated 90 degrees about x, the -z face (index 0) looks up.
    auto orn = quaternion_axis_angle(vector3_x, half_pi);
    r = shape_raycast(cube,
                      ray({scalar(0.2), 5, scalar(0.3)}, {scalar(0.2), -5, scalar(0.3)}, vector3_zero, orn));
    EXPECT_NEAR(r.fraction, scalar(0.4), 1e-6);
    expect_vector_near(r.normal, vector3_y, 1e-6);
    EXPECT_EQ(std::get<polyhedron_raycast_info>(r.info_var).face_index, 0u);

    // Parallel to the top face: outside misses, sliding along it hits through -x (face 4).
    EXPECT_FALSE(shape_raycast(cube, ray({-5, 0, scalar(1.5)}, {5, 0, scalar(1.5)})).hit());
    r = shape_raycast(cube, ray({-5, 0, 1}, {5, 0, 1}));
    EXPECT_NEAR(r.fraction, scalar(0.4), 1e-6);
    EXPECT_EQ(std::get<polyhedron_raycast_info>(r.info_var).face_index, 4u);

    // The slanted face of a tetrahedron, x + y + z = 1, hit at (1/3, 1/3, 1/3).
    auto tetra = polyhedron_shape{std::vector<vector3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    r = shape_raycast(tetra, ray({2, 2, 2}, {-1, -1, -1}));
    EXPECT_NEAR(r.fraction, scalar(5) / 9, 1e-6);
    auto slanted = normalize(vector3_one);
    expect_vector_near(r.normal, slanted, 1e-6);
    auto face = std::get<polyhedron_raycast_info>(r.info_var).face_index;
    expect_vector_near(tetra.mesh->normals[face], slanted, 1e-6, "reported face");

    r = shape_raycast(cube, ray({0, 0, 0}, {0, 2, 0}));
    EXPECT_EQ(r.fraction, 0);
    expect_vector_near(r.normal, -vector3_y, 1e-6);
}

TEST(shape_raycast_test, plane) {
    auto ground = plane_shape{vector3_y, 0};
    // Planes ignore the transform.
    auto pos = vector3{3, 7, -2};
    auto orn = quaternion_axis_angle(vector3_x, 1);
    auto r = shape_raycast(ground, ray({1, 5, 0}, {1, -5, 0}, pos, orn));
    EXPECT_NEAR(r.fraction, scalar(0.5), 1e-6);
    expect_vector_near(r.normal, vector3_y, 1e-6);
    EXPECT_TRUE(std::holds_alternative<std::monostate>(r.info_var));
    // From below (inside the solid half-space).
    r = shape_raycast(ground, ray({0, -1, 0}, {0, 5, 0}));
    EXPECT_EQ(r.fraction, 0);
    expect_vector_near(r.normal, -vector3_y, 1e-6);
    EXPECT_FALSE(shape_raycast(ground, ray({-5, 1, 0}, {5, 1, 0})).hit());
    EXPECT_FALSE(shape_raycast(ground, ray({0, 1, 0}, {0, 5, 0})).hit());
    EXPECT_FALSE(shape_raycast(ground, ray({0, 5, 0}, {0, 1, 0})).hit());
    // Sliding on the surface counts as touching from the start.
    EXPECT_EQ(shape_raycast(ground, ray({-5, 0, 0}, {5, 0, 0})).fraction, 0);
}

TEST(shape_raycast_test, compound_reports_child) {
    compound_shape compound;
    compound.add_shape(box_shape{1, 1, 1}, {-3, 0, 0});
    compound.add_shape(box_shape{1, 1, 1}, {3, 0, 0});
    compound.finish();
    auto r = shape_raycast(compound, ray({10, 0, 0}, {-10, 0, 0}));
    EXPECT_NEAR(r.fraction, scalar(0.3), 1e-6);
    auto info = std::get<compound_raycast_info>(r.info_var);
    EXPECT_EQ(info.child_index, 1u);
    EXPECT_EQ(std::get<box_raycast_info>(info.child_info_var).face_index, 0u);

    r = shape_raycast(compound, ray({-10, 0, 0}, {10, 0, 0}));
    EXPECT_EQ(std::get<compound_raycast_info>(r.info_var).child_index, 0u);

    // Rotated 90 degrees about z: child 1 sits at world +3y and its +x face looks up.
    auto orn = quaternion_axis_angle(vector3_z, half_pi);
    r = shape_raycast(compound, ray({0, 10, 0}, {0, -10, 0}, vector3_zero, orn));
    EXPECT_NEAR(r.fraction, scalar(0.3), 1e-6);
    expect_vector_near(r.normal, vector3_y, 1e-6);
    info = std::get<compound_raycast_info>(r.info_var);
    EXPECT_EQ(info.child_index, 1u);
    EXPECT_EQ(std::get<box_raycast_info>(info.child_info_var).face_index, 0u);

    EXPECT_FALSE(shape_raycast(compound, ray({0, 5, 0}, {0, -5, 0})).hit());
    r = shape_raycast(compound, ray({3, 0, 0}, {3, 0, 5}));
    EXPECT_EQ(r.fraction, 0);
    EXPECT_EQ(std::get<compound_raycast_info>(r.info_var).child_index, 1u);
    expect_vector_near(r.normal, -vector3_z, 1e-6);
}

TEST(shape_raycast_test, compound_with_tree_matches_brute_force) {
    std::mt19937 rng(31);
    compound_shape compound;
    for (int i = 0; i < 40; ++i) {
        auto p = edyn::test::random_vector(rng, -4, 4);
        if (i % 2 == 0) {
            compound.add_shape(sphere_shape{scalar(0.5)}, p);
        } else {
            compound.add_shape(capsule_shape{scalar(0.3), scalar(0.5), coordinate_axis::y}, p,
                               edyn::test::random_orientation(rng));
        }
    }
    compound.finish();
    ASSERT_FALSE(compound.tree.empty());
    int hits = 0;
    for (int trial = 0; trial < 300; ++trial) {
        auto pos = edyn::test::random_vector(rng, -1, 1);
        auto orn = edyn::test::random_orientation(rng);
        // Through the cloud of children, from either side.
        auto p0 = edyn::test::random_vector(rng, -8, 8);
        auto p1 = -p0 + edyn::test::random_vector(rng, -3, 3);
        auto r = shape_raycast(compound, ray(p0, p1, pos, orn));
        // Every child cast on its own at its world transform.
        auto best = raycast_miss_fraction;
        std::size_t best_child = 0;
        for (std::size_t i = 0; i < compound.children.size(); ++i) {
            const auto &child = compound.children[i];
            auto c = shape_raycast(
                child.shape, ray(p0, p1, to_world_space(child.position, pos, orn), orn * child.orientation));
            if (c.fraction < best) {
                best = c.fraction;
                best_child = i;
            }
        }
        ASSERT_EQ(r.hit(), best <= 1) << "trial " << trial;
        if (!r.hit()) continue;
        ++hits;
        EXPECT_NEAR(r.fraction, best, 1e-5) << "trial " << trial;
        EXPECT_EQ(std::get<compound_raycast_info>(r.info_var).child_index, best_child) << "trial " << trial;
    }
    EXPECT_GT(hits, 100);
}

TEST(shape_raycast_test, random_rays_against_containment) {
    std::mt19937 rng(41);
    check_random_rays(sphere_shape{scalar(0.8)}, rng, "sphere");
    check_random_rays(box_shape{scalar(0.4), scalar(1.1), scalar(0.7)}, rng, "box");
    for (auto axis : {coordinate_axis::x, coordinate_axis::y, coordinate_axis::z}) {
        check_random_rays(cylinder_shape{scalar(0.6), scalar(0.9), axis}, rng, "cylinder");
        check_random_rays(capsule_shape{scalar(0.5), scalar(0.8), axis}, rng, "capsule");
    }
    std::vector<vector3> cloud;
    for (int i = 0; i < 60; ++i)
        cloud.push_back(edyn::test::random_vector(rng, -1, 1) + vector3{scalar(0.3), 0, 0});
    check_random_rays(polyhedron_shape{cloud}, rng, "polyhedron");
    compound_shape compound;
    compound.add_shape(box_shape{scalar(0.5), scalar(0.5), scalar(0.5)}, {scalar(-0.6), 0, 0});
    compound.add_shape(cylinder_shape{scalar(0.4), scalar(0.8), coordinate_axis::z}, {scalar(0.7), 0, 0},
                       edyn::test::random_orientation(rng));
    compound.finish();
    check_random_rays(compound, rng, "compound");
}

TEST(shape_raycast_test, variant_dispatches) {
    auto box = box_shape{1, 2, 3};
    auto ctx = ray({10, 0, 0}, {-10, 0, 0});
    auto direct = shape_raycast(box, ctx);
    auto via_variant = shape_raycast(shapes_variant_t{box}, ctx);
    EXPECT_EQ(via_variant.fraction, direct.fraction);
    EXPECT_EQ(via_variant.normal, direct.normal);
    EXPECT_EQ(std::get<box_raycast_info>(via_variant.info_var).face_index, 0u);
    EXPECT_FALSE(shape_raycast(shapes_variant_t{sphere_shape{1}}, ray({5, 5, 5}, {6, 6, 6})).hit());
}
