#include "picking.hpp"

namespace testbed {

ray_hit cast_ray(const edyn::registry &registry, const ray &r, edyn::scalar length) {
    auto p1 = r.origin + r.direction * length;
    auto result = edyn::raycast(registry, r.origin, p1);
    ray_hit hit;
    if (!result.hit()) return hit;
    hit.body = result.entity;
    hit.point = edyn::lerp(r.origin, p1, result.fraction);
    hit.normal = result.normal;
    return hit;
}

bool body_dragger::grab(edyn::registry &registry, const ray &r) {
    release(registry);
    auto hit = cast_ray(registry, r);
    if (hit.body == edyn::null || !registry.all_of<edyn::dynamic_tag>(hit.body)) return false;
    grabbed = hit.body;
    distance = edyn::dot(hit.point - r.origin, r.direction);
    auto &pos = registry.get<edyn::position>(grabbed);
    auto &orn = registry.get<edyn::orientation>(grabbed);
    local_point = edyn::rotate(edyn::conjugate(orn), hit.point - pos);

    edyn::rigidbody_def def;
    def.kind = edyn::rigidbody_kind::rb_kinematic;
    def.position = hit.point;
    def.material.reset();
    anchor = edyn::make_rigidbody(registry, def);
    // Stiff enough to lift the body at about 3 Hz, damped near critically.
    auto mass = registry.get<edyn::mass>(grabbed).s;
    spring = edyn::make_constraint<edyn::soft_distance_constraint>(registry, anchor, grabbed,
                                                                   [&](edyn::soft_distance_constraint &c) {
                                                                       c.pivot[1] = local_point;
                                                                       c.distance = 0;
                                                                       c.stiffness = mass * 400;
                                                                       c.damping = mass * 30;
                                                                   });
    edyn::wake_up_entity(registry, grabbed);
    return true;
}

void body_dragger::drag(edyn::registry &registry, const ray &r) {
    if (!dragging()) return;
    if (!registry.valid(grabbed)) {
        release(registry);
        return;
    }
    auto target = r.origin + r.direction * distance;
    registry.get<edyn::position>(anchor) = target;
    registry.patch<edyn::position>(anchor);
    edyn::wake_up_entity(registry, grabbed);
}

void body_dragger::release(edyn::registry &registry) {
    if (spring != edyn::null && registry.valid(spring)) registry.destroy(spring);
    if (anchor != edyn::null && registry.valid(anchor)) registry.destroy(anchor);
    spring = anchor = grabbed = edyn::null;
}

edyn::vector3 body_dragger::anchor_position(const edyn::registry &registry) const {
    return registry.get<edyn::position>(anchor);
}

edyn::vector3 body_dragger::grab_point(const edyn::registry &registry) const {
    auto &pos = registry.get<edyn::present_position>(grabbed);
    auto &orn = registry.get<edyn::present_orientation>(grabbed);
    return pos + edyn::rotate(orn, local_point);
}

edyn::entity shoot_ball(edyn::registry &registry, const ray &r, edyn::scalar speed) {
    edyn::rigidbody_def def;
    def.mass = 2;
    def.shape = edyn::sphere_shape{edyn::scalar(0.25)};
    def.position = r.origin + r.direction * edyn::scalar(0.5);
    def.linvel = r.direction * speed;
    return edyn::make_rigidbody(registry, def);
}

} // namespace testbed
