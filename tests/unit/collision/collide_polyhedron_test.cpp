#include "collide_test_helpers.hpp"
#include "edyn/collision/detail/polyhedron_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/shapes/polyhedron_shape.hpp"
#include <functional>
#include <type_traits>

// collide() for every pair with a polyhedron. A box-shaped polyhedron must behave as the box
// it spans (against the box routines, in both argument orders); a tetrahedron and an irregular
// hull are checked against exact geometry; random placements compare the reported distance with
// brute force written here (signed distances by projection onto triangles, ternary searches
// along edges and over faces, and the largest gap over candidate and searched directions).

using namespace edyn;
using namespace collide_test;

namespace {

constexpr scalar polyhedron_tol = scalar(2e-5);

// Runs collide(a, b) and checks what every result must satisfy.
template<typename A, typename B>
collision_result collide_polyhedron_checked(const A &a, const B &b, const collision_context &ctx,
                                            scalar t = polyhedron_tol) {
    collision_result r;
    collide(a, b, ctx, r);
    expect_consistent(r, ctx, t);
    return r;
}

vector3 box_corner(const vector3 &he, int i) {
    return {i & 1 ? -he.x : he.x, i & 2 ? -he.y : he.y, i & 4 ? -he.z : he.z};
}

polyhedron_shape box_hull(const vector3 &he) {
    std::vector<vector3> points;
    for (int i = 0; i < 8; ++i)
        points.push_back(box_corner(he, i));
    return polyhedron_shape(points);
}

// Regular tetrahedron of circumradius sqrt(3) * s centred at the origin; face k is opposite
// vertex 3 - k.
polyhedron_shape tetrahedron(scalar s) {
    std::vector<vector3> v{{s, s, s}, {s, -s, -s}, {-s, s, -s}, {-s, -s, s}};
    return polyhedron_shape(v, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
}

// 20 points on a sheared ellipsoid, all of them vertices of their hull.
std::vector<vector3> irregular_points() {
    std::vector<vector3> points;
    for (int i = 0; i < 20; ++i) {
        auto y = 1 - 2 * (scalar(i) + scalar(0.5)) / 20;
        auto rho = std::sqrt(1 - y * y);
        auto phi = scalar(i) * scalar(2.399963229728653);
        vector3 p{rho * std::cos(phi) * scalar(0.6), y * scalar(0.4), rho * std::sin(phi) * scalar(0.5)};
        points.push_back(p + vector3{p.y * scalar(0.3), 0, 0} + vector3{0.05, -0.02, 0.03});
    }
    return points;
}

polyhedron_shape irregular_hull() { return polyhedron_shape(irregular_points()); }

// Independent geometry of a polyhedron placed at (pos, orn), from its vertices and face lists
// only.
struct placed_polyhedron {
    std::vector<vector3> vertices;              // World.
    std::vector<std::vector<vector3>> polygons; // World, counter-clockwise from outside.
    std::vector<std::pair<vector3, vector3>> edges;

    placed_polyhedron(const polyhedron_shape &shape, const vector3 &pos, const quaternion &orn) {
        const auto &mesh = *shape.mesh;
        for (auto &v : mesh.vertices)
            vertices.push_back(to_world_space(v, pos, orn));
        for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
            std::vector<vector3> polygon;
            for (auto i : mesh.face_indices(f))
                polygon.push_back(vertices[i]);
            for (std::size_t k = 0; k < polygon.size(); ++k) {
                // Each edge once: from the lower to the higher address in the vertex array.
                auto i0 = mesh.face_indices(f)[k], i1 = mesh.face_indices(f)[(k + 1) % polygon.size()];
                if (i0 < i1) edges.emplace_back(vertices[i0], vertices[i1]);
            }
            polygons.push_back(polygon);
        }
    }

    vector3 face_normal(std::size_t f) const {
        auto &p = polygons[f];
        return normalize(cross(p[1] - p[0], p[2] - p[0]));
    }
};

scalar point_triangle_distance(const vector3 &p, const vector3 &a, const vector3 &b, const vector3 &c) {
    auto n = normalize(cross(b - a, c - a));
    auto q = p - n * dot(p - a, n);
    auto inside = dot(cross(b - a, q - a), n) >= 0 && dot(cross(c - b, q - b), n) >= 0 &&
                  dot(cross(a - c, q - c), n) >= 0;
    if (inside) return std::abs(dot(p - a, n));
    return std::min(
        {point_segment_distance(a, b, p), point_segment_distance(b, c, p), point_segment_distance(c, a, p)});
}

// Signed distance from a world point: the nearest face plane inside, the nearest triangle outside.
scalar polyhedron_sdf(const placed_polyhedron &poly, const vector3 &p) {
    auto inside = -large_scalar;
    for (std::size_t f = 0; f < poly.polygons.size(); ++f) {
        inside = std::max(inside, dot(p - poly.polygons[f][0], poly.face_normal(f)));
    }
    if (inside <= 0) return inside;
    auto best = large_scalar;
    for (auto &polygon : poly.polygons) {
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
            best = std::min(best, point_triangle_distance(p, polygon[0], polygon[k], polygon[k + 1]));
        }
    }
    return best;
}

// Minimum of a convex function on [0, 1] by ternary search, to a parameter within 1e-7.
template<typename F>
scalar ternary_min(F &&f) {
    double lo = 0, hi = 1;
    for (int i = 0; i < 40; ++i) {
        auto m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        if (f(scalar(m1)) < f(scalar(m2)))
            hi = m2;
        else
            lo = m1;
    }
    return std::min({f(scalar((lo + hi) / 2)), f(scalar(0)), f(scalar(1))});
}

// Minimum of a convex function over a triangle, by ternary search nested in ternary search (the
// minimum over each segment from side to side is convex along the sides).
scalar convex_min_triangle(const std::function<scalar(const vector3 &)> &f, const vector3 &a,
                           const vector3 &b, const vector3 &c) {
    return ternary_min([&](scalar u) {
        auto p = lerp(a, b, u), q = lerp(a, c, u);
        return ternary_min([&](scalar v) { return f(lerp(p, q, v)); });
    });
}

// Smallest value of a convex signed distance over a polyhedron's surface (its minimum over the
// solid when that is positive: the distance of two disjoint convex shapes).
scalar min_over_surface(const placed_polyhedron &poly, const std::function<scalar(const vector3 &)> &sdf) {
    auto best = large_scalar;
    for (auto &polygon : poly.polygons) {
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
            best = std::min(best, convex_min_triangle(sdf, polygon[0], polygon[k], polygon[k + 1]));
        }
    }
    return best;
}

// Exact distance between two disjoint polyhedra: the closest pair holds a point of an edge of
// one of them, so the smallest signed distance along all edges finds it.
scalar polyhedra_distance(const placed_polyhedron &a, const placed_polyhedron &b) {
    auto best = large_scalar;
    for (auto &edge : a.edges) {
        best = std::min(
            best, convex_min([&](scalar t) { return polyhedron_sdf(b, lerp(edge.first, edge.second, t)); }));
    }
    for (auto &edge : b.edges) {
        best = std::min(
            best, convex_min([&](scalar t) { return polyhedron_sdf(a, lerp(edge.first, edge.second, t)); }));
    }
    return best;
}

std::vector<vector3> edge_directions(const placed_polyhedron &poly) {
    std::vector<vector3> dirs;
    for (auto &[e0, e1] : poly.edges)
        dirs.push_back(normalize(e1 - e0));
    return dirs;
}

// Face normals of A and B and the cross products of A's edge directions with `others`, plus
// random directions: the candidates of the separating-axis theorem.
std::vector<vector3> polyhedron_directions(const placed_polyhedron &a, const std::vector<vector3> &b_normals,
                                           const std::vector<vector3> &others, rng &random) {
    std::vector<vector3> dirs = b_normals;
    for (std::size_t f = 0; f < a.polygons.size(); ++f)
        dirs.push_back(a.face_normal(f));
    for (auto &e : edge_directions(a)) {
        for (auto &o : others) {
            auto c = cross(e, o);
            if (length(c) > scalar(1e-3)) dirs.push_back(normalize(c));
        }
    }
    for (int i = 0; i < 200; ++i)
        dirs.push_back(random.unit());
    return dirs;
}

std::vector<vector3> face_normals(const placed_polyhedron &poly) {
    std::vector<vector3> normals;
    for (std::size_t f = 0; f < poly.polygons.size(); ++f)
        normals.push_back(poly.face_normal(f));
    return normals;
}

// Largest gap over all unit directions between A's lowest and B's highest support, searched
// from the best dense directions and from `extra`; `support_a(n)` is A's support value along n.
scalar searched_gap(const std::function<scalar(const vector3 &)> &support_a,
                    const std::function<scalar(const vector3 &)> &support_b,
                    const std::vector<vector3> &extra = {}) {
    return searched_max_gap([&](const vector3 &n, bool) { return -support_a(-n) - support_b(n); }, extra, 10);
}

