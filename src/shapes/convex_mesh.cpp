#include "edyn/shapes/convex_mesh.hpp"
#include "dvec3.hpp"
#include "edyn/math/math.hpp"
#include "invalid_argument.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace edyn {

namespace {

using detail::dvec3;
using detail::throw_invalid_argument;
using detail::to_dvec3;
using detail::to_vector3;

constexpr const char *who = "polyhedron_shape: ";

// Sine of the angle below which two edges count as parallel in unique_edge_directions.
constexpr scalar parallel_edge_sine = scalar(1e-5);

struct directed_edge {
    std::uint32_t from;
    std::uint32_t to;
    std::uint32_t face;

    bool operator<(const directed_edge &other) const noexcept {
        return std::tie(from, to, face) < std::tie(other.from, other.to, other.face);
    }
};

// Plane of a face from Newell's method (exact for planar polygons, the least-squares direction
// for others) through the vertex average. In double: a thin face's normal computed in float can
// be off by far more than the tolerances below.
struct face_plane {
    dvec3 normal;
    double constant;
    double twice_area;
};

face_plane compute_plane(const convex_mesh &mesh, std::size_t face) {
    auto count = mesh.faces[face].count;
    // Relative to the first vertex, which keeps the cross products small.
    auto origin = to_dvec3(mesh.face_vertex(face, 0));
    dvec3 n{0, 0, 0}, sum{0, 0, 0};
    for (std::uint32_t i = 0; i < count; ++i) {
        auto p = to_dvec3(mesh.face_vertex(face, i));
        sum += p;
        if (i > 0 && i + 1 < count) n += cross(p - origin, to_dvec3(mesh.face_vertex(face, i + 1)) - origin);
    }
    auto len = length(n);
    auto unit = len > 0 ? n * (1 / len) : dvec3{0, 0, 0};
    return {unit, dot(unit, sum * (1.0 / count)), len};
}

double plane_distance(const face_plane &plane, const vector3 &p) {
    return dot(plane.normal, to_dvec3(p)) - plane.constant;
}

// Size of a vertex set: its largest extent along an axis and its largest absolute coordinate.
struct mesh_scale {
    scalar extent;
    scalar max_abs;
};

mesh_scale measure(std::span<const vector3> vertices) {
    if (vertices.empty()) return {0, 0};
    auto lo = vertices[0], hi = vertices[0];
    scalar max_abs = 0;
    for (auto &v : vertices) {
        lo = min(lo, v);
        hi = max(hi, v);
        max_abs = std::max(max_abs, max_component(abs(v)));
    }
    return {max_component(hi - lo), max_abs};
}

std::vector<directed_edge> directed_edges(const convex_mesh &mesh) {
    std::vector<directed_edge> result;
    result.reserve(mesh.indices.size());
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
        auto idx = mesh.face_indices(f);
        for (std::size_t i = 0; i < idx.size(); ++i) {
            result.push_back({idx[i], idx[(i + 1) % idx.size()], f});
        }
    }
    std::sort(result.begin(), result.end());
    return result;
}

void validate_counts_and_indices(const convex_mesh &mesh) {
    if (mesh.vertices.size() < 4) {
        throw_invalid_argument(who, "vertices must hold at least 4 points, got ", mesh.vertices.size());
    }
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const auto &v = mesh.vertices[i];
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(v[c])) {
                throw_invalid_argument(who, "vertices[", i, "].", "xyz"[c], " must be finite, got ", v[c]);
            }
        }
    }
    if (mesh.faces.size() < 4) {
        throw_invalid_argument(who, "faces must hold at least 4 faces, got ", mesh.faces.size());
    }
    std::vector<bool> used(mesh.vertices.size(), false);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        auto range = mesh.faces[f];
        if (range.count < 3) {
            throw_invalid_argument(who, "faces[", f, "] must have at least 3 vertices, got ", range.count);
        }
        if (std::size_t(range.first) + range.count > mesh.indices.size()) {
            throw_invalid_argument(who, "faces[", f, "] spans indices ", range.first, "..",
                                   range.first + range.count, " beyond the ", mesh.indices.size(),
                                   " indices");
        }
        auto idx = mesh.face_indices(f);
        for (std::size_t i = 0; i < idx.size(); ++i) {
            if (idx[i] >= mesh.vertices.size()) {
                throw_invalid_argument(who, "faces[", f, "][", i, "] = ", idx[i], " is out of range (",
                                       mesh.vertices.size(), " vertices)");
            }
            for (std::size_t j = 0; j < i; ++j) {
                if (idx[j] == idx[i]) {
                    throw_invalid_argument(who, "faces[", f, "] repeats vertex ", idx[i]);
                }
            }
            used[idx[i]] = true;
        }
    }
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (!used[i]) throw_invalid_argument(who, "vertices[", i, "] is used by no face");
    }
}

