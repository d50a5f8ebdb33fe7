#include "collide_test_helpers.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/shapes/mesh_shape.hpp"
#include "edyn/shapes/polyhedron_shape.hpp"
#include "support/grid_mesh.hpp"
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <variant>

// collide() of every convex shape and compounds against triangle meshes: resting on a face at a
// known depth (flat, tilted, with the mesh's body moved), on a convex ridge, on a pyramid's apex,
// across the internal edges of a tessellated floor (where only the floor's normal may appear),
// behind the one-sided triangles, beyond the threshold, both argument orders and the variant
// dispatcher. Expected depths come from the shapes' lowest points written out here.

using namespace edyn;
using namespace collide_test;

namespace {

constexpr scalar mesh_tol = scalar(1e-4);

// Floor of n x n unit cells in the xz plane at y = 0, front +y; cell (i, j) spans
// [i, i + 1] x [j, j + 1] (support/grid_mesh.hpp).
mesh_shape floor_mesh(int n) { return mesh_shape{test::make_grid(n)}; }

// Triangle 0 far away; triangle 1 large, facing +y at y = 0, around the origin, transformed by
// (pos, orn).
mesh_shape big_triangle(const vector3 &pos = vector3_zero, const quaternion &orn = quaternion_identity) {
    std::vector<vector3> v{vec(100, 0, 100), vec(100, 0, 101), vec(101, 0, 100),
                           vec(-4, 0, -4),   vec(-4, 0, 4),    vec(6, 0, 0)};
    for (auto &p : v)
        p = to_world_space(p, pos, orn);
    return test::make_mesh(v, {0, 1, 2, 3, 4, 5});
}

// Ridge from (0, h, -1) to (0, h, 1): triangle 0 on the -x side, triangle 1 on the +x side; the
// ridge is edge 1 of both.
mesh_shape roof_mesh(scalar h) {
    return test::make_mesh({vec(-1, 0, 0), vec(0, h, 1), vec(0, h, -1), vec(1, 0, 0)}, {0, 1, 2, 3, 2, 1});
}

// Square pyramid of apex (0, 1, 0) over (+-1, 0, +-1): the apex is vertex 0 of all four triangles.
mesh_shape pyramid_mesh() {
    std::vector<vector3> v{vec(0, 1, 0), vec(-1, 0, -1), vec(1, 0, -1), vec(1, 0, 1), vec(-1, 0, 1)};
    return test::make_mesh(v, {0, 2, 1, 0, 3, 2, 0, 4, 3, 0, 1, 4});
}

// The convex shapes and a compound, each with its lowest point, written out independently.
struct test_shape {
    std::string name;
    shapes_variant_t shape;
};

polyhedron_shape octahedron() {
    return polyhedron_shape(std::vector<vector3>{vec(0.4, 0, 0), vec(-0.4, 0, 0), vec(0, 0.3, 0),
                                                 vec(0, -0.3, 0), vec(0, 0, 0.4), vec(0, 0, -0.4)});
}

compound_shape two_children() {
    compound_shape c;
    c.add_shape(box_shape{vec(0.2, 0.2, 0.2)}, vec(-0.5, 0, 0));
    c.add_shape(sphere_shape{scalar(0.25)}, vec(0.5, 0.05, 0));
    c.finish();
    return c;
}

std::vector<test_shape> all_shapes() {
    return {{"sphere", sphere_shape{scalar(0.5)}},
            {"box", box_shape{vec(0.4, 0.3, 0.5)}},
            {"capsule", capsule_shape{scalar(0.3), scalar(0.4), coordinate_axis::x}},
            {"cylinder", cylinder_shape{scalar(0.4), scalar(0.3), coordinate_axis::y}},
            {"polyhedron", octahedron()},
            {"compound", two_children()}};
}

scalar lowest_y(const compound_child_shape_t &shape, const vector3 &pos, const quaternion &orn);

// Lowest world y of a shape at (pos, orn).
scalar lowest_y(const shapes_variant_t &shape, const vector3 &pos, const quaternion &orn) {
    if (auto *c = std::get_if<compound_shape>(&shape)) {
        auto y = large_scalar;
        for (auto &child : c->children) {
            y = std::min(
                y, lowest_y(child.shape, to_world_space(child.position, pos, orn), orn * child.orientation));
        }
        return y;
    }
    return std::visit(
        [&](const auto &s) -> scalar {
            using S = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<S, sphere_shape>) {
                return pos.y - s.radius;
            } else if constexpr (std::is_same_v<S, box_shape>) {
                auto y = large_scalar;
                for (auto &v : box_vertices(s.half_extents, pos, orn))
                    y = std::min(y, v.y);
                return y;
            } else if constexpr (std::is_same_v<S, capsule_shape>) {
                vector3 p0, p1;
                capsule_ends(s, pos, orn, p0, p1);
                return std::min(p0.y, p1.y) - s.radius;
            } else if constexpr (std::is_same_v<S, cylinder_shape>) {
                vector3 axis = vector3_zero;
                axis[int(s.axis)] = 1;
                auto a = rotate(orn, axis);
                return pos.y - s.half_length * std::abs(a.y) - s.radius * length_across_axis(a, 1);
            } else if constexpr (std::is_same_v<S, polyhedron_shape>) {
                auto y = large_scalar;
                for (auto &v : s.mesh->vertices)
                    y = std::min(y, to_world_space(v, pos, orn).y);
                return y;
            } else {
                ADD_FAILURE() << "no lowest point for this shape";
                return 0;
            }
        },
        shape);
}

