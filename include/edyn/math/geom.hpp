#ifndef EDYN_MATH_GEOM_HPP
#define EDYN_MATH_GEOM_HPP

#include "edyn/math/vector2.hpp"
#include "edyn/math/vector3.hpp"
#include <cstddef>

/// @file
/// @brief Closest-point and clipping routines shared by every collide() pair.
///
/// None of them allocates; polygon routines write into caller-provided arrays whose required size
/// is stated with each function. None of them validates its input: they run on hot paths.
namespace edyn {

// Segments and lines.

/// Closest point to `q` on the segment [p0, p1]. A degenerate segment (p0 == p1 within
/// `epsilon`) gives p0 and t = 0.
/// @param p0 Start of the segment.
/// @param p1 End of the segment.
/// @param q The query point.
/// @param t Receives the parameter of the closest point, in [0, 1] (0 at p0, 1 at p1).
/// @return The closest point, p0 + (p1 - p0) t.
vector3 closest_point_segment(const vector3 &p0, const vector3 &p1, const vector3 &q, scalar &t) noexcept;

/// Closest point to `p` on the solid triangle (a, b, c), by the Voronoi region of the triangle
/// that holds p: a vertex, an edge or the face. A degenerate triangle (zero area) gives a point
/// of its edges.
/// @param p The query point.
/// @param a First vertex.
/// @param b Second vertex.
/// @param c Third vertex.
/// @return The point of the triangle closest to p.
vector3 closest_point_triangle(const vector3 &p, const vector3 &a, const vector3 &b,
                               const vector3 &c) noexcept;

/// Closest point to `q` on the segment [p0, p1], when its parameter is not needed.
/// @param p0 Start of the segment.
/// @param p1 End of the segment.
/// @param q The query point.
/// @return The closest point.
inline vector3 closest_point_segment(const vector3 &p0, const vector3 &p1, const vector3 &q) noexcept {
    scalar t;
    return closest_point_segment(p0, p1, q, t);
}

/// Squared distance from `q` to the segment [p0, p1].
/// @param p0 Start of the segment.
/// @param p1 End of the segment.
/// @param q The query point.
/// @return The squared distance.
inline scalar distance_sqr_point_segment(const vector3 &p0, const vector3 &p1, const vector3 &q) noexcept {
    return distance_sqr(closest_point_segment(p0, p1, q), q);
}

/// Closest point to `q` on the infinite line p + dir t.
/// @param p A point of the line.
/// @param dir Direction of the line, any length but not zero (precondition, checked by
/// `EDYN_ASSERT` only).
/// @param q The query point.
/// @param t Receives the parameter of the closest point (unbounded).
/// @return The closest point, p + dir t.
vector3 closest_point_line(const vector3 &p, const vector3 &dir, const vector3 &q, scalar &t) noexcept;

/// Result of `closest_points_segment_segment`. Point i is pointA[i] = a0 + (a1 - a0) * sA[i] on
/// segment A paired with pointB[i] = b0 + (b1 - b0) * sB[i] on segment B. Only the first
/// `num_points` entries of the arrays are set.
struct segment_closest_points {
    /// 1, or 2 when the segments are parallel and their projections overlap: then the two pairs
    /// sit at the ends of the overlap, each pointB the closest point of B to its pointA.
    std::size_t num_points{0};
    vector3 pointA[2]; ///< Closest points on segment A.
    vector3 pointB[2]; ///< Closest points on segment B, paired with `pointA`.
    scalar sA[2];      ///< Parameters of `pointA` on segment A, in [0, 1].
    scalar sB[2];      ///< Parameters of `pointB` on segment B, in [0, 1].
    /// Smallest squared distance among the pairs.
    scalar distance_sqr{0};
};

/// Sine of the angle below which `closest_points_segment_segment` treats two segments as
/// parallel. The distance of the parallel pairs exceeds the true minimum by at most this sine
/// times the shorter segment's length.
inline constexpr scalar segment_parallel_tolerance = scalar(1e-3);

/// Closest points between the segments [a0, a1] and [b0, b1] (for example two capsules' axes).
/// Degenerate segments (points) are handled. When they are parallel (see
/// `segment_parallel_tolerance`) and their projections on A's line overlap by more than a
/// rounding error, two pairs are returned (see `segment_closest_points`).
/// @param a0 Start of segment A.
/// @param a1 End of segment A.
/// @param b0 Start of segment B.
/// @param b1 End of segment B.
/// @param parallel_tolerance Sine of the angle below which the segments count as parallel.
/// @return One or two pairs of closest points and the smallest squared distance.
segment_closest_points
closest_points_segment_segment(const vector3 &a0, const vector3 &a1, const vector3 &b0, const vector3 &b1,
                               scalar parallel_tolerance = segment_parallel_tolerance) noexcept;

/// Support point of the segment [p0, p1] in direction `dir`: the end farthest along it (p0 on
/// ties).
/// @param p0 Start of the segment.
/// @param p1 End of the segment.
/// @param dir The direction, any length.
/// @return `p0` or `p1`.
inline vector3 support_point_segment(const vector3 &p0, const vector3 &p1, const vector3 &dir) noexcept {
    return dot(p1 - p0, dir) > 0 ? p1 : p0;
}

/// Clips the parametric interval [t0, t1] of the line p + dir t to the half-space
/// dot(normal, x) <= constant.
/// @param p A point of the line.
/// @param dir Direction of the line.
/// @param normal Normal of the half-space's boundary, pointing out of the half-space.
/// @param constant Offset of the boundary along `normal` (distance from the origin for a unit
/// normal).
/// @param t0 Start of the interval; raised in place when clipped.
/// @param t1 End of the interval; lowered in place when clipped.
/// @return False when nothing is left (t0 > t1, or a line parallel to the boundary outside it).
bool clip_line_interval(const vector3 &p, const vector3 &dir, const vector3 &normal, scalar constant,
                        scalar &t0, scalar &t1) noexcept;

/// Clips the segment [p0, p1] in place to the half-space dot(normal, x) <= constant.
/// @param p0 Start of the segment; moved onto the boundary when outside.
/// @param p1 End of the segment; moved onto the boundary when outside.
/// @param normal Normal of the boundary, pointing out of the half-space.
/// @param constant Offset of the boundary along `normal`.
/// @return False (leaving p0, p1 unspecified) when nothing is left.
bool clip_segment_half_space(vector3 &p0, vector3 &p1, const vector3 &normal, scalar constant) noexcept;

// Planes: the points x with dot(normal, x) == constant; `normal` is unit length.

/// Signed distance from `p` to the plane dot(normal, x) == constant.
/// @param normal Unit normal of the plane.
/// @param constant Distance of the plane from the origin along `normal`.
/// @param p The query point.
/// @return Positive on the side `normal` points to, negative behind.
constexpr scalar distance_point_plane(const vector3 &normal, scalar constant, const vector3 &p) noexcept {
    return dot(normal, p) - constant;
}

/// Orthogonal projection of `p` onto the plane dot(normal, x) == constant.
/// @param normal Unit normal of the plane.
/// @param constant Distance of the plane from the origin along `normal`.
/// @param p The point to project.
/// @return The closest point of the plane to `p`.
constexpr vector3 project_point_plane(const vector3 &normal, scalar constant, const vector3 &p) noexcept {
    return p - normal * distance_point_plane(normal, constant, p);
}

// Boxes: axis aligned, centred at the origin, given by their half extents (a box's object space).

/// Closest point of the solid box to `p` (`p` itself when inside).
/// @param half_extents Half the box's size along each axis, m.
/// @param p The query point, in the box's space.
/// @return The closest point, `p` clamped to the box.
constexpr vector3 closest_point_box(const vector3 &half_extents, const vector3 &p) noexcept {
    return {std::clamp(p.x, -half_extents.x, half_extents.x),
            std::clamp(p.y, -half_extents.y, half_extents.y),
            std::clamp(p.z, -half_extents.z, half_extents.z)};
}

/// Whether `p` lies in the box grown by `tolerance` on every side (boundary included).
/// @param half_extents Half the box's size along each axis.
/// @param p The query point, in the box's space.
/// @param tolerance Margin added to each side; negative shrinks the box.
/// @return True when inside or on the grown box.
constexpr bool point_in_box(const vector3 &half_extents, const vector3 &p, scalar tolerance = 0) noexcept {
    return p.x <= half_extents.x + tolerance && p.x >= -half_extents.x - tolerance &&
           p.y <= half_extents.y + tolerance && p.y >= -half_extents.y - tolerance &&
           p.z <= half_extents.z + tolerance && p.z >= -half_extents.z - tolerance;
}

/// Vertex of the box farthest along `dir` (the positive vertex on ties).
/// @param half_extents Half the box's size along each axis.
/// @param dir The direction, in the box's space, any length.
/// @return The support vertex.
constexpr vector3 support_point_box(const vector3 &half_extents, const vector3 &dir) noexcept {
    return {dir.x < 0 ? -half_extents.x : half_extents.x, dir.y < 0 ? -half_extents.y : half_extents.y,
            dir.z < 0 ? -half_extents.z : half_extents.z};
}

/// Half length of the box's projection on `axis`, as separating-axis tests need.
/// @param half_extents Half the box's size along each axis.
/// @param axis The axis in the box's space; unit length for a distance.
/// @return The projection radius.
inline scalar box_projection_radius(const vector3 &half_extents, const vector3 &axis) noexcept {
    return half_extents.x * std::abs(axis.x) + half_extents.y * std::abs(axis.y) +
           half_extents.z * std::abs(axis.z);
}

/// sqrt(1 - v[k]^2) for a unit vector v, from its other two components: exact to rounding even
/// where v nearly runs along coordinate axis k.
inline scalar length_across_axis(const vector3 &v, int k) noexcept {
    auto i = (k + 1) % 3, j = (k + 2) % 3;
    return std::sqrt(v[i] * v[i] + v[j] * v[j]);
}

/// Half the length of the projection of a cylinder on a direction:
/// |dir.axis| h + r |dir x axis|. The sine comes from the cross product, not from
/// sqrt(1 - (dir.axis)^2), which keeps only half the digits where dir nearly runs along the axis
/// (in single precision about 3e-4, a tenth of a millimetre on a 0.4 m radius).
/// @param axis The cylinder's axis, unit length.
/// @param half_length Half the cylinder's length along its axis.
/// @param radius The cylinder's radius.
/// @param dir The direction; unit length.
/// @return The projection radius.
inline scalar cylinder_projection_radius(const vector3 &axis, scalar half_length, scalar radius,
                                         const vector3 &dir) noexcept {
    return std::abs(dot(dir, axis)) * half_length + radius * length(cross(dir, axis));
}

/// The face of the box nearest to a point inside it; the point's projection on that face is
/// the closest point of the box surface. Ties go to the lower axis.
/// @param half_extents Half the box's size along each axis.
/// @param p The query point, in the box's space.
/// @param sign Receives +1 or -1 for the face's side along the axis.
/// @param depth Receives the distance from `p` to the face (>= 0 inside).
/// @return The face's axis: 0, 1 or 2.
int nearest_box_face(const vector3 &half_extents, const vector3 &p, scalar &sign, scalar &depth) noexcept;

/// Closest points between the segment [p0, p1] and the solid box. Exact: the squared distance
/// is a convex piecewise quadratic in t whose pieces are minimised in closed form.
/// @param half_extents Half the box's size along each axis.
/// @param p0 Start of the segment, in the box's space.
/// @param p1 End of the segment, in the box's space.
/// @param t Receives the parameter of the point on the segment, in [0, 1].
/// @param on_segment Receives the closest point on the segment.
/// @param on_box Receives the closest point of the box to it.
/// @return The squared distance (0 when the segment touches or crosses the box).
scalar closest_points_segment_box(const vector3 &half_extents, const vector3 &p0, const vector3 &p1,
                                  scalar &t, vector3 &on_segment, vector3 &on_box) noexcept;

// Discs and circles (a cylinder's caps and rims).

/// Closest point to `p` on the solid disc of `radius` centred at `center` with unit `normal`
/// (for example a cylinder's cap).
/// @param center Centre of the disc.
/// @param normal Unit normal of the disc's plane.
/// @param radius Radius of the disc, m.
/// @param p The query point.
/// @return The closest point of the disc.
vector3 closest_point_disc(const vector3 &center, const vector3 &normal, scalar radius,
                           const vector3 &p) noexcept;

/// Closest point to `p` on the circle of `radius` centred at `center` with unit `normal`
/// (for example a cylinder's rim).
/// @param center Centre of the circle.
/// @param normal Unit normal of the circle's plane.
/// @param radius Radius of the circle, m.
/// @param p The query point.
/// @return The closest point of the circle; when `p` is on the axis (every point is closest),
/// the point along the first vector of `plane_space(normal)`.
vector3 closest_point_circle(const vector3 &center, const vector3 &normal, scalar radius,
                             const vector3 &p) noexcept;

// Polygons: arrays of at least three vertices in order (clip segments with
// clip_segment_half_space); clipping follows Sutherland–Hodgman, so convex inputs give convex
// outputs. A vertex lying exactly on a clipping line is kept once, never duplicated.

/// Keeps the part of the convex polygon `in` with dot(normal, p) <= constant.
/// @param in The polygon's vertices, in order.
/// @param n Number of vertices of `in`; 0 gives 0.
/// @param normal Normal of the clipping line, pointing out of the kept side.
/// @param constant Offset of the clipping line along `normal`.
/// @param out Receives the clipped polygon; needs room for n + 1 vertices and must not overlap
/// `in`.
/// @return The number of vertices written to `out` (0 when nothing is left).
std::size_t clip_polygon_half_plane(const vector2 *in, std::size_t n, const vector2 &normal, scalar constant,
                                    vector2 *out) noexcept;

/// Keeps the part of the convex planar polygon `in` with dot(normal, p) <= constant: the 3D
/// counterpart of `clip_polygon_half_plane`.
/// @param in The polygon's vertices, in order.
/// @param n Number of vertices of `in`.
/// @param normal Normal of the clipping plane, pointing out of the kept side.
/// @param constant Offset of the clipping plane along `normal`.
/// @param out Receives the clipped polygon; needs room for n + 1 vertices.
/// @return The number of vertices written to `out`.
std::size_t clip_polygon_half_space(const vector3 *in, std::size_t n, const vector3 &normal, scalar constant,
                                    vector3 *out) noexcept;

/// Intersection of the polygon `subject` with the convex polygon `clip`, for example two contact
/// faces.
/// @param subject The polygon to clip.
/// @param n Number of vertices of `subject`.
/// @param clip The convex clipping polygon, counter-clockwise.
/// @param m Number of vertices of `clip`; 0 copies `subject` unchanged.
/// @param out Receives the intersection; needs room for n + m vertices.
/// @param scratch Working space; needs room for n + m vertices.
/// @return The number of vertices written to `out`.
std::size_t clip_polygon_convex(const vector2 *subject, std::size_t n, const vector2 *clip, std::size_t m,
                                vector2 *out, vector2 *scratch) noexcept;

/// Whether `p` lies in the convex counter-clockwise polygon grown by `tolerance`.
/// @param polygon The vertices, counter-clockwise.
/// @param n Number of vertices; 0 gives false.
/// @param p The query point.
/// @param tolerance Distance by which each edge is pushed outwards.
/// @return True when inside or on the grown polygon.
bool point_in_convex_polygon(const vector2 *polygon, std::size_t n, const vector2 &p,
                             scalar tolerance = 0) noexcept;

/// Signed area of a polygon (shoelace formula).
/// @param polygon The vertices, in order.
/// @param n Number of vertices.
/// @return The area, positive when counter-clockwise, negative when clockwise.
scalar polygon_signed_area(const vector2 *polygon, std::size_t n) noexcept;

/// Area of the quadrilateral with vertices p0..p3 taken in the order (of the three possible)
/// that gives the largest area; for four points in convex position, the area of their hull.
/// @return The area, in the square of the points' unit.
inline scalar quadrilateral_area(const vector3 &p0, const vector3 &p1, const vector3 &p2,
                                 const vector3 &p3) noexcept {
    // Area of a quad is half the cross product of its diagonals.
    auto a0 = length_sqr(cross(p2 - p0, p3 - p1));
    auto a1 = length_sqr(cross(p3 - p0, p1 - p2));
    auto a2 = length_sqr(cross(p1 - p0, p2 - p3));
    return scalar(0.5) * std::sqrt(std::max(a0, std::max(a1, a2)));
}

} // namespace edyn

#endif // EDYN_MATH_GEOM_HPP