// Every edge a->b must meet exactly one b->a: a closed surface whose faces agree on the sense.
void validate_winding_consistency(const convex_mesh &mesh) {
    auto edges = directed_edges(mesh);
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const auto &e = edges[i];
        if (i + 1 < edges.size() && edges[i + 1].from == e.from && edges[i + 1].to == e.to) {
            throw_invalid_argument(who, "inconsistent winding: faces[", e.face, "] and faces[",
                                   edges[i + 1].face, "] both traverse edge ", e.from, "->", e.to,
                                   " in the same sense");
        }
        auto reverse = directed_edge{e.to, e.from, 0};
        auto it = std::lower_bound(edges.begin(), edges.end(), reverse);
        if (it == edges.end() || it->from != e.to || it->to != e.from) {
            throw_invalid_argument(
                who, "faces[", e.face, "] edge ", e.from, "->", e.to,
                " has no opposite edge in another face (surface not closed or inconsistent winding)");
        }
    }
}

void validate_faces_geometry(const convex_mesh &mesh, scalar tolerance) {
    // Lengths below one rounding of the coordinates carry no direction.
    auto rounding = scalar(detail::coordinate_rounding) * measure(mesh.vertices).max_abs;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        auto count = mesh.faces[f].count;
        scalar longest = 0;
        for (std::uint32_t i = 0; i < count; ++i) {
            auto len = distance(mesh.face_vertex(f, i), mesh.face_vertex(f, (i + 1) % count));
            if (!(len > rounding)) {
                throw_invalid_argument(who, "faces[", f, "] has a zero-length edge from vertex ",
                                       mesh.indices[mesh.faces[f].first + i], " to vertex ",
                                       mesh.indices[mesh.faces[f].first + (i + 1) % count]);
            }
            longest = std::max(longest, len);
        }
        auto plane = compute_plane(mesh, f);
        // Twice the area against a sliver of width `rounding`.
        if (!(plane.twice_area > rounding * longest)) {
            throw_invalid_argument(who, "faces[", f, "] is degenerate: area ", plane.twice_area / 2,
                                   " (its vertices are collinear)");
        }
        for (std::uint32_t i = 0; i < count; ++i) {
            auto d = std::abs(plane_distance(plane, mesh.face_vertex(f, i)));
            if (d > tolerance) {
                throw_invalid_argument(who, "faces[", f, "] is not planar: vertex ",
                                       mesh.indices[mesh.faces[f].first + i], " is ", d,
                                       " from the face plane (tolerance ", tolerance, ")");
            }
        }
    }
}

double signed_volume(const convex_mesh &mesh) {
    // Relative to the vertex average: smaller products, less rounding.
    dvec3 ref{0, 0, 0};
    for (auto &v : mesh.vertices) {
        ref += to_dvec3(v);
    }
    ref = ref * (1.0 / double(mesh.vertices.size()));
    double six_volume = 0;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        auto a = to_dvec3(mesh.face_vertex(f, 0)) - ref;
        for (std::uint32_t i = 1; i + 1 < mesh.faces[f].count; ++i) {
            auto b = to_dvec3(mesh.face_vertex(f, i)) - ref;
            auto c = to_dvec3(mesh.face_vertex(f, i + 1)) - ref;
            six_volume += dot(a, cross(b, c));
        }
    }
    return six_volume / 6;
}

void validate_volume_and_convexity(const convex_mesh &mesh, scalar tolerance) {
    auto extent = measure(mesh.vertices).extent;
    auto volume = signed_volume(mesh);
    // A slab `tolerance` thick across the whole extent.
    auto min_volume = double(tolerance) * extent * extent;
    if (volume < -min_volume) {
        throw_invalid_argument(who, "faces are wound clockwise seen from outside (signed volume ", volume,
                               "); the winding must be counter-clockwise");
    }
    if (!(volume > min_volume)) {
        throw_invalid_argument(who, "the mesh is degenerate: volume ", volume, " for extent ", extent);
    }
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        auto plane = compute_plane(mesh, f);
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
            auto dist = plane_distance(plane, mesh.vertices[i]);
            if (dist > tolerance) {
                throw_invalid_argument(who, "the mesh is not convex: vertices[", i, "] lies ", dist,
                                       " in front of the plane of faces[", f, "] (tolerance ", tolerance,
                                       ")");
            }
        }
    }
}

void validate_raw(const convex_mesh &mesh) {
    validate_counts_and_indices(mesh);
    validate_winding_consistency(mesh);
    auto tolerance = convex_mesh_tolerance(mesh.vertices);
    validate_faces_geometry(mesh, tolerance);
    validate_volume_and_convexity(mesh, tolerance);
}