scalar lowest_y(const compound_child_shape_t &shape, const vector3 &pos, const quaternion &orn) {
    return std::visit([&](const auto &s) { return lowest_y(shapes_variant_t{s}, pos, orn); }, shape);
}

// collide(shape, mesh) for the shape held in the variant, with the checks every result passes.
collision_result collide_mesh_checked(const shapes_variant_t &a, const mesh_shape &b,
                                      const collision_context &ctx) {
    collision_result r;
    std::visit(
        [&](const auto &s) {
            using S = std::decay_t<decltype(s)>;
            if constexpr (!std::is_same_v<S, plane_shape> && !std::is_same_v<S, mesh_shape>) {
                collide(s, b, ctx, r);
            } else {
                ADD_FAILURE() << "not a convex shape or compound";
            }
        },
        a);
    expect_consistent(r, ctx, mesh_tol);
    return r;
}

// collide(mesh, shape).
collision_result run_swapped(const mesh_shape &a, const shapes_variant_t &b, const collision_context &ctx) {
    collision_result r;
    std::visit(
        [&](const auto &s) {
            using S = std::decay_t<decltype(s)>;
            if constexpr (!std::is_same_v<S, plane_shape> && !std::is_same_v<S, mesh_shape>)
                collide(a, s, ctx, r);
        },
        b);
    expect_consistent(r, ctx, mesh_tol);
    return r;
}

const triangle_feature *mesh_feature(const collision_result::collision_point &p) {
    if (!p.featureB) return nullptr;
    return std::get_if<triangle_feature>(&p.featureB->feature);
}

// Places `shape` so that its lowest point lies `depth` below the plane y = 0 of the frame
// (frame_pos, frame_orn), centred over (x, z) of that frame with orientation `local_orn` there.
collision_context resting(const shapes_variant_t &shape, scalar x, scalar z, scalar depth,
                          const quaternion &local_orn, const vector3 &frame_pos = vector3_zero,
                          const quaternion &frame_orn = quaternion_identity) {
    auto bottom = lowest_y(shape, vector3_zero, local_orn);
    auto local_pos = vector3{x, -bottom - depth, z};
    collision_context ctx;
    ctx.posA = to_world_space(local_pos, frame_pos, frame_orn);
    ctx.ornA = frame_orn * local_orn;
    return ctx;
}

// Every point: normal `n`, distance -depth, a face of triangle `part`.
void expect_face_contact(const collision_result &r, const vector3 &n, scalar depth, std::int32_t part,
                         const std::string &what) {
    SCOPED_TRACE(what);
    ASSERT_GT(r.num_points, 0u);
    for (std::size_t i = 0; i < r.num_points; ++i) {
        const auto &p = r.point[i];
        expect_vec_near(p.normal, n, mesh_tol);
        EXPECT_NEAR(p.distance, -depth, mesh_tol) << "point " << i;
        auto f = mesh_feature(p);
        ASSERT_NE(f, nullptr) << "point " << i << " has no triangle feature";
        EXPECT_EQ(int(*f), int(triangle_feature::face)) << "point " << i;
        EXPECT_EQ(p.featureB->part, part) << "point " << i;
    }
}

} // namespace

TEST(collide_mesh_test, resting_on_a_face) {
    auto mesh = big_triangle();
    for (auto &s : all_shapes()) {
        for (scalar depth : {scalar(0.01), scalar(0.05)}) {
            for (scalar yaw : {scalar(0), scalar(0.7)}) {
                auto ctx =
                    resting(s.shape, scalar(0.2), scalar(-0.3), depth, quaternion_axis_angle(vector3_y, yaw));
                auto r = collide_mesh_checked(s.shape, mesh, ctx);
                expect_face_contact(r, vector3_y, depth, 1, s.name + " depth " + std::to_string(depth));
            }
        }
    }
}

