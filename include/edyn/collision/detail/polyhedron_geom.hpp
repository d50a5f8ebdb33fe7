#ifndef EDYN_COLLISION_DETAIL_POLYHEDRON_GEOM_HPP
#define EDYN_COLLISION_DETAIL_POLYHEDRON_GEOM_HPP

#include "edyn/collision/collision_result.hpp"
#include "edyn/collision/detail/cylinder_geom.hpp"
#include "edyn/math/matrix3x3.hpp"
#include "edyn/shapes/capsule_shape.hpp"
#include "edyn/shapes/convex_mesh.hpp"
#include "edyn/shapes/sphere_shape.hpp"
#include <array>
#include <cstdint>
#include <optional>
#include <span>

// Geometry of convex polytopes for the collide() pairs with a polyhedron: closest points to a
// point, a segment or another polytope, supporting features, the Gauss-map test of SAT, and the
// manifold of a polygonal face against a cylinder's supporting feature. None of it allocates, and
// faces and meshes of any size are handled: polygons are clipped edge by edge instead of into
// buffers, and the fixed-size per-call caches of collide_polytopes give way to computing in place
// for meshes larger than they hold.
namespace edyn::detail {

// A convex polytope in its own object space, seen through spans so that a polyhedron's mesh and
// a box (box_polytope) go through the same routines. Layout and conventions as convex_mesh.
struct polytope {
    std::span<const vector3> vertices;
    std::span<const std::uint32_t> indices;
    std::span<const convex_mesh::face_range> faces;
    std::span<const vector3> normals;
    std::span<const scalar> plane_constants;
    std::span<const std::array<std::uint32_t, 2>> edges;
    std::span<const std::array<std::uint32_t, 2>> edge_faces;
    std::span<const vector3> unique_edge_directions;
    scalar bounding_radius{0};
    // Set when the polytope is a box laid out by box_polytope: its vertex, edge and face indices
    // are then the box's (box_features.hpp) and collision points name its features.
    const vector3 *box_half_extents{nullptr};

    std::uint32_t face_size(std::size_t face) const noexcept { return faces[face].count; }

    std::uint32_t face_vertex_index(std::size_t face, std::size_t i) const noexcept {
        return indices[faces[face].first + i];
    }

    const vector3 &face_vertex(std::size_t face, std::size_t i) const noexcept {
        return vertices[face_vertex_index(face, i)];
    }

    // Signed distance of p from the plane of `face` (positive in front).
    scalar face_distance(std::size_t face, const vector3 &p) const noexcept {
        return dot(normals[face], p) - plane_constants[face];
    }
};

polytope make_polytope(const convex_mesh &mesh) noexcept;

// A box of `half_extents` as a polytope with the box's own indices: vertex i is box_vertex(i),
// edge i runs box_edge_vertex_indices(i), face i is box face i with box_face_vertex_indices.
// view() refers to this object, which must outlive it (hence not copyable).
struct box_polytope {
    vector3 half_extents;
    std::array<vector3, 8> vertices;
    std::array<scalar, 6> plane_constants;

    explicit box_polytope(const vector3 &half_extents) noexcept;
    box_polytope(const box_polytope &) = delete;
    box_polytope &operator=(const box_polytope &) = delete;

    polytope view() const noexcept;
};

// Lowest and highest projection of the polytope's vertices on `dir`.
void polytope_interval(const polytope &poly, const vector3 &dir, scalar &lo, scalar &hi) noexcept;

// Lowest projection of the polytope's vertices on `dir`.
scalar polytope_min_projection(const polytope &poly, const vector3 &dir) noexcept;

// Index of the vertex farthest along `dir` (the lowest index on ties).
std::uint32_t polytope_support_vertex(const polytope &poly, const vector3 &dir) noexcept;

// Whether p, projected along the face's normal, falls inside face `face` grown by `tolerance`
// (a distance).
bool point_over_face(const polytope &poly, std::size_t face, const vector3 &p, scalar tolerance = 0) noexcept;

// Vertex, edge or face of a polytope by its index in the polytope's arrays.
struct polytope_feature {
    polyhedron_feature kind{polyhedron_feature::vertex};
    std::uint32_t index{0};
};

// The feature as reported in a collision point: the box's feature for a box_polytope, none for
// a polyhedron (the manual: polyhedron features would need extra work to be exact).
std::optional<collision_feature> reported_feature(const polytope &poly, const polytope_feature &f) noexcept;

// Closest point of a solid polytope to p.
struct polytope_closest_point {
    vector3 point;   // On the surface.
    vector3 normal;  // Unit: from `point` towards p when outside; the face's normal when inside.
    scalar distance; // Signed: negative inside (then the depth below the least penetrated face).
    polytope_feature feature;
};

// Exact: a face whose prism holds p, else the nearest point of the edges of the faces that p
// sees. Inside, p leaves through the face of least penetration.
polytope_closest_point closest_point_polytope(const polytope &poly, const vector3 &p) noexcept;

// Closest points between the segment [p0, p1] and a solid polytope.
struct segment_polytope_closest {
    bool intersects{false}; // The segment meets the solid: nothing else is filled in.
    scalar distance{0};
    scalar t{0}; // Parameter of on_segment (0 at p0, 1 at p1).
    vector3 on_segment{vector3_zero};
    vector3 on_polytope{vector3_zero};
    polytope_feature feature;
};

// Exact: the ends against the polytope and the segment against the edges of the faces that the
// segment sees.
segment_polytope_closest closest_points_segment_polytope(const polytope &poly, const vector3 &p0,
                                                         const vector3 &p1) noexcept;

// Placement of polytope B in A's object space: x_A = r * x_B + t.
struct polytope_placement {
    matrix3x3 r;
    vector3 t;

