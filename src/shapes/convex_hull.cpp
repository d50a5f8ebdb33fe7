#include "edyn/shapes/convex_hull.hpp"
#include "dvec3.hpp"
#include "invalid_argument.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace edyn {

namespace {

using detail::throw_invalid_argument;

// The hull is built in double even in float builds: its decisions (is a point in front of a
// face?) must be consistent, which needs computation error far below the tolerance.
using detail::component;
using detail::dvec3;

constexpr auto no_index = std::numeric_limits<std::uint32_t>::max();

struct hull_face {
    // Point indices, counter-clockwise seen from outside.
    std::array<std::uint32_t, 3> v;
    // adj[i] is the face across the edge v[i] -> v[(i + 1) % 3].
    std::array<std::uint32_t, 3> adj{no_index, no_index, no_index};
    dvec3 normal;
    double offset;
    double area;
    // Points in front of this face that it is responsible for.
    std::vector<std::uint32_t> outside;
    bool alive{true};
};

struct horizon_edge {
    std::uint32_t face;
    std::uint32_t edge;
};

class quickhull {
public:
    explicit quickhull(std::span<const vector3> input);
    convex_mesh run();

private:
    double distance(std::uint32_t face, std::uint32_t point) const {
        return dot(faces[face].normal, pts[point]) - faces[face].offset;
    }
    std::uint32_t add_face(std::uint32_t a, std::uint32_t b, std::uint32_t c);
    void build_initial_simplex();
    void assign(std::uint32_t point, std::uint32_t first_face);
    void add_eye(std::uint32_t face);
    bool find_horizon(std::uint32_t face, std::uint32_t eye, double threshold);
    bool add_concave_neighbours(std::uint32_t eye);
    bool horizon_is_cycle();
    void stitch(std::uint32_t eye);
    std::vector<std::vector<std::uint32_t>> merge_coplanar_faces() const;
    bool boundary_loop(const std::vector<std::uint32_t> &group, const std::vector<std::uint32_t> &group_of,
                       std::uint32_t id, std::vector<std::uint32_t> &loop) const;

    std::span<const vector3> input;
    std::vector<dvec3> pts;
    double tolerance;
    std::vector<hull_face> faces;

    // Scratch for add_eye, indexed by face or by point; stamps avoid clearing.
    std::uint32_t stamp{0};
    std::vector<std::uint32_t> face_stamp;
    std::vector<std::uint32_t> point_stamp;
    std::vector<std::uint32_t> start_of;
    std::vector<std::uint32_t> new_face_from;
    std::vector<std::uint32_t> new_face_to;
    std::vector<std::uint32_t> visible;
    std::vector<horizon_edge> horizon;
};

quickhull::quickhull(std::span<const vector3> points)
    : input(points) {
    pts.reserve(points.size());
    dvec3 max_abs{0, 0, 0};
    for (std::size_t i = 0; i < points.size(); ++i) {
        auto &p = points[i];
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(p[c])) {
                throw_invalid_argument("convex_hull: points[", i, "].", "xyz"[c], " must be finite, got ",
                                       p[c]);
            }
        }
        pts.push_back({double(p.x), double(p.y), double(p.z)});
        max_abs = {std::max(max_abs.x, std::abs(double(p.x))), std::max(max_abs.y, std::abs(double(p.y))),
                   std::max(max_abs.z, std::abs(double(p.z)))};
    }
    if (points.size() < 4) {
        throw_invalid_argument("convex_hull: points must hold at least 4 points spanning a volume, got ",
                               points.size());
    }
    // A few roundings of the largest coordinate: input points computed in float (rotated,
    // scaled) are coplanar only to that precision.
    tolerance = 3 * detail::coordinate_rounding * std::max({max_abs.x, max_abs.y, max_abs.z});
}

std::uint32_t quickhull::add_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    hull_face face;
    face.v = {a, b, c};
    auto n = cross(pts[b] - pts[a], pts[c] - pts[a]);
    auto len = length(n);
    // A zero-area face only arises from points within rounding of a line; any normal works
    // there as the face is merged away or never sees a point.
    face.normal = len > 0 ? n * (1 / len) : dvec3{0, 0, 0};
    face.offset = dot(face.normal, (pts[a] + pts[b] + pts[c]) * (1.0 / 3));
    face.area = len / 2;
    faces.push_back(std::move(face));
    return static_cast<std::uint32_t>(faces.size() - 1);
}

// Index in [0, count) with the largest metric(i); `best` receives that value.
template<typename Metric>
std::uint32_t argmax(std::size_t count, Metric metric, double &best) {
    std::uint32_t index = 0;
    best = -1;
    for (std::uint32_t i = 0; i < count; ++i) {
        auto value = metric(i);
        if (value > best) {
            best = value;
            index = i;
        }
    }
    return index;
}

