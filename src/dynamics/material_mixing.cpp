#include "edyn/dynamics/material_mixing.hpp"
#include "edyn/dynamics/visit_shape.hpp"
#include "edyn/shapes/mesh_shape.hpp"
#include "edyn/shapes/paged_mesh_shape.hpp"
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace edyn {

material_base mix_materials(const material_base &a, const material_base &b) noexcept {
    material_base m;
    m.friction = mix_friction(a.friction, b.friction);
    m.restitution = mix_restitution(a.restitution, b.restitution);
    m.roll_friction = mix_roll_friction(a.roll_friction, b.roll_friction);
    m.spin_friction = mix_spin_friction(a.spin_friction, b.spin_friction);
    m.stiffness = mix_stiffness(a.stiffness, b.stiffness);
    m.damping = mix_damping(a.damping, b.damping);
    return m;
}

const material_base *material_mix_table::find(material_id_type id0, material_id_type id1) const {
    if (id0 > id1) std::swap(id0, id1);
    auto it = pairs.find({id0, id1});
    return it == pairs.end() ? nullptr : &it->second;
}

void insert_material_mixing(registry &registry, material_id_type id0, material_id_type id1,
                            const material_base &mixed) {
    auto fail = [](const std::string &what) {
        throw std::invalid_argument("insert_material_mixing: " + what);
    };
    if (id0 == invalid_material_id || id1 == invalid_material_id)
        fail("material ids must not be invalid_material_id");
    validate_material("insert_material_mixing", "mixed", mixed);
    if (id0 > id1) std::swap(id0, id1);
    registry.ctx().emplace<material_mix_table>().pairs[{id0, id1}] = mixed;
    // Bodies at rest on each other sleep with their contacts: each body with one of the two ids
    // is told that its material changed, which wakes it (and in asynchronous mode sends it).
    std::vector<entity> changed;
    for (auto [e, mat] : registry.view<material>().each()) {
        if (mat.id == id0 || mat.id == id1) changed.push_back(e);
    }
    for (auto e : changed)
        registry.patch<material>(e);
}

material_base get_mixed_material(const registry &registry, const material &a, const material &b) {
    return get_mixed_material(registry.ctx().find<material_mix_table>(), a, b);
}

material_base get_mixed_material(const material_mix_table *table, const material &a, const material &b) {
    if (table && a.id != invalid_material_id && b.id != invalid_material_id) {
        if (auto *mixed = table->find(a.id, b.id)) return *mixed;
    }
    return mix_materials(a, b);
}

namespace {

bool has_coefficients(const triangle_mesh &mesh) {
    return mesh.has_per_vertex_friction() || mesh.has_per_vertex_restitution();
}

// The triangle mesh holding triangle `part` of the body's mesh (a paged mesh's page), and the
// triangle's index in it, when the mesh has per-vertex coefficients.
struct mesh_triangle {
    const triangle_mesh *mesh{nullptr};
    std::size_t triangle{0};
};

mesh_triangle per_vertex_triangle(const mesh_shape &shape, std::int32_t part) {
    if (part < 0 || !shape.trimesh || !has_coefficients(*shape.trimesh) ||
        std::size_t(part) >= shape.trimesh->num_triangles())
        return {};
    return {shape.trimesh.get(), std::size_t(part)};
}

mesh_triangle per_vertex_triangle(const paged_mesh_shape &shape, std::int32_t part) {
    if (part < 0 || !shape.trimesh) return {};
    const auto &paged = *shape.trimesh;
    if (std::size_t(part) >= paged.num_triangles()) return {};
    auto page = paged.page_of_triangle(std::size_t(part));
    const auto *mesh = paged.get_page(page);
    if (!mesh || !has_coefficients(*mesh)) return {};
    return {mesh, std::size_t(part) - paged.first_triangle(page)};
}

// No other shape has per-vertex coefficients.
template<typename Shape>
mesh_triangle per_vertex_triangle(const Shape &, std::int32_t) {
    return {};
}

// The body's material with the mesh's coefficients at `pivot` (object space) on the triangle
// its feature names, where it has them.
material_base at_point(shape_ref shape, const material &base, const std::optional<collision_feature> &feature,
                       const vector3 &pivot) {
    material_base m = base;
    if (!feature) return m;
    auto [mesh, t] = visit_shape(shape, [&](const auto &s) { return per_vertex_triangle(s, feature->part); });
    if (!mesh) return m;
    auto tri = mesh->get_triangle_vertices(t);
    auto w = barycentric_coordinates(pivot, tri[0], tri[1], tri[2]);
    // Clamped onto the triangle: points just outside it take its edge's values.
    w = max(w, vector3_zero);
    auto sum = w.x + w.y + w.z;
    w = sum > 0 ? w / sum : vector3{1, 0, 0};
    if (mesh->has_per_vertex_friction()) m.friction = mesh->get_friction(t, w);
    if (mesh->has_per_vertex_restitution()) m.restitution = std::min(scalar(1), mesh->get_restitution(t, w));
    return m;
}

} // namespace

bool has_point_materials(const mesh_shape &shape) {
    return shape.trimesh && has_coefficients(*shape.trimesh);
}

// A paged mesh's pages tell when they are loaded.
bool has_point_materials(const paged_mesh_shape &) { return true; }

material_base get_point_material(const registry &registry, entity a, entity b, const contact_point &point) {
    return get_point_material(registry.ctx().find<material_mix_table>(), registry.get<material>(a),
                              get_shape_ref(registry, a), registry.get<material>(b),
                              get_shape_ref(registry, b), point);
}

material_base get_point_material(const material_mix_table *table, const material &mat_a, shape_ref shape_a,
                                 const material &mat_b, shape_ref shape_b, const contact_point &point) {
    if (table && mat_a.id != invalid_material_id && mat_b.id != invalid_material_id) {
        if (auto *mixed = table->find(mat_a.id, mat_b.id)) return *mixed;
    }
    auto ma = at_point(shape_a, mat_a, point.featureA, point.pivotA);
    auto mb = at_point(shape_b, mat_b, point.featureB, point.pivotB);
    return mix_materials(ma, mb);
}

} // namespace edyn