// The cylinder's support value along unit n, its radial part from |n x axis|: exact to rounding
// even where n nearly runs along the axis, where sqrt(1 - c^2) keeps only half the digits (in
// float, a tenth of a millimetre on a 0.4 m radius) and a search for the largest gap finds them.
scalar cylinder_support(const cylinder_shape &cylinder, const vector3 &pos, const quaternion &orn,
                        const vector3 &n) {
    auto axis = coordinate_axis_vector(cylinder.axis, orn);
    return dot(pos, n) + std::abs(dot(axis, n)) * cylinder.half_length +
           cylinder.radius * length(cross(n, axis));
}

scalar points_support(const std::vector<vector3> &points, const vector3 &n) {
    auto best = -large_scalar;
    for (auto &p : points)
        best = std::max(best, dot(p, n));
    return best;
}

quaternion random_orientation(rng &random) {
    for (;;) {
        quaternion q{random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1),
                     random.uniform(-1, 1)};
        if (length(q) > scalar(0.2)) return normalize(q);
    }
}

// Whether two results hold the same points with A and B exchanged.
void expect_swapped(const collision_result &r, const collision_result &s, scalar t, const std::string &what) {
    ASSERT_EQ(r.num_points, s.num_points) << what;
    for (std::size_t i = 0; i < r.num_points; ++i) {
        auto &p = r.point[i];
        auto found = false;
        for (std::size_t j = 0; j < s.num_points && !found; ++j) {
            auto &q = s.point[j];
            found = distance(p.pivotA, q.pivotB) <= t && distance(p.pivotB, q.pivotA) <= t &&
                    distance(p.normal, -q.normal) <= t && std::abs(p.distance - q.distance) <= t &&
                    p.featureA == q.featureB && p.featureB == q.featureA;
        }
        EXPECT_TRUE(found) << what << ": point " << i << " at " << str(p.pivotA) << " distance " << p.distance
                           << " has no swapped twin";
    }
}

// collide(box-shaped polyhedron, other) against collide(box, other), in both orders: the same
// number of points, the same deepest distance and normal, the same points when `same_points`.
template<typename S>
void expect_same_as_box(const vector3 &he, const S &other, const collision_context &ctx,
                        const std::string &what, bool same_points = true) {
    auto hull = box_hull(he);
    box_shape box{he};
    auto compare = [&](const collision_result &rp, const collision_result &rb, bool poly_is_a,
                       const char *order) {
        ASSERT_EQ(rp.num_points, rb.num_points) << what << " " << order;
        if (rp.num_points == 0) return;
        auto ip = deepest_index(rp), ib = deepest_index(rb);
        EXPECT_NEAR(rp.point[ip].distance, rb.point[ib].distance, polyhedron_tol) << what << " " << order;
        expect_vec_near(rp.point[ip].normal, rb.point[ib].normal, polyhedron_tol);
        if (!same_points) return;
        for (std::size_t i = 0; i < rp.num_points; ++i) {
            auto found = false;
            for (std::size_t j = 0; j < rb.num_points && !found; ++j) {
                auto &p = rp.point[i];
                auto &q = rb.point[j];
                // Same points, and the other shape's features as the box routine names them.
                found = distance(p.pivotA, q.pivotA) <= 1e-4 && distance(p.pivotB, q.pivotB) <= 1e-4 &&
                        std::abs(p.distance - q.distance) <= 1e-4 &&
                        (poly_is_a ? p.featureB == q.featureB : p.featureA == q.featureA);
            }
            EXPECT_TRUE(found) << what << " " << order << ": point " << i << " " << str(rp.point[i].pivotA)
                               << " is not among the box's";
        }
        // The polyhedron reports no features.
        for (std::size_t i = 0; i < rp.num_points; ++i) {
            EXPECT_FALSE((poly_is_a ? rp.point[i].featureA : rp.point[i].featureB).has_value()) << what;
        }
    };
    compare(collide_polyhedron_checked(hull, other, ctx), collide_polyhedron_checked(box, other, ctx), true,
            "(polyhedron, other)");
    auto swapped = swap_context(ctx);
    compare(collide_polyhedron_checked(other, hull, swapped), collide_polyhedron_checked(other, box, swapped),
            false, "(other, polyhedron)");
}

// The configurations every pair is compared in, for a box-shaped polyhedron of half extents
// `he` at the origin (turned by `orn`) and another shape at `pos` (turned by `orn_b`).
collision_context at(const vector3 &pos_b, const quaternion &orn_b = quaternion_identity,
                     const quaternion &orn_a = quaternion_identity, scalar threshold = scalar(0.02)) {
    return {vector3_zero, orn_a, pos_b, orn_b, threshold};
}

const vector3 cube_he{0.4, 0.3, 0.5};

} // namespace

// A box-shaped polyhedron against every shape, as the box.

TEST(collide_polyhedron_test, box_hull_against_box_as_box_box) {
    box_shape big{{1, 0.5, 1}};
    auto rest_y = -(cube_he.y + big.half_extents.y);
    auto turn = quaternion_axis_angle(vector3_y, 0.3);
    expect_same_as_box(cube_he, big, at(vec(-0.1, rest_y + 0.005, 0.05), turn), "resting");
    expect_same_as_box(cube_he, big, at(vec(-0.1, rest_y - 0.01, 0.05), turn), "apart within");
    expect_same_as_box(cube_he, big, at(vec(-0.1, rest_y - 0.03, 0.05), turn), "apart beyond");
    expect_same_as_box(cube_he, big, at(vec(-0.1, rest_y + 0.2, 0.05), turn), "deep");
    // A's edge along z down, B's edge along x up.
    auto a_edge = quaternion_axis_angle(vector3_z, pi / 4), b_edge = quaternion_axis_angle(vector3_x, pi / 4);
    auto edge_y = -(box_projection_radius(cube_he, rotate(conjugate(a_edge), vector3_y)) +
                    box_projection_radius(big.half_extents, rotate(conjugate(b_edge), vector3_y)));
    expect_same_as_box(cube_he, big, at(vec(0, edge_y + 0.01, 0), b_edge, a_edge), "edge on edge");
    // A's vertex down on B's face.
    auto a_vertex = shortest_arc(normalize(-cube_he), -vector3_y);
    expect_same_as_box(cube_he, big,
                       at(vec(0.1, -(length(cube_he) + 0.5) + 0.004, 0), quaternion_identity, a_vertex),
                       "vertex on face");
    rng random(7);
    for (int i = 0; i < 20; ++i) {
        auto orn = random_orientation(random);
        auto y = -(box_projection_radius(cube_he, rotate(conjugate(orn), vector3_y)) + 0.5);
        expect_same_as_box(
            cube_he, big,
            at(vec(random.uniform(-0.3, 0.3), y + 0.01, random.uniform(-0.3, 0.3)), quaternion_identity, orn),
            "rotated " + std::to_string(i));
    }
}

TEST(collide_polyhedron_test, box_hulls_as_box_box) {
    // Both shapes polyhedra against both shapes boxes.
    vector3 big_he{1, 0.5, 1};
    auto a = box_hull(cube_he), b = box_hull(big_he);
    box_shape box_a{cube_he}, box_b{big_he};
    auto check = [&](const collision_context &ctx, const std::string &what) {
        auto rp = collide_polyhedron_checked(a, b, ctx);
        auto rb = collide_polyhedron_checked(box_a, box_b, ctx);
        ASSERT_EQ(rp.num_points, rb.num_points) << what;
        if (rp.num_points == 0) return;
        EXPECT_NEAR(min_distance(rp), min_distance(rb), polyhedron_tol) << what;
        expect_vec_near(rp.point[deepest_index(rp)].normal, rb.point[deepest_index(rb)].normal,
                        polyhedron_tol);
        for (std::size_t i = 0; i < rp.num_points; ++i) {
            EXPECT_FALSE(rp.point[i].featureA.has_value());
            EXPECT_FALSE(rp.point[i].featureB.has_value());
        }
    };
    auto rest_y = -(cube_he.y + big_he.y);
    auto turn = quaternion_axis_angle(vector3_y, 0.3);
    check(at(vec(-0.1, rest_y + 0.005, 0.05), turn), "resting");
    check(at(vec(-0.1, rest_y - 0.01, 0.05), turn), "apart within");
    check(at(vec(-0.1, rest_y - 0.03, 0.05), turn), "apart beyond");
    check(at(vec(-0.1, rest_y + 0.2, 0.05), turn), "deep");
    auto a_edge = quaternion_axis_angle(vector3_z, pi / 4), b_edge = quaternion_axis_angle(vector3_x, pi / 4);
    auto edge_y = -(box_projection_radius(cube_he, rotate(conjugate(a_edge), vector3_y)) +
                    box_projection_radius(big_he, rotate(conjugate(b_edge), vector3_y)));
    check(at(vec(0, edge_y + 0.01, 0), b_edge, a_edge), "edge on edge");
    check(at(vec(0, edge_y - 0.015, 0), b_edge, a_edge), "edge apart");
    auto a_vertex = shortest_arc(normalize(-cube_he), -vector3_y);
    check(at(vec(0.1, -(length(cube_he) + 0.5) + 0.004, 0), quaternion_identity, a_vertex), "vertex on face");
    // Corner to corner apart: the exact closest pair, not the face axis' lower bound.
    check(at(-(cube_he + big_he + vector3{0.005, 0.005, 0.005})), "corner to corner");
    rng random(8);
    for (int i = 0; i < 20; ++i) {
        auto orn = random_orientation(random);
        auto y = -(box_projection_radius(cube_he, rotate(conjugate(orn), vector3_y)) + 0.5);
        check(
            at(vec(random.uniform(-0.3, 0.3), y + 0.01, random.uniform(-0.3, 0.3)), quaternion_identity, orn),
            "rotated " + std::to_string(i));
    }
}

