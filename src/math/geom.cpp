#include "edyn/math/geom.hpp"
#include <utility>

namespace edyn {

namespace {
// Squared length below which a segment is treated as a point.
constexpr scalar degenerate_length_sqr = epsilon * epsilon;
} // namespace

vector3 closest_point_triangle(const vector3 &p, const vector3 &a, const vector3 &b,
                               const vector3 &c) noexcept {
    auto ab = b - a, ac = c - a, ap = p - a;
    auto d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a; // Vertex a.
    auto bp = p - b;
    auto d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b; // Vertex b.
    auto vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3)); // Edge ab.
    auto cp = p - c;
    auto d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c; // Vertex c.
    auto vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6)); // Edge ac.
    auto va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))); // Edge bc.
    auto sum = va + vb + vc;
    if (!(sum > 0)) { // Degenerate: the nearest of its edges.
        auto best = closest_point_segment(a, b, p);
        for (auto q : {closest_point_segment(b, c, p), closest_point_segment(c, a, p)})
            if (distance_sqr(q, p) < distance_sqr(best, p)) best = q;
        return best;
    }
    auto denom = scalar(1) / sum;
    return a + ab * (vb * denom) + ac * (vc * denom); // Face.
}

vector3 closest_point_segment(const vector3 &p0, const vector3 &p1, const vector3 &q, scalar &t) noexcept {
    auto d = p1 - p0;
    auto len_sqr = length_sqr(d);
    if (len_sqr <= degenerate_length_sqr) {
        t = 0;
        return p0;
    }
    t = std::clamp(dot(q - p0, d) / len_sqr, scalar(0), scalar(1));
    return p0 + d * t;
}

vector3 closest_point_line(const vector3 &p, const vector3 &dir, const vector3 &q, scalar &t) noexcept {
    auto len_sqr = length_sqr(dir);
    EDYN_ASSERT(len_sqr > 0, "closest_point_line: zero direction");
    t = dot(q - p, dir) / len_sqr;
    return p + dir * t;
}

namespace {

void set_pair(segment_closest_points &r, std::size_t i, const vector3 &a0, const vector3 &d1, scalar s,
              const vector3 &b0, const vector3 &d2, scalar t) noexcept {
    r.sA[i] = s;
    r.sB[i] = t;
    r.pointA[i] = a0 + d1 * s;
    r.pointB[i] = b0 + d2 * t;
}

// Parallel segments: either the two ends of the overlap of their projections on A, or the
// single pair of nearest ends.
void parallel_segments(segment_closest_points &r, const vector3 &a0, const vector3 &d1, scalar a,
                       const vector3 &b0, const vector3 &d2) noexcept {
    auto b1 = b0 + d2;
    auto sb0 = dot(b0 - a0, d1) / a;
    auto sb1 = dot(b1 - a0, d1) / a;
    auto lo = std::max(scalar(0), std::min(sb0, sb1));
    auto hi = std::min(scalar(1), std::max(sb0, sb1));
    // Overlap must exceed rounding (relative to A's length) to give two distinct points.
    if (hi - lo > scalar(1e-5)) {
        scalar t;
        closest_point_segment(b0, b1, a0 + d1 * lo, t);
        set_pair(r, 0, a0, d1, lo, b0, d2, t);
        closest_point_segment(b0, b1, a0 + d1 * hi, t);
        set_pair(r, 1, a0, d1, hi, b0, d2, t);
        r.num_points = 2;
        r.distance_sqr =
            std::min(distance_sqr(r.pointA[0], r.pointB[0]), distance_sqr(r.pointA[1], r.pointB[1]));
        return;
    }
    auto s = lo > hi ? (std::max(sb0, sb1) < 0 ? scalar(0) : scalar(1)) : (lo + hi) * scalar(0.5);
    scalar t;
    auto pb = closest_point_segment(b0, b1, a0 + d1 * s, t);
    closest_point_segment(a0, a0 + d1, pb, s);
    set_pair(r, 0, a0, d1, s, b0, d2, t);
    r.num_points = 1;
    r.distance_sqr = distance_sqr(r.pointA[0], r.pointB[0]);
}

} // namespace