TEST(collide_mesh_test, resting_on_a_tilted_face) {
    auto tilt = normalize(quaternion_axis_angle(normalize(vec(1, 0, 0.5)), scalar(0.6)));
    auto offset = vec(3, -2, 1);
    auto mesh = big_triangle(offset, tilt);
    auto n = rotate(tilt, vector3_y);
    expect_vec_near(mesh.trimesh->get_triangle_normal(1), n, scalar(1e-5));
    for (auto &s : all_shapes()) {
        auto ctx = resting(s.shape, scalar(-0.4), scalar(0.5), scalar(0.03),
                           quaternion_axis_angle(vector3_y, 1), offset, tilt);
        auto r = collide_mesh_checked(s.shape, mesh, ctx);
        expect_face_contact(r, n, scalar(0.03), 1, s.name);
    }
}

TEST(collide_mesh_test, mesh_body_transform_is_honoured) {
    auto mesh = big_triangle();
    auto orn_b = normalize(quaternion_axis_angle(normalize(vec(0.3, 0.2, 1)), scalar(2.1)));
    auto pos_b = vec(-5, 7, 2.5);
    auto n = rotate(orn_b, vector3_y);
    for (auto &s : all_shapes()) {
        auto ctx = resting(s.shape, scalar(0.5), scalar(0.1), scalar(0.04),
                           quaternion_axis_angle(vector3_y, -0.4), pos_b, orn_b);
        ctx.posB = pos_b;
        ctx.ornB = orn_b;
        auto r = collide_mesh_checked(s.shape, mesh, ctx);
        expect_face_contact(r, n, scalar(0.04), 1, s.name);

        // The same placement with the mesh left at the origin touches nothing.
        auto far = ctx;
        far.posB = vector3_zero;
        far.ornB = quaternion_identity;
        EXPECT_EQ(collide_mesh_checked(s.shape, mesh, far).num_points, 0u) << s.name;
    }
}

TEST(collide_mesh_test, sphere_on_a_convex_ridge_gets_the_bisector) {
    const scalar h = 0.5, r = 0.5, depth = 0.05;
    auto mesh = roof_mesh(h);
    ASSERT_TRUE(mesh.trimesh->is_edge_active(0, 1));
    sphere_shape sphere{r};
    // Straight above the ridge: +y; tilted 15 degrees towards +x (within the ridge's normal cone,
    // which spans +-26.6 degrees): that direction.
    for (scalar angle : {scalar(0), to_radians(15), to_radians(-20)}) {
        auto u = vec(std::sin(angle), std::cos(angle), 0);
        collision_context ctx;
        auto ridge_point = vec(0, h, 0.2);
        ctx.posA = ridge_point + u * (r - depth);
        auto res = collide_mesh_checked(sphere, mesh, ctx);
        SCOPED_TRACE("angle " + std::to_string(angle));
        ASSERT_GT(res.num_points, 0u);
        for (std::size_t i = 0; i < res.num_points; ++i) {
            const auto &p = res.point[i];
            expect_vec_near(p.normal, u, mesh_tol);
            EXPECT_NEAR(p.distance, -depth, mesh_tol);
            expect_vec_near(to_world_space(p.pivotB, ctx.posB, ctx.ornB), ridge_point, scalar(1e-3));
            auto f = mesh_feature(p);
            ASSERT_NE(f, nullptr);
            EXPECT_EQ(int(*f), int(triangle_feature::edge));
            EXPECT_EQ(p.featureB->index, 1u);
            EXPECT_TRUE(p.featureB->part == 0 || p.featureB->part == 1) << p.featureB->part;
        }
    }
}

TEST(collide_mesh_test, flat_bottoms_on_a_convex_ridge) {
    // Shapes with a flat bottom across the ridge rest on it: +y (between the faces' normals) at
    // the ridge's depth, on the ridge edge.
    const scalar h = 0.5, depth = 0.04;
    auto mesh = roof_mesh(h);
    compound_shape compound;
    compound.add_shape(box_shape{vec(0.2, 0.2, 0.2)}, vec(-0.5, 0, 0));
    compound.add_shape(sphere_shape{scalar(0.25)}, vec(0.5, 0.3, 0));
    compound.finish();
    std::vector<std::pair<std::string, std::pair<shapes_variant_t, scalar>>> cases{
        {"box", {box_shape{vec(0.4, 0.3, 0.5)}, 0}},
        {"capsule along the ridge", {capsule_shape{scalar(0.3), scalar(0.4), coordinate_axis::z}, 0}},
        {"capsule across the ridge", {capsule_shape{scalar(0.3), scalar(0.4), coordinate_axis::x}, 0}},
        {"cylinder", {cylinder_shape{scalar(0.4), scalar(0.3), coordinate_axis::y}, 0}},
        {"box polyhedron",
         {polyhedron_shape(box_vertices(vec(0.3, 0.2, 0.25), vector3_zero, quaternion_identity)), 0}},
        // The box child over the ridge; the sphere child well above the +x slope.
        {"compound", {compound, scalar(0.5)}},
    };
    for (auto &[name, c] : cases) {
        auto &[shape, x] = c;
        SCOPED_TRACE(name);
        collision_context ctx;
        ctx.posA = vec(x, h - lowest_y(shape, vector3_zero, quaternion_identity) - depth, 0);
        auto r = collide_mesh_checked(shape, mesh, ctx);
        ASSERT_GT(r.num_points, 0u);
        EXPECT_NEAR(min_distance(r), -depth, mesh_tol);
        for (std::size_t i = 0; i < r.num_points; ++i) {
            const auto &p = r.point[i];
            expect_vec_near(p.normal, vector3_y, mesh_tol);
            EXPECT_NEAR(to_world_space(p.pivotB, ctx.posB, ctx.ornB).x, 0, scalar(1e-3)) << "on the ridge";
            auto f = mesh_feature(p);
            ASSERT_NE(f, nullptr);
            EXPECT_EQ(int(*f), int(triangle_feature::edge)) << "point " << i;
            EXPECT_EQ(p.featureB->index, 1u);
        }
    }
}

