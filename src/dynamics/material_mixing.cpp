#include "edyn/dynamics/material_mixing.hpp"
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

} // namespace edyn
