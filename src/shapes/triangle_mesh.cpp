#include "edyn/shapes/triangle_mesh.hpp"
#include "invalid_argument.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace edyn {

using detail::throw_invalid_argument;

void triangle_mesh::check_not_initialized(const char *function) const {
    if (is_initialized) {
        throw_invalid_argument("triangle_mesh::", function,
                               ": the mesh is initialized, and read-only: it may be shared by shapes "
                               "and threads (fill a new mesh instead)");
    }
}

void triangle_mesh::append_vertices(const std::vector<vector3> &values) {
    check_not_initialized("insert_vertices");
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!isfinite(values[i])) {
            throw_invalid_argument("triangle_mesh::insert_vertices: vertex ", vertices.size() + i,
                                   " must be finite, got ", values[i]);
        }
    }
    vertices.insert(vertices.end(), values.begin(), values.end());
    is_initialized = false;
}

void triangle_mesh::append_index_checked(std::vector<std::uint64_t> &values, long long value) {
    if (value < 0 || static_cast<unsigned long long>(value) >= no_triangle) {
        throw_invalid_argument("triangle_mesh::insert_indices: index ", values.size(),
                               " of the range must be in [0, 2^32 - 1), got ", value);
    }
    values.push_back(static_cast<std::uint64_t>(value));
}

void triangle_mesh::append_indices(const std::vector<std::uint64_t> &values) {
    check_not_initialized("insert_indices");
    for (auto v : values)
        indices.push_back(static_cast<std::uint32_t>(v));
    is_initialized = false;
}

void triangle_mesh::append_coefficients(const std::vector<scalar> &values, std::vector<scalar> &target,
                                        const char *function, scalar max) {
    check_not_initialized(function);
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i]) || values[i] < 0 || values[i] > max) {
            throw_invalid_argument("triangle_mesh::", function, ": coefficient ", target.size() + i,
                                   " must be in [0, ", max, "], got ", values[i]);
        }
    }
    target.insert(target.end(), values.begin(), values.end());
    is_initialized = false;
}

namespace {

constexpr const char *initialize_name = "triangle_mesh::initialize";

void check_mesh(const std::vector<vector3> &vertices, const std::vector<std::uint32_t> &indices,
                const std::vector<scalar> &friction, const std::vector<scalar> &restitution) {
    auto fn = initialize_name;
    if (vertices.empty()) throw_invalid_argument(fn, ": the mesh has no vertices");
    if (indices.empty()) throw_invalid_argument(fn, ": the mesh has no indices");
    if (indices.size() % 3 != 0) {
        throw_invalid_argument(fn, ": the index count must be a multiple of 3, got ", indices.size());
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= vertices.size()) {
            throw_invalid_argument(fn, ": index ", i, " is ", indices[i], ", out of range for ",
                                   vertices.size(), " vertices");
        }
    }
    if (!friction.empty() && friction.size() != vertices.size()) {
        throw_invalid_argument(fn, ": there must be one friction coefficient per vertex (", vertices.size(),
                               "), got ", friction.size());
    }
    if (!restitution.empty() && restitution.size() != vertices.size()) {
        throw_invalid_argument(fn, ": there must be one restitution coefficient per vertex (",
                               vertices.size(), "), got ", restitution.size());
    }
}

// The triangles of some area, relative to the mesh's size, and their normals.
struct kept_triangles {
    std::vector<std::uint32_t> indices;
    std::vector<vector3> normals;
    std::size_t dropped{0};
};

kept_triangles drop_degenerate_triangles(const std::vector<vector3> &vertices,
                                         const std::vector<std::uint32_t> &indices) {
    AABB bounds{vertices[0], vertices[0]};
    for (const auto &v : vertices)
        bounds = {min(bounds.min, v), max(bounds.max, v)};
    auto size = length(bounds.max - bounds.min);
    auto min_double_area = scalar(1e-12) * size * size;
    kept_triangles kept;
    kept.indices.reserve(indices.size());
    kept.normals.reserve(indices.size() / 3);
    for (std::size_t t = 0; t < indices.size() / 3; ++t) {
        auto i0 = indices[t * 3], i1 = indices[t * 3 + 1], i2 = indices[t * 3 + 2];
        auto n = cross(vertices[i1] - vertices[i0], vertices[i2] - vertices[i0]);
        auto len = length(n);
        if (!(len > min_double_area) || i0 == i1 || i1 == i2 || i0 == i2) {
            ++kept.dropped;
            continue;
        }
        kept.indices.insert(kept.indices.end(), {i0, i1, i2});
        kept.normals.push_back(n / len);
    }
    if (kept.indices.empty()) {
        throw_invalid_argument(initialize_name, ": all ", indices.size() / 3, " triangles have zero area");
    }
    return kept;
}

// One triangle's edge, keyed by its vertices in increasing order.
struct edge_use {
    std::uint32_t lo, hi;
    std::uint32_t triangle;
    std::uint8_t edge;
    bool forward; // The triangle runs the edge from lo to hi.
};

// Each triangle's neighbour across each of its edges, and which of its edges are active.
struct edge_topology {
    std::vector<std::uint32_t> adjacency;
    std::vector<std::uint8_t> flags;
};