TEST(collide_mesh_test, shapes_on_a_nearly_flat_inactive_ridge_are_supported) {
    // A convex ridge of 3 degrees is inactive (triangle_mesh::active_edge_cosine): contacts there
    // take a triangle's normal. Shapes pressed into it by `depth` must still be held up, with a
    // normal within the ridge's 3 degrees of +y and about the ridge's depth (the faces are only
    // 1.5 degrees off +y, so the depth along either normal differs from it by well under 1 mm).
    const scalar h = std::tan(to_radians(1.5)), depth = 0.05;
    auto mesh = roof_mesh(h);
    ASSERT_FALSE(mesh.trimesh->is_edge_active(0, 1));
    std::vector<std::pair<std::string, shapes_variant_t>> cases{
        {"sphere", sphere_shape{scalar(0.5)}},
        {"capsule along the ridge", capsule_shape{scalar(0.3), scalar(0.4), coordinate_axis::z}},
        {"cylinder lying along the ridge", cylinder_shape{scalar(0.3), scalar(0.4), coordinate_axis::z}},
        {"box", box_shape{vec(0.4, 0.3, 0.5)}},
    };
    for (auto &[name, shape] : cases) {
        for (scalar x : {scalar(0), scalar(0.004), scalar(-0.008)}) {
            SCOPED_TRACE(name + " x " + std::to_string(x));
            collision_context ctx;
            ctx.posA = vec(x, h - lowest_y(shape, vector3_zero, quaternion_identity) - depth, 0);
            auto r = collide_mesh_checked(shape, mesh, ctx);
            EXPECT_GT(r.num_points, 0u) << "no contact: the shape would fall through the ridge";
            if (r.num_points == 0) continue;
            EXPECT_NEAR(min_distance(r), -depth, scalar(2e-3));
            for (std::size_t i = 0; i < r.num_points; ++i)
                EXPECT_GT(r.point[i].normal.y, std::cos(to_radians(3))) << str(r.point[i].normal);
        }
    }
}

TEST(collide_mesh_test, sphere_on_a_pyramid_apex) {
    auto mesh = pyramid_mesh();
    for (std::size_t t = 0; t < 4; ++t)
        ASSERT_TRUE(mesh.trimesh->is_vertex_active(t, 0));
    const scalar r = 0.4, depth = 0.03;
    sphere_shape sphere{r};
    auto apex = vec(0, 1, 0);
    for (auto dir : {vec(0, 1, 0), vec(0.1, 1, 0.05), vec(-0.3, 1, 0.2)}) {
        auto u = normalize(dir);
        collision_context ctx;
        ctx.posA = apex + u * (r - depth);
        auto res = collide_mesh_checked(sphere, mesh, ctx);
        SCOPED_TRACE(str(u));
        ASSERT_GT(res.num_points, 0u);
        EXPECT_NEAR(min_distance(res), -depth, mesh_tol);
        for (std::size_t i = 0; i < res.num_points; ++i) {
            const auto &p = res.point[i];
            expect_vec_near(p.normal, u, mesh_tol);
            expect_vec_near(to_world_space(p.pivotB, ctx.posB, ctx.ornB), apex, scalar(1e-3));
            auto f = mesh_feature(p);
            ASSERT_NE(f, nullptr);
            EXPECT_EQ(int(*f), int(triangle_feature::vertex));
            EXPECT_EQ(p.featureB->index, 0u);
        }
    }
}

