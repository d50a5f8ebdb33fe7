#include "edyn/collision/detail/box_features.hpp"
#include "edyn/collision/detail/cylinder_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/shapes/coordinate_axis.hpp"
#include <algorithm>
#include <cmath>

namespace edyn::detail {

placed_cylinder place_cylinder(const cylinder_shape &shape, const vector3 &pos,
                               const quaternion &orn) noexcept {
    return {pos, coordinate_axis_vector(shape.axis, orn), shape.half_length, shape.radius};
}

vector3 cylinder_support_point(const placed_cylinder &cyl, const vector3 &dir) noexcept {
    auto c = dot(dir, cyl.axis);
    auto radial = dir;
    if (!try_normalize_across(radial, cyl.axis)) {
        vector3 t1;
        plane_space(cyl.axis, radial, t1);
    }
    return cyl.center + cyl.axis * (c < 0 ? -cyl.half_length : cyl.half_length) + radial * cyl.radius;
}

namespace {

// Double-precision vector for the iterative circle routines, whose conditioning float cannot
// carry when the quartic's coefficients span many orders of magnitude.
struct dvec {
    double x, y, z;
};

dvec to_dvec(const vector3 &v) noexcept { return {double(v.x), double(v.y), double(v.z)}; }
vector3 to_vector3(const dvec &v) noexcept { return {scalar(v.x), scalar(v.y), scalar(v.z)}; }
dvec operator+(const dvec &a, const dvec &b) noexcept { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
dvec operator-(const dvec &a, const dvec &b) noexcept { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
dvec operator*(const dvec &a, double s) noexcept { return {a.x * s, a.y * s, a.z * s}; }
double dot(const dvec &a, const dvec &b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Horner's rule, the degree known at compile time so that the loop unrolls.
template<int Degree>
double poly_eval(const double *c, double x) noexcept {
    auto v = c[Degree];
    for (int i = Degree - 1; i >= 0; --i) {
        v = v * x + c[i];
    }
    return v;
}

// Root of the polynomial in [a, b], where it changes sign (fa, fb its values at the ends):
// Newton's method kept inside a shrinking bracket, bisecting whenever a step would leave it, and
// stopping once a step moves less than 1e-9 relative (far below what float callers resolve) or
// the value drops below 1e-13 of the coefficients' scale (rounding level).
// An end that is an extremum (`a_extremum`, `b_extremum`) starts the search from its quadratic
// model: two roots close to one extremum (nearly a double root) otherwise make Newton crawl.
template<int Degree>
double refine_root(const double *c, const double *dc, double a, double b, double fa, double fb,
                   bool a_extremum, bool b_extremum) noexcept {
    auto x = a - fa * (b - a) / (fb - fa);
    if (a_extremum || b_extremum) {
        auto e = a_extremum ? a : b;
        auto fe = a_extremum ? fa : fb;
        double ddc[Degree - 1];
        for (int i = 0; i + 1 < Degree; ++i)
            ddc[i] = double(i + 1) * dc[i + 1];
        auto curvature = poly_eval<Degree - 2>(ddc, e);
        auto ratio = curvature != 0 ? -2 * fe / curvature : -1.0;
        if (ratio > 0) x = a_extremum ? e + std::sqrt(ratio) : e - std::sqrt(ratio);
    }
    if (!(x > a && x < b)) x = (a + b) * 0.5;
    // Bound of |c_i x^i| summed over the bracket.
    auto reach = std::max(1.0, std::max(std::abs(a), std::abs(b)));
    double size = 0, power = 1;
    for (int i = 0; i <= Degree; ++i, power *= reach)
        size += std::abs(c[i]) * power;
    auto negligible = 1e-13 * size;
    for (int iteration = 0; iteration < 60; ++iteration) {
        auto f = poly_eval<Degree>(c, x);
        if (std::abs(f) <= negligible) return x;
        if ((f < 0) == (fa < 0)) {
            a = x;
            fa = f;
        } else {
            b = x;
        }
        auto df = poly_eval<Degree - 1>(dc, x);
        auto next = df != 0 ? x - f / df : (a + b) * 0.5;
        if (!(next > a && next < b)) next = (a + b) * 0.5;
        auto scale = std::max(1.0, std::abs(next));
        if (std::abs(next - x) <= 1e-9 * scale || b - a <= 1e-9 * scale) return next;
        x = next;
    }
    return x;
}

// Real roots of c0 + c1 x + c2 x^2 (c2 != 0) in [lo, hi], increasing; cancellation-free form.
std::size_t quadratic_roots(const double *c, double lo, double hi, double *roots) noexcept {
    auto disc = c[1] * c[1] - 4 * c[2] * c[0];
    if (disc < 0) return 0;
    auto q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
    double r[2] = {q / c[2], q != 0 ? c[0] / q : q / c[2]};
    if (r[0] > r[1]) std::swap(r[0], r[1]);
    std::size_t count = 0;
    for (auto x : r) {
        if (x >= lo && x <= hi) roots[count++] = x;
    }
    return count;
}

// Root of c0 + c1 x (c1 != 0) in [lo, hi], if there is one.
std::size_t linear_root(const double *c, double lo, double hi, double *roots) noexcept {
    auto x = -c[0] / c[1];
    if (x >= lo && x <= hi) {
        roots[0] = x;
        return 1;
    }
    return 0;
}

// polynomial_roots() for a polynomial of degree 2 to 4 whose leading coefficient is not zero,
// with lo <= hi.
template<int Degree>
std::size_t roots_of_degree(const double *c, double lo, double hi, double *roots, double *extrema,
                            std::size_t *num_extrema) noexcept {
    // Between consecutive roots of the derivative the polynomial is monotonic: one sign change
    // at most per piece.
    double dc[Degree];
    for (int i = 0; i < Degree; ++i) {
        dc[i] = double(i + 1) * c[i + 1];
    }
    double breaks[Degree + 1];
    std::size_t num_crit;
    if constexpr (Degree == 2) {
        num_crit = linear_root(dc, lo, hi, breaks + 1);
    } else {
        num_crit = roots_of_degree<Degree - 1>(dc, lo, hi, breaks + 1, nullptr, nullptr);
    }
    if (extrema) {
        std::copy(breaks + 1, breaks + 1 + num_crit, extrema);
        *num_extrema = num_crit;
    }
    if constexpr (Degree == 2) {
        return quadratic_roots(c, lo, hi, roots);
    } else {
        breaks[0] = lo;
        breaks[num_crit + 1] = hi;

        std::size_t count = 0;
        auto f_prev = poly_eval<Degree>(c, lo);
        if (f_prev == 0) roots[count++] = lo;
        for (std::size_t i = 0; i <= num_crit; ++i) {
            auto a = breaks[i], b = breaks[i + 1];
            auto fb = poly_eval<Degree>(c, b);
            if (fb == 0) {
                if (count == 0 || roots[count - 1] != b) roots[count++] = b;
            } else if (f_prev != 0 && (f_prev < 0) != (fb < 0)) {
                roots[count++] = refine_root<Degree>(c, dc, a, b, f_prev, fb, i > 0, i < num_crit);
            }
            f_prev = fb;
        }
        return count;
    }
}

} // namespace

std::size_t polynomial_roots(const double *c, int degree, double lo, double hi, double *roots,
                             double *extrema, std::size_t *num_extrema) noexcept {
    EDYN_ASSERT(degree <= 4);
    if (num_extrema) *num_extrema = 0;
    while (degree > 0 && c[degree] == 0)
        --degree;
    if (degree <= 0 || lo > hi) return 0;
    switch (degree) {
    case 1:
        return linear_root(c, lo, hi, roots);
    case 2:
        return roots_of_degree<2>(c, lo, hi, roots, extrema, num_extrema);
    case 3:
        return roots_of_degree<3>(c, lo, hi, roots, extrema, num_extrema);
    default:
        return roots_of_degree<4>(c, lo, hi, roots, extrema, num_extrema);
    }
}

std::size_t circle_segment_critical_points(const vector3 &center, const vector3 &normal, scalar radius,
                                           const vector3 &p0, const vector3 &p1,
                                           scalar (&t)[max_circle_segment_critical]) noexcept {
    // Segment point s(t) = p0 + e t. With z the height over the circle's plane and u the
    // in-plane offset from the centre, the squared distance to the circle is
    // z^2 + (|u| - r)^2, whose derivative vanishes where F |u| = r G with
    // F = z z' + u.u' and G = u.u' (both linear in t); squaring gives F^2 |u|^2 - r^2 G^2 = 0.
    auto o = to_dvec(center);
    auto m = to_dvec(normal);
    auto w0 = to_dvec(p0) - o;
    auto e = to_dvec(p1) - to_dvec(p0);
    auto r = double(radius);
    auto z0 = dot(m, w0), z1 = dot(m, e);
    auto u0 = w0 - m * z0, u1 = e - m * z1;
    auto c0 = z0 * z1 + dot(u0, u1), c1 = z1 * z1 + dot(u1, u1);
    auto g0 = dot(u0, u1), g1 = dot(u1, u1);
    auto q0 = dot(u0, u0), q1 = 2 * g0, q2 = g1;
    auto f0 = c0 * c0, f1 = 2 * c0 * c1, f2 = c1 * c1;
    auto r2 = r * r;
    double poly[5] = {f0 * q0 - r2 * g0 * g0, f0 * q1 + f1 * q0 - 2 * r2 * g0 * g1,
                      f0 * q2 + f1 * q1 + f2 * q0 - r2 * g1 * g1, f1 * q2 + f2 * q1, f2 * q2};

    std::size_t count = 0;
    t[count++] = 0;
    t[count++] = 1;
    double roots[4], extrema[3];
    std::size_t num_extrema = 0;
    auto num_roots = polynomial_roots(poly, 4, 0, 1, roots, extrema, &num_extrema);
    for (std::size_t i = 0; i < num_roots; ++i)
        t[count++] = scalar(roots[i]);
    // Extrema of the quartic stand in for double roots, which a sign test cannot see. Where F and
    // G vanish together (a segment parallel to the circle's plane passing outside it, say) the
    // quartic has a double root at G = 0.
    for (std::size_t i = 0; i < num_extrema; ++i)
        t[count++] = scalar(extrema[i]);
    if (g1 > 0) t[count++] = scalar(std::clamp(-g0 / g1, 0.0, 1.0));
    if (c1 > 0) t[count++] = scalar(std::clamp(-c0 / c1, 0.0, 1.0));
    EDYN_ASSERT(count <= max_circle_segment_critical);
    // Drop repeats (an extremum at a double root, say): each costs the caller an axis test.
    std::sort(t, t + count);
    std::size_t unique = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (unique == 0 || t[i] - t[unique - 1] > scalar(1e-6)) t[unique++] = t[i];
    }
    return unique;
}

namespace {

// Where the cubic Hermite interpolant of a function on [0, 1] (values f0, f1, derivatives d0, d1
// scaled to the unit interval) changes sign twice inside: writes to `t` its extremum of sign
// opposite to both end values, if there is one.
bool hermite_dip(double f0, double f1, double d0, double d1, double &t) noexcept {
    if ((f0 < 0) != (f1 < 0)) return false;
    // In Hermite form H = f0 h00 + f1 h01 + d0 h10 + d1 h11, where h00 + h01 = 1 with both
    // non-negative and |h10|, |h11| <= 4/27 on [0, 1]: H keeps the end values' sign while the
    // smaller of them outweighs 4/27 (|d0| + |d1|). Most intervals are such, and need no roots;
    // the margin is far above the rounding of the search below, which would find no dip either.
    auto reach = (std::abs(d0) + std::abs(d1)) * (4.0 / 27.0);
    auto low = std::min(std::abs(f0), std::abs(f1));
    if (low - reach > 1e-9 * (low + reach)) return false;
    // H(t) = a t^3 + b t^2 + d0 t + f0.
    auto a = 2 * f0 - 2 * f1 + d0 + d1;
    auto b = -3 * f0 + 3 * f1 - 2 * d0 - d1;
    double roots[2];
    double dh[3] = {d0, 2 * b, 3 * a};
    auto n = polynomial_roots(dh, 2, 0, 1, roots);
    for (std::size_t i = 0; i < n; ++i) {
        auto x = roots[i];
        auto h = ((a * x + b) * x + d0) * x + f0;
        if ((h < 0) != (f0 < 0)) {
            t = x;
            return true;
        }
    }
    return false;
}

// A point of circle A parametrised by angle, and the derivatives of its squared distance to
// circle B along that angle: D = |w|^2 + rb^2 - 2 rb |w_plane| with w = point - ob.
struct circle_pair {
    dvec oa, ua, va, ob, nb;
    double ra, rb;

    dvec point(double c, double s) const noexcept { return oa + (ua * c + va * s) * ra; }

    double distance_sqr(double angle) const noexcept {
        auto w = point(std::cos(angle), std::sin(angle)) - ob;
        auto q = w - nb * dot(w, nb);
        return dot(w, w) + rb * rb - 2 * rb * std::sqrt(dot(q, q));
    }

    // First derivative at the angle whose cosine and sine are c and s; the second when asked.
    double derivative(double c, double s, double *second = nullptr) const noexcept {
        auto w = point(c, s) - ob;
        auto dp = (va * c - ua * s) * ra;
        auto q = w - nb * dot(w, nb);
        auto rho = std::sqrt(dot(q, q));
        auto d = 2 * dot(w, dp);
        // On B's axis every point of B is equally far: a cusp (a maximum), no slope to add.
        auto on_axis = !(rho > 1e-12 * (ra + rb));
        if (!on_axis) d -= 2 * rb * dot(q, dp) / rho;
        if (second) {
            auto ddp = (ua * c + va * s) * -ra;
            auto dq = dp - nb * dot(dp, nb);
            auto dd = 2 * (dot(dp, dp) + dot(w, ddp));
            if (!on_axis) {
                auto qdp = dot(q, dp);
                dd -= 2 * rb * ((dot(dq, dp) + dot(q, ddp)) / rho - qdp * qdp / (rho * rho * rho));
            }
            *second = dd;
        }
        return d;
    }

    // Zero of the derivative in [a, b] where it goes from negative (fa) to positive (fb): Newton
    // on the derivative inside the shrinking bracket, bisecting when a step would leave it.
    double refine(double a, double b, double fa, double fb) const noexcept {
        auto x = a - fa * (b - a) / (fb - fa);
        if (!(x > a && x < b)) x = (a + b) * 0.5;
        for (int iteration = 0; iteration < 40; ++iteration) {
            double second;
            auto f = derivative(std::cos(x), std::sin(x), &second);
            if (f == 0) return x;
            if (f < 0) {
                a = x;
            } else {
                b = x;
            }
            auto next = second > 0 ? x - f / second : (a + b) * 0.5;
            if (!(next > a && next < b)) next = (a + b) * 0.5;
            auto moved = std::abs(next - x);
            x = next;
            if (moved < 1e-9 || b - a < 1e-9) break;
        }
        return x;
    }
};

} // namespace

std::size_t circle_circle_local_minima(const vector3 &center_a, const vector3 &normal_a, scalar radius_a,
                                       const vector3 &center_b, const vector3 &normal_b, scalar radius_b,
                                       vector3 (&on_a)[max_circle_circle_minima],
                                       vector3 (&on_b)[max_circle_circle_minima]) noexcept {
    vector3 ua, va;
    plane_space(normal_a, ua, va);
    // Work relative to A's centre so that large coordinates do not eat the precision.
    circle_pair cp{{0, 0, 0},         to_dvec(ua),      to_dvec(va),     to_dvec(center_b - center_a),
                   to_dvec(normal_b), double(radius_a), double(radius_b)};

    constexpr int samples = 16;
    constexpr double step = 6.283185307179586 / samples;
    // Sample angles by rotating (cos, sin) rather than calling the trigonometric functions.
    const double cos_step = std::cos(step), sin_step = std::sin(step);
    double slope[samples + 1], curvature[samples + 1];
    double c = 1, s = 0;
    for (int k = 0; k < samples; ++k) {
        slope[k] = cp.derivative(c, s, &curvature[k]);
        auto c_next = c * cos_step - s * sin_step;
        s = s * cos_step + c * sin_step;
        c = c_next;
    }
    slope[samples] = slope[0];
    curvature[samples] = curvature[0];

    double angle[2 * samples];
    double dist[2 * samples];
    std::size_t count = 0;
    auto add = [&](double a, double b, double fa, double fb) {
        angle[count] = cp.refine(a, b, fa, fb);
        dist[count] = cp.distance_sqr(angle[count]);
        ++count;
    };
    for (int k = 0; k < samples; ++k) {
        auto a = k * step, b = (k + 1) * step;
        if (slope[k] < 0 && slope[k + 1] >= 0) {
            add(a, b, slope[k], slope[k + 1]);
            continue;
        }
        // A maximum and a minimum closer than the sampling can hide in one interval, the slope
        // dipping below zero and back: look for the dip in the cubic Hermite model of the slope.
        double dip;
        if (!hermite_dip(slope[k], slope[k + 1], curvature[k] * step, curvature[k + 1] * step, dip)) continue;
        auto x = a + dip * step;
        auto fx = cp.derivative(std::cos(x), std::sin(x));
        if (slope[k] >= 0 && fx < 0 && slope[k + 1] >= 0) {
            add(x, b, fx, slope[k + 1]);
        } else if (slope[k] < 0 && fx >= 0) {
            add(a, x, slope[k], fx);
        }
    }
    if (count == 0) {
        // No slope changes sign: the distance is constant (coaxial circles).
        angle[0] = 0;
        dist[0] = 0;
        count = 1;
    }
    // Keep the closest minima (a degree-8 condition has at most four).
    for (std::size_t i = 1; i < count; ++i) {
        for (auto j = i; j > 0 && dist[j - 1] > dist[j]; --j) {
            std::swap(dist[j - 1], dist[j]);
            std::swap(angle[j - 1], angle[j]);
        }
    }
    count = std::min(count, max_circle_circle_minima);
    for (std::size_t i = 0; i < count; ++i) {
        on_a[i] = center_a + to_vector3(cp.point(std::cos(angle[i]), std::sin(angle[i])));
        on_b[i] = closest_point_circle(center_b, normal_b, radius_b, on_a[i]);
    }
    return count;
}

bool clip_segment_sphere(const vector3 &p0, const vector3 &p1, const vector3 &center, scalar radius,
                         scalar &t0, scalar &t1) noexcept {
    auto d = p1 - p0;
    auto w = p0 - center;
    auto a = dot(d, d);
    auto c = dot(w, w) - radius * radius;
    if (a <= epsilon * epsilon) {
        t0 = 0;
        t1 = 0;
        return c <= 0;
    }
    auto b = dot(w, d);
    auto disc = b * b - a * c;
    if (disc < 0) return false;
    auto root = std::sqrt(disc);
    t0 = std::max(scalar(0), (-b - root) / a);
    t1 = std::min(scalar(1), (-b + root) / a);
    return t0 <= t1;
}

contact_feature cylinder_support_feature(const placed_cylinder &cyl, const vector3 &dir) noexcept {
    contact_feature f;
    auto c = dot(dir, cyl.axis);
    auto s = length(dir - cyl.axis * c);
    auto radial = dir;
    if (!try_normalize_across(radial, cyl.axis)) {
        vector3 t1;
        plane_space(cyl.axis, radial, t1);
    }
    unsigned cap = c < 0 ? 1 : 0;
    f.has_id = true;
    f.support = cyl.center + cyl.axis * (c < 0 ? -cyl.half_length : cyl.half_length) + radial * cyl.radius;
    if (std::abs(c) <= feature_tolerance) {
        f.kind = contact_feature_kind::segment;
        f.vertices[0] = cyl.center + cyl.axis * cyl.half_length + radial * cyl.radius;
        f.vertices[1] = cyl.center - cyl.axis * cyl.half_length + radial * cyl.radius;
        f.id = {cylinder_feature::side_edge, 0};
        return f;
    }
    f.center = cylinder_cap_center(cyl, cap);
    f.normal = cyl.axis * cylinder_cap_sign(cap);
    f.radius = cyl.radius;
    f.vertices[0] = f.center + radial * cyl.radius;
    if (s <= feature_tolerance) {
        f.kind = contact_feature_kind::disc;
        f.id = {cylinder_feature::face, cap};
    } else {
        f.kind = contact_feature_kind::rim;
        f.id = {cylinder_feature::cap_edge, cap};
    }
    return f;
}

contact_feature box_support_feature(const vector3 &half_extents, const vector3 &dir) noexcept {
    contact_feature f;
    f.has_id = true;
    f.support = support_point_box(half_extents, dir);
    int across[3];
    int num_across = 0;
    for (int k = 0; k < 3; ++k) {
        if (std::abs(dir[k]) <= feature_tolerance) across[num_across++] = k;
    }
    if (num_across >= 2) {
        auto face = box_support_face(dir);
        vector3 vertices[4];
        box_face_vertices(half_extents, face, vertices);
        f.kind = contact_feature_kind::polygon;
        std::copy(vertices, vertices + 4, f.vertices);
        f.normal = box_face_normal(face);
        f.id = {box_feature::face, face};
    } else if (num_across == 1) {
        auto edge = box_edge_index(across[0], dir);
        f.kind = contact_feature_kind::segment;
        box_edge_vertices(half_extents, edge, f.vertices[0], f.vertices[1]);
        f.id = {box_feature::edge, edge};
    } else {
        f.kind = contact_feature_kind::point;
        f.vertices[0] = support_point_box(half_extents, dir);
        f.id = {box_feature::vertex, box_vertex_index(dir)};
    }
    return f;
}

contact_feature capsule_support_feature(const vector3 &p0, const vector3 &p1, scalar radius,
                                        const vector3 &dir) noexcept {
    contact_feature f;
    f.has_id = true;
    auto axis = p0 - p1;
    auto c = try_normalize(axis) ? dot(dir, axis) : scalar(1); // A point-like capsule: its end.
    f.support = (c < 0 ? p1 : p0) + dir * radius;
    if (std::abs(c) <= feature_tolerance) {
        // The side line, ending at the exact support point on the deeper hemisphere and on the
        // side surface at the other end, so that both ends lie on the capsule.
        auto radial = dir - axis * c;
        if (!try_normalize(radial)) radial = dir;
        f.kind = contact_feature_kind::segment;
        f.vertices[0] = p0 + (c >= 0 ? dir : radial) * radius;
        f.vertices[1] = p1 + (c >= 0 ? radial : dir) * radius;
        f.id = {capsule_feature::side, 0};
    } else {
        f.kind = contact_feature_kind::point;
        f.vertices[0] = (c > 0 ? p0 : p1) + dir * radius;
        f.id = {capsule_feature::hemisphere, c > 0 ? 0u : 1u};
    }
    return f;
}

} // namespace edyn::detail