TEST(collide_polyhedron_test, box_hull_against_sphere_as_box_sphere) {
    sphere_shape sphere{0.3};
    auto top = cube_he.y + sphere.radius;
    expect_same_as_box(cube_he, sphere, at(vec(0.05, top - 0.01, 0.1)), "over face");
    expect_same_as_box(cube_he, sphere, at(vec(0.05, top + 0.01, 0.1)), "apart within");
    expect_same_as_box(cube_he, sphere, at(vec(0.05, top + 0.03, 0.1)), "apart beyond");
    expect_same_as_box(cube_he, sphere, at(vec(cube_he.x + 0.2, cube_he.y + 0.2, 0)), "over edge");
    expect_same_as_box(cube_he, sphere, at(cube_he + vector3{0.15, 0.15, 0.15}), "over vertex");
    expect_same_as_box(cube_he, sphere, at(vec(0.1, 0.2, 0.05)), "centre inside");
    rng random(9);
    for (int i = 0; i < 20; ++i) {
        expect_same_as_box(cube_he, sphere,
                           at(random.vec(-0.8, 0.8), quaternion_identity, random_orientation(random)),
                           "rotated " + std::to_string(i));
    }
}

TEST(collide_polyhedron_test, box_hull_against_plane_as_box_plane) {
    auto plane_at = [](scalar constant) { return plane_shape{vector3_y, constant}; };
    expect_same_as_box(cube_he, plane_at(-cube_he.y + 0.005), at(vector3_zero), "resting");
    expect_same_as_box(cube_he, plane_at(-cube_he.y - 0.01), at(vector3_zero), "apart within");
    expect_same_as_box(cube_he, plane_at(-cube_he.y - 0.03), at(vector3_zero), "apart beyond");
    expect_same_as_box(cube_he, plane_at(-cube_he.y + 0.2), at(vector3_zero), "deep");
    auto edge = quaternion_axis_angle(vector3_z, pi / 4);
    auto edge_low = box_projection_radius(cube_he, rotate(conjugate(edge), vector3_y));
    expect_same_as_box(cube_he, plane_at(-edge_low + 0.005), at(vector3_zero, quaternion_identity, edge),
                       "edge");
    auto vertex = shortest_arc(normalize(-cube_he), -vector3_y);
    expect_same_as_box(cube_he, plane_at(-length(cube_he) + 0.005),
                       at(vector3_zero, quaternion_identity, vertex), "vertex");
    rng random(10);
    for (int i = 0; i < 20; ++i) {
        auto orn = random_orientation(random);
        auto low = box_projection_radius(cube_he, rotate(conjugate(orn), vector3_y));
        expect_same_as_box(cube_he, plane_at(-low + random.uniform(-0.03, 0.05)),
                           at(vector3_zero, quaternion_identity, orn), "rotated " + std::to_string(i));
    }
}

TEST(collide_polyhedron_test, box_hull_against_capsule_as_box_capsule) {
    capsule_shape capsule{0.1, 0.3, coordinate_axis::x};
    auto top = cube_he.y + capsule.radius;
    expect_same_as_box(cube_he, capsule, at(vec(0.02, top - 0.005, 0.1)), "lying on a face");
    expect_same_as_box(cube_he, capsule, at(vec(0.02, top + 0.01, 0.1)), "apart within");
    expect_same_as_box(cube_he, capsule, at(vec(0.02, top + 0.03, 0.1)), "apart beyond");
    auto standing = quaternion_axis_angle(vector3_z, pi / 2);
    expect_same_as_box(cube_he, capsule, at(vec(0.1, top + capsule.half_length - 0.005, 0), standing),
                       "standing");
    auto along_z = quaternion_axis_angle(vector3_y, pi / 2);
    expect_same_as_box(cube_he, capsule, at(vec(cube_he.x + 0.07, cube_he.y + 0.07, 0), along_z),
                       "along an edge");
    expect_same_as_box(cube_he, capsule, at(vec(0, 0.2, 0)), "segment inside");
    rng random(11);
    for (int i = 0; i < 20; ++i) {
        expect_same_as_box(cube_he, capsule,
                           at(random.vec(-0.6, 0.6), random_orientation(random), random_orientation(random)),
                           "rotated " + std::to_string(i), false);
    }
}

TEST(collide_polyhedron_test, box_hull_against_cylinder_as_box_cylinder) {
    cylinder_shape cylinder{0.2, 0.15, coordinate_axis::y};
    auto top = cube_he.y + cylinder.half_length;
    expect_same_as_box(cube_he, cylinder, at(vec(0.05, top - 0.005, 0.1)), "standing");
    expect_same_as_box(cube_he, cylinder, at(vec(0.05, top + 0.01, 0.1)), "apart within");
    expect_same_as_box(cube_he, cylinder, at(vec(0.05, top + 0.03, 0.1)), "apart beyond");
    expect_same_as_box(cube_he, cylinder, at(vec(0.05, top - 0.1, 0.1)), "deep");
    auto lying = quaternion_axis_angle(vector3_z, pi / 2);
    expect_same_as_box(cube_he, cylinder, at(vec(0, cube_he.y + cylinder.radius - 0.005, 0), lying), "lying");
    auto tilt = quaternion_axis_angle(vector3_z, 0.3);
    auto low = cylinder.half_length * std::cos(scalar(0.3)) + cylinder.radius * std::sin(scalar(0.3));
    expect_same_as_box(cube_he, cylinder, at(vec(0, cube_he.y + low - 0.005, 0), tilt), "tilted rim");
    expect_same_as_box(cube_he, cylinder, at(vec(cube_he.x, top - 0.005, cube_he.z)), "cap over a corner",
                       false);
    rng random(12);
    for (int i = 0; i < 20; ++i) {
        expect_same_as_box(cube_he, cylinder,
                           at(random.vec(-0.6, 0.6), random_orientation(random), random_orientation(random)),
                           "rotated " + std::to_string(i), false);
    }
}

// A tetrahedron against every shape.

namespace {

constexpr scalar tet_s = scalar(0.5);
const scalar tet_inradius = tet_s / std::sqrt(scalar(3));
const scalar tet_circumradius = tet_s * std::sqrt(scalar(3));
const vector3 tet_n0 = normalize(vector3{1, 1, -1}); // Normal of face 0 (vertices 0, 1, 2).

// Turns the tetrahedron so that face 3 (vertices 1, 3, 2) faces down, or vertex 0 points down,
// or face 0 faces up.
const quaternion tet_face_down = shortest_arc(normalize(vector3{-1, -1, -1}), -vector3_y);
const quaternion tet_vertex_down = shortest_arc(normalize(vector3{1, 1, 1}), -vector3_y);
const quaternion tet_face_up = shortest_arc(tet_n0, vector3_y);

// Distance from p to the nearest edge of a triangle.
scalar distance_to_boundary(const vector3 &p, const vector3 &a, const vector3 &b, const vector3 &c) {
    return std::min(
        {point_segment_distance(a, b, p), point_segment_distance(b, c, p), point_segment_distance(c, a, p)});
}

} // namespace

