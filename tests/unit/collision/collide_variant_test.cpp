#include "collide_test_helpers.hpp"
#include <tuple>
#include <type_traits>
#include <utility>

// collide(shapes_variant_t, shapes_variant_t): every ordered pair of alternatives, each at a
// touching configuration (A resting on B, sunk `variant_depth` into it), must report the depth and give
// exactly what the pair's own overload gives; plane against plane reports nothing.

using namespace edyn;
using namespace collide_test;

namespace {

constexpr scalar variant_depth = scalar(0.01);
constexpr scalar variant_tol = scalar(1e-4);

// A shape, and how far it reaches below and above its origin along y.
template<typename Shape>
struct sample {
    Shape shape;
    scalar bottom;
    scalar top;
};

sample<sphere_shape> make_sample(std::type_identity<sphere_shape>) { return {sphere_shape{0.5}, 0.5, 0.5}; }

sample<cylinder_shape> make_sample(std::type_identity<cylinder_shape>) {
    return {cylinder_shape{0.5, 0.4, coordinate_axis::y}, 0.4, 0.4};
}

sample<capsule_shape> make_sample(std::type_identity<capsule_shape>) {
    return {capsule_shape{0.3, 0.5, coordinate_axis::x}, 0.3, 0.3};
}

sample<box_shape> make_sample(std::type_identity<box_shape>) {
    return {box_shape{{0.5, 0.4, 0.6}}, 0.4, 0.4};
}

// Frustum of a square pyramid: flat bottom and top.
sample<polyhedron_shape> make_sample(std::type_identity<polyhedron_shape>) {
    auto shape = polyhedron_shape(std::vector<vector3>{{0.5, -0.4, 0.5},
                                                       {-0.5, -0.4, 0.5},
                                                       {-0.5, -0.4, -0.5},
                                                       {0.5, -0.4, -0.5},
                                                       {0.3, 0.4, 0.3},
                                                       {-0.3, 0.4, 0.3},
                                                       {-0.3, 0.4, -0.3},
                                                       {0.3, 0.4, -0.3}});
    return {shape, 0.4, 0.4};
}

// Two blocks side by side, both spanning y [-0.4, 0.4].
sample<compound_shape> make_sample(std::type_identity<compound_shape>) {
    compound_shape c;
    c.add_shape(box_shape{{0.3, 0.4, 0.5}}, {0, 0, 0});
    c.add_shape(box_shape{{0.3, 0.4, 0.5}}, {0.6, 0, 0});
    c.finish();
    return {c, 0.4, 0.4};
}

// The ground plane y = 0 as B; as A, the plane facing down whose solid side is above `height`
// (planes ignore their position).
plane_shape plane_below() { return {vector3_y, 0}; }
plane_shape plane_above(scalar height) { return {-vector3_y, -height}; }

// A flat 4 m square of 8 triangles at y = `height` (mesh space), facing up or down.
mesh_shape flat_mesh(scalar height, bool facing_up) {
    std::vector<vector3> vertices;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            vertices.push_back({scalar(j) * 2 - 2, height, scalar(i) * 2 - 2});
    }
    std::vector<std::uint32_t> indices;
    for (std::uint32_t i = 0; i < 2; ++i) {
        for (std::uint32_t j = 0; j < 2; ++j) {
            auto v00 = i * 3 + j, v01 = v00 + 1, v10 = v00 + 3, v11 = v00 + 4;
            if (facing_up) {
                indices.insert(indices.end(), {v00, v10, v11, v00, v11, v01});
            } else {
                indices.insert(indices.end(), {v00, v11, v10, v00, v01, v11});
            }
        }
    }
    auto mesh = std::make_shared<triangle_mesh>();
    mesh->insert_vertices(vertices.begin(), vertices.end());
    mesh->insert_indices(indices.begin(), indices.end());
    mesh->initialize();
    return {mesh};
}

// The same as a paged mesh of two pages, both loaded.
paged_mesh_shape flat_paged_mesh(scalar height, bool facing_up) {
    auto whole = flat_mesh(height, facing_up).trimesh;
    auto v = whole->get_vertices();
    auto i = whole->get_indices();
    auto paged = create_paged_triangle_mesh({v.begin(), v.end()}, {i.begin(), i.end()}, 4);
    paged->require(paged->get_aabb(), 0);
    return {paged};
}

struct scene {
    shapes_variant_t a;
    shapes_variant_t b;
    collision_context ctx;
};