TEST(collide_mesh_test, internal_edges_of_a_flat_floor_give_only_the_floor_normal) {
    auto mesh = floor_mesh(4);
    const auto &trimesh = *mesh.trimesh;
    rng random(21);
    auto shapes = all_shapes();
    int checked = 0;
    for (auto &s : shapes) {
        for (int k = 0; k < 150; ++k) {
            scalar x, z;
            // Some positions right on an internal edge or vertex, the rest anywhere in the middle.
            switch (k % 5) {
            case 0:
                x = scalar(2) + random.uniform(-1e-3, 1e-3);
                z = random.uniform(1, 3);
                break;
            case 1:
                x = random.uniform(1, 3);
                z = x + random.uniform(-1e-3, 1e-3); // A diagonal.
                break;
            case 2:
                x = scalar(2) + random.uniform(-2e-3, 2e-3);
                z = scalar(2) + random.uniform(-2e-3, 2e-3);
                break;
            default:
                x = random.uniform(1, 3);
                z = random.uniform(1, 3);
            }
            auto depth = random.uniform(0.002, 0.1);
            auto orn =
                k % 2 == 0 ? random.orientation() : quaternion_axis_angle(vector3_y, random.uniform(-3, 3));
            auto ctx = resting(s.shape, x, z, depth, orn);
            auto r = collide_mesh_checked(s.shape, mesh, ctx);
            auto what = s.name + " at " + str(ctx.posA) + " depth " + std::to_string(depth);
            ASSERT_GT(r.num_points, 0u) << what;
            EXPECT_NEAR(min_distance(r), -depth, mesh_tol) << what;
            for (std::size_t i = 0; i < r.num_points; ++i) {
                const auto &p = r.point[i];
                EXPECT_NEAR(p.normal.y, 1, mesh_tol) << what << " normal " << str(p.normal);
                ASSERT_TRUE(p.featureB.has_value()) << what;
                auto part = p.featureB->part;
                ASSERT_TRUE(part >= 0 && part < 32) << what << " part " << part;
                // The point lies on its triangle.
                auto tri = trimesh.get_triangle_vertices(std::size_t(part));
                auto w = barycentric_coordinates(p.pivotB, tri[0], tri[1], tri[2]);
                EXPECT_GE(std::min({w.x, w.y, w.z}), scalar(-2e-3)) << what << " pivot " << str(p.pivotB);
                EXPECT_NEAR(p.pivotB.y, 0, mesh_tol) << what;
            }
            ++checked;
        }
    }
    EXPECT_EQ(checked, 150 * int(shapes.size()));
}

TEST(collide_mesh_test, nothing_pushes_down_from_behind_a_floor) {
    auto mesh = floor_mesh(4);
    auto shapes = all_shapes();
    rng random(4);
    for (auto &s : shapes) {
        // Tops at: 0.005 above the plane (just overlapping from behind), 0.005 below, 0.1 below,
        // and 0.5 below.
        for (scalar top : {scalar(0.005), scalar(-0.005), scalar(-0.1), scalar(-0.5)}) {
            auto orn = random.orientation();
            // The highest point: minus the lowest of the shape turned upside down (a half turn
            // about x maps y to -y).
            auto flip = quaternion_axis_angle(vector3_x, pi) * orn;
            auto highest = -lowest_y(s.shape, vector3_zero, flip);
            collision_context ctx;
            ctx.posA = {random.uniform(1.2, 2.8), top - highest, random.uniform(1.2, 2.8)};
            ctx.ornA = orn;
            auto r = collide_mesh_checked(s.shape, mesh, ctx);
            for (std::size_t i = 0; i < r.num_points; ++i) {
                EXPECT_GT(r.point[i].normal.y, scalar(0.99))
                    << s.name << " top " << top << " point " << i << " normal " << str(r.point[i].normal);
            }
        }
        // Far below (beyond the triangles' depth): nothing at all.
        collision_context ctx;
        ctx.posA = vec(2.3, -10, 1.7);
        EXPECT_EQ(collide_mesh_checked(s.shape, mesh, ctx).num_points, 0u) << s.name;
    }
}

TEST(collide_mesh_test, threshold_limits_the_points) {
    auto mesh = floor_mesh(4);
    rng random(8);
    for (auto &s : all_shapes()) {
        auto orn = random.orientation();
        collision_context ctx;
        ASSERT_NEAR(ctx.threshold, 0.02, 1e-6);
        // Apart by more than the threshold: nothing.
        auto beyond = resting(s.shape, 2.3, 1.6, -(ctx.threshold + scalar(0.01)), orn);
        EXPECT_EQ(collide_mesh_checked(s.shape, mesh, beyond).num_points, 0u) << s.name;
        // Apart by less: points at the gap.
        auto within = resting(s.shape, 2.3, 1.6, scalar(-0.01), orn);
        auto r = collide_mesh_checked(s.shape, mesh, within);
        ASSERT_GT(r.num_points, 0u) << s.name;
        EXPECT_NEAR(min_distance(r), 0.01, mesh_tol) << s.name;
        // A larger threshold reaches further.
        beyond.threshold = scalar(0.1);
        auto r2 = collide_mesh_checked(s.shape, mesh, beyond);
        ASSERT_GT(r2.num_points, 0u) << s.name;
        EXPECT_NEAR(min_distance(r2), 0.03, mesh_tol) << s.name;
    }
}

