#include "picking.hpp"

namespace testbed {

namespace {

ray_hit to_hit(const edyn::raycast_result &result, edyn::vector3 p0, edyn::vector3 p1) {
    ray_hit hit;
    if (!result.hit()) return hit;
    hit.body = result.entity;
    hit.point = edyn::lerp(p0, p1, result.fraction);
    hit.normal = result.normal;
    return hit;
}

} // namespace

void ray_probe::cast(edyn::registry &registry, const ray &r, edyn::scalar length) {
    edyn::raycast_delegate_type delegate;
    delegate.connect<&ray_probe::on_result>(*this);
    edyn::raycast_async(registry, r.origin, r.origin + r.direction * length, delegate);
}

void ray_probe::on_result(edyn::raycast_id_type, const edyn::raycast_result &result, edyn::vector3 p0,
                          edyn::vector3 p1) {
    last = to_hit(result, p0, p1);
}

void body_dragger::grab(edyn::registry &registry, const ray &r) {
    release(registry);
    edyn::raycast_delegate_type delegate;
    delegate.connect<&body_dragger::on_result>(*this);
    pending_ray = r;
    waiting_for =
        edyn::raycast_async(registry, r.origin, r.origin + r.direction * edyn::scalar(500), delegate);
}

void body_dragger::on_result(edyn::raycast_id_type id, const edyn::raycast_result &result, edyn::vector3 p0,
                             edyn::vector3 p1) {
    // A hit for a grab released (or replaced) since is dropped.
    if (waiting_for != id) return;
    waiting_for.reset();
    pending_hit = to_hit(result, p0, p1);
}

void body_dragger::poll(edyn::registry &registry) {
    if (!pending_hit) return;
    auto hit = *pending_hit;
    auto r = *pending_ray;
    pending_hit.reset();
    pending_ray.reset();
    // The body may have gone since the ray was cast (asynchronous mode: a frame or two ago).
    if (hit.body == edyn::null || !registry.valid(hit.body) || !registry.all_of<edyn::dynamic_tag>(hit.body))
        return;
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
    forget();
}

void body_dragger::forget() {
    spring = anchor = grabbed = edyn::null;
    waiting_for.reset();
    pending_ray.reset();
    pending_hit.reset();
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