// Keeps one direction per set of parallel edges (either sense). Directions are bucketed in a
// grid of cells `parallel_edge_sine` wide so that each edge is compared with nearby kept
// directions only; the result is the same as comparing with all of them, in edge order.
void compute_unique_edge_directions(convex_mesh &mesh) {
    mesh.unique_edge_directions.clear();
    using cell_key = std::array<std::int64_t, 3>;
    std::map<cell_key, std::vector<std::uint32_t>> grid;
    auto cell_of = [](const vector3 &d) {
        return cell_key{std::int64_t(std::floor(d.x / parallel_edge_sine)),
                        std::int64_t(std::floor(d.y / parallel_edge_sine)),
                        std::int64_t(std::floor(d.z / parallel_edge_sine))};
    };
    auto parallel_known = [&](const vector3 &dir) {
        for (auto sense : {dir, -dir}) {
            auto c = cell_of(sense);
            for (std::int64_t i = -1; i <= 1; ++i) {
                for (std::int64_t j = -1; j <= 1; ++j) {
                    for (std::int64_t k = -1; k <= 1; ++k) {
                        auto it = grid.find({c[0] + i, c[1] + j, c[2] + k});
                        if (it == grid.end()) continue;
                        for (auto u : it->second) {
                            auto &known = mesh.unique_edge_directions[u];
                            if (length_sqr(cross(known, dir)) <= square(parallel_edge_sine)) return true;
                        }
                    }
                }
            }
        }
        return false;
    };
    for (auto &e : mesh.edges) {
        // Validation guarantees a length above rounding (normalize would assert on tiny meshes).
        auto edge = mesh.vertices[e[1]] - mesh.vertices[e[0]];
        auto dir = edge / length(edge);
        // One sense per direction: the largest component positive.
        if (dir[max_index(abs(dir))] < 0) dir = -dir;
        if (parallel_known(dir)) continue;
        grid[cell_of(dir)].push_back(static_cast<std::uint32_t>(mesh.unique_edge_directions.size()));
        mesh.unique_edge_directions.push_back(dir);
    }
}

} // namespace

scalar convex_mesh_tolerance(std::span<const vector3> vertices) noexcept {
    auto scale = measure(vertices);
    // Above the hull's merging tolerance (6 coordinate roundings), so that hulls always validate.
    return std::max(scalar(1e-5) * scale.extent, scalar(16 * detail::coordinate_rounding) * scale.max_abs);
}

void update_convex_mesh_features(convex_mesh &mesh) {
    auto num_faces = mesh.faces.size();
    mesh.normals.resize(num_faces);
    mesh.plane_constants.resize(num_faces);
    for (std::size_t f = 0; f < num_faces; ++f) {
        auto plane = compute_plane(mesh, f);
        mesh.normals[f] = to_vector3(plane.normal);
        mesh.plane_constants[f] = scalar(plane.constant);
    }

    // Each undirected edge appears twice; the copy running from the lower to the higher index
    // names edge_faces[e][0].
    mesh.edges.clear();
    mesh.edge_faces.clear();
    auto directed = directed_edges(mesh);
    for (auto &e : directed) {
        if (e.from > e.to) continue;
        auto it = std::lower_bound(directed.begin(), directed.end(), directed_edge{e.to, e.from, 0});
        EDYN_ASSERT(it != directed.end() && it->from == e.to && it->to == e.from);
        mesh.edges.push_back({e.from, e.to});
        mesh.edge_faces.push_back({e.face, it->face});
    }
    compute_unique_edge_directions(mesh);

    mesh.bounding_radius = 0;
    for (auto &v : mesh.vertices)
        mesh.bounding_radius = std::max(mesh.bounding_radius, length(v));
}

void validate_convex_mesh(const convex_mesh &mesh) {
    validate_raw(mesh);
    auto check_size = [](const char *field, std::size_t size, std::size_t expected) {
        if (size != expected) {
            throw_invalid_argument(who, field, " holds ", size, " entries, expected ", expected);
        }
    };
    check_size("normals", mesh.normals.size(), mesh.faces.size());
    check_size("plane_constants", mesh.plane_constants.size(), mesh.faces.size());
    // A closed surface uses every edge twice.
    check_size("edges", mesh.edges.size(), mesh.indices.size() / 2);
    check_size("edge_faces", mesh.edge_faces.size(), mesh.edges.size());
    if (mesh.unique_edge_directions.empty()) {
        throw_invalid_argument(who, "unique_edge_directions is empty");
    }
    // Derived data that came from elsewhere (a file, the network) must match the geometry.
    auto tolerance = convex_mesh_tolerance(mesh.vertices);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        auto plane = compute_plane(mesh, f);
        auto n = mesh.normals[f];
        if (!(dot(to_dvec3(n), plane.normal) > 1 - 1e-4) || !(std::abs(length(n) - 1) < 1e-4)) {
            throw_invalid_argument(who, "normals[", f, "] = ", n, " does not match the face, expected ",
                                   to_vector3(plane.normal));
        }
        if (!(std::abs(mesh.plane_constants[f] - plane.constant) <= tolerance)) {
            throw_invalid_argument(who, "plane_constants[", f, "] = ", mesh.plane_constants[f],
                                   " does not match the face, expected ", plane.constant);
        }
    }
}

convex_mesh make_convex_mesh(std::vector<vector3> vertices,
                             const std::vector<std::vector<std::uint32_t>> &faces) {
    convex_mesh mesh;
    mesh.vertices = std::move(vertices);
    mesh.faces.reserve(faces.size());
    for (auto &face : faces) {
        mesh.faces.push_back(
            {static_cast<std::uint32_t>(mesh.indices.size()), static_cast<std::uint32_t>(face.size())});
        mesh.indices.insert(mesh.indices.end(), face.begin(), face.end());
    }
    validate_raw(mesh);
    update_convex_mesh_features(mesh);
    return mesh;
}

} // namespace edyn