TEST(collide_mesh_test, both_argument_orders_agree) {
    auto mesh = floor_mesh(4);
    rng random(13);
    auto orn_b = quaternion_axis_angle(normalize(vec(1, 2, 0.5)), scalar(0.4));
    auto pos_b = vec(1, -1, 0.5);
    for (auto &s : all_shapes()) {
        for (int k = 0; k < 10; ++k) {
            auto ctx = resting(s.shape, random.uniform(1, 3), random.uniform(1, 3), random.uniform(0, 0.05),
                               random.orientation(), pos_b, orn_b);
            ctx.posB = pos_b;
            ctx.ornB = orn_b;
            auto ab = collide_mesh_checked(s.shape, mesh, ctx);
            auto swapped_ctx = collision_context{ctx.posB, ctx.ornB, ctx.posA, ctx.ornA, ctx.threshold};
            auto ba = run_swapped(mesh, s.shape, swapped_ctx);
            SCOPED_TRACE(s.name + " " + std::to_string(k));
            ASSERT_GT(ab.num_points, 0u);
            ASSERT_EQ(ab.num_points, ba.num_points);
            for (std::size_t i = 0; i < ab.num_points; ++i) {
                const auto &p = ab.point[i], &q = ba.point[i];
                expect_vec_near(q.pivotA, p.pivotB, scalar(1e-6));
                expect_vec_near(q.pivotB, p.pivotA, scalar(1e-6));
                expect_vec_near(q.normal, -p.normal, scalar(1e-6));
                EXPECT_NEAR(q.distance, p.distance, 1e-6);
                EXPECT_EQ(q.featureA, p.featureB);
                EXPECT_EQ(q.featureB, p.featureA);
            }
        }
    }
}

TEST(collide_mesh_test, variant_dispatcher) {
    auto mesh = floor_mesh(2);
    shapes_variant_t mesh_var{mesh};
    for (auto &s : all_shapes()) {
        auto ctx = resting(s.shape, 1.2, 0.9, 0.02, quaternion_axis_angle(vector3_y, 0.3));
        auto direct = collide_mesh_checked(s.shape, mesh, ctx);
        collision_result via;
        collide(s.shape, mesh_var, ctx, via);
        ASSERT_GT(direct.num_points, 0u) << s.name;
        ASSERT_EQ(via.num_points, direct.num_points) << s.name;
        for (std::size_t i = 0; i < direct.num_points; ++i) {
            expect_vec_near(via.point[i].normal, direct.point[i].normal, 0);
            EXPECT_EQ(via.point[i].distance, direct.point[i].distance);
            EXPECT_EQ(via.point[i].featureB, direct.point[i].featureB);
        }
        collision_result reversed;
        auto swapped_ctx = collision_context{ctx.posB, ctx.ornB, ctx.posA, ctx.ornA, ctx.threshold};
        collide(mesh_var, s.shape, swapped_ctx, reversed);
        EXPECT_EQ(reversed.num_points, direct.num_points) << s.name;
    }

    // Static-only pairs: nothing, even overlapping.
    collision_context ctx;
    collision_result r;
    collide(mesh_var, mesh_var, ctx, r);
    EXPECT_EQ(r.num_points, 0u);
    shapes_variant_t plane{plane_shape{vector3_y, 0}};
    collide(mesh_var, plane, ctx, r);
    EXPECT_EQ(r.num_points, 0u);
    collide(plane, mesh_var, ctx, r);
    EXPECT_EQ(r.num_points, 0u);
}

namespace {

// Distance from q to triangle (a, b, c), written out independently: the plane's when q's
// projection falls inside, else the nearest of the three edges.
scalar distance_point_triangle(const vector3 &q, const vector3 &a, const vector3 &b, const vector3 &c) {
    auto n = normalize(cross(b - a, c - a));
    auto inside = dot(cross(b - a, q - a), n) >= 0 && dot(cross(c - b, q - b), n) >= 0 &&
                  dot(cross(a - c, q - c), n) >= 0;
    if (inside) return std::abs(dot(q - a, n));
    auto to_edge = [&](const vector3 &p0, const vector3 &p1) {
        auto d = p1 - p0;
        auto t = std::clamp(dot(q - p0, d) / dot(d, d), scalar(0), scalar(1));
        return length(q - (p0 + d * t));
    };
    return std::min({to_edge(a, b), to_edge(b, c), to_edge(c, a)});
}

} // namespace

