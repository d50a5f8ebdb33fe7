#include "edyn/dynamics/material_mixing.hpp"
#include "edyn/shapes/mesh_shape.hpp"
#include <algorithm>
#include <stdexcept>
#include <string>

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
    if (!(mixed.friction >= 0) || !std::isfinite(mixed.friction))
        fail("friction must be in [0, inf), got " + std::to_string(mixed.friction));
    if (!(mixed.restitution >= 0 && mixed.restitution <= 1))
        fail("restitution must be in [0, 1], got " + std::to_string(mixed.restitution));
    if (!(mixed.roll_friction >= 0))
        fail("roll_friction must be non-negative, got " + std::to_string(mixed.roll_friction));
    if (!(mixed.spin_friction >= 0))
        fail("spin_friction must be non-negative, got " + std::to_string(mixed.spin_friction));
    if (id0 > id1) std::swap(id0, id1);
    registry.ctx().emplace<material_mix_table>().pairs[{id0, id1}] = mixed;
}

material_base get_mixed_material(const registry &registry, const material &a, const material &b) {
    if (a.id != invalid_material_id && b.id != invalid_material_id) {
        if (auto *table = registry.ctx().find<material_mix_table>()) {
            if (auto *mixed = table->find(a.id, b.id)) return *mixed;
        }
    }
    return mix_materials(a, b);
}

namespace {

const triangle_mesh *per_vertex_mesh(const registry &registry, entity e) {
    auto *shape = registry.try_get<mesh_shape>(e);
    if (!shape || !shape->trimesh) return nullptr;
    const auto &mesh = *shape->trimesh;
    return mesh.has_per_vertex_friction() || mesh.has_per_vertex_restitution() ? &mesh : nullptr;
}

// The body's material with the mesh's coefficients at `pivot` (object space) on the triangle
// its feature names, where it has them.
material_base at_point(const material &base, const triangle_mesh *mesh,
                       const std::optional<collision_feature> &feature, const vector3 &pivot) {
    material_base m = base;
    if (!mesh || !feature || feature->part < 0 || std::size_t(feature->part) >= mesh->num_triangles())
        return m;
    auto t = std::size_t(feature->part);
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

bool has_per_vertex_material(const registry &registry, entity a, entity b) {
    return per_vertex_mesh(registry, a) || per_vertex_mesh(registry, b);
}

material_base get_point_material(const registry &registry, entity a, entity b, const contact_point &point) {
    const auto &mat_a = registry.get<material>(a);
    const auto &mat_b = registry.get<material>(b);
    if (mat_a.id != invalid_material_id && mat_b.id != invalid_material_id) {
        if (auto *table = registry.ctx().find<material_mix_table>()) {
            if (auto *mixed = table->find(mat_a.id, mat_b.id)) return *mixed;
        }
    }
    auto ma = at_point(mat_a, per_vertex_mesh(registry, a), point.featureA, point.pivotA);
    auto mb = at_point(mat_b, per_vertex_mesh(registry, b), point.featureB, point.pivotB);
    return mix_materials(ma, mb);
}

} // namespace edyn
