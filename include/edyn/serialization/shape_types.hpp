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
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace edyn {

/// The most vertices a polyhedron read from bytes may have (4096); more fail the archive.
///
/// Bounds on a polyhedron read from bytes are checked before anything is built: validation costs
/// vertices times faces, and a convex polyhedron has at most 2V - 4 faces and 6V - 12 indices.
inline constexpr std::size_t max_serialized_polyhedron_vertices = 4096;
/// The most faces a polyhedron read from bytes may have (twice the vertices' bound).
inline constexpr std::size_t max_serialized_polyhedron_faces = 2 * max_serialized_polyhedron_vertices;
/// The most vertex indices, over all faces, a polyhedron read from bytes may have (six times the
/// vertices' bound).
inline constexpr std::size_t max_serialized_polyhedron_indices = 6 * max_serialized_polyhedron_vertices;

/// Writes or reads a coordinate axis, failing the input archive on a value that names no axis.
/// Called directly by the shapes' serializers: `archive(axis)` would bypass the range check.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param axis The axis to write from or read into.
template<typename Archive>
void serialize(Archive &archive, coordinate_axis &axis) {
    serialize_enum(archive, axis, coordinate_axis::z);
}

/// Writes or reads a plane: its normal and constant. Not checked.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param shape The shape to write from or read into.
template<typename Archive>
void serialize(Archive &archive, plane_shape &shape) {
    archive(shape.normal, shape.constant);
}

/// Writes or reads a sphere: its radius. Not checked.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param shape The shape to write from or read into.
template<typename Archive>
void serialize(Archive &archive, sphere_shape &shape) {
    archive(shape.radius);
}

/// Writes or reads a cylinder: radius, half length and axis. Only the axis is checked.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param shape The shape to write from or read into.
template<typename Archive>
void serialize(Archive &archive, cylinder_shape &shape) {
    archive(shape.radius, shape.half_length);
    serialize(archive, shape.axis);
}

/// Writes or reads a capsule: radius, half length and axis. Only the axis is checked.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param shape The shape to write from or read into.
template<typename Archive>
void serialize(Archive &archive, capsule_shape &shape) {
    archive(shape.radius, shape.half_length);
    serialize(archive, shape.axis);
}

/// Writes or reads a box: its half extents. Not checked.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param shape The shape to write from or read into.
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

/// Writes or reads a polyhedron as its vertices and the vertex indices of each face.
///
/// Reading rebuilds it through its constructor, which validates: counts beyond the
/// `max_serialized_polyhedron_*` bounds, bad indices, or a non-convex or open surface fail the
/// archive and leave `shape` as it was. A polyhedron without a mesh (default constructed)
/// round-trips as one.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param shape The shape to write from or read into.
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

/// The most vertices (and per-vertex coefficients) a triangle mesh read from bytes may have
/// (2^20); more fail the archive.
inline constexpr std::size_t max_serialized_mesh_vertices = std::size_t(1) << 20;
/// The most vertex indices a triangle mesh read from bytes may have (six times the vertices'
/// bound).
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

/// Writes or reads a triangle mesh shape as its vertices, indices and per-vertex friction and
/// restitution coefficients.
///
/// The rest is rebuilt by `triangle_mesh::initialize()`, which validates: whatever it refuses,
/// or counts beyond the `max_serialized_mesh_*` bounds, fail the archive and leave `shape` as it
/// was. Sent after initialize(), so the copy numbers its triangles as the original does. A shape
/// without a mesh round-trips as one. The mesh read is a new one, not shared with other shapes.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param shape The shape to write from or read into.
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

/// The most pages a paged mesh read from bytes may have (65,536); more fail the archive.
inline constexpr std::size_t max_serialized_mesh_pages = std::size_t(1) << 16;
/// The most triangles one page of a paged mesh read from bytes may have (a third of
/// max_serialized_mesh_indices); more fail the archive.
inline constexpr std::size_t max_serialized_page_triangles = max_serialized_mesh_indices / 3;
/// The longest page directory a paged mesh read from bytes may name (4,096 bytes).
inline constexpr std::size_t max_serialized_page_directory = 4096;

namespace detail {

// How a paged mesh's pages travel.
enum class paged_mesh_source : std::uint8_t {
    absent, // No mesh, or pages from a loader of the program's own: not sent.
    memory, // The pages' arrays (make_memory_page_loader).
    files   // The directory of the page files (make_file_page_loader, open_file_page_loader).
};

inline bool is_finite(const vector3 &v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The page's arrays as a memory loader keeps them, read with the same bounds as a mesh_shape's;
// false (and the archive failed) when they do not describe `num_triangles` triangles.
inline bool read_page(memory_input_archive &archive, triangle_mesh_page &page, std::size_t num_triangles) {
    if (!read_bounded_array(archive, page.vertices, max_serialized_mesh_vertices) ||
        !read_bounded_array(archive, page.indices, max_serialized_mesh_indices) ||
        !read_bounded_array(archive, page.friction, max_serialized_mesh_vertices) ||
        !read_bounded_array(archive, page.restitution, max_serialized_mesh_vertices) ||
        !read_bounded_array(archive, page.edge_flags, max_serialized_page_triangles)) {
        return false;
    }
    if (page.indices.size() != 3 * num_triangles || page.edge_flags.size() != num_triangles) {
        archive.fail();
        return false;
    }
    return true;
}

inline void write_paged_mesh(memory_output_archive &archive, const paged_mesh_shape &shape) {
    using source = paged_mesh_source;
    const auto *pages = shape.trimesh ? shape.trimesh->get_loader().memory_pages() : nullptr;
    auto directory = shape.trimesh ? shape.trimesh->get_loader().page_directory() : std::string{};
    auto kind = pages ? source::memory : !directory.empty() ? source::files : source::absent;
    serialize_enum(archive, kind, source::files);
    if (kind == source::absent) return;
    const auto &mesh = *shape.trimesh;
    auto lookahead = mesh.lookahead_time;
    auto delay = mesh.unload_delay;
    archive(lookahead, delay);
    archive.write_size(mesh.num_pages());
    for (std::size_t p = 0; p < mesh.num_pages(); ++p) {
        auto aabb = mesh.get_page_aabb(p);
        archive(aabb.min, aabb.max);
        archive.write_size(mesh.num_page_triangles(p));
    }
    if (kind == source::files) {
        archive(directory);
        return;
    }
    for (const auto &page : *pages) {
        write_array(archive, std::span<const vector3>(page.vertices));
        write_array(archive, std::span<const std::uint32_t>(page.indices));
        write_array(archive, std::span<const scalar>(page.friction));
        write_array(archive, std::span<const scalar>(page.restitution));
        write_array(archive, std::span<const std::uint8_t>(page.edge_flags));
    }
}

// Each page's bounds and triangle count; false (and the archive failed) for bounds that are not
// finite or not ordered.
inline bool read_page_layout(memory_input_archive &archive, std::vector<AABB> &aabbs,
                             std::vector<std::size_t> &counts) {
    for (std::size_t p = 0; p < aabbs.size(); ++p) {
        archive(aabbs[p].min, aabbs[p].max);
        counts[p] = archive.read_size(max_serialized_page_triangles);
        if (archive.failed()) return false;
        const auto &lo = aabbs[p].min, &hi = aabbs[p].max;
        if (!is_finite(lo) || !is_finite(hi) || lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) {
            archive.fail();
            return false;
        }
    }
    return true;
}

// The loader of the pages as they travel (see paged_mesh_source); null (and the archive failed)
// when they do not match `counts`.
inline std::unique_ptr<triangle_mesh_page_loader> read_page_loader(memory_input_archive &archive,
                                                                   paged_mesh_source kind,
                                                                   const std::vector<std::size_t> &counts) {
    if (kind == paged_mesh_source::files) {
        auto size = archive.read_size(max_serialized_page_directory);
        if (archive.failed()) return nullptr;
        std::string directory(size, '\0');
        archive.read_bytes(directory.data(), size);
        if (archive.failed()) return nullptr;
        if (directory.empty()) {
            archive.fail();
            return nullptr;
        }
        return open_file_page_loader(directory);
    }
    std::vector<triangle_mesh_page> pages(counts.size());
    for (std::size_t p = 0; p < counts.size(); ++p) {
        if (!read_page(archive, pages[p], counts[p])) return nullptr;
    }
    auto loader = make_memory_page_loader(std::move(pages));
    // Every page once, as the peer's loads will build it: one the loader refuses would stay
    // empty there, a hole in the terrain, so it fails the archive here.
    for (std::size_t p = 0; p < counts.size(); ++p) {
        auto page = loader->load(p);
        if (!page || page->num_triangles() != counts[p]) {
            archive.fail();
            return nullptr;
        }
    }
    return loader;
}

inline void read_paged_mesh(memory_input_archive &archive, paged_mesh_shape &shape) {
    auto kind = paged_mesh_source::absent;
    serialize_enum(archive, kind, paged_mesh_source::files);
    if (archive.failed()) return;
    if (kind == paged_mesh_source::absent) {
        shape.trimesh.reset();
        return;
    }
    scalar lookahead = 0;
    std::uint32_t delay = 0;
    archive(lookahead, delay);
    // Each page takes at least two vectors and a count.
    auto num_pages = archive.read_size(std::min(max_serialized_mesh_pages, archive.remaining() / 7));
    if (archive.failed()) return;
    if (!std::isfinite(lookahead) || lookahead < 0 || num_pages == 0) {
        archive.fail();
        return;
    }
    std::vector<AABB> aabbs(num_pages);
    std::vector<std::size_t> counts(num_pages);
    if (!read_page_layout(archive, aabbs, counts)) return;
    auto loader = read_page_loader(archive, kind, counts);
    if (!loader) {
        archive.fail();
        return;
    }
    try {
        auto mesh =
            std::make_shared<paged_triangle_mesh>(std::move(aabbs), std::move(counts), std::move(loader));
        mesh->lookahead_time = lookahead;
        mesh->unload_delay = delay;
        shape.trimesh = std::move(mesh);
    } catch (...) {
        archive.fail();
    }
}

} // namespace detail

/// Writes or reads a paged mesh shape: its page layout (each page's bounds and triangle count,
/// from which the page tree is rebuilt the same), `lookahead_time` and `unload_delay`, and where
/// its pages come from.
///
/// Pages held by make_memory_page_loader() travel whole (each page's vertices, indices,
/// per-vertex friction and restitution, and edge activity), and the copy keeps them in a loader
/// of the same kind; for make_file_page_loader() or open_file_page_loader(), the directory
/// travels, and the copy reads the page files there (open_file_page_loader()), which the peer
/// must have. Either way the copy numbers its pages and triangles as the original does, so that
/// contact features and ray-cast infos agree. Pages from a loader of the program's own are not
/// sent: the shape is written as one without a mesh, which make_rigidbody refuses (send such
/// terrain as an asset). What a mesh is loading or has loaded is not sent: the copy loads its own.
///
/// Reading validates everything it rebuilds: counts beyond the `max_serialized_*` bounds, bounds
/// that are not finite, a page whose arrays are not its triangle count's or that
/// triangle_mesh::initialize() refuses, a negative or non-finite lookahead, fail the archive and
/// leave `shape` as it was. The mesh read is a new one, not shared with other shapes.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param shape The shape to write from or read into.
template<typename Archive>
void serialize(Archive &archive, paged_mesh_shape &shape) {
    if constexpr (Archive::is_output) {
        detail::write_paged_mesh(archive, shape);
    } else {
        detail::read_paged_mesh(archive, shape);
    }
}

/// Writes or reads a compound shape: each child as its shape, position and orientation (its
/// bounds are recomputed), then whether finish() had been called.
///
/// Reading rebuilds it through add_shape and finish, which validate: whatever they refuse fails
/// the archive and leaves `shape` as it was.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param shape The shape to write from or read into.
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