    vector3 to_a(const vector3 &x_b) const noexcept { return r * x_b + t; }
    vector3 to_b(const vector3 &x_a) const noexcept { return (x_a - t) * r; }
};

// Exact closest points of two disjoint polytopes (in A's space), given a separating axis `axis`
// (unit, from A towards B) along which they are `separation` apart. Only features that reach
// within `reach` of the gap along the axis are examined, which is exact when the distance is at
// most `reach`: the closest pair then lies inside that slab. Returns the squared distance.
struct polytope_closest_pair {
    scalar distance_sqr{large_scalar};
    vector3 on_a{vector3_zero};
    vector3 on_b{vector3_zero}; // A's space.
    polytope_feature feature_a;
    polytope_feature feature_b;
};

polytope_closest_pair closest_pair_polytopes(const polytope &a, const polytope &b,
                                             const polytope_placement &place, const vector3 &axis,
                                             scalar reach) noexcept;

// Gauss-map test of SAT for an edge of A (normals a0, a1 of its two faces) against an edge of B
// (normals b0, b1 of its faces, all in one frame): whether the arcs a0-a1 and (-b0)-(-b1) cross
// on the unit sphere, i.e. whether the edges span a face of the Minkowski difference A - B. Only
// such pairs can give the least separation; the others are skipped. `s0` and `s1` are
// dot(b0, cross(a0, a1)) and dot(b1, cross(a0, a1)), and `n_b` is cross(b0, b1), which loops
// over edge pairs compute once per face or edge.
inline bool is_minkowski_face(const vector3 &a0, const vector3 &a1, const vector3 &b0, const vector3 &b1,
                              scalar s0, scalar s1, const vector3 &n_b) noexcept {
    // -b0 and -b1 on opposite sides of the great circle through a0 and a1.
    if (!(s0 * s1 < 0)) return false;
    // a0 and a1 on opposite sides of the great circle through -b0 and -b1.
    if (!(dot(a0, n_b) * dot(a1, n_b) < 0)) return false;
    // The circles meet at +-x; the point of arc (-b0)-(-b1) on circle a0-a1, a positive
    // combination of -b0 and -b1, must be the one on arc a0-a1, which faces a0 + a1 (the arc
    // spans under 180 degrees).
    auto y = (b0 * s1 - b1 * s0) * (s1 > 0 ? scalar(-1) : scalar(1));
    return dot(y, a0 + a1) > 0;
}

inline bool is_minkowski_face(const vector3 &a0, const vector3 &a1, const vector3 &b0,
                              const vector3 &b1) noexcept {
    auto n_a = cross(a0, a1);
    return is_minkowski_face(a0, a1, b0, b1, dot(b0, n_a), dot(b1, n_a), cross(b0, b1));
}

// Supporting feature of a polytope in direction `dir` (unit): a face whose normal lies within
// feature_tolerance (a sine) of `dir`, else an edge through the support vertex that lies across
// `dir` within that tolerance, else the support vertex.
polytope_feature polytope_support_feature(const polytope &poly, const vector3 &dir) noexcept;

// Manifold of a cylinder's (or capsule's) supporting feature `a` of shape A against face `face`
// of polytope B, both in the frame of `ctx` as for build_manifold(), which this completes for
// polygons of any number of vertices: candidate points are the corners of their overlap seen
// along `normal` (unit, from B towards A), each lifted onto the other feature; the cap disc is
// intersected with the polygon exactly. Points beyond ctx.threshold are dropped.
void build_polygon_manifold(const contact_feature &a, const polytope &poly, std::size_t face,
                            const vector3 &normal, const collision_context &ctx, const quaternion &to_world,
                            collision_result &result) noexcept;

// Lower bound of the distance between the segment [p0, p1] and the circle (center, unit normal,
// radius): the segment's distance from the centre less the radius, and its distance from the
// circle's plane when it lies on one side of it.
scalar segment_circle_distance_bound(const vector3 &p0, const vector3 &p1, const vector3 &center,
                                     const vector3 &normal, scalar radius) noexcept;

// Exact separating-axis search and manifold for two polytopes, the core of polyhedron–polyhedron
// and polyhedron–box (defined in collide_polyhedron_polyhedron.cpp).
void collide_polytopes(const polytope &a, const polytope &b, const collision_context &ctx,
                       collision_result &result) noexcept;

// The cores of polyhedron–sphere, polyhedron–capsule and cylinder–polyhedron for any polytope
// (the polyhedron's mesh, or a triangle's prism): the polytope is shape A, or B for the cylinder,
// at the transform `ctx` gives it.
void collide_polytope_sphere(const polytope &poly, const sphere_shape &b, const collision_context &ctx,
                             collision_result &result) noexcept;
// The closest pair of a segment and a polytope, both in the polytope's space:
// closest_points_segment_polytope, or a quicker routine for a polytope of a known shape.
using segment_polytope_closest_fn = segment_polytope_closest (*)(const polytope &poly, const vector3 &p0,
                                                                 const vector3 &p1) noexcept;
void collide_polytope_capsule(
    const polytope &poly, const capsule_shape &b, const collision_context &ctx, collision_result &result,
    segment_polytope_closest_fn closest_fn = closest_points_segment_polytope) noexcept;
void collide_cylinder_polytope(const cylinder_shape &a, const polytope &poly, const collision_context &ctx,
                               collision_result &result) noexcept;

} // namespace edyn::detail

#endif // EDYN_COLLISION_DETAIL_POLYHEDRON_GEOM_HPP