segment_closest_points closest_points_segment_segment(const vector3 &a0, const vector3 &a1, const vector3 &b0,
                                                      const vector3 &b1, scalar parallel_tolerance) noexcept {
    segment_closest_points r;
    auto d1 = a1 - a0;
    auto d2 = b1 - b0;
    auto rv = a0 - b0;
    auto a = dot(d1, d1);
    auto e = dot(d2, d2);
    auto f = dot(d2, rv);
    scalar s = 0, t = 0;

    if (a <= degenerate_length_sqr && e <= degenerate_length_sqr) {
        // Both points.
    } else if (a <= degenerate_length_sqr) {
        t = std::clamp(f / e, scalar(0), scalar(1));
    } else {
        auto c = dot(d1, rv);
        if (e <= degenerate_length_sqr) {
            s = std::clamp(-c / a, scalar(0), scalar(1));
        } else {
            auto b = dot(d1, d2);
            auto denom = a * e - b * b;
            if (denom <= parallel_tolerance * parallel_tolerance * a * e) {
                parallel_segments(r, a0, d1, a, b0, d2);
                return r;
            }
            s = std::clamp((b * f - c * e) / denom, scalar(0), scalar(1));
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = std::clamp(-c / a, scalar(0), scalar(1));
            } else if (t > 1) {
                t = 1;
                s = std::clamp((b - c) / a, scalar(0), scalar(1));
            }
        }
    }

    set_pair(r, 0, a0, d1, s, b0, d2, t);
    r.num_points = 1;
    r.distance_sqr = distance_sqr(r.pointA[0], r.pointB[0]);
    return r;
}

bool clip_line_interval(const vector3 &p, const vector3 &dir, const vector3 &normal, scalar constant,
                        scalar &t0, scalar &t1) noexcept {
    auto dn = dot(normal, dir);
    auto dist = dot(normal, p) - constant;
    if (std::abs(dn) <= epsilon * epsilon) {
        return dist <= 0 && t0 <= t1;
    }
    auto t = -dist / dn;
    if (dn > 0) {
        t1 = std::min(t1, t);
    } else {
        t0 = std::max(t0, t);
    }
    return t0 <= t1;
}

bool clip_segment_half_space(vector3 &p0, vector3 &p1, const vector3 &normal, scalar constant) noexcept {
    auto dir = p1 - p0;
    scalar t0 = 0, t1 = 1;
    if (!clip_line_interval(p0, dir, normal, constant, t0, t1)) {
        return false;
    }
    auto start = p0;
    p0 = start + dir * t0;
    p1 = start + dir * t1;
    return true;
}

int nearest_box_face(const vector3 &half_extents, const vector3 &p, scalar &sign, scalar &depth) noexcept {
    auto depths = half_extents - abs(p);
    auto axis = min_index(depths);
    sign = p[axis] < 0 ? scalar(-1) : scalar(1);
    depth = depths[axis];
    return axis;
}

namespace {

// Squared distance from p to the box, summed over the clamped coordinates.
scalar box_distance_sqr(const vector3 &half_extents, const vector3 &p) noexcept {
    return distance_sqr(p, closest_point_box(half_extents, p));
}

// Sorts a short array in place (insertion sort: at most 8 values).
void sort_small(scalar *values, std::size_t n) noexcept {
    for (std::size_t i = 1; i < n; ++i) {
        auto v = values[i];
        auto j = i;
        for (; j > 0 && values[j - 1] > v; --j) {
            values[j] = values[j - 1];
        }
        values[j] = v;
    }
}

} // namespace

scalar closest_points_segment_box(const vector3 &half_extents, const vector3 &p0, const vector3 &p1,
                                  scalar &t, vector3 &on_segment, vector3 &on_box) noexcept {
    auto d = p1 - p0;
    // Parameters where the segment crosses a slab boundary split [0, 1] into pieces on which
    // the set of clamped coordinates, hence the quadratic, is fixed.
    scalar breaks[8];
    std::size_t num_breaks = 0;
    breaks[num_breaks++] = 0;
    breaks[num_breaks++] = 1;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0) continue;
        for (auto bound : {half_extents[k], -half_extents[k]}) {
            auto tb = (bound - p0[k]) / d[k];
            if (tb > 0 && tb < 1) breaks[num_breaks++] = tb;
        }
    }
    sort_small(breaks, num_breaks);

    auto best_t = scalar(0);
    auto best_dist_sqr = large_scalar;
    for (std::size_t i = 0; i + 1 < num_breaks; ++i) {
        auto ta = breaks[i], tb = breaks[i + 1];
        auto mid = p0 + d * ((ta + tb) * scalar(0.5));
        scalar num = 0, den = 0;
        for (int k = 0; k < 3; ++k) {
            scalar target;
            if (mid[k] > half_extents[k]) {
                target = half_extents[k];
            } else if (mid[k] < -half_extents[k]) {
                target = -half_extents[k];
            } else {
                continue;
            }
            num -= d[k] * (p0[k] - target);
            den += d[k] * d[k];
        }
        auto tc = den > epsilon * epsilon ? std::clamp(num / den, ta, tb) : ta;
        auto dist_sqr = box_distance_sqr(half_extents, p0 + d * tc);
        if (dist_sqr < best_dist_sqr) {
            best_dist_sqr = dist_sqr;
            best_t = tc;
        }
    }

    t = best_t;
    on_segment = p0 + d * best_t;
    on_box = closest_point_box(half_extents, on_segment);
    return best_dist_sqr;
}

