#include "edyn/collision/collide.hpp"
#include "edyn/collision/shape_raycast.hpp"
#include "edyn/serialization/shape_types.hpp"
#include "edyn/shapes/moment_of_inertia.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "unit/serialization/archive_round_trip.hpp"
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <thread>
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

namespace {

// A hilly 12 x 12 grid of unit cells (288 triangles) with per-vertex friction and restitution,
// in pages of at most 20 triangles.
std::shared_ptr<paged_triangle_mesh> hilly_paged_mesh(const std::string &directory = {}) {
    std::vector<vector3> vertices, colors;
    std::vector<std::uint32_t> indices;
    const std::uint32_t n = 12;
    for (std::uint32_t i = 0; i <= n; ++i) {
        for (std::uint32_t j = 0; j <= n; ++j) {
            auto x = scalar(i) - 6, z = scalar(j) - 6;
            vertices.push_back({x, std::sin(x * scalar(0.7)) * std::cos(z * scalar(0.5)), z});
            colors.push_back({scalar(0.3) + scalar(i) / 40, scalar(j) / 20, 0});
        }
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = 0; j < n; ++j) {
            auto at = [&](std::uint32_t a, std::uint32_t b) { return a * (n + 1) + b; };
            indices.insert(indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            indices.insert(indices.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    }
    auto mesh = create_paged_triangle_mesh(vertices, indices, 20, &colors, directory);
    mesh->lookahead_time = scalar(0.75);
    mesh->unload_delay = 17;
    return mesh;
}

// The copy has the original's layout, triangles, edges and coefficients, and collides and ray
// casts as the original does, bit for bit.
void expect_same_paged_mesh(paged_triangle_mesh &copy, paged_triangle_mesh &original) {
    ASSERT_EQ(copy.num_pages(), original.num_pages());
    EXPECT_EQ(copy.num_triangles(), original.num_triangles());
    EXPECT_EQ(copy.lookahead_time, original.lookahead_time);
    EXPECT_EQ(copy.unload_delay, original.unload_delay);
    EXPECT_EQ(copy.get_aabb(), original.get_aabb());
    copy.require(copy.get_aabb(), 0);
    original.require(original.get_aabb(), 0);
    ASSERT_EQ(copy.num_loaded_pages(), copy.num_pages());
    for (std::size_t p = 0; p < original.num_pages(); ++p) {
        EXPECT_EQ(copy.get_page_aabb(p), original.get_page_aabb(p)) << "page " << p;
        ASSERT_EQ(copy.first_triangle(p), original.first_triangle(p)) << "page " << p;
        const auto &a = *copy.get_page(p), &b = *original.get_page(p);
        ASSERT_EQ(a.num_triangles(), b.num_triangles());
        for (std::size_t t = 0; t < b.num_triangles(); ++t) {
            auto ta = a.get_triangle_vertices(t), tb = b.get_triangle_vertices(t);
            for (std::size_t k = 0; k < 3; ++k) {
                EDYN_EXPECT_SAME(ta[k], tb[k]) << " page " << p << " triangle " << t;
                EXPECT_EQ(a.is_edge_active(t, k), b.is_edge_active(t, k))
                    << "page " << p << " triangle " << t;
            }
            EXPECT_EQ(a.get_friction(t, {scalar(0.2), scalar(0.3), scalar(0.5)}),
                      b.get_friction(t, {scalar(0.2), scalar(0.3), scalar(0.5)}));
            EXPECT_EQ(a.get_restitution(t, {scalar(0.6), scalar(0.3), scalar(0.1)}),
                      b.get_restitution(t, {scalar(0.6), scalar(0.3), scalar(0.1)}));
        }
    }
    paged_mesh_shape sa{std::shared_ptr<paged_triangle_mesh>(&copy, [](auto *) {})};
    paged_mesh_shape sb{std::shared_ptr<paged_triangle_mesh>(&original, [](auto *) {})};
    std::size_t points = 0, hits = 0;
    for (int k = 0; k < 40; ++k) {
        auto x = scalar(-5.5) + scalar(k % 8) * scalar(1.37), z = scalar(-5.2) + scalar(k / 8) * scalar(2.1);
        auto y = std::sin(x * scalar(0.7)) * std::cos(z * scalar(0.5));
        collision_context ctx;
        ctx.posA = {x, y + scalar(0.38), z};
        ctx.ornA = quaternion_axis_angle(vector3_y, scalar(k) * scalar(0.3));
        collision_result ra, rb;
        collide(box_shape{scalar(0.4), scalar(0.4), scalar(0.4)}, sa, ctx, ra);
        collide(box_shape{scalar(0.4), scalar(0.4), scalar(0.4)}, sb, ctx, rb);
        ASSERT_EQ(ra.num_points, rb.num_points) << "at " << x << ", " << z;
        for (std::size_t i = 0; i < rb.num_points; ++i) {
            EDYN_EXPECT_SAME(ra.point[i].pivotB, rb.point[i].pivotB);
            EDYN_EXPECT_SAME(ra.point[i].normal, rb.point[i].normal);
            EXPECT_EQ(ra.point[i].distance, rb.point[i].distance);
            ASSERT_EQ(ra.point[i].featureB.has_value(), rb.point[i].featureB.has_value());
            if (rb.point[i].featureB) {
                EXPECT_TRUE(*ra.point[i].featureB == *rb.point[i].featureB) << "point " << i;
            }
        }
        points += rb.num_points;
        raycast_context ray{
            vector3_zero, quaternion_identity, {x, 5, z}, {x + scalar(0.3), -5, z - scalar(0.2)}};
        auto ha = shape_raycast(sa, ray), hb = shape_raycast(sb, ray);
        ASSERT_EQ(ha.hit(), hb.hit());
        if (!hb.hit()) continue;
        ++hits;
        EXPECT_EQ(ha.fraction, hb.fraction);
        EDYN_EXPECT_SAME(ha.normal, hb.normal);
        auto ia = std::get<paged_mesh_raycast_info>(ha.info_var),
             ib = std::get<paged_mesh_raycast_info>(hb.info_var);
        EXPECT_EQ(ia.submesh_index, ib.submesh_index);
        EXPECT_EQ(ia.triangle_index, ib.triangle_index);
    }
    EXPECT_GT(points, 40u);
    EXPECT_EQ(hits, 40u);
}

std::filesystem::path scratch_directory(const char *name) {
    auto dir = std::filesystem::temp_directory_path() /
               (std::string(name) + std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id())));
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace

TEST(shape_serialization_test, paged_mesh_in_memory_travels_whole) {
    auto original = hilly_paged_mesh();
    ASSERT_GT(original->num_pages(), 10u);
    auto copy = round_trip(paged_mesh_shape{original});
    ASSERT_TRUE(copy.trimesh);
    EXPECT_NE(copy.trimesh, original);
    ASSERT_NE(copy.trimesh->get_loader().memory_pages(), nullptr) << "the copy keeps its pages in memory";
    expect_same_paged_mesh(*copy.trimesh, *original);
    expect_truncations_fail(paged_mesh_shape{original});
    // In the shapes' variant too.
    auto variant = round_trip(shapes_variant_t{paged_mesh_shape{original}});
    ASSERT_TRUE(std::holds_alternative<paged_mesh_shape>(variant));
    EXPECT_NE(std::get<paged_mesh_shape>(variant).trimesh, nullptr);
}

TEST(shape_serialization_test, file_backed_paged_mesh_travels_as_its_directory) {
    auto dir = scratch_directory("edyn_serialized_pages_");
    auto original = hilly_paged_mesh(dir.string());
    auto bytes = encode(paged_mesh_shape{original});
    // The layout and the directory, not the triangles: a page's box and triangle count, the
    // lookahead and delay, and a few bytes of sizes.
    EXPECT_LT(bytes.size(), original->num_pages() * (6 * sizeof(scalar) + 16) + dir.string().size() +
                                2 * sizeof(scalar) + 24);
    auto copy = round_trip(paged_mesh_shape{original});
    ASSERT_TRUE(copy.trimesh);
    EXPECT_EQ(copy.trimesh->get_loader().page_directory(), dir.string());
    EXPECT_EQ(copy.trimesh->get_loader().memory_pages(), nullptr);
    expect_same_paged_mesh(*copy.trimesh, *original);
    expect_truncations_fail(paged_mesh_shape{original});
    std::filesystem::remove_all(dir);
}

TEST(shape_serialization_test, paged_mesh_of_a_program_loader_or_none_is_read_as_absent) {
    struct own_loader final : triangle_mesh_page_loader {
        std::shared_ptr<triangle_mesh> load(std::size_t) override { return nullptr; }
    };
    paged_mesh_shape own{
        std::make_shared<paged_triangle_mesh>(std::vector<AABB>{AABB{vector3_zero, vector3_one}},
                                              std::vector<std::size_t>{1}, std::make_unique<own_loader>())};
    paged_mesh_shape copy{hilly_paged_mesh()};
    EXPECT_FALSE(decode_fails(encode(own), copy));
    EXPECT_EQ(copy.trimesh, nullptr);
    EXPECT_EQ(encode(own), encode(paged_mesh_shape{}));
    EXPECT_EQ(round_trip(paged_mesh_shape{}).trimesh, nullptr);
}

TEST(shape_serialization_test, malformed_paged_meshes_fail) {
    // One page of one triangle, written field by field so that each can be spoiled.
    struct fields {
        std::uint8_t kind{1};
        scalar lookahead{scalar(0.5)};
        std::uint32_t delay{60};
        std::size_t num_pages{1};
        AABB aabb{{0, 0, 0}, {1, 0, 1}};
        std::size_t triangles{1};
        std::vector<vector3> vertices{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
        std::vector<std::uint32_t> indices{0, 2, 1};
        std::vector<scalar> friction{};
        std::vector<std::uint8_t> edge_flags{7};
        std::string directory{};
    };
    auto bytes_of = [](const fields &f) {
        std::vector<std::uint8_t> bytes;
        memory_output_archive archive(bytes);
        auto kind = f.kind;
        auto lookahead = f.lookahead;
        auto delay = f.delay;
        archive(kind, lookahead, delay);
        archive.write_size(f.num_pages);
        for (std::size_t p = 0; p < f.num_pages; ++p) {
            auto aabb = f.aabb;
            archive(aabb.min, aabb.max);
            archive.write_size(f.triangles);
        }
        if (f.kind == 2) {
            auto directory = f.directory;
            archive(directory);
            return bytes;
        }
        for (std::size_t p = 0; p < f.num_pages; ++p) {
            archive.write_size(f.vertices.size());
            for (auto v : f.vertices)
                archive(v);
            archive.write_size(f.indices.size());
            for (auto i : f.indices)
                archive(i);
            archive.write_size(f.friction.size());
            for (auto c : f.friction)
                archive(c);
            archive.write_size(0);
            archive.write_size(f.edge_flags.size());
            for (auto e : f.edge_flags)
                archive(e);
        }
        return bytes;
    };
    auto fails = [&](const fields &f) { return decode_fails<paged_mesh_shape>(bytes_of(f)); };
    fields good;
    ASSERT_FALSE(fails(good));
    fields directory;
    directory.kind = 2;
    directory.directory = "pages";
    ASSERT_FALSE(fails(directory));

    auto spoiled = [&](auto &&spoil, fields f = {}) {
        spoil(f);
        return fails(f);
    };
    constexpr auto nan = std::numeric_limits<scalar>::quiet_NaN();
    EXPECT_TRUE(spoiled([](fields &f) { f.kind = 3; }));
    EXPECT_TRUE(spoiled([](fields &f) { f.lookahead = -1; }));
    EXPECT_TRUE(spoiled([](fields &f) { f.lookahead = nan; }));
    EXPECT_TRUE(spoiled([](fields &f) { f.num_pages = 0; }));
    EXPECT_TRUE(spoiled([](fields &f) { f.aabb.min.y = nan; }));
    EXPECT_TRUE(spoiled([](fields &f) { f.aabb.min.x = 2; })); // min past max
    EXPECT_TRUE(spoiled([](fields &f) { f.triangles = 2; }));  // the page's arrays hold one
    EXPECT_TRUE(spoiled([](fields &f) { f.triangles = max_serialized_page_triangles + 1; }));
    EXPECT_TRUE(spoiled([](fields &f) { f.indices = {0, 2, 3}; }));   // out of range
    EXPECT_TRUE(spoiled([](fields &f) { f.indices = {0, 0, 0}; }));   // degenerate: no triangle left
    EXPECT_TRUE(spoiled([](fields &f) { f.friction = {1, 1}; }));     // wrong count
    EXPECT_TRUE(spoiled([](fields &f) { f.friction = {1, -1, 1}; })); // negative
    EXPECT_TRUE(spoiled([](fields &f) { f.edge_flags = {}; }));       // one per triangle
    EXPECT_TRUE(spoiled([](fields &f) { f.vertices[1].z = nan; }));
    EXPECT_TRUE(spoiled([](fields &f) { f.directory.clear(); }, directory));
    EXPECT_TRUE(
        spoiled([](fields &f) { f.directory.assign(max_serialized_page_directory + 1, 'd'); }, directory));
    // Counts beyond the bytes.
    EXPECT_TRUE(spoiled([](fields &f) { f.num_pages = 1000000; }));
    std::vector<std::uint8_t> lying;
    memory_output_archive archive(lying);
    std::uint8_t kind = 1;
    scalar lookahead = 1;
    std::uint32_t delay = 1;
    archive(kind, lookahead, delay);
    archive.write_size(max_serialized_mesh_pages + 1);
    EXPECT_TRUE(decode_fails<paged_mesh_shape>(lying));

    // A failed read leaves the shape as it was.
    auto mesh = hilly_paged_mesh();
    paged_mesh_shape kept{mesh};
    EXPECT_TRUE(decode_fails(bytes_of([] {
                                 fields f;
                                 f.triangles = 2;
                                 return f;
                             }()),
                             kept));
    EXPECT_EQ(kept.trimesh, mesh);
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
    // A paged mesh has tests of its own above.
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