// A capsule in front of a lone triangle (all its edges on the boundary, so every feature is
// active): the least distance reported is the true one, found by walking the capsule's segment
// in 4,000 steps, and no point is nearer than that. Covers segments over the face, beside edges
// and vertices, parallel to the face and to an edge, and touching it.
TEST(collide_mesh_test, capsule_in_front_of_a_triangle_finds_the_true_distance) {
    std::mt19937 rng(17);
    auto uniform = [&](scalar lo, scalar hi) { return std::uniform_real_distribution<scalar>(lo, hi)(rng); };
    auto random_vec = [&](scalar r) { return vector3{uniform(-r, r), uniform(-r, r), uniform(-r, r)}; };
    std::size_t checked = 0;
    for (int trial = 0; trial < 600; ++trial) {
        std::vector<vector3> v{random_vec(1), random_vec(1), random_vec(1)};
        auto n = cross(v[1] - v[0], v[2] - v[0]);
        if (length(n) < scalar(0.05)) continue;
        n = normalize(n);
        auto mesh = test::make_mesh(v, {0, 1, 2});
        capsule_shape capsule{uniform(scalar(0.05), scalar(0.3)), uniform(0, scalar(0.8)),
                              coordinate_axis::x};
        collision_context ctx;
        ctx.posA = (v[0] + v[1] + v[2]) / scalar(3) + random_vec(scalar(1.2)) + n * uniform(0, scalar(0.6));
        ctx.ornA = normalize(quaternion{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)});
        // Every few trials, the segment is laid parallel to the face or to an edge.
        if (trial % 5 == 1 || trial % 5 == 2) {
            auto along = trial % 5 == 1 ? normalize(cross(n, random_vec(1))) : normalize(v[1] - v[0]);
            ctx.ornA = shortest_arc(vector3_x, along);
        }
        ctx.threshold = 10;
        vector3 p0, p1;
        capsule_ends(capsule, ctx.posA, ctx.ornA, p0, p1);
        if (dot(p0 - v[0], n) < 0 || dot(p1 - v[0], n) < 0) continue;

        auto expected = large_scalar;
        constexpr int steps = 4000;
        for (int i = 0; i <= steps; ++i) {
            auto q = p0 + (p1 - p0) * (scalar(i) / steps);
            expected = std::min(expected, distance_point_triangle(q, v[0], v[1], v[2]) - capsule.radius);
        }
        SCOPED_TRACE("trial " + std::to_string(trial));
        auto r = collide_mesh_checked(capsule, mesh, ctx);
        ASSERT_GT(r.num_points, 0u);
        // The walk's spacing bounds how far above the true least distance it can land.
        auto spacing = length(p1 - p0) / steps;
        EXPECT_NEAR(min_distance(r), expected, spacing + scalar(1e-4));
        for (std::size_t i = 0; i < r.num_points; ++i)
            EXPECT_GE(r.point[i].distance, expected - spacing - scalar(1e-4)) << "point " << i;
        ++checked;
    }
    EXPECT_GT(checked, 150u);
}