TEST(collide_polyhedron_test, tetrahedron_against_plane) {
    auto tet = tetrahedron(tet_s);
    auto r = collide_polyhedron_checked(tet, plane_shape{vector3_y, -tet_inradius + scalar(0.005)},
                                        at(vector3_zero, quaternion_identity, tet_face_down));
    ASSERT_EQ(r.num_points, 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.005, polyhedron_tol);
        expect_vec_near(r.point[i].normal, vector3_y, polyhedron_tol);
        // Vertices 1, 2, 3: not the one at (s, s, s).
        EXPECT_GT(distance(r.point[i].pivotA, vector3{tet_s, tet_s, tet_s}), 0.1);
        EXPECT_NEAR(length(r.point[i].pivotA), tet_circumradius, polyhedron_tol);
    }
    r = collide_polyhedron_checked(tet, plane_shape{vector3_y, -tet_circumradius + scalar(0.004)},
                                   at(vector3_zero, quaternion_identity, tet_vertex_down));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.004, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, {tet_s, tet_s, tet_s}, polyhedron_tol);
    expect_vec_near(r.point[0].pivotB, {0, -tet_circumradius + scalar(0.004), 0}, polyhedron_tol);
    // The plane's own orientation does not matter; the other order swaps the roles.
    auto s = collide_polyhedron_checked(plane_shape{vector3_y, -tet_circumradius + scalar(0.004)}, tet,
                                        swap_context(at(vector3_zero, quaternion_identity, tet_vertex_down)));
    ASSERT_EQ(s.num_points, 1u);
    expect_vec_near(s.point[0].normal, -vector3_y, polyhedron_tol);
    expect_vec_near(s.point[0].pivotB, {tet_s, tet_s, tet_s}, polyhedron_tol);
}

TEST(collide_polyhedron_test, tetrahedron_against_sphere) {
    auto tet = tetrahedron(tet_s);
    sphere_shape sphere{0.2};
    // Over the centre of face 0.
    auto r =
        collide_polyhedron_checked(tet, sphere, at(tet_n0 * (tet_inradius + sphere.radius - scalar(0.01))));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.01, polyhedron_tol);
    expect_vec_near(r.point[0].normal, -tet_n0, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, tet_n0 * tet_inradius, polyhedron_tol);
    expect_vec_near(r.point[0].pivotB, -tet_n0 * sphere.radius, polyhedron_tol);
    // Beyond vertex 0, apart within the threshold.
    auto v0_dir = normalize(vector3_one);
    r = collide_polyhedron_checked(tet, sphere,
                                   at(v0_dir * (tet_circumradius + sphere.radius + scalar(0.01))));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0.01, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, {tet_s, tet_s, tet_s}, polyhedron_tol);
    // Beyond the middle of edge 0-1, whose faces' normals straddle +x.
    r = collide_polyhedron_checked(tet, sphere, at(vec(tet_s + sphere.radius + 0.005, 0, 0)));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0.005, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, {tet_s, 0, 0}, polyhedron_tol);
    expect_vec_near(r.point[0].normal, -vector3_x, polyhedron_tol);
    EXPECT_EQ(collide_polyhedron_checked(tet, sphere, at(vec(tet_s + sphere.radius + 0.03, 0, 0))).num_points,
              0u);
    // Centre inside, nearest to face 0: out through it.
    auto center = vector3{0.1, 0.05, 0} * tet_s;
    r = collide_polyhedron_checked(tet, sphere, at(center));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, dot(center, tet_n0) - tet_inradius - sphere.radius, polyhedron_tol);
    expect_vec_near(r.point[0].normal, -tet_n0, polyhedron_tol);
}

TEST(collide_polyhedron_test, tetrahedron_against_box) {
    auto tet = tetrahedron(tet_s);
    box_shape big{{1, 0.5, 1}};
    auto r = collide_polyhedron_checked(
        tet, big, at(vec(0.1, -(tet_inradius + 0.5) + 0.005, 0), quaternion_identity, tet_face_down));
    ASSERT_EQ(r.num_points, 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.005, polyhedron_tol);
        expect_vec_near(r.point[i].normal, vector3_y, polyhedron_tol);
        EXPECT_NEAR(length(r.point[i].pivotA), tet_circumradius, polyhedron_tol);
        EXPECT_NEAR(r.point[i].pivotB.y, 0.5, polyhedron_tol);
        EXPECT_FALSE(r.point[i].featureA.has_value());
        expect_feature(r.point[i].featureB, box_feature::face, 2);
    }
    r = collide_polyhedron_checked(
        tet, big, at(vec(0.1, -(tet_circumradius + 0.5) + 0.004, 0), quaternion_identity, tet_vertex_down));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.004, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, {tet_s, tet_s, tet_s}, polyhedron_tol);
    expect_feature(r.point[0].featureB, box_feature::face, 2);
    // Box vertex into the middle of face 0.
    auto box_down = shortest_arc(normalize(vector3_one), -tet_n0);
    box_shape small{{0.1, 0.1, 0.1}};
    auto center = tet_n0 * (tet_inradius + length(small.half_extents) - scalar(0.003));
    r = collide_polyhedron_checked(tet, small, at(center, box_down));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.003, polyhedron_tol);
    expect_vec_near(r.point[0].normal, -tet_n0, polyhedron_tol);
    expect_vec_near(r.point[0].pivotB, small.half_extents, polyhedron_tol);
    expect_feature(r.point[0].featureB, box_feature::vertex, 0);
}

TEST(collide_polyhedron_test, tetrahedron_against_tetrahedron) {
    auto tet = tetrahedron(tet_s);
    // A's vertex 0 down into the middle of B's upward face 0.
    auto r = collide_polyhedron_checked(
        tet, tet, at(vec(0, -(tet_circumradius + tet_inradius) + 0.003, 0), tet_face_up, tet_vertex_down));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.003, polyhedron_tol);
    expect_vec_near(r.point[0].normal, vector3_y, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, {tet_s, tet_s, tet_s}, polyhedron_tol);
    // Face on face, B turned about the vertical: the overlap of two triangles (a hexagon),
    // reduced to four of its corners.
    auto turned = quaternion_axis_angle(vector3_y, 0.5) * tet_face_up;
    r = collide_polyhedron_checked(tet, tet,
                                   at(vec(0.02, -2 * tet_inradius + 0.005, 0), turned, tet_face_down));
    ASSERT_EQ(r.num_points, 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.005, polyhedron_tol);
        expect_vec_near(r.point[i].normal, vector3_y, polyhedron_tol);
        // On both faces' planes.
        EXPECT_NEAR(to_world_space(r.point[i].pivotA, vector3_zero, tet_face_down).y, -tet_inradius,
                    polyhedron_tol);
    }
    // Apart beyond the threshold.
    EXPECT_EQ(collide_polyhedron_checked(tet, tet,
                                         at(vec(0.02, -2 * tet_inradius - 0.03, 0), turned, tet_face_down))
                  .num_points,
              0u);
}

TEST(collide_polyhedron_test, tetrahedron_against_capsule) {
    auto tet = tetrahedron(tet_s);
    // Face 0 up; a short capsule lying on its middle, a long one across it.
    capsule_shape short_capsule{0.1, 0.2, coordinate_axis::x};
    auto r = collide_polyhedron_checked(
        tet, short_capsule, at(vec(0, tet_inradius + 0.1 - 0.005, 0), quaternion_identity, tet_face_up));
    ASSERT_EQ(r.num_points, 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.005, polyhedron_tol);
        expect_vec_near(r.point[i].normal, -vector3_y, polyhedron_tol);
        // The ends of the side line (the surface faces the face there, not along the axis).
        EXPECT_NEAR(std::abs(r.point[i].pivotB.x), 0.2, polyhedron_tol);
        expect_feature(r.point[i].featureB, capsule_feature::side, 0);
    }
    capsule_shape long_capsule{0.1, 1.5, coordinate_axis::x};
    r = collide_polyhedron_checked(
        tet, long_capsule, at(vec(0, tet_inradius + 0.1 - 0.005, 0), quaternion_identity, tet_face_up));
    ASSERT_EQ(r.num_points, 2u);
    auto v = [&](int i) {
        vector3 corners[3] = {{tet_s, tet_s, tet_s}, {tet_s, -tet_s, -tet_s}, {-tet_s, tet_s, -tet_s}};
        return corners[i];
    };
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.005, polyhedron_tol);
        // Where the segment leaves the face: on the triangle's boundary.
        EXPECT_NEAR(distance_to_boundary(r.point[i].pivotA, v(0), v(1), v(2)), 0, polyhedron_tol);
        expect_feature(r.point[i].featureB, capsule_feature::side, 0);
    }
    // Standing on vertex 0.
    auto standing = quaternion_axis_angle(vector3_z, pi / 2);
    auto vertex_up = quaternion_axis_angle(vector3_x, pi) * tet_vertex_down;
    r = collide_polyhedron_checked(tet, short_capsule,
                                   at(vec(0, tet_circumradius + 0.3 - 0.002, 0), standing, vertex_up));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.002, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, {tet_s, tet_s, tet_s}, polyhedron_tol);
}

