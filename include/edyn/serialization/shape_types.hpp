#ifndef EDYN_SERIALIZATION_SHAPE_TYPES_HPP
#define EDYN_SERIALIZATION_SHAPE_TYPES_HPP

// Serialization of every shape of shapes_variant_t, so that a peer can recreate a body's shape.
//
// Shapes are read as the bytes describe them: a sphere of negative radius decodes, and
// make_rigidbody (validate_shape) rejects it later. The exceptions are polyhedra and compounds,
// whose derived data (face planes, edges, child bounds, bounding volume tree) is rebuilt on
// reading through their public constructors, which validate: anything they refuse fails the
// archive. A polyhedron is sent as its vertices and the vertex indices of each face, and
// rebuilt by make_convex_mesh, which derives the rest deterministically from exactly those, so
// the copy has the same feature indices as the original. Meshes shared between shapes are sent
// once per shape and no longer shared after reading.

#include "edyn/serialization/enum_range.hpp"
#include "edyn/serialization/math_types.hpp"
#include "edyn/serialization/memory_archive.hpp"
#include "edyn/serialization/std_types.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "edyn/shapes/shapes.hpp"
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace edyn {

// Bounds on a polyhedron read from bytes, checked before anything is built: validation costs
// vertices times faces, and a convex polyhedron has at most 2V - 4 faces and 6V - 12 indices.
inline constexpr std::size_t max_serialized_polyhedron_vertices = 4096;
inline constexpr std::size_t max_serialized_polyhedron_faces = 2 * max_serialized_polyhedron_vertices;
inline constexpr std::size_t max_serialized_polyhedron_indices = 6 * max_serialized_polyhedron_vertices;

// Called directly by the shapes' serializers: `archive(axis)` would bypass the range check.
template<typename Archive>
void serialize(Archive &archive, coordinate_axis &axis) {
    serialize_enum(archive, axis, coordinate_axis::z);
}

template<typename Archive>
void serialize(Archive &archive, plane_shape &shape) {
    archive(shape.normal, shape.constant);
}

template<typename Archive>
void serialize(Archive &archive, sphere_shape &shape) {
    archive(shape.radius);
}

template<typename Archive>
void serialize(Archive &archive, cylinder_shape &shape) {
    archive(shape.radius, shape.half_length);
    serialize(archive, shape.axis);
}

template<typename Archive>
void serialize(Archive &archive, capsule_shape &shape) {
    archive(shape.radius, shape.half_length);
    serialize(archive, shape.axis);
}

template<typename Archive>
void serialize(Archive &archive, box_shape &shape) {
    archive(shape.half_extents);
}

namespace detail {

template<typename Archive>
void write_convex_mesh(Archive &archive, const convex_mesh &mesh) {
    archive.write_size(mesh.vertices.size());
    for (const auto &v : mesh.vertices)
        archive(v);
    archive.write_size(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        auto indices = mesh.face_indices(f);
        archive.write_size(indices.size());
        for (auto i : indices)
            archive(i);
    }
}

// The vertices and faces as written by write_convex_mesh; false (and the archive failed) when
// they are truncated or exceed the bounds above. Nothing about the geometry is checked here.
template<typename Archive>
bool read_convex_mesh_data(Archive &archive, std::vector<vector3> &vertices,
                           std::vector<std::vector<std::uint32_t>> &faces) {
    // Capped by the bytes left too, so that a short packet cannot make us allocate.
    constexpr std::size_t vertex_bytes = 3 * sizeof(scalar);
    auto num_vertices =
        archive.read_size(std::min(max_serialized_polyhedron_vertices, archive.remaining() / vertex_bytes));
    if (archive.failed()) return false;
    vertices.resize(num_vertices);
    for (auto &v : vertices)
        archive(v);

    auto num_faces = archive.read_size(std::min(max_serialized_polyhedron_faces, archive.remaining()));
    if (archive.failed()) return false;
    faces.resize(num_faces);
    std::size_t indices_left = max_serialized_polyhedron_indices;
    for (auto &face : faces) {
        auto count = archive.read_size(std::min(indices_left, archive.remaining() / sizeof(std::uint32_t)));
        if (archive.failed()) return false;
        indices_left -= count;
        face.resize(count);
        for (auto &i : face)
            archive(i);
    }
    return !archive.failed();
}

} // namespace detail

// A polyhedron without a mesh (default constructed) round-trips as one.
template<typename Archive>
void serialize(Archive &archive, polyhedron_shape &shape) {
    bool has_mesh = shape.mesh != nullptr;
    archive(has_mesh);
    if constexpr (Archive::is_output) {
        if (has_mesh) detail::write_convex_mesh(archive, *shape.mesh);
    } else {
        if (archive.failed()) return;
        if (!has_mesh) {
            shape.mesh.reset();
            return;
        }
        std::vector<vector3> vertices;
        std::vector<std::vector<std::uint32_t>> faces;
        if (!detail::read_convex_mesh_data(archive, vertices, faces)) return;
        // Bytes from a peer must not throw: whatever the constructor refuses (bad indices, a
        // non-convex or open surface) or cannot allocate fails the archive.
        try {
            shape = polyhedron_shape(std::move(vertices), faces);
        } catch (...) {
            archive.fail();
        }
    }
}

// Bounds on a triangle mesh read from bytes.
inline constexpr std::size_t max_serialized_mesh_vertices = std::size_t(1) << 20;
inline constexpr std::size_t max_serialized_mesh_indices = 6 * max_serialized_mesh_vertices;

namespace detail {

template<typename T>
bool read_bounded_array(memory_input_archive &archive, std::vector<T> &values, std::size_t max_count) {
    auto count = archive.read_size(std::min(max_count, archive.remaining() / sizeof(T)));
    if (archive.failed()) return false;
    values.resize(count);
    for (auto &v : values)
        archive(v);
    return !archive.failed();
}

template<typename T>
void write_array(memory_output_archive &archive, std::span<const T> values) {
    archive.write_size(values.size());
    for (auto v : values)
        archive(v);
}

} // namespace detail

// A mesh as its vertices, indices and per-vertex coefficients; the rest is rebuilt by
// initialize(), which validates (whatever it refuses fails the archive). Sent after
// initialize(), so the copy numbers its triangles as the original does. A shape without a mesh
// round-trips as one.
template<typename Archive>
void serialize(Archive &archive, mesh_shape &shape) {
    bool has_mesh = shape.trimesh != nullptr;
    archive(has_mesh);
    if constexpr (Archive::is_output) {
        if (!has_mesh) return;
        const auto &mesh = *shape.trimesh;
        detail::write_array(archive, mesh.get_vertices());
        detail::write_array(archive, mesh.get_indices());
        detail::write_array(archive, mesh.get_friction_coefficients());
        detail::write_array(archive, mesh.get_restitution_coefficients());
    } else {
        if (archive.failed()) return;
        if (!has_mesh) {
            shape.trimesh.reset();
            return;
        }
        std::vector<vector3> vertices;
        std::vector<std::uint32_t> indices;
        std::vector<scalar> friction, restitution;
        if (!detail::read_bounded_array(archive, vertices, max_serialized_mesh_vertices) ||
            !detail::read_bounded_array(archive, indices, max_serialized_mesh_indices) ||
            !detail::read_bounded_array(archive, friction, max_serialized_mesh_vertices) ||
            !detail::read_bounded_array(archive, restitution, max_serialized_mesh_vertices)) {
            return;
        }
        try {
            auto mesh = std::make_shared<triangle_mesh>();
            mesh->insert_vertices(vertices.begin(), vertices.end());
            mesh->insert_indices(indices.begin(), indices.end());
            mesh->insert_friction_coefficients(friction.begin(), friction.end());
            mesh->insert_restitution_coefficients(restitution.begin(), restitution.end());
            mesh->initialize();
            shape.trimesh = std::move(mesh);
        } catch (...) {
            archive.fail();
        }
    }
}

// A paged mesh is not sent: its pages come from the program's own loader, which a peer
// provides through an asset (see the manual's assets). It is written as absent and read as a
// shape without a mesh, which make_rigidbody refuses.
template<typename Archive>
void serialize(Archive &archive, paged_mesh_shape &shape) {
    bool has_mesh = false;
    archive(has_mesh);
    if constexpr (!Archive::is_output) {
        if (!archive.failed()) shape.trimesh.reset();
    }
}

// Each child as its shape, position and orientation (its bounds are recomputed), then whether
// finish() had been called.
template<typename Archive>
void serialize(Archive &archive, compound_shape &shape) {
    if constexpr (Archive::is_output) {
        archive.write_size(shape.children.size());
        for (auto &child : shape.children)
            archive(child.shape, child.position, child.orientation);
        archive(shape.finished);
    } else {
        // Every child takes more than one byte.
        auto count = archive.read_size(archive.remaining());
        if (archive.failed()) return;
        compound_shape result;
        try {
            for (std::size_t i = 0; i < count; ++i) {
                compound_child_shape_t child_shape;
                vector3 position{vector3_zero};
                quaternion orientation{quaternion_identity};
                archive(child_shape, position, orientation);
                if (archive.failed()) return;
                // Validates the child, the position and the orientation.
                result.add_shape(std::move(child_shape), position, orientation);
                // add_shape normalises the orientation again, which moves the last bits of one
                // that was normalised already: keep the sender's when it is unit to rounding,
                // so that the copy's bounds, tree and contacts are the original's bit for bit.
                if (is_unit(orientation, epsilon)) {
                    auto &child = result.children.back();
                    child.orientation = orientation;
                    child.aabb = shape_aabb(child.shape, position, orientation);
                }
            }
            bool finished = false;
            archive(finished);
            if (archive.failed()) return;
            if (finished) result.finish();
        } catch (...) {
            archive.fail();
            return;
        }
        shape = std::move(result);
    }
}

} // namespace edyn

#endif // EDYN_SERIALIZATION_SHAPE_TYPES_HPP
