#include "edyn/shapes/moment_of_inertia.hpp"
#include "edyn/math/transform.hpp"
#include "invalid_argument.hpp"
#include <cmath>
#include <limits>

namespace edyn {

namespace {

constexpr matrix3x3 outer(const vector3 &a, const vector3 &b) noexcept {
    return matrix3x3_rows(b * a.x, b * a.y, b * a.z);
}

constexpr scalar trace(const matrix3x3 &m) noexcept { return m[0][0] + m[1][1] + m[2][2]; }

// Diagonal inertia with `axial` about coordinate axis `axis` and `transverse` about the others.
matrix3x3 axial_inertia(coordinate_axis axis, scalar axial, scalar transverse) {
    auto d = vector3{transverse, transverse, transverse};
    d[coordinate_axis_index(axis)] = axial;
    return diagonal_matrix(d);
}

// Volume integrals of a polyhedron: the fan of every face and a reference point make signed
// tetrahedra. For the tetrahedron (0, a, b, c) with det = a . (b x c), the volume is det / 6,
// the first moment det (a + b + c) / 24 and the second moment
// integral of x x^T = det / 120 (S S^T + a a^T + b b^T + c c^T), S = a + b + c.
struct polyhedron_integrals {
    scalar volume;
    // Centroid, and second moment about the centroid (unit density).
    vector3 centroid;
    matrix3x3 second_moment;
};

polyhedron_integrals integrate(const convex_mesh &mesh) {
    // The vertex average as reference keeps the products small.
    auto ref = vector3_zero;
    for (const auto &v : mesh.vertices)
        ref += v;
    ref /= scalar(mesh.vertices.size());

    scalar six_volume = 0;
    auto first = vector3_zero;
    auto second = matrix3x3_zero;
    for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
        auto a = mesh.face_vertex(f, 0) - ref;
        for (std::size_t i = 1; i + 1 < mesh.faces[f].count; ++i) {
            auto b = mesh.face_vertex(f, i) - ref;
            auto c = mesh.face_vertex(f, i + 1) - ref;
            auto det = dot(a, cross(b, c));
            auto s = a + b + c;
            six_volume += det;
            first += s * det;
            second += (outer(s, s) + outer(a, a) + outer(b, b) + outer(c, c)) * det;
        }
    }
    polyhedron_integrals result;
    result.volume = six_volume / 6;
    auto centroid = first / (4 * six_volume);
    // Second moment about the reference, moved to the centroid.
    result.second_moment = second * (scalar(1) / 120) - outer(centroid, centroid) * result.volume;
    result.centroid = ref + centroid;
    return result;
}

// Inertia of a body with second moment `second` (mass-weighted integral of x x^T).
matrix3x3 inertia_from_second_moment(const matrix3x3 &second) {
    return matrix3x3_identity * trace(second) - second;
}

// A dimension (radius, half length, half extent) of a primitive solid.
void validate_dimension(scalar value, const char *function, const char *name) {
    if (!detail::positive_finite(value)) {
        detail::throw_invalid_argument(function, ": ", name, " must be positive and finite, got ", value);
    }
}

} // namespace

void validate_mass(scalar mass, const char *function) {
    if (!detail::positive_finite(mass)) {
        detail::throw_invalid_argument(function, ": mass must be positive and finite, got ", mass);
    }
}

matrix3x3 moment_of_inertia_solid_sphere(scalar mass, scalar radius) {
    validate_mass(mass, "moment_of_inertia_solid_sphere");
    validate_dimension(radius, "moment_of_inertia_solid_sphere", "radius");
    auto s = scalar(0.4) * mass * radius * radius;
    return diagonal_matrix({s, s, s});
}

matrix3x3 moment_of_inertia_solid_box(scalar mass, const vector3 &half_extents) {
    validate_mass(mass, "moment_of_inertia_solid_box");
    validate_dimension(half_extents.x, "moment_of_inertia_solid_box", "half_extents.x");
    validate_dimension(half_extents.y, "moment_of_inertia_solid_box", "half_extents.y");
    validate_dimension(half_extents.z, "moment_of_inertia_solid_box", "half_extents.z");
    // m/12 (b^2 + c^2) with full sides b = 2 h_y, c = 2 h_z.
    auto sq = half_extents * half_extents;
    return diagonal_matrix(vector3{sq.y + sq.z, sq.x + sq.z, sq.x + sq.y} * (mass / 3));
}

matrix3x3 moment_of_inertia_solid_cylinder(scalar mass, scalar radius, scalar half_length,
                                           coordinate_axis axis) {
    validate_mass(mass, "moment_of_inertia_solid_cylinder");
    validate_dimension(radius, "moment_of_inertia_solid_cylinder", "radius");
    validate_dimension(half_length, "moment_of_inertia_solid_cylinder", "half_length");
    auto r2 = radius * radius;
    auto h2 = half_length * half_length;
    return axial_inertia(axis, mass * r2 / 2, mass * (3 * r2 + 4 * h2) / 12);
}

matrix3x3 moment_of_inertia_solid_capsule(scalar mass, scalar radius, scalar half_length,
                                          coordinate_axis axis) {
    validate_mass(mass, "moment_of_inertia_solid_capsule");
    validate_dimension(radius, "moment_of_inertia_solid_capsule", "radius");
    validate_dimension(half_length, "moment_of_inertia_solid_capsule", "half_length");
    auto r = radius, h = half_length;
    auto cylinder_volume = pi * r * r * 2 * h;
    auto sphere_volume = scalar(4) / 3 * pi * r * r * r;
    auto cylinder_mass = mass * cylinder_volume / (cylinder_volume + sphere_volume);
    auto sphere_mass = mass - cylinder_mass;
    auto axial = cylinder_mass * r * r / 2 + sphere_mass * scalar(0.4) * r * r;
    // Each hemisphere: 2/5 M r^2 about its flat face's centre, moved to its centroid (3r/8 from
    // the face) and then to the capsule's centre (h + 3r/8 away), which sums to
    // M (2/5 r^2 + h^2 + 3/4 h r).
    auto transverse = cylinder_mass * (3 * r * r + 4 * h * h) / 12 +
                      sphere_mass * (scalar(0.4) * r * r + h * h + scalar(0.75) * h * r);
    return axial_inertia(axis, axial, transverse);
}

