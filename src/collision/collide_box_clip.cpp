#include "edyn/collision/detail/box_features.hpp"
#include "edyn/collision/detail/clip.hpp"
#include "edyn/math/math.hpp"
#include <algorithm>

namespace edyn::detail {

std::size_t clip_polygon_half_space(const clip_vertex *in, std::size_t n, const vector3 &normal,
                                    scalar constant, const collision_feature &cut_feature,
                                    clip_vertex *out) noexcept {
    if (n == 0) return 0;
    std::size_t count = 0;
    const clip_vertex *prev = &in[n - 1];
    auto prev_dist = dot(normal, prev->position) - constant;
    for (std::size_t i = 0; i < n; ++i) {
        const clip_vertex *curr = &in[i];
        auto curr_dist = dot(normal, curr->position) - constant;
        // Strict signs: a vertex on the plane is kept as is rather than duplicated.
        if (prev_dist < 0 && curr_dist > 0) {
            // Leaving: the rest of this edge is cut and the polygon continues along the plane.
            auto s = prev_dist / (prev_dist - curr_dist);
            out[count++] = {lerp(prev->position, curr->position, s), prev->next_edge, cut_feature};
        } else if (prev_dist > 0 && curr_dist < 0) {
            // Entering: the point and the edge that follows both lie on the original edge.
            auto s = prev_dist / (prev_dist - curr_dist);
            out[count++] = {lerp(prev->position, curr->position, s), prev->next_edge, prev->next_edge};
        }
        if (curr_dist <= 0) {
            out[count] = *curr;
            // A vertex on the plane followed by one outside starts an edge along the plane.
            auto next_dist = dot(normal, in[(i + 1) % n].position) - constant;
            if (curr_dist == 0 && next_dist > 0) out[count].next_edge = cut_feature;
            ++count;
        }
        prev = curr;
        prev_dist = curr_dist;
    }
    return count;
}

std::size_t clip_polygon_box_face_sides(const clip_vertex *in, std::size_t n, const vector3 &half_extents,
                                        unsigned face, const collision_feature &cut_feature,
                                        clip_vertex *out) noexcept {
    EDYN_ASSERT(n + 4 <= max_clip_vertices);
    auto axis = box_face_axis(face);
    clip_vertex buffer[max_clip_vertices];
    // Four passes alternate between a local buffer and `out`, starting with the buffer so that
    // the last pass writes into `out`.
    clip_vertex *dst[4] = {buffer, out, buffer, out};
    const clip_vertex *src = in;
    auto count = n;
    int pass = 0;
    for (int k = 1; k < 3; ++k) {
        auto side = (axis + k) % 3;
        for (auto sign : {scalar(1), scalar(-1)}) {
            vector3 normal = vector3_zero;
            normal[side] = sign;
            count = clip_polygon_half_space(src, count, normal, half_extents[side], cut_feature, dst[pass]);
            src = dst[pass];
            ++pass;
        }
    }
    return count;
}

void box_face_polygon(const vector3 &half_extents, unsigned face, const vector3 &pos, const quaternion &orn,
                      clip_vertex (&out)[4]) noexcept {
    unsigned indices[4];
    box_face_vertex_indices(face, indices);
    for (int i = 0; i < 4; ++i) {
        auto next = indices[(i + 1) % 4];
        out[i].position = pos + rotate(orn, box_vertex(half_extents, indices[i]));
        out[i].feature = {box_feature::vertex, indices[i]};
        out[i].next_edge = {box_feature::edge, box_edge_between(indices[i], next)};
    }
}

} // namespace edyn::detail
