#ifndef EDYN_COLLISION_DETAIL_BOX_FEATURES_HPP
#define EDYN_COLLISION_DETAIL_BOX_FEATURES_HPP

#include "edyn/collision/collision_feature.hpp"
#include "edyn/math/vector3.hpp"

// Box vertices, edges and faces by the indices documented in box_shape.hpp, in box space.
//   vertex i: signs x, y, z negative where bits 0, 1, 2 of i are set.
//   edge i:   along axis a = i / 4; of the two other axes taken in increasing order, bit 0 of
//             i % 4 set means the lower one is negative, bit 1 the higher one. The edge's vertex
//             0 lies at +half_extents[a], vertex 1 at -half_extents[a].
//   face i:   axis i / 2, positive side when i is even (0..5: +x, -x, +y, -y, +z, -z).
namespace edyn::detail {

constexpr scalar sign_of(scalar v) noexcept { return v < 0 ? scalar(-1) : scalar(1); }

constexpr vector3 box_vertex(const vector3 &half_extents, unsigned index) noexcept {
    return {index & 1 ? -half_extents.x : half_extents.x, index & 2 ? -half_extents.y : half_extents.y,
            index & 4 ? -half_extents.z : half_extents.z};
}

// Index of the vertex whose coordinates have the signs of `p` (zero counts as positive).
constexpr unsigned box_vertex_index(const vector3 &p) noexcept {
    return (p.x < 0 ? 1u : 0u) | (p.y < 0 ? 2u : 0u) | (p.z < 0 ? 4u : 0u);
}

constexpr unsigned box_face_index(int axis, scalar sign) noexcept {
    return unsigned(axis) * 2 + (sign < 0 ? 1u : 0u);
}

constexpr int box_face_axis(unsigned face) noexcept { return int(face / 2); }

constexpr scalar box_face_sign(unsigned face) noexcept { return face % 2 ? scalar(-1) : scalar(1); }

constexpr vector3 box_face_normal(unsigned face) noexcept {
    vector3 n = vector3_zero;
    n[box_face_axis(face)] = box_face_sign(face);
    return n;
}

// Index of the edge along `axis` on the side given by the signs of p's other two coordinates.
constexpr unsigned box_edge_index(int axis, const vector3 &p) noexcept {
    auto lo = axis == 0 ? 1 : 0;
    auto hi = axis == 2 ? 1 : 2;
    return unsigned(axis) * 4 + (p[lo] < 0 ? 1u : 0u) + (p[hi] < 0 ? 2u : 0u);
}

constexpr int box_edge_axis(unsigned edge) noexcept { return int(edge / 4); }

// Indices of the two vertices of an edge: vertex 0 on the positive side of the edge's axis.
constexpr void box_edge_vertex_indices(unsigned edge, unsigned &v0, unsigned &v1) noexcept {
    auto axis = box_edge_axis(edge);
    auto lo = axis == 0 ? 1 : 0;
    auto hi = axis == 2 ? 1 : 2;
    auto bits = ((edge & 1u) << lo) | (((edge >> 1) & 1u) << hi);
    v0 = bits;
    v1 = bits | (1u << axis);
}

constexpr void box_edge_vertices(const vector3 &half_extents, unsigned edge, vector3 &v0,
                                 vector3 &v1) noexcept {
    unsigned i0 = 0, i1 = 0;
    box_edge_vertex_indices(edge, i0, i1);
    v0 = box_vertex(half_extents, i0);
    v1 = box_vertex(half_extents, i1);
}

// The four vertex indices of a face, counter-clockwise seen from outside the box.
constexpr void box_face_vertex_indices(unsigned face, unsigned (&indices)[4]) noexcept {
    auto axis = box_face_axis(face);
    // (u, v, axis) is right-handed, so (+u+v, -u+v, -u-v, +u-v) turns counter-clockwise about
    // +axis; the negative face takes the reverse order.
    auto u = (axis + 1) % 3;
    auto v = (axis + 2) % 3;
    unsigned side = face % 2 ? (1u << axis) : 0u;
    unsigned ccw[4] = {0u, 1u << u, (1u << u) | (1u << v), 1u << v};
    for (int i = 0; i < 4; ++i) {
        indices[i] = side | ccw[face % 2 ? (4 - i) % 4 : i];
    }
}

constexpr void box_face_vertices(const vector3 &half_extents, unsigned face,
                                 vector3 (&vertices)[4]) noexcept {
    unsigned indices[4];
    box_face_vertex_indices(face, indices);
    for (int i = 0; i < 4; ++i) {
        vertices[i] = box_vertex(half_extents, indices[i]);
    }
}

// Index of the edge joining two vertices that differ in exactly one sign bit.
constexpr unsigned box_edge_between(unsigned v0, unsigned v1) noexcept {
    auto diff = v0 ^ v1;
    auto axis = diff == 1 ? 0 : (diff == 2 ? 1 : 2);
    auto p = box_vertex(vector3_one, v0);
    return box_edge_index(axis, p);
}

// Face whose outward normal is closest to the direction `dir` (box space).
inline unsigned box_support_face(const vector3 &dir) noexcept {
    auto axis = max_index(abs(dir));
    return box_face_index(axis, dir[axis]);
}

// Feature of the box surface at p, a point on (or within `tolerance` of) the surface: the
// vertex, edge or face whose bounds p meets. A point inside the box gets its nearest face.
inline collision_feature box_feature_at(const vector3 &half_extents, const vector3 &p,
                                        scalar tolerance) noexcept {
    int on_bound[3];
    int count = 0;
    for (int k = 0; k < 3; ++k) {
        if (std::abs(p[k]) >= half_extents[k] - tolerance) on_bound[count++] = k;
    }
    if (count == 3) {
        return {box_feature::vertex, box_vertex_index(p)};
    }
    if (count == 2) {
        return {box_feature::edge, box_edge_index(3 - on_bound[0] - on_bound[1], p)};
    }
    if (count == 1) {
        return {box_feature::face, box_face_index(on_bound[0], p[on_bound[0]])};
    }
    auto axis = min_index(half_extents - abs(p));
    return {box_feature::face, box_face_index(axis, p[axis])};
}

} // namespace edyn::detail

#endif // EDYN_COLLISION_DETAIL_BOX_FEATURES_HPP