scalar shape_volume(const plane_shape &) { return std::numeric_limits<scalar>::infinity(); }

scalar shape_volume(const mesh_shape &) { return std::numeric_limits<scalar>::infinity(); }

scalar shape_volume(const paged_mesh_shape &) { return std::numeric_limits<scalar>::infinity(); }
scalar shape_volume(const sphere_shape &s) { return scalar(4) / 3 * pi * s.radius * s.radius * s.radius; }
scalar shape_volume(const box_shape &s) { return 8 * s.half_extents.x * s.half_extents.y * s.half_extents.z; }
scalar shape_volume(const cylinder_shape &s) { return pi * s.radius * s.radius * 2 * s.half_length; }

scalar shape_volume(const capsule_shape &s) {
    return pi * s.radius * s.radius * (2 * s.half_length + scalar(4) / 3 * s.radius);
}

scalar shape_volume(const polyhedron_shape &s) {
    EDYN_ASSERT(s.mesh);
    return integrate(*s.mesh).volume;
}

scalar shape_volume(const compound_shape &s) {
    scalar volume = 0;
    for (const auto &child : s.children)
        volume += shape_volume(child.shape);
    return volume;
}

scalar shape_volume(const compound_child_shape_t &s) {
    return std::visit([](const auto &shape) { return shape_volume(shape); }, s);
}

vector3 shape_centroid(const plane_shape &) { return vector3_zero; }

vector3 shape_centroid(const mesh_shape &) { return vector3_zero; }

vector3 shape_centroid(const paged_mesh_shape &) { return vector3_zero; }
vector3 shape_centroid(const sphere_shape &) { return vector3_zero; }
vector3 shape_centroid(const box_shape &) { return vector3_zero; }
vector3 shape_centroid(const cylinder_shape &) { return vector3_zero; }
vector3 shape_centroid(const capsule_shape &) { return vector3_zero; }

vector3 shape_centroid(const polyhedron_shape &s) {
    EDYN_ASSERT(s.mesh);
    return integrate(*s.mesh).centroid;
}

vector3 shape_centroid(const compound_shape &s) {
    scalar volume = 0;
    auto weighted = vector3_zero;
    for (const auto &child : s.children) {
        auto v = shape_volume(child.shape);
        volume += v;
        weighted += to_world_space(shape_centroid(child.shape), child.position, child.orientation) * v;
    }
    EDYN_ASSERT(volume > 0);
    return weighted / volume;
}

vector3 shape_centroid(const compound_child_shape_t &s) {
    return std::visit([](const auto &shape) { return shape_centroid(shape); }, s);
}

matrix3x3 moment_of_inertia(const sphere_shape &s, scalar mass) {
    validate_mass(mass);
    return moment_of_inertia_solid_sphere(mass, s.radius);
}

matrix3x3 moment_of_inertia(const box_shape &s, scalar mass) {
    validate_mass(mass);
    return moment_of_inertia_solid_box(mass, s.half_extents);
}

matrix3x3 moment_of_inertia(const cylinder_shape &s, scalar mass) {
    validate_mass(mass);
    return moment_of_inertia_solid_cylinder(mass, s.radius, s.half_length, s.axis);
}

matrix3x3 moment_of_inertia(const capsule_shape &s, scalar mass) {
    validate_mass(mass);
    return moment_of_inertia_solid_capsule(mass, s.radius, s.half_length, s.axis);
}

matrix3x3 moment_of_inertia(const polyhedron_shape &s, scalar mass) {
    validate_mass(mass);
    EDYN_ASSERT(s.mesh);
    auto integrals = integrate(*s.mesh);
    return inertia_from_second_moment(integrals.second_moment * (mass / integrals.volume));
}

matrix3x3 moment_of_inertia(const compound_shape &s, scalar mass) {
    validate_mass(mass);
    auto volume = shape_volume(s);
    auto centroid = shape_centroid(s);
    auto inertia = matrix3x3_zero;
    for (const auto &child : s.children) {
        auto child_mass = mass * shape_volume(child.shape) / volume;
        auto basis = to_matrix3x3(child.orientation);
        auto local = moment_of_inertia(child.shape, child_mass);
        auto child_centroid = to_world_space(shape_centroid(child.shape), child.position, child.orientation);
        inertia +=
            shift_moment_of_inertia(basis * local * transpose(basis), child_mass, child_centroid - centroid);
    }
    return inertia;
}

matrix3x3 moment_of_inertia(const compound_child_shape_t &s, scalar mass) {
    return std::visit([mass](const auto &shape) { return moment_of_inertia(shape, mass); }, s);
}

matrix3x3 shift_moment_of_inertia(const matrix3x3 &inertia, scalar mass, const vector3 &offset) {
    if (!(mass >= 0) || !std::isfinite(mass)) {
        detail::throw_invalid_argument("shift_moment_of_inertia: mass must be finite and not negative, got ",
                                       mass);
    }
    if (!isfinite(offset)) {
        detail::throw_invalid_argument("shift_moment_of_inertia: offset must be finite, got ", offset);
    }
    return inertia + (matrix3x3_identity * length_sqr(offset) - outer(offset, offset)) * mass;
}

} // namespace edyn