void quickhull::build_initial_simplex() {
    // The two most distant of the per-axis extreme points, the point farthest from their line,
    // the point farthest from the plane of the three.
    std::array<std::uint32_t, 6> extreme{};
    for (std::uint32_t i = 0; i < pts.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            if (component(pts[i], c) < component(pts[extreme[2 * c]], c)) extreme[2 * c] = i;
            if (component(pts[i], c) > component(pts[extreme[2 * c + 1]], c)) extreme[2 * c + 1] = i;
        }
    }
    double best;
    auto pair = argmax(
        36, [&](std::uint32_t k) { return length(pts[extreme[k / 6]] - pts[extreme[k % 6]]); }, best);
    auto i0 = extreme[pair / 6], i1 = extreme[pair % 6];
    if (best <= tolerance) {
        throw_invalid_argument("convex_hull: all ", pts.size(), " points coincide within tolerance ",
                               tolerance);
    }
    auto dir = (pts[i1] - pts[i0]) * (1 / best);
    auto i2 = argmax(
        pts.size(), [&](std::uint32_t i) { return length(cross(pts[i] - pts[i0], dir)); }, best);
    if (best <= tolerance) {
        throw_invalid_argument("convex_hull: all ", pts.size(), " points are collinear within tolerance ",
                               tolerance, " (largest distance from a line ", best, ")");
    }
    auto n = cross(pts[i1] - pts[i0], pts[i2] - pts[i0]);
    n = n * (1 / length(n));
    auto i3 = argmax(
        pts.size(), [&](std::uint32_t i) { return std::abs(dot(pts[i] - pts[i0], n)); }, best);
    if (best <= tolerance) {
        throw_invalid_argument("convex_hull: all ", pts.size(), " points are coplanar within tolerance ",
                               tolerance, " (largest distance from a plane ", best, ")");
    }
    // The base must face away from the apex.
    if (dot(pts[i3] - pts[i0], n) > 0) std::swap(i1, i2);
    add_face(i0, i1, i2);
    add_face(i1, i0, i3);
    add_face(i2, i1, i3);
    add_face(i0, i2, i3);
    for (std::uint32_t f = 0; f < 4; ++f) {
        for (std::uint32_t i = 0; i < 3; ++i) {
            auto a = faces[f].v[i], b = faces[f].v[(i + 1) % 3];
            for (std::uint32_t g = 0; g < 4; ++g) {
                for (std::uint32_t j = 0; j < 3; ++j) {
                    if (faces[g].v[j] == b && faces[g].v[(j + 1) % 3] == a) faces[f].adj[i] = g;
                }
            }
        }
    }
    for (std::uint32_t i = 0; i < pts.size(); ++i) {
        if (i != i0 && i != i1 && i != i2 && i != i3) assign(i, 0);
    }
}

// Gives the point to the face from first_face on that it is farthest in front of, if any.
void quickhull::assign(std::uint32_t point, std::uint32_t first_face) {
    auto best_face = no_index;
    auto best = tolerance;
    for (auto f = first_face; f < faces.size(); ++f) {
        if (!faces[f].alive) continue;
        auto d = distance(f, point);
        if (d > best) {
            best = d;
            best_face = f;
        }
    }
    if (best_face != no_index) faces[best_face].outside.push_back(point);
}

// Collects the faces that see `eye` (those connected to `face` whose plane it is more than
// `threshold` in front of), and the horizon around them.
bool quickhull::find_horizon(std::uint32_t face, std::uint32_t eye, double threshold) {
    ++stamp;
    visible.clear();
    face_stamp[face] = stamp;
    visible.push_back(face);
    for (std::size_t grown = 0;;) {
        for (; grown < visible.size(); ++grown) {
            for (auto g : faces[visible[grown]].adj) {
                if (face_stamp[g] != stamp && distance(g, eye) > threshold) {
                    face_stamp[g] = stamp;
                    visible.push_back(g);
                }
            }
        }
        if (!add_concave_neighbours(eye)) break;
    }
    return horizon_is_cycle();
}