// A cylinder in front of a lone triangle, near its open edges, is found at its true distance.
// The exact pair's normal there can be a rim-against-edge axis a fraction of a degree off the
// face's; the manifold is then built along the face's normal, and where that support lies
// beyond the open edge the exact point over the triangle still stands: no neighbour reports it.
// (A cylinder 2 cm from such an edge used to get no point at all, and one falling at 60 m/s
// passed through.)
TEST(collide_mesh_test, cylinder_in_front_of_a_triangle_finds_the_true_distance) {
    std::mt19937 rng(23);
    auto uniform = [&](scalar lo, scalar hi) { return std::uniform_real_distribution<scalar>(lo, hi)(rng); };
    auto random_vec = [&](scalar r) { return vector3{uniform(-r, r), uniform(-r, r), uniform(-r, r)}; };
    // The first case: the pose that had no point, 0.0201 m from the edge opposite vertex 0.
    std::vector<std::vector<vector3>> triangles{
        {vec(-1.2574, 0.2126, -0.7911), vec(0.2961, 0.3258, 1.3863), vec(-0.9989, -1.3421, -0.1230)}};
    std::vector<vector3> positions{vec(-0.0236, -0.6379, 0.4484)};
    std::vector<quaternion> orientations{
        normalize(quaternion{scalar(0.21719), scalar(0.44533), -scalar(0.56387), -scalar(0.66072)})};
    std::size_t checked = 0;
    for (int trial = 0; trial < 400; ++trial) {
        std::vector<vector3> v;
        collision_context ctx;
        if (trial < int(triangles.size())) {
            v = triangles[trial];
            ctx.posA = positions[trial];
            ctx.ornA = orientations[trial];
        } else {
            // Over a point near the triangle, often beyond an edge, its lowest point a few
            // centimetres over the plane.
            v = {random_vec(1), random_vec(1), random_vec(1)};
            ctx.ornA = normalize(quaternion{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)});
        }
        auto n = cross(v[1] - v[0], v[2] - v[0]);
        if (length(n) < scalar(0.05)) continue;
        n = normalize(n);
        cylinder_shape cylinder{scalar(0.25), scalar(0.3), coordinate_axis::z};
        if (trial >= int(triangles.size())) {
            auto a = uniform(-scalar(0.3), scalar(1.3)), b = uniform(-scalar(0.3), scalar(1.3) - a);
            auto over = v[0] + (v[1] - v[0]) * a + (v[2] - v[0]) * b;
            auto c = std::abs(dot(rotate(ctx.ornA, vector3_z), n));
            auto reach =
                cylinder.half_length * c + cylinder.radius * std::sqrt(std::max(scalar(0), 1 - c * c));
            ctx.posA = over + n * (reach + uniform(scalar(0.005), scalar(0.12)));
        }
        ctx.threshold = scalar(0.2);
        // The cylinder's surface, sampled: sides, and both caps in rings.
        constexpr int heights = 60, angles = 180, rings = 10;
        auto expected = large_scalar;
        scalar lowest = large_scalar;
        auto sample = [&](scalar r, scalar angle, scalar z) {
            auto q = ctx.posA + rotate(ctx.ornA, vector3{r * std::cos(angle), r * std::sin(angle), z});
            expected = std::min(expected, distance_point_triangle(q, v[0], v[1], v[2]));
            lowest = std::min(lowest, dot(q - v[0], n));
        };
        for (int j = 0; j < angles; ++j) {
            auto angle = 2 * pi * scalar(j) / angles;
            for (int i = 0; i <= heights; ++i)
                sample(cylinder.radius, angle, cylinder.half_length * (2 * scalar(i) / heights - 1));
            for (int k = 0; k < rings; ++k) {
                sample(cylinder.radius * scalar(k) / rings, angle, -cylinder.half_length);
                sample(cylinder.radius * scalar(k) / rings, angle, cylinder.half_length);
            }
        }
        // Wholly in front of the triangle's plane and within the threshold of the triangle.
        if (lowest < scalar(0.005) || expected > scalar(0.15)) continue;
        SCOPED_TRACE("trial " + std::to_string(trial));
        auto r = collide_mesh_checked(cylinder, test::make_mesh(v, {0, 1, 2}), ctx);
        ASSERT_GT(r.num_points, 0u) << "the cylinder is " << expected << " m from the triangle";
        // The samples' spacing (the rim's chords, the sides' rows) bounds how far above the true
        // least distance the walk can land; a point along the face's normal is the height over
        // the plane, at least the distance.
        auto spacing = cylinder.radius * (1 - std::cos(pi / angles)) + cylinder.half_length / heights;
        EXPECT_NEAR(min_distance(r), expected, spacing + scalar(2e-3));
        for (std::size_t i = 0; i < r.num_points; ++i)
            EXPECT_GE(r.point[i].distance, expected - spacing - scalar(1e-4)) << "point " << i;
        ++checked;
    }
    EXPECT_GT(checked, 200u);
}

// A cylinder tilted 10 degrees over a plate's open edge, its lowest rim point 7 cm beyond the
// edge and 0.75 m up: the look-ahead of a body falling 1 m a step. The nearest pair is the rim
// against the edge, which the plate reports at that distance (none came back, and the cylinder
// fell through the plate at 60 m/s).
TEST(collide_mesh_test, a_tilted_cylinder_over_an_open_edge_is_seen_from_afar) {
    auto plate =
        test::make_mesh({vec(-2, 0, -6), vec(-2, 0, 6), vec(2, 0, 6), vec(2, 0, -6)}, {0, 1, 2, 0, 2, 3});
    cylinder_shape cylinder{scalar(0.3), scalar(0.2), coordinate_axis::y};
    auto tilt = quaternion_axis_angle(vector3_z, -scalar(0.1745));
    for (auto height : {scalar(1), scalar(0.8), scalar(0.5)}) {
        collision_context ctx;
        ctx.posA = vec(1.77, height, -2);
        ctx.ornA = tilt;
        ctx.threshold = scalar(1.2);
        // The lowest rim point, and its distance from the edge x = 2, y = 0.
        auto rim = to_world_space(vec(0.3, -0.2, 0), ctx.posA, ctx.ornA);
        auto expected = std::hypot(rim.x - 2, rim.y);
        SCOPED_TRACE("height " + std::to_string(height));
        ASSERT_GT(rim.x, 2) << "the lowest rim point is over the plate";
        auto r = collide_mesh_checked(cylinder, plate, ctx);
        ASSERT_GT(r.num_points, 0u);
        EXPECT_NEAR(min_distance(r), expected, scalar(2e-3));
    }
}