TEST(collide_polyhedron_test, tetrahedron_against_cylinder) {
    auto tet = tetrahedron(tet_s);
    // A narrow cylinder standing on face 0: its cap lies inside the triangle, four rim points.
    cylinder_shape narrow{0.15, 0.2, coordinate_axis::y};
    auto r = collide_polyhedron_checked(
        tet, narrow, at(vec(0, tet_inradius + 0.2 - 0.005, 0), quaternion_identity, tet_face_up));
    ASSERT_EQ(r.num_points, 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.005, polyhedron_tol);
        expect_vec_near(r.point[i].normal, -vector3_y, polyhedron_tol);
        EXPECT_NEAR(std::hypot(r.point[i].pivotB.x, r.point[i].pivotB.z), 0.15, polyhedron_tol);
        expect_feature(r.point[i].featureB, cylinder_feature::face, 1);
    }
    // A wide one covers the triangle: its three corners.
    cylinder_shape wide{1.2, 0.2, coordinate_axis::y};
    r = collide_polyhedron_checked(
        tet, wide, at(vec(0, tet_inradius + 0.2 - 0.005, 0), quaternion_identity, tet_face_up));
    ASSERT_EQ(r.num_points, 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.005, polyhedron_tol);
        EXPECT_NEAR(length(r.point[i].pivotA), tet_circumradius, polyhedron_tol);
    }
    // Lying on face 0 along x: the side line's two ends over the triangle.
    auto lying = quaternion_axis_angle(vector3_z, pi / 2);
    cylinder_shape short_cylinder{0.1, 0.15, coordinate_axis::y};
    r = collide_polyhedron_checked(tet, short_cylinder,
                                   at(vec(0, tet_inradius + 0.1 - 0.005, 0), lying, tet_face_up));
    ASSERT_EQ(r.num_points, 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.005, polyhedron_tol);
        EXPECT_NEAR(std::abs(r.point[i].pivotB.y), 0.15, polyhedron_tol);
        expect_feature(r.point[i].featureB, cylinder_feature::side_edge, 0);
    }
    // Rim on vertex 0 pointing up.
    auto up = quaternion_axis_angle(vector3_x, pi) * tet_vertex_down;
    r = collide_polyhedron_checked(tet, narrow,
                                   at(vec(0.05, tet_circumradius + 0.2 - 0.004, 0), quaternion_identity, up));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.004, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, {tet_s, tet_s, tet_s}, polyhedron_tol);
    expect_feature(r.point[0].featureB, cylinder_feature::face, 1);
}

// An irregular hull against every shape, on its face 0.

namespace {

struct hull_face {
    vector3 centroid;
    vector3 normal;
    scalar inradius; // Distance from the centroid to the nearest edge.
};

hull_face face_of(const polyhedron_shape &hull, std::size_t f) {
    const auto &mesh = *hull.mesh;
    hull_face face{vector3_zero, vector3_zero, large_scalar};
    auto idx = mesh.face_indices(f);
    for (auto i : idx)
        face.centroid += mesh.vertices[i];
    face.centroid /= scalar(idx.size());
    auto &p = mesh.vertices;
    face.normal = normalize(cross(p[idx[1]] - p[idx[0]], p[idx[2]] - p[idx[0]]));
    for (std::size_t k = 0; k < idx.size(); ++k) {
        face.inradius = std::min(
            face.inradius, point_segment_distance(p[idx[k]], p[idx[(k + 1) % idx.size()]], face.centroid));
    }
    return face;
}

} // namespace

TEST(collide_polyhedron_test, irregular_hull_against_plane_and_sphere) {
    auto hull = irregular_hull();
    auto points = irregular_points();
    auto lowest = *std::min_element(points.begin(), points.end(), [](auto &a, auto &b) { return a.y < b.y; });
    auto r =
        collide_polyhedron_checked(hull, plane_shape{vector3_y, lowest.y + scalar(0.005)}, at(vector3_zero));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.005, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, lowest, polyhedron_tol);

    auto face = face_of(hull, 0);
    sphere_shape sphere{0.2};
    r = collide_polyhedron_checked(hull, sphere,
                                   at(face.centroid + face.normal * (sphere.radius - scalar(0.01))));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.01, polyhedron_tol);
    expect_vec_near(r.point[0].normal, -face.normal, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, face.centroid, polyhedron_tol);
}

TEST(collide_polyhedron_test, irregular_hull_against_box_and_polyhedron) {
    auto hull = irregular_hull();
    auto face = face_of(hull, 0);
    // A small box's vertex 0 into the face's centroid.
    box_shape small{{0.05, 0.04, 0.03}};
    auto box_down = shortest_arc(normalize(small.half_extents), -face.normal);
    auto r = collide_polyhedron_checked(
        hull, small,
        at(face.centroid + face.normal * (length(small.half_extents) - scalar(0.003)), box_down));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.003, polyhedron_tol);
    expect_vec_near(r.point[0].normal, -face.normal, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, face.centroid, polyhedron_tol);
    expect_vec_near(r.point[0].pivotB, small.half_extents, polyhedron_tol);
    expect_feature(r.point[0].featureB, box_feature::vertex, 0);
    // A small tetrahedron's vertex 0 likewise.
    auto tet = tetrahedron(0.1);
    auto tet_down = shortest_arc(normalize(vector3_one), -face.normal);
    auto tip = std::sqrt(scalar(3)) * scalar(0.1);
    r = collide_polyhedron_checked(hull, tet,
                                   at(face.centroid + face.normal * (tip - scalar(0.003)), tet_down));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.003, polyhedron_tol);
    expect_vec_near(r.point[0].normal, -face.normal, polyhedron_tol);
    expect_vec_near(r.point[0].pivotB, {0.1, 0.1, 0.1}, polyhedron_tol);
    // Two copies resting vertex to vertex, apart: the exact closest pair.
    auto points = irregular_points();
    auto top = *std::max_element(points.begin(), points.end(), [](auto &a, auto &b) { return a.y < b.y; });
    auto flip = quaternion_axis_angle(vector3_z, pi);
    // B upside down, its top vertex (now its lowest) 0.01 above A's top vertex.
    auto pos_b = top + vec(0, 0.01, 0) - rotate(flip, top);
    r = collide_polyhedron_checked(hull, hull, at(pos_b, flip));
    auto expected = polyhedra_distance(placed_polyhedron(hull, vector3_zero, quaternion_identity),
                                       placed_polyhedron(hull, pos_b, flip));
    EXPECT_GT(expected, 0);
    EXPECT_LE(expected, 0.01 + polyhedron_tol);
    ASSERT_GE(r.num_points, 1u);
    EXPECT_NEAR(min_distance(r), expected, 1e-4);
}

TEST(collide_polyhedron_test, irregular_hull_against_capsule_and_cylinder) {
    auto hull = irregular_hull();
    auto face = face_of(hull, 0);
    // A capsule standing on the face's centroid.
    capsule_shape capsule{0.05, 0.2, coordinate_axis::x};
    auto standing = shortest_arc(vector3_x, face.normal);
    auto r =
        collide_polyhedron_checked(hull, capsule, at(face.centroid + face.normal * (0.25 - 0.005), standing));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.005, polyhedron_tol);
    expect_vec_near(r.point[0].pivotA, face.centroid, polyhedron_tol);
    expect_feature(r.point[0].featureB, capsule_feature::hemisphere, 1);
    // A cylinder standing on it with its cap inside the face: four rim points.
    ASSERT_GT(face.inradius, 0.02);
    cylinder_shape cylinder{face.inradius * scalar(0.5), 0.1, coordinate_axis::y};
    auto upright = shortest_arc(vector3_y, face.normal);
    r = collide_polyhedron_checked(hull, cylinder,
                                   at(face.centroid + face.normal * scalar(0.1 - 0.005), upright));
    ASSERT_EQ(r.num_points, 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.005, polyhedron_tol);
        expect_vec_near(r.point[i].normal, -face.normal, polyhedron_tol);
        EXPECT_NEAR(std::hypot(r.point[i].pivotB.x, r.point[i].pivotB.z), cylinder.radius, polyhedron_tol);
        expect_feature(r.point[i].featureB, cylinder_feature::face, 1);
    }
}

// Random placements against brute force.

namespace {

polyhedron_shape random_hull(rng &random, int i) {
    switch (i % 4) {
    case 0:
        return irregular_hull();
    case 1:
        return tetrahedron(random.uniform(0.1, 0.4));
    case 2:
        return box_hull(random.vec(0.1, 0.5));
    default: {
        std::vector<vector3> points;
        auto scale = random.vec(0.15, 0.5);
        auto count = 5 + int(random.uniform(0, 12));
        for (int k = 0; k < count; ++k)
            points.push_back(random.vec(-1, 1) * scale);
        return polyhedron_shape(points);
    }
    }
}

collision_context random_context(rng &random, scalar spread) {
    return {random.vec(-spread, spread), random_orientation(random), random.vec(-spread, spread),
            random_orientation(random), random.uniform(0, 0.2)};
}

// Checks a reported minimum against the exact distance of apart shapes: no points beyond the
// threshold, some within it, and the exact value.
void expect_apart(const collision_result &r, scalar expected, scalar threshold, int i) {
    if (expected > threshold + 1e-4) {
        EXPECT_EQ(r.num_points, 0u) << "case " << i << " distance " << expected;
        return;
    }
    if (expected < threshold - 1e-4) {
        ASSERT_GE(r.num_points, 1u) << "case " << i << " distance " << expected;
    }
    if (r.num_points > 0) {
        EXPECT_NEAR(min_distance(r), expected, 1e-4) << "case " << i;
    }
}

scalar cylinder_sdf(const cylinder_shape &c, const vector3 &pos, const quaternion &orn, const vector3 &x) {
    auto p = to_object_space(x, pos, orn);
    auto k = int(c.axis);
    auto radial = p;
    radial[k] = 0;
    auto dx = std::abs(p[k]) - c.half_length;
    auto dr = length(radial) - c.radius;
    if (dx <= 0 && dr <= 0) return std::max(dx, dr);
    return std::hypot(std::max(dx, scalar(0)), std::max(dr, scalar(0)));
}

} // namespace

