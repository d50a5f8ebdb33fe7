#include "shape_meshes.hpp"
#include <cmath>
#include <numbers>

namespace testbed {

namespace {

mesh_vertex vertex(const edyn::vector3 &p, const edyn::vector3 &n) {
    return {float(p.x), float(p.y), float(p.z), float(n.x), float(n.y), float(n.z)};
}

void add_flat_triangle(std::vector<mesh_vertex> &out, const edyn::vector3 &a, const edyn::vector3 &b,
                       const edyn::vector3 &c) {
    auto n = edyn::cross(b - a, c - a);
    auto len = edyn::length(n);
    if (len <= 0) return;
    n /= len;
    out.push_back(vertex(a, n));
    out.push_back(vertex(b, n));
    out.push_back(vertex(c, n));
}

} // namespace

std::vector<mesh_vertex> make_box_mesh() {
    std::vector<mesh_vertex> out;
    for (int axis = 0; axis < 3; ++axis) {
        for (int sign : {-1, 1}) {
            edyn::vector3 n{0, 0, 0};
            n[axis] = edyn::scalar(sign);
            edyn::vector3 u{0, 0, 0}, v{0, 0, 0};
            u[(axis + 1) % 3] = 1;
            v[(axis + 2) % 3] = 1;
            if (sign < 0) std::swap(u, v);
            auto c00 = n - u - v, c10 = n + u - v, c11 = n + u + v, c01 = n - u + v;
            add_flat_triangle(out, c00, c10, c11);
            add_flat_triangle(out, c00, c11, c01);
        }
    }
    return out;
}

std::vector<mesh_vertex> make_sphere_mesh(int rings, int segments) {
    std::vector<mesh_vertex> out;
    auto point = [&](int ring, int seg) {
        double theta = std::numbers::pi * ring / rings;
        double phi = 2 * std::numbers::pi * seg / segments;
        return edyn::vector3{edyn::scalar(std::sin(theta) * std::cos(phi)), edyn::scalar(std::cos(theta)),
                             edyn::scalar(std::sin(theta) * std::sin(phi))};
    };
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            auto a = point(r, s), b = point(r + 1, s), c = point(r + 1, s + 1), d = point(r, s + 1);
            // Smooth normals: on a unit sphere the normal is the position.
            for (auto p : {a, c, b, a, d, c})
                out.push_back(vertex(p, p));
        }
    }
    return out;
}

std::vector<mesh_vertex> make_cylinder_mesh(int segments) {
    std::vector<mesh_vertex> out;
    auto rim = [&](int s) {
        double phi = 2 * std::numbers::pi * s / segments;
        return edyn::vector3{0, edyn::scalar(std::cos(phi)), edyn::scalar(std::sin(phi))};
    };
    for (int s = 0; s < segments; ++s) {
        auto r0 = rim(s), r1 = rim(s + 1);
        edyn::vector3 x{1, 0, 0};
        auto a0 = r0 - x, a1 = r1 - x, b0 = r0 + x, b1 = r1 + x;
        for (auto [p, n] : {std::pair{a0, r0}, {b1, r1}, {b0, r0}, {a0, r0}, {a1, r1}, {b1, r1}})
            out.push_back(vertex(p, n));
        add_flat_triangle(out, x, b0, b1);
        add_flat_triangle(out, -x, a1, a0);
    }
    return out;
}

std::vector<mesh_vertex> make_quad_mesh() {
    std::vector<mesh_vertex> out;
    add_flat_triangle(out, {-1, 0, -1}, {-1, 0, 1}, {1, 0, 1});
    add_flat_triangle(out, {-1, 0, -1}, {1, 0, 1}, {1, 0, -1});
    return out;
}

std::vector<mesh_vertex> make_polyhedron_mesh(const edyn::convex_mesh &mesh) {
    std::vector<mesh_vertex> out;
    for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
        auto count = mesh.faces[f].count;
        for (std::size_t i = 1; i + 1 < count; ++i)
            add_flat_triangle(out, mesh.face_vertex(f, 0), mesh.face_vertex(f, i),
                              mesh.face_vertex(f, i + 1));
    }
    return out;
}

std::vector<mesh_vertex> make_triangle_mesh(const edyn::triangle_mesh &mesh) {
    std::vector<mesh_vertex> out;
    out.reserve(mesh.num_triangles() * 3);
    for (std::size_t t = 0; t < mesh.num_triangles(); ++t) {
        auto v = mesh.get_triangle_vertices(t);
        add_flat_triangle(out, v[0], v[1], v[2]);
    }
    return out;
}

} // namespace testbed