// Fills `horizon` and returns false, or marks as visible the faces beyond the horizon that the
// new faces would not meet convexly, and returns true. When the eye lies (nearly) in the plane
// of such a face, a new face built on the shared edge can be steep enough to put the face's far
// vertex in front of it, or lie in the same plane folded back over it.
bool quickhull::add_concave_neighbours(std::uint32_t eye) {
    horizon.clear();
    bool grew = false;
    for (std::size_t k = 0; k < visible.size(); ++k) {
        auto f = visible[k];
        for (std::uint32_t i = 0; i < 3; ++i) {
            auto g = faces[f].adj[i];
            if (face_stamp[g] == stamp) continue;
            auto a = faces[f].v[i], b = faces[f].v[(i + 1) % 3];
            auto c = faces[g].v[0] + faces[g].v[1] + faces[g].v[2] - a - b;
            auto n = cross(pts[b] - pts[a], pts[eye] - pts[a]);
            auto len = length(n);
            auto height = dot(n, pts[c] - pts[a]);
            // In front, or in the plane of the new face but folded back over it.
            auto folded = std::abs(height) <= tolerance * len && dot(n, faces[g].normal) < 0;
            if (len == 0 || height > 0 || folded) {
                face_stamp[g] = stamp;
                visible.push_back(g);
                grew = true;
            } else {
                horizon.push_back({f, i});
            }
        }
    }
    return grew;
}

// The new faces form a cone over the horizon, which must be one simple loop. Near-coplanar
// configurations can break that within the tolerance; the caller then retries.
bool quickhull::horizon_is_cycle() {
    if (horizon.size() < 3) return false;
    for (std::uint32_t h = 0; h < horizon.size(); ++h) {
        auto a = faces[horizon[h].face].v[horizon[h].edge];
        if (point_stamp[a] == stamp) return false;
        point_stamp[a] = stamp;
        start_of[a] = h;
    }
    std::uint32_t current = 0;
    for (std::size_t steps = 1; steps <= horizon.size(); ++steps) {
        auto &e = horizon[current];
        auto b = faces[e.face].v[(e.edge + 1) % 3];
        if (point_stamp[b] != stamp) return false;
        current = start_of[b];
        if (current == 0 && steps != horizon.size()) return false;
    }
    return current == 0;
}

void quickhull::stitch(std::uint32_t eye) {
    auto first_new = static_cast<std::uint32_t>(faces.size());
    for (auto [f, i] : horizon) {
        auto a = faces[f].v[i], b = faces[f].v[(i + 1) % 3];
        auto g = faces[f].adj[i];
        auto nf = add_face(a, b, eye);
        faces[nf].adj[0] = g;
        for (std::uint32_t j = 0; j < 3; ++j) {
            if (faces[g].v[j] == b && faces[g].v[(j + 1) % 3] == a) faces[g].adj[j] = nf;
        }
        new_face_from[a] = nf;
        new_face_to[b] = nf;
    }
    for (auto nf = first_new; nf < faces.size(); ++nf) {
        faces[nf].adj[1] = new_face_from[faces[nf].v[1]];
        faces[nf].adj[2] = new_face_to[faces[nf].v[0]];
    }
    for (auto f : visible) {
        faces[f].alive = false;
    }
    for (auto f : visible) {
        for (auto p : faces[f].outside) {
            if (p != eye) assign(p, first_new);
        }
        std::vector<std::uint32_t>().swap(faces[f].outside);
    }
    face_stamp.resize(faces.size(), 0);
}

void quickhull::add_eye(std::uint32_t face) {
    auto &outside = faces[face].outside;
    auto far = std::max_element(outside.begin(), outside.end(), [&](std::uint32_t a, std::uint32_t b) {
        return distance(face, a) < distance(face, b);
    });
    auto eye = *far;
    // Exact visibility first. Should near-coplanar faces make the horizon something else than
    // one loop, they count as seeing the eye, then as not seeing it. Failing all, the eye is
    // within rounding of the surface and is dropped.
    if (find_horizon(face, eye, 0) || find_horizon(face, eye, -tolerance) ||
        find_horizon(face, eye, tolerance)) {
        stitch(eye);
    } else {
        outside.erase(far);
    }
}