TEST(collide_polyhedron_test, random_polyhedron_sphere_matches_brute_force) {
    rng random(51);
    int apart = 0, overlapping = 0;
    for (int i = 0; i < 400; ++i) {
        auto hull = random_hull(random, i);
        sphere_shape sphere{random.uniform(0.05, 0.4)};
        auto ctx = random_context(random, 0.6);
        placed_polyhedron poly(hull, ctx.posA, ctx.ornA);
        auto expected = polyhedron_sdf(poly, ctx.posB) - sphere.radius;
        auto r = collide_polyhedron_checked(hull, sphere, ctx, 1e-4);
        expect_apart(r, expected, ctx.threshold, i);
        (expected > 0 ? apart : overlapping) += r.num_points > 0;
        ASSERT_LE(r.num_points, 1u);
        if (r.num_points == 1) {
            EXPECT_NEAR(polyhedron_sdf(poly, to_world_space(r.point[0].pivotA, ctx.posA, ctx.ornA)), 0, 1e-4);
            EXPECT_NEAR(length(r.point[0].pivotB), sphere.radius, 1e-4);
        }
    }
    EXPECT_GT(apart, 20);
    EXPECT_GT(overlapping, 80);
}

TEST(collide_polyhedron_test, random_polyhedron_polyhedron_matches_brute_force) {
    rng random(52);
    int apart = 0, overlapping = 0;
    for (int i = 0; i < 300; ++i) {
        auto a = random_hull(random, i);
        auto b = random_hull(random, i / 4 + i);
        auto ctx = random_context(random, 0.5);
        auto r = collide_polyhedron_checked(a, b, ctx, 1e-4);
        placed_polyhedron pa(a, ctx.posA, ctx.ornA), pb(b, ctx.posB, ctx.ornB);
        auto dirs = polyhedron_directions(pa, face_normals(pb), edge_directions(pb), random);
        auto max_sep = max_separation(pa.vertices, 0, pb.vertices, 0, dirs);
        if (max_sep > 0) {
            expect_apart(r, polyhedra_distance(pa, pb), ctx.threshold, i);
            apart += r.num_points > 0;
        } else {
            ASSERT_GE(r.num_points, 1u) << "case " << i;
            ++overlapping;
            auto d = min_distance(r);
            // Not deeper than the least penetration plus the face bias, and not shallower than
            // the least penetration.
            EXPECT_GE(d, max_sep - sat_bias(max_sep)) << "case " << i;
            EXPECT_LE(d, max_sep + 1e-4) << "case " << i;
        }
        for (std::size_t k = 0; k < r.num_points; ++k) {
            auto w = world_points(r.point[k], ctx);
            EXPECT_NEAR(polyhedron_sdf(pa, w.a), 0, 1e-4) << "case " << i;
            EXPECT_NEAR(polyhedron_sdf(pb, w.b), 0, 1e-4) << "case " << i;
        }
        auto s = collide_polyhedron_checked(b, a, swap_context(ctx), 1e-4);
        ASSERT_EQ(s.num_points > 0, r.num_points > 0) << "case " << i;
        if (r.num_points > 0) {
            EXPECT_NEAR(min_distance(s), min_distance(r), sat_bias(min_distance(r))) << "case " << i;
        }
    }
    EXPECT_GT(apart, 15);
    EXPECT_GT(overlapping, 120);
}

TEST(collide_polyhedron_test, random_polyhedron_box_matches_brute_force) {
    rng random(53);
    int apart = 0, overlapping = 0;
    for (int i = 0; i < 300; ++i) {
        auto a = random_hull(random, i);
        box_shape b{random.vec(0.1, 0.5)};
        auto ctx = random_context(random, 0.5);
        auto r = collide_polyhedron_checked(a, b, ctx, 1e-4);
        placed_polyhedron pa(a, ctx.posA, ctx.ornA), pb(box_hull(b.half_extents), ctx.posB, ctx.ornB);
        auto dirs = polyhedron_directions(pa, face_normals(pb), edge_directions(pb), random);
        auto max_sep = max_separation(pa.vertices, 0, pb.vertices, 0, dirs);
        if (max_sep > 0) {
            expect_apart(r, polyhedra_distance(pa, pb), ctx.threshold, i);
            apart += r.num_points > 0;
        } else {
            ASSERT_GE(r.num_points, 1u) << "case " << i;
            ++overlapping;
            auto d = min_distance(r);
            EXPECT_GE(d, max_sep - sat_bias(max_sep)) << "case " << i;
            EXPECT_LE(d, max_sep + 1e-4) << "case " << i;
        }
        for (std::size_t k = 0; k < r.num_points; ++k) {
            auto w = world_points(r.point[k], ctx);
            EXPECT_NEAR(polyhedron_sdf(pa, w.a), 0, 1e-4) << "case " << i;
            EXPECT_NEAR(box_sdf(b.half_extents, r.point[k].pivotB), 0, 1e-4) << "case " << i;
            // The box's feature holds its pivot.
            ASSERT_TRUE(r.point[k].featureB.has_value());
            auto kind = std::get<box_feature>(r.point[k].featureB->feature);
            auto index = r.point[k].featureB->index;
            auto pivot = r.point[k].pivotB;
            if (kind == box_feature::vertex) {
                EXPECT_NEAR(distance(pivot, box_corner(b.half_extents, int(index))), 0, 1e-4) << "case " << i;
            } else if (kind == box_feature::face) {
                auto axis = int(index / 2);
                EXPECT_NEAR(pivot[axis], index % 2 ? -b.half_extents[axis] : b.half_extents[axis], 1e-4);
            }
        }
        auto s = collide_polyhedron_checked(b, a, swap_context(ctx), 1e-4);
        ASSERT_EQ(s.num_points > 0, r.num_points > 0) << "case " << i;
        if (r.num_points > 0) {
            EXPECT_NEAR(min_distance(s), min_distance(r), sat_bias(min_distance(r))) << "case " << i;
        }
    }
    EXPECT_GT(apart, 15);
    EXPECT_GT(overlapping, 120);
}

TEST(collide_polyhedron_test, random_polyhedron_capsule_matches_brute_force) {
    rng random(54);
    int apart = 0, overlapping = 0;
    for (int i = 0; i < 400; ++i) {
        auto hull = random_hull(random, i);
        capsule_shape capsule{random.uniform(0.05, 0.3), random.uniform(0, 0.6), coordinate_axis(i % 3)};
        auto ctx = random_context(random, 0.4);
        auto r = collide_polyhedron_checked(hull, capsule, ctx, 1e-4);
        placed_polyhedron poly(hull, ctx.posA, ctx.ornA);
        vector3 p0, p1;
        capsule_ends(capsule, ctx.posB, ctx.ornB, p0, p1);
        auto segment_sdf = convex_min([&](scalar t) { return polyhedron_sdf(poly, lerp(p0, p1, t)); });
        if (segment_sdf > 0) {
            expect_apart(r, segment_sdf - capsule.radius, ctx.threshold, i);
            apart += r.num_points > 0;
        } else {
            ASSERT_GE(r.num_points, 1u) << "case " << i;
            ++overlapping;
            auto axis = p1 - p0;
            std::vector<vector3> others;
            if (try_normalize(axis)) others.push_back(axis);
            auto dirs = polyhedron_directions(poly, {}, others, random);
            auto max_sep = max_separation(poly.vertices, 0, {p0, p1}, capsule.radius, dirs);
            auto d = min_distance(r);
            EXPECT_GE(d, max_sep - sat_bias(max_sep)) << "case " << i;
            EXPECT_LE(d, max_sep + 1e-4) << "case " << i;
        }
        for (std::size_t k = 0; k < r.num_points; ++k) {
            auto w = world_points(r.point[k], ctx);
            EXPECT_NEAR(polyhedron_sdf(poly, w.a), 0, 1e-4) << "case " << i;
            // On the capsule's surface at the segment's ends and for segments parallel to the
            // face; inside it otherwise (points over a face sit a radius from the segment).
            EXPECT_LE(point_segment_distance(p0, p1, w.b), capsule.radius + 1e-4) << "case " << i;
        }
    }
    EXPECT_GT(apart, 20);
    EXPECT_GT(overlapping, 100);
}

