#include "edyn/serialization/shape_types.hpp"
#include "edyn/shapes/moment_of_inertia.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "unit/serialization/archive_round_trip.hpp"
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

using namespace edyn;
using edyn::test::decode_fails;
using edyn::test::encode;
using edyn::test::expect_truncations_fail;
using edyn::test::round_trip;

// A member added to a shape must be serialized too; update shape_types.hpp, then these.
static_assert(sizeof(plane_shape) == 4 * sizeof(scalar), "plane_shape changed: update its serializer");
static_assert(sizeof(sphere_shape) == sizeof(scalar), "sphere_shape changed: update its serializer");
static_assert(sizeof(box_shape) == 3 * sizeof(scalar), "box_shape changed: update its serializer");
static_assert(sizeof(cylinder_shape) == 3 * sizeof(scalar), "cylinder_shape changed: update its serializer");
static_assert(sizeof(capsule_shape) == 3 * sizeof(scalar), "capsule_shape changed: update its serializer");
static_assert(sizeof(polyhedron_shape) == sizeof(std::shared_ptr<const convex_mesh>),
              "polyhedron_shape changed: update its serializer");
namespace {
struct compound_shape_members {
    std::vector<compound_shape::child> children;
    static_tree tree;
    bool finished;
};
} // namespace
static_assert(sizeof(compound_shape) == sizeof(compound_shape_members),
              "compound_shape changed: update its serializer");
static_assert(std::variant_size_v<shapes_variant_t> == 9,
              "a shape was added: give it a serializer and a test");

