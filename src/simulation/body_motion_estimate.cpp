#include "edyn/simulation/body_motion_estimate.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/dynamics/visit_shape.hpp"
#include "edyn/shapes/shape_bounding_radius.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

bool estimate_body_motion(const settings &settings, const registry &registry, entity e, const AABB &aabb,
                          proxy_motion_estimate &estimate) {
    if (!registry.all_of<dynamic_tag>(e)) return false;
    auto *lv = registry.try_get<linvel>(e);
    auto *av = registry.try_get<angvel>(e);
    auto *centre = registry.try_get<position>(e); // of mass
    auto *orn = registry.try_get<orientation>(e);
    if (lv == nullptr || av == nullptr || centre == nullptr || orn == nullptr) return false;
    if (!std::isfinite(length_sqr(*lv)) || !std::isfinite(length_sqr(*av))) return false;

    auto dt = settings.fixed_dt;
    // How far the shape reaches from the centre of mass: the smaller of two bounds, the sphere
    // about the shape's origin that holds it and the AABB's half diagonal, each plus the
    // centre's offset from the sphere's or the box's centre.
    auto radius = visit_shape(registry, e, [](const auto &shape) { return shape_bounding_radius(shape); });
    auto origin = rigidbody_origin(*centre, *orn, registry.try_get<center_of_mass>(e));
    auto by_sphere = radius + distance(origin, *centre);
    auto by_aabb = length(aabb_half_extents(aabb)) + distance(aabb_center(aabb), *centre);
    auto arm = std::min(by_sphere, by_aabb);
    // A turn by an angle moves no point farther than the angle times the arm, and keeps the shape
    // inside the sphere of radius `arm` about the centre: no side of the AABB moves out past it.
    auto nearest_side = std::min(min_component(aabb.max - *centre), min_component(*centre - aabb.min));
    auto reach = std::min(length(*av) * dt * arm, std::max(arm - nearest_side, scalar(0)));
    estimate = {*lv * dt, reach};
    return true;
}

} // namespace edyn