// Groups coplanar hull triangles into polygons and returns their boundary loops.
std::vector<std::vector<std::uint32_t>> quickhull::merge_coplanar_faces() const {
    std::vector<std::uint32_t> order;
    for (std::uint32_t f = 0; f < faces.size(); ++f) {
        if (faces[f].alive) order.push_back(f);
    }
    // Large triangles seed the groups: their planes are the most accurate.
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return faces[a].area > faces[b].area; });
    std::vector<std::uint32_t> group_of(faces.size(), no_index);
    std::vector<std::vector<std::uint32_t>> loops;
    std::vector<std::uint32_t> group, loop;
    auto merge_tolerance = 2 * tolerance;
    for (auto seed : order) {
        if (group_of[seed] != no_index) continue;
        auto id = static_cast<std::uint32_t>(loops.size());
        const auto &plane = faces[seed];
        group.assign(1, seed);
        group_of[seed] = id;
        for (std::size_t k = 0; k < group.size(); ++k) {
            for (auto g : faces[group[k]].adj) {
                if (group_of[g] != no_index || dot(faces[g].normal, plane.normal) <= 0) continue;
                auto near = std::all_of(faces[g].v.begin(), faces[g].v.end(), [&](std::uint32_t p) {
                    return std::abs(dot(plane.normal, pts[p]) - plane.offset) <= merge_tolerance;
                });
                if (near) {
                    group_of[g] = id;
                    group.push_back(g);
                }
            }
        }
        if (boundary_loop(group, group_of, id, loop)) {
            loops.push_back(loop);
            continue;
        }
        // Not a disc: keep the triangles as faces of their own.
        loops.push_back({faces[seed].v.begin(), faces[seed].v.end()});
        for (std::size_t k = 1; k < group.size(); ++k) {
            group_of[group[k]] = static_cast<std::uint32_t>(loops.size());
            loops.push_back({faces[group[k]].v.begin(), faces[group[k]].v.end()});
        }
    }
    return loops;
}

// Chains the edges of `group` that border other groups into one loop; false when they do not
// form exactly one simple loop.
bool quickhull::boundary_loop(const std::vector<std::uint32_t> &group,
                              const std::vector<std::uint32_t> &group_of, std::uint32_t id,
                              std::vector<std::uint32_t> &loop) const {
    std::vector<std::array<std::uint32_t, 2>> edges;
    for (auto f : group) {
        for (std::uint32_t i = 0; i < 3; ++i) {
            if (group_of[faces[f].adj[i]] != id) edges.push_back({faces[f].v[i], faces[f].v[(i + 1) % 3]});
        }
    }
    if (edges.empty()) return false;
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 1; i < edges.size(); ++i) {
        if (edges[i][0] == edges[i - 1][0]) return false;
    }
    loop.clear();
    auto current = edges.front();
    for (std::size_t steps = 0; steps < edges.size(); ++steps) {
        loop.push_back(current[0]);
        auto next = std::lower_bound(edges.begin(), edges.end(), std::array<std::uint32_t, 2>{current[1], 0});
        if (next == edges.end() || (*next)[0] != current[1]) return false;
        current = *next;
    }
    return current == edges.front() && loop.size() == edges.size();
}

// Drops polygon vertices shared by fewer than three polygons: they lie on an edge (or inside a
// face), not at a corner. Dropping one can leave a two-vertex polygon, whose removal lowers
// other counts, hence the loop.
void remove_non_corner_vertices(std::vector<std::vector<std::uint32_t>> &polygons, std::size_t num_points) {
    std::vector<std::uint32_t> count(num_points);
    for (bool changed = true; changed;) {
        changed = false;
        std::fill(count.begin(), count.end(), 0);
        for (auto &poly : polygons) {
            for (auto v : poly)
                ++count[v];
        }
        for (auto &poly : polygons) {
            auto size = poly.size();
            std::erase_if(poly, [&](std::uint32_t v) { return count[v] < 3; });
            changed |= poly.size() != size;
        }
        auto size = polygons.size();
        std::erase_if(polygons, [](const std::vector<std::uint32_t> &poly) { return poly.size() < 3; });
        changed |= polygons.size() != size;
    }
}

convex_mesh quickhull::run() {
    face_stamp.assign(4, 0);
    point_stamp.assign(pts.size(), 0);
    start_of.assign(pts.size(), 0);
    new_face_from.assign(pts.size(), no_index);
    new_face_to.assign(pts.size(), no_index);
    build_initial_simplex();
    face_stamp.assign(faces.size(), 0);
    // New faces are appended, so one pass visits every face that ever holds points.
    for (std::uint32_t f = 0; f < faces.size(); ++f) {
        while (faces[f].alive && !faces[f].outside.empty()) {
            add_eye(f);
        }
    }

    auto polygons = merge_coplanar_faces();
    remove_non_corner_vertices(polygons, pts.size());

    // Keep the input order of the points that remain vertices.
    std::vector<std::uint32_t> remap(pts.size(), no_index);
    for (auto &poly : polygons) {
        for (auto v : poly)
            remap[v] = 0;
    }
    std::vector<vector3> vertices;
    for (std::uint32_t i = 0; i < pts.size(); ++i) {
        if (remap[i] == no_index) continue;
        remap[i] = static_cast<std::uint32_t>(vertices.size());
        vertices.push_back(input[i]);
    }
    for (auto &poly : polygons) {
        for (auto &v : poly)
            v = remap[v];
    }
    return make_convex_mesh(std::move(vertices), polygons);
}

} // namespace

convex_mesh convex_hull(std::span<const vector3> points) { return quickhull(points).run(); }

} // namespace edyn