namespace {

polyhedron_shape cube_hull() {
    // Corners of a box plus points the hull discards: the centre and the middle of a face.
    std::vector<vector3> points{{1, 2, 3},   {-1, 2, 3},  {1, -2, 3},   {-1, -2, 3}, {1, 2, -3},
                                {-1, 2, -3}, {1, -2, -3}, {-1, -2, -3}, {0, 0, 0},   {1, 0, 0}};
    return polyhedron_shape(points);
}

polyhedron_shape tetrahedron() {
    std::vector<vector3> vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    std::vector<std::vector<std::uint32_t>> faces{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return polyhedron_shape(vertices, faces);
}

void expect_same_mesh(const convex_mesh &actual, const convex_mesh &expected) {
    ASSERT_EQ(actual.num_vertices(), expected.num_vertices());
    ASSERT_EQ(actual.num_faces(), expected.num_faces());
    EXPECT_EQ(actual.num_edges(), expected.num_edges());
    for (std::size_t i = 0; i < expected.num_vertices(); ++i) {
        EDYN_EXPECT_SAME(actual.vertices[i], expected.vertices[i]) << " vertex " << i;
    }
    // Same faces in the same order: collision features index them.
    EXPECT_EQ(actual.indices, expected.indices);
    EXPECT_EQ(actual.faces, expected.faces);
    for (std::size_t f = 0; f < expected.num_faces(); ++f) {
        EDYN_EXPECT_SAME(actual.normals[f], expected.normals[f]) << " face " << f;
    }
    EXPECT_EQ(actual.plane_constants, expected.plane_constants);
    EXPECT_EQ(actual.edges, expected.edges);
    EXPECT_EQ(actual.edge_faces, expected.edge_faces);
    EXPECT_EQ(actual.unique_edge_directions.size(), expected.unique_edge_directions.size());
    EXPECT_EQ(actual.bounding_radius, expected.bounding_radius);
}

void expect_same_aabb(const AABB &actual, const AABB &expected) {
    EDYN_EXPECT_SAME(actual.min, expected.min);
    EDYN_EXPECT_SAME(actual.max, expected.max);
}

// Writes a polyhedron's encoding by hand: a mesh with these vertices and faces.
std::vector<std::uint8_t> polyhedron_bytes(const std::vector<vector3> &vertices,
                                           const std::vector<std::vector<std::uint32_t>> &faces) {
    std::vector<std::uint8_t> bytes;
    memory_output_archive archive(bytes);
    archive(true);
    archive.write_size(vertices.size());
    for (auto &v : vertices)
        archive(v);
    archive.write_size(faces.size());
    for (auto &face : faces) {
        archive.write_size(face.size());
        for (auto i : face)
            archive(i);
    }
    return bytes;
}

compound_shape box_and_sphere() {
    compound_shape shape;
    auto orn = normalize(quaternion{scalar(0.1), scalar(0.2), scalar(0.3), 1});
    shape.add_shape(box_shape{scalar(0.5), 1, scalar(1.5)}, vector3{1, 2, 3}, orn);
    shape.add_shape(sphere_shape{scalar(0.75)}, vector3{-2, 0, scalar(0.5)});
    shape.finish();
    return shape;
}

void expect_same_compound(const compound_shape &actual, const compound_shape &expected) {
    ASSERT_EQ(actual.children.size(), expected.children.size());
    EXPECT_EQ(actual.finished, expected.finished);
    for (std::size_t i = 0; i < expected.children.size(); ++i) {
        const auto &a = actual.children[i], &e = expected.children[i];
        EXPECT_EQ(a.shape.index(), e.shape.index()) << "child " << i;
        EDYN_EXPECT_SAME(a.position, e.position) << " child " << i;
        EDYN_EXPECT_SAME(a.orientation, e.orientation) << " child " << i;
        expect_same_aabb(a.aabb, e.aabb);
    }
    ASSERT_EQ(actual.tree.nodes.size(), expected.tree.nodes.size());
    for (std::size_t i = 0; i < expected.tree.nodes.size(); ++i) {
        expect_same_aabb(actual.tree.nodes[i].aabb, expected.tree.nodes[i].aabb);
        EXPECT_EQ(actual.tree.nodes[i].index, expected.tree.nodes[i].index) << "node " << i;
        EXPECT_EQ(actual.tree.nodes[i].leaf, expected.tree.nodes[i].leaf) << "node " << i;
    }
}

} // namespace

TEST(shape_serialization_test, simple_shapes_round_trip) {
    auto plane = round_trip(plane_shape{{scalar(0.6), scalar(0.8), 0}, scalar(-2.5)});
    EDYN_EXPECT_SAME(plane.normal, (vector3{scalar(0.6), scalar(0.8), 0}));
    EXPECT_EQ(plane.constant, scalar(-2.5));

    EXPECT_EQ(round_trip(sphere_shape{scalar(0.75)}).radius, scalar(0.75));

    auto cylinder = round_trip(cylinder_shape{scalar(0.5), scalar(1.25), coordinate_axis::z});
    EXPECT_EQ(cylinder.radius, scalar(0.5));
    EXPECT_EQ(cylinder.half_length, scalar(1.25));
    EXPECT_EQ(cylinder.axis, coordinate_axis::z);

    auto capsule = round_trip(capsule_shape{scalar(0.3), scalar(0.9), coordinate_axis::y});
    EXPECT_EQ(capsule.radius, scalar(0.3));
    EXPECT_EQ(capsule.half_length, scalar(0.9));
    EXPECT_EQ(capsule.axis, coordinate_axis::y);

    auto box = round_trip(box_shape{1, 2, 3});
    EDYN_EXPECT_SAME(box.half_extents, (vector3{1, 2, 3}));
}

TEST(shape_serialization_test, coordinate_axis_out_of_range_fails) {
    for (std::uint8_t bad : {std::uint8_t(3), std::uint8_t(255)}) {
        // The axis is the last byte of both encodings.
        auto cylinder = encode(cylinder_shape{1, 1, coordinate_axis::y});
        cylinder.back() = bad;
        EXPECT_TRUE(decode_fails<cylinder_shape>(cylinder)) << "axis byte " << int(bad);
        auto capsule = encode(capsule_shape{1, 1, coordinate_axis::y});
        capsule.back() = bad;
        EXPECT_TRUE(decode_fails<capsule_shape>(capsule)) << "axis byte " << int(bad);
    }
    for (auto axis : {coordinate_axis::x, coordinate_axis::y, coordinate_axis::z}) {
        EXPECT_EQ(round_trip(cylinder_shape{1, 1, axis}).axis, axis);
    }
}

TEST(shape_serialization_test, polyhedron_hull_round_trip) {
    auto original = cube_hull();
    ASSERT_EQ(original.mesh->num_vertices(), 8u);
    auto copy = round_trip(original);
    ASSERT_NE(copy.mesh, nullptr);
    EXPECT_NE(copy.mesh, original.mesh) << "the copy must own its mesh";
    expect_same_mesh(*copy.mesh, *original.mesh);
    EXPECT_EQ(copy.mesh->num_faces(), 6u);
    EXPECT_EQ(shape_volume(copy), shape_volume(original));
    EXPECT_NEAR(shape_volume(copy), 48, 1e-4);
    auto orn = normalize(quaternion{1, 2, 3, 4});
    expect_same_aabb(shape_aabb(copy, vector3{1, 2, 3}, orn), shape_aabb(original, vector3{1, 2, 3}, orn));
}

TEST(shape_serialization_test, polyhedron_tetrahedron_round_trip) {
    auto original = tetrahedron();
    auto copy = round_trip(original);
    ASSERT_NE(copy.mesh, nullptr);
    expect_same_mesh(*copy.mesh, *original.mesh);
    EXPECT_EQ(copy.mesh->num_vertices(), 4u);
    EXPECT_EQ(copy.mesh->num_faces(), 4u);
    EXPECT_NEAR(shape_volume(copy), scalar(1) / 6, 1e-6);
    expect_same_aabb(shape_aabb(copy, vector3_zero, quaternion_identity),
                     shape_aabb(original, vector3_zero, quaternion_identity));
}

TEST(shape_serialization_test, polyhedron_without_mesh_round_trips) {
    polyhedron_shape copy = tetrahedron();
    auto bytes = encode(polyhedron_shape{});
    EXPECT_FALSE(decode_fails(bytes, copy));
    EXPECT_EQ(copy.mesh, nullptr);
}

TEST(shape_serialization_test, mesh_round_trips_with_its_triangles_and_coefficients) {
    auto mesh = std::make_shared<triangle_mesh>();
    std::vector<vector3> vertices{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {2, 0, 0}};
    // The last triangle has no area: initialize() drops it, and the copy numbers as the original.
    std::vector<std::uint32_t> indices{0, 2, 1, 0, 3, 2, 1, 1, 4};
    std::vector<scalar> friction{0, scalar(0.25), scalar(0.5), scalar(0.75), 1};
    mesh->insert_vertices(vertices.begin(), vertices.end());
    mesh->insert_indices(indices.begin(), indices.end());
    mesh->insert_friction_coefficients(friction.begin(), friction.end());
    mesh->initialize();
    ASSERT_EQ(mesh->num_triangles(), 2u);

    auto copy = round_trip(mesh_shape{mesh});
    ASSERT_TRUE(copy.trimesh);
    ASSERT_TRUE(copy.trimesh->initialized());
    ASSERT_EQ(copy.trimesh->num_triangles(), 2u);
    for (std::size_t t = 0; t < 2; ++t) {
        for (std::size_t i = 0; i < 3; ++i)
            EXPECT_EQ(copy.trimesh->get_vertex_index(t, i), mesh->get_vertex_index(t, i));
        EXPECT_EQ(copy.trimesh->get_triangle_normal(t), mesh->get_triangle_normal(t));
    }
    EXPECT_TRUE(copy.trimesh->has_per_vertex_friction());
    EXPECT_FALSE(copy.trimesh->has_per_vertex_restitution());
    EXPECT_EQ(copy.trimesh->get_friction(1, {0, 0, 1}), mesh->get_friction(1, {0, 0, 1}));

    mesh_shape none = mesh_shape{mesh};
    EXPECT_FALSE(decode_fails(encode(mesh_shape{}), none));
    EXPECT_EQ(none.trimesh, nullptr);
}

TEST(shape_serialization_test, malformed_meshes_fail) {
    auto bytes_of = [](const std::vector<vector3> &vertices, const std::vector<std::uint32_t> &indices,
                       const std::vector<scalar> &friction) {
        std::vector<std::uint8_t> bytes;
        memory_output_archive archive(bytes);
        archive(true);
        archive.write_size(vertices.size());
        for (auto v : vertices)
            archive(v);
        archive.write_size(indices.size());
        for (auto i : indices)
            archive(i);
        archive.write_size(friction.size());
        for (auto f : friction)
            archive(f);
        archive.write_size(0);
        return bytes;
    };
    std::vector<vector3> vertices{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}};
    ASSERT_FALSE(decode_fails<mesh_shape>(bytes_of(vertices, {0, 2, 1}, {})));
    // An index out of range, a count not a multiple of three, no triangles, coefficients of the
    // wrong count or negative, a non-finite vertex, a count beyond the bytes.
    EXPECT_TRUE(decode_fails<mesh_shape>(bytes_of(vertices, {0, 2, 3}, {})));
    EXPECT_TRUE(decode_fails<mesh_shape>(bytes_of(vertices, {0, 2}, {})));
    EXPECT_TRUE(decode_fails<mesh_shape>(bytes_of(vertices, {}, {})));
    EXPECT_TRUE(decode_fails<mesh_shape>(bytes_of(vertices, {0, 2, 1}, {1, 1})));
    EXPECT_TRUE(decode_fails<mesh_shape>(bytes_of(vertices, {0, 2, 1}, {1, -1, 1})));
    auto nan_vertices = vertices;
    nan_vertices[2].z = std::numeric_limits<scalar>::quiet_NaN();
    EXPECT_TRUE(decode_fails<mesh_shape>(bytes_of(nan_vertices, {0, 2, 1}, {})));
    std::vector<std::uint8_t> lying;
    memory_output_archive archive(lying);
    archive(true);
    archive.write_size(1000000);
    EXPECT_TRUE(decode_fails<mesh_shape>(lying));
}