// A resting on B with `variant_depth` of overlap: B at the origin, A above it. Both get a yaw so that
// the pivots' object spaces differ from world space.
template<typename A, typename B>
scene make_scene() {
    collision_context ctx;
    ctx.ornA = quaternion_axis_angle(vector3_y, scalar(0.3));
    ctx.ornB = quaternion_axis_angle(vector3_y, scalar(-0.2));
    ctx.threshold = scalar(0.02);
    scalar b_top = 0;
    shapes_variant_t b;
    if constexpr (std::is_same_v<B, plane_shape>) {
        b = plane_below();
    } else if constexpr (std::is_same_v<B, mesh_shape>) {
        b = flat_mesh(0, true);
    } else if constexpr (std::is_same_v<B, paged_mesh_shape>) {
        b = flat_paged_mesh(0, true);
    } else {
        auto s = make_sample(std::type_identity<B>{});
        b = s.shape;
        b_top = s.top;
    }
    shapes_variant_t a;
    if constexpr (std::is_same_v<A, plane_shape>) {
        a = plane_above(b_top - variant_depth);
    } else if constexpr (std::is_same_v<A, mesh_shape>) {
        // The mesh takes its body's transform: at the origin, facing down at B's top less depth.
        a = flat_mesh(b_top - variant_depth, false);
        ctx.ornA = quaternion_identity;
    } else if constexpr (std::is_same_v<A, paged_mesh_shape>) {
        a = flat_paged_mesh(b_top - variant_depth, false);
        ctx.ornA = quaternion_identity;
    } else {
        auto s = make_sample(std::type_identity<A>{});
        a = s.shape;
        ctx.posA = {0, b_top + s.bottom - variant_depth, 0};
    }
    return {std::move(a), std::move(b), ctx};
}

template<typename A, typename B>
void check_pair() {
    auto s = make_scene<A, B>();
    SCOPED_TRACE(testing::Message() << "pair (" << s.a.index() << ", " << s.b.index() << ")");
    collision_result r;
    collide(s.a, s.b, s.ctx, r);
    if constexpr (is_static_only_shape_v<A> && is_static_only_shape_v<B>) {
        EXPECT_EQ(r.num_points, 0u);
    } else {
        ASSERT_GT(r.num_points, 0u);
        // The narrowphase keeps a single point for these pairs (update_contact_manifold).
        if constexpr (touches_at_one_point_v<A, B>) {
            EXPECT_EQ(r.num_points, 1u);
        }
        EXPECT_NEAR(min_distance(r), -variant_depth, variant_tol);
        expect_consistent(r, s.ctx, variant_tol);
        // Each point's normal points from B (below) up towards A.
        for (std::size_t i = 0; i < r.num_points; ++i)
            expect_vec_near(r.point[i].normal, vector3_y, variant_tol);

        // The dispatcher is the pair's own overload, bit for bit.
        collision_result direct;
        collide(std::get<A>(s.a), std::get<B>(s.b), s.ctx, direct);
        ASSERT_EQ(r.num_points, direct.num_points);
        for (std::size_t i = 0; i < r.num_points; ++i) {
            expect_vec_near(r.point[i].pivotA, direct.point[i].pivotA, 0);
            expect_vec_near(r.point[i].pivotB, direct.point[i].pivotB, 0);
            EXPECT_EQ(r.point[i].distance, direct.point[i].distance);
            EXPECT_EQ(r.point[i].featureA, direct.point[i].featureA);
            EXPECT_EQ(r.point[i].featureB, direct.point[i].featureB);
        }
    }
}

template<typename A, typename... Bs>
int check_row(std::tuple<Bs...> *) {
    (check_pair<A, Bs>(), ...);
    return int(sizeof...(Bs));
}

template<typename... As>
int check_all(std::tuple<As...> *) {
    return (check_row<As>(static_cast<shapes_tuple_t *>(nullptr)) + ...);
}

} // namespace

TEST(collide_variant_test, every_pair_reports_the_resting_depth) {
    EXPECT_EQ(check_all(static_cast<shapes_tuple_t *>(nullptr)), int(num_shapes * num_shapes));
}

TEST(collide_variant_test, plane_against_plane_reports_nothing) {
    collision_result r;
    collision_context ctx;
    // Crossing planes, facing each other and coincident: never a point.
    collide(shapes_variant_t{plane_shape{vector3_y, 0}}, shapes_variant_t{plane_shape{vector3_x, 0}}, ctx, r);
    collide(shapes_variant_t{plane_shape{vector3_y, 0}}, shapes_variant_t{plane_shape{-vector3_y, 1}}, ctx,
            r);
    collide(shapes_variant_t{plane_shape{vector3_y, 0}}, shapes_variant_t{plane_shape{vector3_y, 0}}, ctx, r);
    EXPECT_EQ(r.num_points, 0u);
}

TEST(collide_variant_test, separated_pairs_report_nothing) {
    // A lifted by the threshold and a bit more above B: no pair reports a point.
    auto s = make_scene<box_shape, compound_shape>();
    s.ctx.posA.y += variant_depth + s.ctx.threshold + scalar(0.01);
    collision_result r;
    collide(s.a, s.b, s.ctx, r);
    EXPECT_EQ(r.num_points, 0u);
    auto t = make_scene<compound_shape, sphere_shape>();
    t.ctx.posA.y += variant_depth + t.ctx.threshold + scalar(0.01);
    collide(t.a, t.b, t.ctx, r);
    EXPECT_EQ(r.num_points, 0u);
    auto u = make_scene<plane_shape, polyhedron_shape>();
    u.a = plane_above(scalar(0.4) + u.ctx.threshold + scalar(0.01));
    collide(u.a, u.b, u.ctx, r);
    EXPECT_EQ(r.num_points, 0u);
}
