#include "edyn/simulation/body_motion_estimate.hpp"
#include "edyn/dynamics/visit_shape.hpp"
#include "edyn/shapes/shape_bounding_radius.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

namespace {

// Below this reach (m), the AABB's bound of a turn is taken as it is, without looking at the
// shape: resting bodies turn by far less.
constexpr scalar large_turn_reach = scalar(0.001);

} // namespace

body_motion_estimate::body_motion_estimate(const settings &settings, const registry &registry)
    : dt(settings.fixed_dt)
    , dynamic(&registry.storage<dynamic_tag>())
    , linear(&registry.storage<linvel>())
    , angular(&registry.storage<angvel>())
    , centres(&registry.storage<position>())
    , offsets(&registry.storage<center_of_mass>()) {}

bool body_motion_estimate::operator()(const registry &registry, entity e, const AABB &aabb,
                                      proxy_motion_estimate &estimate) const {
    if (!dynamic->contains(e)) return false;
    auto *lv = linear->try_get(e);
    auto *av = angular->try_get(e);
    auto *centre = centres->try_get(e); // of mass
    if (lv == nullptr || av == nullptr || centre == nullptr) return false;
    if (!std::isfinite(length_sqr(*lv)) || !std::isfinite(length_sqr(*av))) return false;

    // A turn by an angle moves no point farther than the angle times the farthest the shape
    // reaches from the centre of mass. The AABB bounds that reach; where the turn is large enough
    // to matter, so does the shape's bounding sphere, and the turn keeps the shape inside the
    // sphere of that reach about the centre: no side of the AABB moves out past it.
    auto turn = length(*av) * dt;
    auto reach = turn * aabb_reach(aabb, *centre);
    if (reach > large_turn_reach) {
        auto radius =
            visit_shape(registry, e, [](const auto &shape) { return shape_bounding_radius(shape); });
        auto *com = offsets->try_get(e);
        // The origin lies the centre of mass's offset away from the centre.
        auto arm = shape_reach(aabb, *centre, radius, com != nullptr ? length(*com) : scalar(0));
        auto nearest_side = std::min(min_component(aabb.max - *centre), min_component(*centre - aabb.min));
        reach = std::min(turn * arm, std::max(arm - nearest_side, scalar(0)));
    }
    estimate = {*lv * dt, reach};
    return true;
}

bool estimate_body_motion(const settings &settings, const registry &registry, entity e, const AABB &aabb,
                          proxy_motion_estimate &estimate) {
    return body_motion_estimate{settings, registry}(registry, e, aabb, estimate);
}

} // namespace edyn