TEST(collide_polyhedron_test, random_polyhedron_cylinder_matches_brute_force) {
    rng random(55);
    int apart = 0, overlapping = 0;
    for (int i = 0; i < 120; ++i) {
        auto hull = random_hull(random, i);
        cylinder_shape cylinder{random.uniform(0.1, 0.5), random.uniform(0.1, 0.5), coordinate_axis(i % 3)};
        auto ctx = random_context(random, 0.6);
        ctx.threshold = 100;
        auto r = collide_polyhedron_checked(hull, cylinder, ctx, 1e-4);
        ASSERT_GE(r.num_points, 1u) << "case " << i;
        placed_polyhedron poly(hull, ctx.posA, ctx.ornA);
        auto support_cylinder = [&](const vector3 &n) {
            return cylinder_support(cylinder, ctx.posB, ctx.ornB, n);
        };
        // Any direction's gap is a lower bound of the largest: the reported normals join the
        // search's starts, lest the search miss a narrow ridge of the gap.
        std::vector<vector3> normals;
        for (std::size_t k = 0; k < r.num_points; ++k)
            normals.push_back(r.point[k].normal);
        auto searched = searched_gap([&](const vector3 &n) { return points_support(poly.vertices, n); },
                                     support_cylinder, normals);
        auto d = min_distance(r);
        EXPECT_NEAR(d, searched, 1e-4) << "case " << i;
        if (searched > 0.01) {
            ++apart;
            auto exact = min_over_surface(
                poly, [&](const vector3 &x) { return cylinder_sdf(cylinder, ctx.posB, ctx.ornB, x); });
            EXPECT_NEAR(d, exact, 1e-4) << "case " << i;
        } else {
            ++overlapping;
        }
        for (std::size_t k = 0; k < r.num_points; ++k) {
            if (r.point[k].distance > d + scalar(1e-3)) continue;
            // The deepest points lie on both surfaces.
            auto w = world_points(r.point[k], ctx);
            EXPECT_NEAR(polyhedron_sdf(poly, w.a), 0, 1e-3) << "case " << i;
            EXPECT_NEAR(cylinder_sdf(cylinder, ctx.posB, ctx.ornB, w.b), 0, 1e-3) << "case " << i;
        }
    }
    EXPECT_GT(apart, 15);
    EXPECT_GT(overlapping, 15);
}

// Touching (-2 mm to 2 mm) at 20 m from the origin, where float rounding of the positions is
// about 1e-6 m and the line between two nearly coincident points is noise: the pair is reported
// within the threshold and its deepest point within 0.1 mm of the direction search. The hull is
// moved along the line between the centres until the search says it touches.
TEST(collide_polyhedron_test, random_polyhedron_cylinder_touching_far_from_the_origin) {
    rng random(57);
    const vector3 pos_b{scalar(20.3), scalar(1.7), scalar(-15.2)};
    for (int i = 0; i < 40; ++i) {
        auto hull = random_hull(random, i);
        cylinder_shape cylinder{random.uniform(0.1, 0.5), random.uniform(0.1, 0.5), coordinate_axis(i % 3)};
        auto orn_a = random.orientation(), orn_b = random.orientation();
        auto dir = random.unit();
        auto target = random.uniform(-0.002, 0.002);
        auto support_cylinder = [&](const vector3 &n) { return cylinder_support(cylinder, pos_b, orn_b, n); };
        auto separation = [&](scalar t) {
            placed_polyhedron poly(hull, pos_b + dir * t, orn_a);
            return searched_gap([&](const vector3 &n) { return points_support(poly.vertices, n); },
                                support_cylinder);
        };
        auto [t, searched] = secant_to(separation, scalar(1), target);
        ASSERT_LT(std::abs(searched), scalar(0.005)) << "case " << i << " did not come to touch";
        collision_context ctx{pos_b + dir * t, orn_a, pos_b, orn_b, scalar(0.02)};
        collision_result r;
        collide(hull, cylinder, ctx, r);
        ASSERT_GE(r.num_points, 1u) << "case " << i << " at " << searched;
        EXPECT_NEAR(min_distance(r), searched, 1e-4) << "case " << i;
    }
}

// A cylinder's cap touching a hull (-2 mm to 2 mm) at 20 m from the origin: in even cases within
// 2e-3 rad of parallel to a face, as a cylinder resting on the hull, in odd cases at any angle, a
// corner or an edge of the hull against the cap. The deepest point within 0.02 mm of the
// direction search (4e-6 m at worst today). The cylinder is moved along a line near the face's
// normal or its own axis until the search says it touches.
TEST(collide_polyhedron_test, random_cylinder_cap_touching_a_hull) {
    rng random(59);
    const vector3 pos_a{scalar(20.3), scalar(1.7), scalar(-15.2)};
    for (int i = 0; i < 60; ++i) {
        auto hull = random_hull(random, i);
        cylinder_shape cylinder{random.uniform(0.1, 0.5), random.uniform(0.1, 0.5), coordinate_axis(i % 3)};
        auto orn_a = random.orientation();
        placed_polyhedron poly(hull, pos_a, orn_a);
        vector3 start, normal;
        quaternion orn_b;
        if (i % 2 == 0) {
            auto face = std::min(std::size_t(random.uniform(0, scalar(poly.polygons.size()))),
                                 poly.polygons.size() - 1);
            normal = poly.face_normal(face);
            start = vector3_zero;
            for (const auto &v : poly.polygons[face])
                start += v / scalar(poly.polygons[face].size());
            auto side = normalize(cross(normal, random.unit()));
            orn_b = quaternion_axis_angle(side, random.uniform(0, 2e-3)) *
                    shortest_arc(coordinate_axis_vector(cylinder.axis), normal);
        } else {
            orn_b = random.orientation();
            normal = coordinate_axis_vector(cylinder.axis, orn_b);
            start = pos_a;
        }
        auto off_normal = normalize(cross(normal, random.unit()));
        auto dir = normalize(normal + off_normal * random.uniform(0, 0.5));
        auto target = random.uniform(-0.002, 0.002);
        auto poly_support = [&](const vector3 &n) { return points_support(poly.vertices, n); };
        auto separation = [&](scalar t) {
            return searched_gap(poly_support, [&](const vector3 &n) {
                return cylinder_support(cylinder, start + dir * t, orn_b, n);
            });
        };
        auto [t, searched] = secant_to(separation, cylinder.half_length + scalar(0.3), target);
        ASSERT_LT(std::abs(searched), scalar(0.005)) << "case " << i << " did not come to touch";
        auto pos_b = start + dir * t;
        collision_context ctx{pos_a, orn_a, pos_b, orn_b, scalar(0.02)};
        collision_result r;
        collide(hull, cylinder, ctx, r);
        ASSERT_GE(r.num_points, 1u) << "case " << i << " at " << searched;
        // Any direction's gap is a lower bound of the distance, the reported normals' too.
        for (std::size_t k = 0; k < r.num_points; ++k) {
            const auto &n = r.point[k].normal;
            searched = std::max(searched, -poly_support(-n) - cylinder_support(cylinder, pos_b, orn_b, n));
        }
        EXPECT_NEAR(min_distance(r), searched, 2e-5) << "case " << i;
    }
}

TEST(collide_polyhedron_test, random_polyhedron_plane_matches_brute_force) {
    rng random(56);
    int touching = 0;
    for (int i = 0; i < 300; ++i) {
        auto hull = random_hull(random, i);
        auto ctx = random_context(random, 0.3);
        plane_shape plane{random.unit(), random.uniform(-0.4, 0.4)};
        auto r = collide_polyhedron_checked(hull, plane, ctx, 1e-4);
        placed_polyhedron poly(hull, ctx.posA, ctx.ornA);
        auto expected = large_scalar;
        std::size_t within = 0;
        for (auto &v : poly.vertices) {
            auto d = dot(plane.normal, v) - plane.constant;
            expected = std::min(expected, d);
            within += d <= ctx.threshold;
        }
        ASSERT_EQ(r.num_points, std::min(within, std::size_t(4))) << "case " << i;
        if (r.num_points == 0) continue;
        ++touching;
        EXPECT_NEAR(min_distance(r), expected, 1e-5) << "case " << i;
        for (std::size_t k = 0; k < r.num_points; ++k) {
            expect_vec_near(r.point[k].normal, plane.normal, 1e-6);
            // On the plane, once in world space (pivots are in their body's object space).
            auto on_plane = to_world_space(r.point[k].pivotB, ctx.posB, ctx.ornB);
            EXPECT_NEAR(dot(plane.normal, on_plane) - plane.constant, 0, 1e-4);
        }
    }
    EXPECT_GT(touching, 100);
}

