#include "edyn/simulation/body_motion_estimate.hpp"
#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
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

bool estimate_body_motion(const settings &settings, const registry &registry, entity e, const AABB &aabb,
                          proxy_motion_estimate &estimate) {
    if (!registry.all_of<dynamic_tag>(e)) return false;
    auto *lv = registry.try_get<linvel>(e);
    auto *av = registry.try_get<angvel>(e);
    auto *centre = registry.try_get<position>(e); // of mass
    if (lv == nullptr || av == nullptr || centre == nullptr) return false;
    if (!std::isfinite(length_sqr(*lv)) || !std::isfinite(length_sqr(*av))) return false;

    auto dt = settings.fixed_dt;
    // A turn by an angle moves no point farther than the angle times the farthest the shape
    // reaches from the centre of mass. The AABB's half diagonal plus the centre's offset from the
    // box's centre bounds that reach; where the turn is large enough to matter, so does the
    // sphere about the shape's origin that holds it (plus the centre's offset from the origin),
    // whichever is smaller, and the turn keeps the shape inside the sphere of that radius about
    // the centre: no side of the AABB moves out past it (a spinning ball reaches nowhere new).
    auto turn = length(*av) * dt;
    auto arm = length(aabb_half_extents(aabb)) + distance(aabb_center(aabb), *centre);
    auto reach = turn * arm;
    if (reach > large_turn_reach) {
        auto radius =
            visit_shape(registry, e, [](const auto &shape) { return shape_bounding_radius(shape); });
        auto *com = registry.try_get<center_of_mass>(e);
        arm = std::min(arm, radius + (com != nullptr ? length(*com) : scalar(0)));
        auto nearest_side = std::min(min_component(aabb.max - *centre), min_component(*centre - aabb.min));
        reach = std::min(turn * arm, std::max(arm - nearest_side, scalar(0)));
    }
    estimate = {*lv * dt, reach};
    return true;
}

} // namespace edyn
