#ifndef EDYN_COLLISION_DETAIL_CLIP_HPP
#define EDYN_COLLISION_DETAIL_CLIP_HPP

#include "edyn/collision/collision_feature.hpp"
#include "edyn/math/quaternion.hpp"
#include <cstddef>

// Polygon clipping that remembers, for each resulting vertex, which feature of the clipped
// (incident) shape it lies on: a manifold built by clipping an incident face against a
// reference face reports the incident vertex, edge or face of every point.
namespace edyn::detail {

struct clip_vertex {
    vector3 position;
    // Feature of the incident shape the point lies on.
    collision_feature feature;
    // Feature of the polygon edge from this vertex to the next one.
    collision_feature next_edge;
};

// Room for any polygon these routines produce from a quadrilateral clipped by four planes
// (at most 8 vertices), with margin for callers clipping larger polygons (n + planes <= 16).
inline constexpr std::size_t max_clip_vertices = 16;

// Keeps the part of the polygon `in` (n vertices) with dot(normal, p) <= constant, writing it to
// `out` (room for n + 1). A vertex created on a polygon edge takes that edge's feature; the new
// edge running along the plane takes `cut_feature` (normally the incident face). Returns the
// number of vertices written.
std::size_t clip_polygon_half_space(const clip_vertex *in, std::size_t n, const vector3 &normal,
                                    scalar constant, const collision_feature &cut_feature,
                                    clip_vertex *out) noexcept;

// Clips the polygon `in` (n <= 12 vertices, in the reference box's space) against the four side
// planes of face `face` of a box of `half_extents`: what remains projects onto the face.
// `out` needs room for n + 4 vertices. Returns the number of vertices written.
std::size_t clip_polygon_box_face_sides(const clip_vertex *in, std::size_t n, const vector3 &half_extents,
                                        unsigned face, const collision_feature &cut_feature,
                                        clip_vertex *out) noexcept;

// Face `face` of a box of `half_extents` as a tagged polygon (box vertex and edge features),
// counter-clockwise seen from outside, with its vertices mapped by p -> pos + rotate(orn, p).
void box_face_polygon(const vector3 &half_extents, unsigned face, const vector3 &pos, const quaternion &orn,
                      clip_vertex (&out)[4]) noexcept;

} // namespace edyn::detail

#endif // EDYN_COLLISION_DETAIL_CLIP_HPP