// Argument order.

TEST(collide_polyhedron_test, argument_order_swaps_the_roles) {
    rng random(61);
    int with_points = 0;
    for (int i = 0; i < 200; ++i) {
        auto hull = random_hull(random, i);
        auto ctx = random_context(random, 0.5);
        auto swapped = swap_context(ctx);
        auto label = "case " + std::to_string(i);
        sphere_shape sphere{random.uniform(0.05, 0.4)};
        capsule_shape capsule{random.uniform(0.05, 0.3), random.uniform(0, 0.5), coordinate_axis(i % 3)};
        cylinder_shape cylinder{random.uniform(0.05, 0.4), random.uniform(0.05, 0.4),
                                coordinate_axis((i + 1) % 3)};
        plane_shape plane{random.unit(), random.uniform(-0.3, 0.3)};
        auto r = collide_polyhedron_checked(hull, sphere, ctx, 1e-4);
        expect_swapped(r, collide_polyhedron_checked(sphere, hull, swapped, 1e-4), 1e-6, "sphere " + label);
        with_points += r.num_points > 0;
        r = collide_polyhedron_checked(hull, capsule, ctx, 1e-4);
        expect_swapped(r, collide_polyhedron_checked(capsule, hull, swapped, 1e-4), 1e-6, "capsule " + label);
        r = collide_polyhedron_checked(hull, cylinder, ctx, 1e-4);
        expect_swapped(r, collide_polyhedron_checked(cylinder, hull, swapped, 1e-4), 1e-6,
                       "cylinder " + label);
        r = collide_polyhedron_checked(hull, plane, ctx, 1e-4);
        expect_swapped(r, collide_polyhedron_checked(plane, hull, swapped, 1e-4), 1e-6, "plane " + label);
    }
    EXPECT_GT(with_points, 60);
}

TEST(collide_polyhedron_test, argument_order_of_polytope_pairs) {
    // Both orders run one separating-axis test that keeps A's face within the bias; where one
    // axis is clearly best, or two faces tie with the same overlap, the roles swap exactly.
    auto hull = box_hull(cube_he);
    box_shape big{{1, 0.5, 1}};
    auto big_hull = box_hull(big.half_extents);
    auto tet = tetrahedron(tet_s);
    auto rest_y = -(cube_he.y + big.half_extents.y);
    auto turn = quaternion_axis_angle(vector3_y, 0.3);
    auto a_edge = quaternion_axis_angle(vector3_z, pi / 4), b_edge = quaternion_axis_angle(vector3_x, pi / 4);
    auto edge_y = -(box_projection_radius(cube_he, rotate(conjugate(a_edge), vector3_y)) +
                    box_projection_radius(big.half_extents, rotate(conjugate(b_edge), vector3_y)));
    auto a_vertex = shortest_arc(normalize(-cube_he), -vector3_y);
    collision_context configs[] = {
        at(vec(-0.1, rest_y + 0.005, 0.05), turn),
        at(vec(-0.1, rest_y - 0.01, 0.05), turn),
        at(vec(0, edge_y + 0.01, 0), b_edge, a_edge),
        at(vec(0.1, -(length(cube_he) + 0.5) + 0.004, 0), quaternion_identity, a_vertex),
        at(-(cube_he + big.half_extents + vector3{0.005, 0.005, 0.005})),
    };
    for (std::size_t i = 0; i < std::size(configs); ++i) {
        auto &ctx = configs[i];
        auto label = "config " + std::to_string(i);
        auto r = collide_polyhedron_checked(hull, big, ctx);
        EXPECT_GE(r.num_points, 1u) << label;
        expect_swapped(r, collide_polyhedron_checked(big, hull, swap_context(ctx)), 1e-5, "box " + label);
        r = collide_polyhedron_checked(hull, big_hull, ctx);
        expect_swapped(r, collide_polyhedron_checked(big_hull, hull, swap_context(ctx)), 1e-5,
                       "polyhedron " + label);
    }
    // A tetrahedron's vertex on an upward face of another.
    auto ctx = at(vec(0, -(tet_circumradius + tet_inradius) + 0.003, 0), tet_face_up, tet_vertex_down);
    expect_swapped(collide_polyhedron_checked(tet, tet, ctx),
                   collide_polyhedron_checked(tet, tet, swap_context(ctx)), 1e-5, "tetrahedra");
}

// Building blocks.

TEST(collide_polyhedron_test, gauss_map_test_matches_arc_intersection) {
    // Arcs a0-a1 and (-b0)-(-b1) cross where their great circles meet, at +-x, if one of the two
    // lies on both arcs: a point p is on the arc u-v when the angles u-p and p-v add up to u-v.
    auto angle = [](const vector3 &u, const vector3 &v) {
        return std::atan2(length(cross(u, v)), dot(u, v));
    };
    auto on_arc = [&](const vector3 &p, const vector3 &u, const vector3 &v, scalar slack) {
        return std::abs(angle(u, p) + angle(p, v) - angle(u, v)) <= slack;
    };
    rng random(71);
    int crossing = 0, tested = 0;
    for (int i = 0; i < 4000; ++i) {
        auto a0 = random.unit(), a1 = random.unit(), b0 = random.unit(), b1 = random.unit();
        // Dihedral angles of convex polytopes: arcs shorter than a half turn.
        if (dot(a0, a1) < scalar(-0.9) || dot(b0, b1) < scalar(-0.9)) continue;
        auto x = cross(cross(a0, a1), cross(-b0, -b1));
        if (!try_normalize(x)) continue;
        auto crosses = [&](scalar slack) {
            return (on_arc(x, a0, a1, slack) && on_arc(x, -b0, -b1, slack)) ||
                   (on_arc(-x, a0, a1, slack) && on_arc(-x, -b0, -b1, slack));
        };
        // Off an arc by an angle d on its circle, the angles add up to 2 d too much: skip the
        // pairs whose crossing lies within a few milliradians of an arc's end, where rounding may
        // decide either way.
        if (crosses(scalar(1e-2)) != crosses(scalar(1e-5))) continue;
        ++tested;
        auto expected = crosses(scalar(1e-5));
        crossing += expected;
        EXPECT_EQ(detail::is_minkowski_face(a0, a1, b0, b1), expected) << "case " << i;
    }
    EXPECT_GT(tested, 2000);
    EXPECT_GT(crossing, 100);
}

TEST(collide_polyhedron_test, hull_with_many_faces_uses_the_uncached_path_alike) {
    // A hull of more faces than collide() caches on the stack: B's normals are then rotated
    // where they are used. Both orders (cached with the small hull as B, uncached with the large
    // one as B) and the brute-force least penetration must agree.
    std::vector<vector3> points;
    for (int i = 0; i < 300; ++i) {
        auto y = 1 - 2 * (scalar(i) + scalar(0.5)) / 300;
        auto rho = std::sqrt(1 - y * y);
        auto phi = scalar(i) * scalar(2.399963229728653);
        points.push_back(vector3{rho * std::cos(phi), y, rho * std::sin(phi)} * scalar(0.5));
    }
    polyhedron_shape big(points);
    ASSERT_GT(big.mesh->faces.size(), 256u);
    auto small = box_hull({0.2, 0.15, 0.1});
    rng random(72);
    int overlapping = 0;
    for (int i = 0; i < 12; ++i) {
        auto ctx = at(random.unit() * random.uniform(0.45, 0.65), random_orientation(random),
                      random_orientation(random));
        auto r = collide_polyhedron_checked(small, big, ctx, 1e-4);
        auto s = collide_polyhedron_checked(big, small, swap_context(ctx), 1e-4);
        placed_polyhedron ps(small, ctx.posA, ctx.ornA), pb(big, ctx.posB, ctx.ornB);
        auto dirs = polyhedron_directions(ps, face_normals(pb), edge_directions(pb), random);
        auto max_sep = max_separation(ps.vertices, 0, pb.vertices, 0, dirs);
        if (max_sep > ctx.threshold + 1e-4) {
            EXPECT_EQ(r.num_points, 0u) << "case " << i;
            EXPECT_EQ(s.num_points, 0u) << "case " << i;
            continue;
        }
        if (max_sep > 0) continue;
        ++overlapping;
        ASSERT_GE(r.num_points, 1u) << "case " << i;
        ASSERT_GE(s.num_points, 1u) << "case " << i;
        EXPECT_GE(min_distance(r), max_sep - sat_bias(max_sep)) << "case " << i;
        EXPECT_LE(min_distance(r), max_sep + 1e-4) << "case " << i;
        EXPECT_GE(min_distance(s), max_sep - sat_bias(max_sep)) << "case " << i;
        EXPECT_LE(min_distance(s), max_sep + 1e-4) << "case " << i;
    }
    EXPECT_GT(overlapping, 6);
}