vector3 closest_point_disc(const vector3 &center, const vector3 &normal, scalar radius,
                           const vector3 &p) noexcept {
    auto w = project_plane(p - center, normal);
    auto len_sqr = length_sqr(w);
    if (len_sqr > radius * radius) {
        w *= radius / std::sqrt(len_sqr);
    }
    return center + w;
}

vector3 closest_point_circle(const vector3 &center, const vector3 &normal, scalar radius,
                             const vector3 &p) noexcept {
    auto w = p - center;
    if (!try_normalize_across(w, normal)) {
        vector3 t1;
        plane_space(normal, w, t1);
    }
    return center + w * radius;
}

namespace {

template<typename Vec, typename Dist>
std::size_t clip_polygon(const Vec *in, std::size_t n, Dist &&dist, Vec *out) noexcept {
    if (n == 0) return 0;
    std::size_t count = 0;
    auto prev = in[n - 1];
    auto prev_dist = dist(prev);
    for (std::size_t i = 0; i < n; ++i) {
        auto curr = in[i];
        auto curr_dist = dist(curr);
        // Strict signs: a vertex on the plane is kept as is rather than duplicated.
        if ((prev_dist < 0 && curr_dist > 0) || (prev_dist > 0 && curr_dist < 0)) {
            auto s = prev_dist / (prev_dist - curr_dist);
            out[count++] = prev + (curr - prev) * s;
        }
        if (curr_dist <= 0) {
            out[count++] = curr;
        }
        prev = curr;
        prev_dist = curr_dist;
    }
    return count;
}

} // namespace

std::size_t clip_polygon_half_plane(const vector2 *in, std::size_t n, const vector2 &normal, scalar constant,
                                    vector2 *out) noexcept {
    return clip_polygon(
        in, n, [&](const vector2 &p) { return dot(normal, p) - constant; }, out);
}

std::size_t clip_polygon_half_space(const vector3 *in, std::size_t n, const vector3 &normal, scalar constant,
                                    vector3 *out) noexcept {
    return clip_polygon(
        in, n, [&](const vector3 &p) { return dot(normal, p) - constant; }, out);
}

std::size_t clip_polygon_convex(const vector2 *subject, std::size_t n, const vector2 *clip, std::size_t m,
                                vector2 *out, vector2 *scratch) noexcept {
    // Ping-pong between the two buffers so that the last pass writes into `out`.
    vector2 *dst = m % 2 == 1 ? out : scratch;
    vector2 *other = m % 2 == 1 ? scratch : out;
    const vector2 *src = subject;
    std::size_t count = n;
    for (std::size_t i = 0; i < m; ++i) {
        auto c0 = clip[i];
        auto c1 = clip[(i + 1) % m];
        auto edge = c1 - c0;
        auto normal = vector2{edge.y, -edge.x};
        count = clip_polygon_half_plane(src, count, normal, dot(normal, c0), dst);
        src = dst;
        std::swap(dst, other);
    }
    if (m == 0) {
        std::copy(subject, subject + n, out);
    }
    return count;
}

bool point_in_convex_polygon(const vector2 *polygon, std::size_t n, const vector2 &p,
                             scalar tolerance) noexcept {
    for (std::size_t i = 0; i < n; ++i) {
        auto c0 = polygon[i];
        auto edge = polygon[(i + 1) % n] - c0;
        if (perp_product(edge, p - c0) < -tolerance * length(edge)) {
            return false;
        }
    }
    return n > 0;
}

scalar polygon_signed_area(const vector2 *polygon, std::size_t n) noexcept {
    scalar twice_area = 0;
    for (std::size_t i = 0; i < n; ++i) {
        twice_area += perp_product(polygon[i], polygon[(i + 1) % n]);
    }
    return twice_area * scalar(0.5);
}

} // namespace edyn