edge_topology find_edge_topology(const std::vector<vector3> &vertices, const kept_triangles &kept,
                                 std::uint32_t no_triangle, scalar active_edge_cosine) {
    // Every triangle's edges, sorted by their vertex pair.
    auto num_tri = kept.indices.size() / 3;
    std::vector<edge_use> uses;
    uses.reserve(kept.indices.size());
    for (std::uint32_t t = 0; t < num_tri; ++t) {
        for (std::uint8_t e = 0; e < 3; ++e) {
            auto a = kept.indices[t * 3 + e], b = kept.indices[t * 3 + (e + 1) % 3];
            uses.push_back({std::min(a, b), std::max(a, b), t, e, a < b});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const edge_use &x, const edge_use &y) {
        return std::tie(x.lo, x.hi, x.triangle, x.edge) < std::tie(y.lo, y.hi, y.triangle, y.edge);
    });
    edge_topology topology{std::vector<std::uint32_t>(kept.indices.size(), no_triangle),
                           std::vector<std::uint8_t>(num_tri, 0)};
    auto &adjacency = topology.adjacency;
    auto &flags = topology.flags;
    for (std::size_t i = 0; i < uses.size();) {
        auto j = i;
        while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi)
            ++j;
        if (j - i == 2) {
            const auto &u = uses[i], &v = uses[i + 1];
            adjacency[u.triangle * 3 + u.edge] = v.triangle;
            adjacency[v.triangle * 3 + v.edge] = u.triangle;
            // Consistently wound neighbours run the shared edge in opposite senses; otherwise the
            // fronts disagree and the edge stays active.
            bool active = u.forward == v.forward;
            if (!active) {
                const auto &n_u = kept.normals[u.triangle];
                const auto &n_v = kept.normals[v.triangle];
                // The vertex of v off the edge lies behind u's plane when the edge is convex.
                auto w = kept.indices[v.triangle * 3 + (v.edge + 2) % 3];
                auto d = dot(vertices[w] - vertices[u.lo], n_u);
                bool convex = d < 0;
                active = convex && dot(n_u, n_v) < active_edge_cosine;
            }
            if (active) {
                flags[u.triangle] |= std::uint8_t(1u << u.edge);
                flags[v.triangle] |= std::uint8_t(1u << v.edge);
            }
        } else {
            // Boundary (one triangle) or non-manifold (three or more): active.
            for (auto k = i; k < j; ++k)
                flags[uses[k].triangle] |= std::uint8_t(1u << uses[k].edge);
        }
        i = j;
    }
    return topology;
}

} // namespace

void triangle_mesh::initialize() { initialize_with(nullptr); }

void triangle_mesh::initialize(std::span<const std::uint8_t> active_edges) { initialize_with(&active_edges); }

void triangle_mesh::initialize_with(const std::span<const std::uint8_t> *given_flags) {
    check_mesh(vertices, indices, friction, restitution);
    auto kept = drop_degenerate_triangles(vertices, indices);
    auto topology = find_edge_topology(vertices, kept, no_triangle, active_edge_cosine);
    auto num_tri = kept.normals.size();

    std::vector<AABB> aabbs(num_tri);
    for (std::size_t t = 0; t < num_tri; ++t) {
        const auto &a = vertices[kept.indices[t * 3]], &b = vertices[kept.indices[t * 3 + 1]],
                   &c = vertices[kept.indices[t * 3 + 2]];
        aabbs[t] = {min(min(a, b), c), max(max(a, b), c)};
    }
    tree.build(aabbs);

    if (given_flags) {
        if (kept.dropped > 0) {
            throw_invalid_argument(initialize_name, ": ", kept.dropped,
                                   " triangles have zero area, which a page with given edge flags "
                                   "cannot drop");
        }
        if (given_flags->size() != num_tri) {
            throw_invalid_argument(initialize_name, ": there must be one set of edge flags per triangle (",
                                   num_tri, "), got ", given_flags->size());
        }
        topology.flags.assign(given_flags->begin(), given_flags->end());
    }

    indices = std::move(kept.indices);
    normals = std::move(kept.normals);
    adjacency = std::move(topology.adjacency);
    edge_flags = std::move(topology.flags);
    triangle_aabbs = std::move(aabbs);
    degenerate_count = kept.dropped;
    is_initialized = true;
}

namespace {

scalar interpolate(const std::vector<scalar> &values, const std::uint32_t *tri, const vector3 &w) noexcept {
    auto v = values[tri[0]] * w.x + values[tri[1]] * w.y + values[tri[2]] * w.z;
    return std::max(scalar(0), v);
}

} // namespace

scalar triangle_mesh::get_friction(std::size_t triangle, const vector3 &barycentric) const noexcept {
    EDYN_ASSERT(has_per_vertex_friction());
    return interpolate(friction, &indices[triangle * 3], barycentric);
}

scalar triangle_mesh::get_restitution(std::size_t triangle, const vector3 &barycentric) const noexcept {
    EDYN_ASSERT(has_per_vertex_restitution());
    return interpolate(restitution, &indices[triangle * 3], barycentric);
}

vector3 barycentric_coordinates(const vector3 &p, const vector3 &a, const vector3 &b,
                                const vector3 &c) noexcept {
    auto v0 = b - a, v1 = c - a, v2 = p - a;
    auto d00 = dot(v0, v0), d01 = dot(v0, v1), d11 = dot(v1, v1);
    auto d20 = dot(v2, v0), d21 = dot(v2, v1);
    auto denom = d00 * d11 - d01 * d01;
    if (!(std::abs(denom) > 0)) return {scalar(1), 0, 0};
    auto v = (d11 * d20 - d01 * d21) / denom;
    auto w = (d00 * d21 - d01 * d20) / denom;
    return {scalar(1) - v - w, v, w};
}

} // namespace edyn