TEST(shape_serialization_test, paged_mesh_is_read_as_absent) {
    std::vector<vector3> vertices{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    std::vector<std::uint32_t> indices{0, 2, 1};
    paged_mesh_shape shape{create_paged_triangle_mesh(vertices, indices, 10)};
    auto bytes = encode(shape);
    paged_mesh_shape copy = shape;
    EXPECT_FALSE(decode_fails(bytes, copy));
    EXPECT_EQ(copy.trimesh, nullptr);
    auto variant = round_trip(shapes_variant_t{shape});
    ASSERT_TRUE(std::holds_alternative<paged_mesh_shape>(variant));
    EXPECT_EQ(std::get<paged_mesh_shape>(variant).trimesh, nullptr);
}

TEST(shape_serialization_test, malformed_polyhedra_fail) {
    auto mesh = tetrahedron().mesh;
    std::vector<vector3> vertices = mesh->vertices;
    std::vector<std::vector<std::uint32_t>> faces{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    ASSERT_FALSE(decode_fails<polyhedron_shape>(polyhedron_bytes(vertices, faces)));

    // Two vertices.
    EXPECT_TRUE(decode_fails<polyhedron_shape>(polyhedron_bytes({{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}})));
    // A face naming a vertex that does not exist, a little and far out of range.
    for (std::uint32_t bad : {std::uint32_t(4), std::uint32_t(0xffffffff)}) {
        auto bad_faces = faces;
        bad_faces[3][1] = bad;
        EXPECT_TRUE(decode_fails<polyhedron_shape>(polyhedron_bytes(vertices, bad_faces))) << "index " << bad;
    }
    // An open surface (a face missing), a face of two vertices, a non-finite vertex, and the
    // winding reversed (negative volume).
    EXPECT_TRUE(decode_fails<polyhedron_shape>(polyhedron_bytes(vertices, {faces[0], faces[1], faces[2]})));
    auto two_vertex_face = faces;
    two_vertex_face[0] = {0, 2};
    EXPECT_TRUE(decode_fails<polyhedron_shape>(polyhedron_bytes(vertices, two_vertex_face)));
    auto nan_vertices = vertices;
    nan_vertices[1].x = std::numeric_limits<scalar>::quiet_NaN();
    EXPECT_TRUE(decode_fails<polyhedron_shape>(polyhedron_bytes(nan_vertices, faces)));
    std::vector<std::vector<std::uint32_t>> reversed{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    EXPECT_TRUE(decode_fails<polyhedron_shape>(polyhedron_bytes(vertices, reversed)));

    // More vertices than allowed, and a count far beyond the bytes that follow.
    std::vector<vector3> too_many(max_serialized_polyhedron_vertices + 1, vector3{1, 2, 3});
    EXPECT_TRUE(decode_fails<polyhedron_shape>(polyhedron_bytes(too_many, faces)));
    std::vector<std::uint8_t> lying;
    memory_output_archive archive(lying);
    archive(true);
    archive.write_size(1000);
    EXPECT_TRUE(decode_fails<polyhedron_shape>(lying));

    // A failed read leaves the shape as it was.
    polyhedron_shape kept = tetrahedron();
    auto before = kept.mesh;
    EXPECT_TRUE(decode_fails(polyhedron_bytes(vertices, {faces[0]}), kept));
    EXPECT_EQ(kept.mesh, before);
}

TEST(shape_serialization_test, compound_round_trip) {
    auto original = box_and_sphere();
    auto copy = round_trip(original);
    expect_same_compound(copy, original);
    ASSERT_EQ(copy.children.size(), 2u);
    ASSERT_TRUE(std::holds_alternative<box_shape>(copy.children[0].shape));
    EDYN_EXPECT_SAME(std::get<box_shape>(copy.children[0].shape).half_extents,
                     (vector3{scalar(0.5), 1, scalar(1.5)}));
    ASSERT_TRUE(std::holds_alternative<sphere_shape>(copy.children[1].shape));
    EXPECT_EQ(std::get<sphere_shape>(copy.children[1].shape).radius, scalar(0.75));
    EXPECT_EQ(shape_volume(copy), shape_volume(original));
    EDYN_EXPECT_SAME(shape_centroid(copy), shape_centroid(original));
    auto orn = normalize(quaternion{-1, 2, 0, 3});
    expect_same_aabb(shape_aabb(copy, vector3{4, 5, 6}, orn), shape_aabb(original, vector3{4, 5, 6}, orn));
}

TEST(shape_serialization_test, compound_with_tree_and_polyhedra_round_trip) {
    compound_shape original;
    auto hull = cube_hull();
    for (int i = 0; i < 12; ++i) {
        auto orn = normalize(quaternion{scalar(i), 1, scalar(-i) / 2, 2});
        vector3 pos{scalar(i) * 3, scalar(i % 3), scalar(-i)};
        if (i % 3 == 0) {
            original.add_shape(hull, pos, orn);
        } else if (i % 3 == 1) {
            original.add_shape(capsule_shape{scalar(0.25), 1, coordinate_axis::z}, pos, orn);
        } else {
            original.add_shape(cylinder_shape{1, scalar(0.5), coordinate_axis::y}, pos, orn);
        }
    }
    original.finish();
    ASSERT_FALSE(original.tree.nodes.empty());
    auto copy = round_trip(original);
    expect_same_compound(copy, original);
    ASSERT_TRUE(std::holds_alternative<polyhedron_shape>(copy.children[0].shape));
    expect_same_mesh(*std::get<polyhedron_shape>(copy.children[0].shape).mesh, *hull.mesh);
}

TEST(shape_serialization_test, unfinished_compound_round_trips) {
    compound_shape original;
    original.add_shape(sphere_shape{1}, vector3{1, 0, 0});
    auto copy = round_trip(original);
    expect_same_compound(copy, original);
    EXPECT_FALSE(copy.finished);
    EXPECT_TRUE(round_trip(compound_shape{}).children.empty());
}

TEST(shape_serialization_test, malformed_compounds_fail) {
    auto write = [](const compound_child_shape_t &child, const vector3 &pos, const quaternion &orn,
                    std::size_t count, bool finished) {
        std::vector<std::uint8_t> bytes;
        memory_output_archive archive(bytes);
        archive.write_size(count);
        for (std::size_t i = 0; i < count; ++i)
            archive(child, pos, orn);
        archive(finished);
        return bytes;
    };
    ASSERT_FALSE(
        decode_fails<compound_shape>(write(sphere_shape{1}, vector3_zero, quaternion_identity, 1, true)));
    // Rejected by add_shape: an invalid child, a non-finite position, a non-unit orientation,
    // and a polyhedron without a mesh.
    EXPECT_TRUE(
        decode_fails<compound_shape>(write(sphere_shape{-1}, vector3_zero, quaternion_identity, 1, true)));
    EXPECT_TRUE(decode_fails<compound_shape>(write(sphere_shape{1},
                                                   vector3{std::numeric_limits<scalar>::infinity(), 0, 0},
                                                   quaternion_identity, 1, true)));
    EXPECT_TRUE(
        decode_fails<compound_shape>(write(sphere_shape{1}, vector3_zero, quaternion{0, 0, 0, 2}, 1, true)));
    EXPECT_TRUE(
        decode_fails<compound_shape>(write(sphere_shape{1}, vector3_zero, quaternion{0, 0, 0, 0}, 1, true)));
    EXPECT_TRUE(
        decode_fails<compound_shape>(write(polyhedron_shape{}, vector3_zero, quaternion_identity, 1, true)));
    // finish() refuses a compound without children.
    EXPECT_TRUE(
        decode_fails<compound_shape>(write(sphere_shape{1}, vector3_zero, quaternion_identity, 0, true)));
    // A child shape index beyond the variant's alternatives.
    auto bytes = write(sphere_shape{1}, vector3_zero, quaternion_identity, 1, true);
    bytes[1] = std::uint8_t(std::variant_size_v<compound_child_shape_t>);
    EXPECT_TRUE(decode_fails<compound_shape>(bytes));

    // A failed read leaves the shape as it was.
    auto kept = box_and_sphere();
    EXPECT_TRUE(decode_fails(write(sphere_shape{-1}, vector3_zero, quaternion_identity, 1, true), kept));
    EXPECT_EQ(kept.children.size(), 2u);
    EXPECT_TRUE(kept.finished);
}

mesh_shape one_triangle_mesh() {
    auto mesh = std::make_shared<triangle_mesh>();
    std::vector<vector3> vertices{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    std::vector<std::uint32_t> indices{0, 2, 1};
    mesh->insert_vertices(vertices.begin(), vertices.end());
    mesh->insert_indices(indices.begin(), indices.end());
    mesh->initialize();
    return {mesh};
}

TEST(shape_serialization_test, shapes_variant_round_trip) {
    std::vector<shapes_variant_t> shapes{plane_shape{vector3_y, 1},
                                         sphere_shape{2},
                                         cylinder_shape{1, 2, coordinate_axis::z},
                                         capsule_shape{1, 2, coordinate_axis::y},
                                         box_shape{1, 2, 3},
                                         tetrahedron(),
                                         box_and_sphere(),
                                         one_triangle_mesh()};
    // A paged mesh is not sent (its own test below).
    ASSERT_EQ(shapes.size() + 1, num_shapes);
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        auto copy = round_trip(shapes[i]);
        EXPECT_EQ(copy.index(), i);
        EXPECT_EQ(shape_volume(copy), shape_volume(shapes[i])) << "shape " << i;
    }
    auto bad_index = encode(shapes[0]);
    bad_index[0] = std::uint8_t(num_shapes);
    EXPECT_TRUE(decode_fails<shapes_variant_t>(bad_index));
}

TEST(shape_serialization_test, truncated_shapes_fail) {
    expect_truncations_fail(plane_shape{vector3_y, 1});
    expect_truncations_fail(sphere_shape{2});
    expect_truncations_fail(cylinder_shape{1, 2, coordinate_axis::z});
    expect_truncations_fail(capsule_shape{1, 2, coordinate_axis::y});
    expect_truncations_fail(box_shape{1, 2, 3});
    expect_truncations_fail(tetrahedron());
    expect_truncations_fail(cube_hull());
    expect_truncations_fail(box_and_sphere());
    expect_truncations_fail(shapes_variant_t{box_and_sphere()});
}
