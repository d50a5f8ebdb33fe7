#include "edyn/constraints/constraint_base.hpp"
#include "../shapes/invalid_argument.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/math/transform.hpp"
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace edyn {

namespace {

using detail::concat;

} // namespace

void throw_constraint_error(const char *type, const char *field, const std::string &what) {
    throw std::invalid_argument(std::string("make_constraint<") + type + ">: " + field + " " + what);
}

void check_constraint_finite(const char *type, const char *field, const vector3 &v) {
    if (!isfinite(v)) throw_constraint_error(type, field, "must be finite, got " + concat(v));
}

void check_constraint_finite(const char *type, const char *field, scalar s) {
    if (!std::isfinite(s)) throw_constraint_error(type, field, "must be finite, got " + concat(s));
}

void check_constraint_non_negative(const char *type, const char *field, scalar s) {
    if (!(s >= 0) || !std::isfinite(s)) {
        throw_constraint_error(type, field, "must be finite and not negative, got " + concat(s));
    }
}

void check_constraint_unit_interval(const char *type, const char *field, scalar s) {
    if (!(s >= 0 && s <= 1)) throw_constraint_error(type, field, "must be in [0, 1], got " + concat(s));
}

void check_constraint_orthonormal(const char *type, const char *field, const matrix3x3 &m) {
    constexpr auto tolerance = scalar(1e-3);
    auto c0 = m.column(0), c1 = m.column(1), c2 = m.column(2);
    auto unit = [&](const vector3 &v) { return std::abs(length_sqr(v) - 1) < tolerance; };
    bool ok = isfinite(c0) && isfinite(c1) && isfinite(c2) && unit(c0) && unit(c1) && unit(c2) &&
              std::abs(dot(c0, c1)) < tolerance && std::abs(dot(c0, c2)) < tolerance &&
              std::abs(dot(c1, c2)) < tolerance;
    if (!ok) {
        throw_constraint_error(type, field,
                               "must be an orthonormal basis, got columns " + concat(c0) + ", " + concat(c1) +
                                   ", " + concat(c2));
    }
}

void check_constraint_range(const char *type, const char *min_field, scalar min, const char *max_field,
                            scalar max) {
    check_constraint_finite(type, min_field, min);
    check_constraint_finite(type, max_field, max);
    if (min > max) {
        throw_constraint_error(type, min_field,
                               "must not exceed " + std::string(max_field) + ", got " + concat(min) + " > " +
                                   concat(max));
    }
}

joint_anchor make_joint_anchor(const registry &registry, const entity (&body)[2], const vector3 (&pivot)[2],
                               constraint_body_indices indices) {
    joint_anchor anchor;
    anchor.body[0] = indices.a;
    anchor.body[1] = indices.b;
    vector3 world_pivot[2];
    vector3 r[2];
    for (int i = 0; i < 2; ++i) {
        auto &pos = registry.get<position>(body[i]);
        auto &orn = registry.get<orientation>(body[i]);
        auto origin = rigidbody_origin(pos, orn, registry.try_get<center_of_mass>(body[i]));
        world_pivot[i] = to_world_space(pivot[i], origin, orn);
        r[i] = world_pivot[i] - pos;
    }
    anchor.rA = r[0];
    anchor.rB = r[1];
    anchor.separation = world_pivot[0] - world_pivot[1];
    return anchor;
}

void check_joint_axis(const char *function, const char *name, const vector3 &axis) {
    if (!isfinite(axis) || !(length_sqr(axis) >= scalar(1e-12))) {
        throw std::invalid_argument(std::string(function) + ": " + name +
                                    " must be finite and not zero, got " + concat(axis));
    }
}

matrix3x3 frame_from_axis(const vector3 &axis) {
    vector3 p, q;
    auto a = normalize(axis);
    plane_space(a, p, q);
    return matrix3x3_columns(a, p, q);
}

matrix3x3 world_frame(const registry &registry, entity body, const matrix3x3 &frame) {
    return to_matrix3x3(registry.get<orientation>(body)) * frame;
}

} // namespace edyn
