#include "edyn/util/ragdoll.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/shapes/moment_of_inertia.hpp"
#include "ragdoll_joints.hpp"
#include "ragdoll_layout.hpp"
#include "ragdoll_sides.hpp"
#include "ragdoll_validate.hpp"
#include <exception>
#include <vector>

namespace edyn {

std::array<entity, ragdoll_entities::num_bodies> ragdoll_entities::bodies() const noexcept {
    return {head,           neck,
            torso_upper,    torso_lower,
            shoulder_left,  shoulder_right,
            arm_upper_left, arm_upper_right,
            arm_lower_left, arm_lower_right,
            arm_twist_left, arm_twist_right,
            hand_left,      hand_right,
            leg_upper_left, leg_upper_right,
            leg_lower_left, leg_lower_right,
            foot_left,      foot_right};
}

std::array<entity, ragdoll_entities::num_constraints> ragdoll_entities::constraints() const noexcept {
    return {spine_cvjoint,         spine_cone,
            neck_cvjoint,          neck_cone,
            head_cvjoint,          head_cone,
            clavicle_cvjoint_left, clavicle_cvjoint_right,
            clavicle_cone_left,    clavicle_cone_right,
            shoulder_cvjoint_left, shoulder_cvjoint_right,
            shoulder_cone_left,    shoulder_cone_right,
            elbow_hinge_left,      elbow_hinge_right,
            arm_twist_hinge_left,  arm_twist_hinge_right,
            wrist_cvjoint_left,    wrist_cvjoint_right,
            wrist_cone_left,       wrist_cone_right,
            hip_cvjoint_left,      hip_cvjoint_right,
            hip_cone_left,         hip_cone_right,
            knee_hinge_left,       knee_hinge_right,
            ankle_cvjoint_left,    ankle_cvjoint_right,
            ankle_cone_left,       ankle_cone_right};
}

namespace {

// One body part to create: where its entity goes, and its definition.
struct ragdoll_part {
    entity *slot;
    rigidbody_def def;
};

capsule_shape limb_capsule(const vector3 &size, coordinate_axis axis) {
    auto radius = detail::ragdoll_capsule_radius(size);
    return {radius, size.x / 2 - radius, axis};
}

class part_list {
public:
    part_list(const ragdoll_def &def)
        : m_def(def) {}

    void add(entity &slot, const vector3 &centre, shapes_variant_t shape, scalar mass) {
        auto body = base(centre, mass);
        body.shape = shape;
        m_parts.push_back({&slot, body});
    }

    // An amorphous part. Its inertia is that of a solid sphere as wide as the part is long,
    // not that of a slender bone: about its own axis a bone's would be so small, next to its
    // neighbours', that the joints turning it (twist limits on both sides) would barely converge.
    void add_amorphous(entity &slot, const vector3 &centre, const vector3 &size, scalar mass) {
        auto body = base(centre, mass);
        body.inertia = moment_of_inertia_solid_sphere(mass, max_component(size) / 2);
        m_parts.push_back({&slot, body});
    }

    std::vector<ragdoll_part> &parts() noexcept { return m_parts; }

private:
    rigidbody_def base(const vector3 &centre, scalar mass) const {
        rigidbody_def body;
        body.mass = mass;
        body.position = m_def.position + rotate(m_def.orientation, centre);
        body.orientation = m_def.orientation;
        body.material->friction = m_def.friction;
        body.material->restitution = m_def.restitution;
        body.collision_group = m_def.collision_group;
        body.collision_mask = m_def.collision_mask;
        body.sleeping_disabled = m_def.sleeping_disabled;
        return body;
    }

    const ragdoll_def &m_def;
    std::vector<ragdoll_part> m_parts;
};

void add_side(part_list &list, const ragdoll_def &def, const detail::ragdoll_side_layout &s,
              ragdoll_entities &e, const detail::ragdoll_side_members &p) {
    list.add_amorphous(e.*p.shoulder, s.shoulder, def.shoulder_size, def.shoulder_mass);
    list.add(e.*p.arm_upper, s.arm_upper, limb_capsule(def.arm_upper_size, coordinate_axis::x),
             def.arm_upper_mass);
    list.add(e.*p.arm_lower, s.arm_lower, limb_capsule(def.arm_lower_size, coordinate_axis::x),
             def.arm_lower_mass);
    list.add_amorphous(e.*p.arm_twist, s.arm_lower, def.arm_twist_size, def.arm_twist_mass);
    // Palm down: the hand's breadth runs front to back, its thickness up and down.
    const auto &h = def.hand_size;
    list.add(e.*p.hand, s.hand, box_shape{vector3{h.x, h.z, h.y} / 2}, def.hand_mass);
    list.add(e.*p.leg_upper, s.leg_upper, limb_capsule(def.leg_upper_size, coordinate_axis::y),
             def.leg_upper_mass);
    list.add(e.*p.leg_lower, s.leg_lower, limb_capsule(def.leg_lower_size, coordinate_axis::y),
             def.leg_lower_mass);
    const auto &f = def.foot_size;
    list.add(e.*p.foot, s.foot, box_shape{vector3{f.y, f.z, f.x} / 2}, def.foot_mass);
}

std::vector<ragdoll_part> make_parts(const ragdoll_def &def, const detail::ragdoll_layout &l,
                                     ragdoll_entities &e) {
    part_list list(def);
    list.add(e.head, l.head, limb_capsule(def.head_size, coordinate_axis::y), def.head_mass);
    list.add(e.neck, l.neck, limb_capsule(def.neck_size, coordinate_axis::y), def.neck_mass);
    const auto &tu = def.torso_upper_size, &tl = def.torso_lower_size;
    list.add(e.torso_upper, l.torso_upper, box_shape{vector3{tu.y, tu.x, tu.z} / 2}, def.torso_upper_mass);
    list.add(e.torso_lower, l.torso_lower, box_shape{vector3{tl.y, tl.x, tl.z} / 2}, def.torso_lower_mass);
    for (int side : {0, 1})
        add_side(list, def, l.side[side], e, detail::ragdoll_sides[side]);
    return std::move(list.parts());
}

} // namespace

ragdoll_entities make_ragdoll(registry &registry, const ragdoll_def &def) {
    detail::validate_ragdoll_def("make_ragdoll", def);
    auto layout = detail::make_ragdoll_layout(def);
    ragdoll_entities entities;
    auto parts = make_parts(def, layout, entities);
    // Every body is checked before the first is made, so that a bad one leaves nothing behind.
    for (auto &part : parts)
        validate_rigidbody_def(part.def);

    std::vector<entity> created;
    try {
        for (auto &part : parts) {
            *part.slot = make_rigidbody(registry, part.def);
            created.push_back(*part.slot);
        }
        detail::make_ragdoll_joints(registry, def, layout, entities, created);
    } catch (...) {
        // A body takes its constraints with it: some may be gone already.
        for (auto it = created.rbegin(); it != created.rend(); ++it) {
            if (registry.valid(*it)) registry.destroy(*it);
        }
        throw;
    }
    return entities;
}

ragdoll_entities make_ragdoll(registry &registry, const ragdoll_simple_def &def) {
    detail::validate_ragdoll_def("make_ragdoll", def);
    return make_ragdoll(registry, make_ragdoll_def_from_simple(def));
}

} // namespace edyn
